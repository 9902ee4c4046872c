# Sourced by scripts/wheels.sh and scripts/wheel_tests.sh: Debian forky root filesystems
# with CPython 3.14, one per architecture, kept in $CACHE (and the step timer,
# scripts/_steps.sh).
CACHE=${DRIVEKIN_CACHE:-$HOME/.cache/drivekin-release}
MIRROR=${DEBIAN_MIRROR:-http://deb.debian.org/debian}

. "$(dirname "${BASH_SOURCE[0]}")/_steps.sh"

# native_pythons: every working CPython 3.10-3.13 on this machine (PATH, then pyenv's),
# one per minor version.
native_pythons() {
    local v py
    for v in 3.10 3.11 3.12 3.13; do
        for py in "$(command -v "python$v" || true)" \
                  "${PYENV_ROOT:-$HOME/.pyenv}"/versions/"$v".*/bin/"python$v"; do
            if [[ -x $py ]] && "$py" -c 'import sys' 2>/dev/null; then
                echo "$py"; break
            fi
        done
    done
}

# Run aarch64 binaries through qemu-user: binfmt_misc is mounted and qemu-aarch64 is
# registered from qemu-user-static's own entry (nothing else does it without systemd).
enable_qemu() {
    if [[ ! -e /proc/sys/fs/binfmt_misc/register ]]; then
        mount -t binfmt_misc binfmt_misc /proc/sys/fs/binfmt_misc
    fi
    if [[ ! -e /proc/sys/fs/binfmt_misc/qemu-aarch64 ]]; then
        grep -v '^#' /usr/lib/binfmt.d/qemu-aarch64.conf > /proc/sys/fs/binfmt_misc/register
    fi
}

# ensure_sysroot ARCH (x86_64 | aarch64): print the root filesystem's path, building it
# first if needed (about 1 minute for amd64, 6 for arm64 under emulation).
ensure_sysroot() {
    local arch=$1 deb rootfs
    case $arch in
        x86_64) deb=amd64 ;;
        aarch64) deb=arm64; enable_qemu ;;
        *) echo "unknown architecture $arch" >&2; return 1 ;;
    esac
    rootfs=$CACHE/sysroots/forky-$deb
    # libatomic1: robotpy-wpimath's aarch64 wheel links it (the differential tests).
    local packages=python3.14,python3.14-venv,python3.14-dev,libatomic1
    if [[ "$(cat "$rootfs/.complete" 2>/dev/null)" != "$packages" ]]; then
        rm -rf "$rootfs" && mkdir -p "$CACHE/sysroots"
        # Debian 12's debootstrap has no forky script; sid's serves forky.
        debootstrap --arch="$deb" --variant=minbase --include="$packages" forky "$rootfs" \
            "$MIRROR" /usr/share/debootstrap/scripts/sid >"$CACHE/sysroots/forky-$deb.log" 2>&1 \
            || { tail -n 20 "$CACHE/sysroots/forky-$deb.log" >&2; return 1; }
        echo "$packages" > "$rootfs/.complete"
    fi
    # pip inside reaches the package index with the host's resolver and CA bundle.
    cp /etc/resolv.conf "$rootfs/etc/resolv.conf"
    mkdir -p "$rootfs/etc/ssl/certs"
    cp /etc/ssl/certs/ca-certificates.crt "$rootfs/etc/ssl/certs/ca-certificates.crt"
    echo "$rootfs"
}

# in_sysroot ROOTFS CMD...: run CMD inside ROOTFS with a clean environment (no host pip
# configuration, no compiler: the root filesystems have none) and /proc, /dev mounted.
# QEMU_CPU: qemu-user emulates SystemCore's own core, a Cortex-A76 (ARMv8.2, NEON, no
# SVE). Its default CPU, "max", offers SVE and SME, and numpy's aarch64 wheel then runs
# OpenBLAS's ARMv9 SME kernels ("Core: armv9sme"), which return wrong numbers there under
# qemu 7.2 and 11.1 alike (np.linalg.pinv of an 8 x 3 matrix came back half filled with
# denormals): the wrong swerve results first seen under emulation were that, not
# drivekin. x86_64 binaries ignore the variable.
in_sysroot() {
    local rootfs=$1; shift
    mountpoint -q "$rootfs/proc" || mount -t proc proc "$rootfs/proc"
    mountpoint -q "$rootfs/dev" || mount --bind /dev "$rootfs/dev"
    env -i HOME=/root LANG=C.UTF-8 PATH=/usr/local/bin:/usr/bin:/bin \
        QEMU_CPU=cortex-a76 \
        PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_CERT=/etc/ssl/certs/ca-certificates.crt \
        ${IN_SYSROOT_ENV:-} /usr/sbin/chroot "$rootfs" "$@"
}

# release_sysroot ROOTFS: undo in_sysroot's mounts. A process the tests started can still
# be exiting inside the root filesystem when they end ("target is busy", seen once in a CI
# dry run): a few tries, then a lazy unmount, which the kernel completes once it is gone.
release_sysroot() {
    local rootfs=$1 m try
    for m in "$rootfs/src" "$rootfs/dev" "$rootfs/proc"; do
        for try in 1 2 3 4 5; do
            mountpoint -q "$m" || break
            umount "$m" 2>/dev/null && break
            sleep 1
        done
        if mountpoint -q "$m"; then umount -l "$m"; fi
    done
}
