# Sourced by .ci/run, scripts/wheels.sh and scripts/wheel_tests.sh: the step timer.
#
# `step NAME` closes the previous step (prints its wall time) and opens NAME; `step ""`
# closes the last one. With DRIVEKIN_STEP_LOG set (.ci/run sets it), every closed step is
# also appended to that file as "lane<TAB>start<TAB>seconds<TAB>name", the lane being
# DRIVEKIN_LANE (steps of one lane run one after another; lanes run side by side), the
# start in seconds since the epoch; `step_table` prints the file as the run's table.

step_start=$(date +%s)
step() {
    local now
    now=$(date +%s)
    if [[ -n "${step_name:-}" ]]; then
        printf '== %-52s %4d s\n' "$step_name" $((now - step_start))
        if [[ -n "${DRIVEKIN_STEP_LOG:-}" ]]; then
            printf '%s\t%d\t%d\t%s\n' "${DRIVEKIN_LANE:-main}" "$step_start" \
                $((now - step_start)) "$step_name" >>"$DRIVEKIN_STEP_LOG"
        fi
    fi
    step_name=$1 step_start=$now
    [[ -n "$1" ]] && echo "-- $1"
    return 0
}

# step_table FILE T0: every step of FILE in order of its start, with its start as
# minutes:seconds after T0, then the run's wall time.
step_table() {
    local file=$1 t0=$2 end
    end=$(date +%s)
    echo
    echo "Step table (wall time; steps of different lanes overlap)"
    printf '%-6s %-8s %-6s  %s\n' start lane wall step
    sort -t $'\t' -k2,2n "$file" | while IFS=$'\t' read -r lane start secs name; do
        printf '%02d:%02d  %-8s %4d s  %s\n' $(((start - t0) / 60)) $(((start - t0) % 60)) \
            "$lane" "$secs" "$name"
    done
    printf 'total: %d s (%d min %d s)\n' $((end - t0)) $(((end - t0) / 60)) $(((end - t0) % 60))
}
