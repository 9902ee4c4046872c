"""Derive the constants of drivekin's own sin, cos and atan2 (src/drivekin/_core/dkmath.h).

The polynomials are minimax (Remez exchange, in mpmath at 60 digits) for the reduced
arguments the functions use, each fixing its leading Taylor terms:

    sin r = r + r^3 P(r^2)              |r| <= pi/4, P: 6 coefficients, relative error
    cos r = 1 - r^2/2 + r^4 Q(r^2)      |r| <= pi/4, Q: 6 coefficients, relative error
    atan u = u + u^3 A(u^2)             |u| <= tan(pi/8), A: 10 coefficients, relative error

and the splits of pi/2 (three 33-bit parts and a tail, for Cody-Waite reduction) and
pi/4, as well as the bits of 2/pi for the Payne-Hanek reduction of huge arguments. Every
coefficient is rounded to the nearest double.

    python scripts/trig_coefficients.py            # print the C block
    python scripts/trig_coefficients.py --check    # exit 1 unless dkmath.h holds it

tests/reference/test_trig_accuracy.py runs --check, so the header's numbers are the ones
this script derives.
"""
from __future__ import annotations

import argparse
import pathlib
import sys

import mpmath as mp

mp.mp.dps = 60
HEADER = pathlib.Path(__file__).resolve().parent.parent / "src/drivekin/_core/dkmath.h"
BEGIN, END = "/* BEGIN trig_coefficients.py */", "/* END trig_coefficients.py */"


def remez(f, w, a, b, degree, iterations=40, grid=4000):
    """Coefficients c[0..degree] of the polynomial p(z) minimising max |w(z)(f(z) - p(z))|
    on [a, b], and that maximum."""
    n = degree + 2
    pts = [(a + b) / 2 - (b - a) / 2 * mp.cos(mp.pi * i / (n - 1)) for i in range(n)]
    err = None
    for _ in range(iterations):
        # Solve p(z_i) + (-1)^i E / w(z_i) = f(z_i) for the coefficients and E.
        rows = [[z ** j for j in range(degree + 1)] + [(-1) ** i / w(z)]
                for i, z in enumerate(pts)]
        sol = mp.lu_solve(mp.matrix(rows), mp.matrix([f(z) for z in pts]))
        c = [sol[j] for j in range(degree + 1)]

        def e(z):
            return w(z) * (f(z) - mp.polyval(c[::-1], z))

        # The error's local extrema: a dense grid, then each refined by golden section.
        zs = [a + (b - a) * i / grid for i in range(grid + 1)]
        es = [e(z) for z in zs]
        ext = [0]
        for i in range(1, grid):
            if (es[i] - es[i - 1]) * (es[i + 1] - es[i]) <= 0:
                ext.append(i)
        ext.append(grid)
        refined = []
        for i in ext:
            if i in (0, grid):
                refined.append(zs[i])
                continue
            lo, hi = zs[i - 1], zs[i + 1]
            sgn = 1 if es[i] > 0 else -1
            for _ in range(60):
                m1, m2 = lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618
                if sgn * e(m1) > sgn * e(m2):
                    hi = m2
                else:
                    lo = m1
            refined.append((lo + hi) / 2)
        # Keep one point per sign change (the largest), n of them in all.
        groups = []
        for z in refined:
            v = e(z)
            if groups and (groups[-1][1] > 0) == (v > 0):
                if abs(v) > abs(groups[-1][1]):
                    groups[-1] = (z, v)
            else:
                groups.append((z, v))
        while len(groups) > n:
            groups.pop(0 if abs(groups[0][1]) < abs(groups[-1][1]) else -1)
        pts = [z for z, _ in groups]
        mags = [abs(v) for _, v in groups]
        err = max(mags)
        if len(pts) == n and max(mags) / min(mags) < 1 + mp.mpf("1e-9"):
            break
    return c, err


def _odd(fn):
    """(fn(r) - r) / r^3 as a function of z = r^2 (fn odd, fn(r) = r + O(r^3))."""
    def f(z):
        r = mp.sqrt(z)
        return (fn(r) - r) / (z * r)
    return f


def polynomials():
    """name -> (coefficients, error bound on the relative error of the whole function)."""
    out = {}
    # The weight turns the error of the fitted part into the relative error of the function.
    b = (mp.pi / 4) ** 2
    out["SIN"] = remez(_odd(mp.sin), lambda z: z * mp.sqrt(z) / mp.sin(mp.sqrt(z)),
                       b * mp.mpf("1e-12"), b, 5)
    out["COS"] = remez(lambda z: (mp.cos(mp.sqrt(z)) - 1 + z / 2) / z ** 2,
                       lambda z: z ** 2 / mp.cos(mp.sqrt(z)), b * mp.mpf("1e-12"), b, 5)
    t = mp.tan(mp.pi / 8) ** 2
    out["ATAN"] = remez(_odd(mp.atan), lambda z: z * mp.sqrt(z) / mp.atan(mp.sqrt(z)),
                        t * mp.mpf("1e-12"), t, ATAN_DEGREE)
    return out


ATAN_DEGREE = 10


def hexd(x) -> str:
    """A double as a C hexadecimal literal (exact)."""
    return float(x).hex()


def split(value, bits, parts):
    """value as `parts` doubles, each of the first parts-1 holding at most `bits`
    significant bits (so that k * part is exact for |k| < 2**(53 - bits)), and the last
    the rounded rest."""
    out, rest = [], mp.mpf(value)
    for _ in range(parts - 1):
        e = mp.floor(mp.log(abs(rest), 2))
        q = mp.mpf(2) ** (e - bits + 1)
        head = mp.floor(rest / q) * q
        out.append(head)
        rest -= head
    out.append(mp.mpf(float(rest)))
    return out


def two_over_pi_words(count: int):
    """The first 32 * count bits of the fraction of 2/pi, as 32-bit words."""
    with mp.workdps(32 * count // 3 + 40):
        v = 2 / mp.pi
        return [int(mp.floor(v * mp.mpf(2) ** (32 * (i + 1)))) % 2 ** 32 for i in range(count)]


def block() -> str:
    lines = [BEGIN,
             "/* Generated by scripts/trig_coefficients.py (mpmath); do not edit by hand. */"]
    for name, (c, e) in polynomials().items():
        lines.append(f"/* {name}: minimax, |relative error| <= 2^{float(mp.log(e, 2)):.1f} */")
        for j, x in enumerate(c):
            lines.append(f"#define DK_{name}{j} {hexd(x)}")
    p1, p2, p3, p4 = split(mp.pi / 2, 33, 4)
    lines.append("/* pi/2 = PIO2_1 + PIO2_2 + PIO2_3 + PIO2_4: 33-bit parts and the rest */")
    for n, v in zip(("PIO2_1", "PIO2_2", "PIO2_3", "PIO2_4"), (p1, p2, p3, p4)):
        lines.append(f"#define DK_{n} {hexd(v)}")
    hi, lo = split(mp.pi / 2, 53, 2)
    lines.append(f"#define DK_PIO2_HI {hexd(hi)}")
    lines.append(f"#define DK_PIO2_LO {hexd(lo)}")
    lines.append("/* pi/4 = PIO4_A + PIO4_B, PIO4_A with 50 bits (m * PIO4_A exact for m <= 4) */")
    a, b = split(mp.pi / 4, 50, 2)
    lines.append(f"#define DK_PIO4_A {hexd(a)}")
    lines.append(f"#define DK_PIO4_B {hexd(b)}")
    lines.append(f"#define DK_TWO_OVER_PI {hexd(2 / mp.pi)}")
    lines.append(f"#define DK_TAN_PI_8 {hexd(mp.tan(mp.pi / 8))}")
    # 70 words reach exponent 2047: the largest double's, and that of a product of two
    # doubles (dk_sincos_scaled, for omega*dt in discretize).
    words = two_over_pi_words(70)
    lines.append("/* The fraction bits of 2/pi, 32 to a word, after two zero words (Payne-Hanek). */")
    lines.append("static const uint32_t dk_two_over_pi_bits[72] = {")
    padded = [0, 0] + words
    for i in range(0, 72, 6):
        lines.append("    " + ", ".join(f"0x{w:08x}u" for w in padded[i:i + 6]) + ",")
    lines.append("};")
    lines.append(END)
    return "\n".join(lines)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    text = block()
    if not args.check:
        print(text)
        return 0
    header = HEADER.read_text()
    start, end = header.find(BEGIN), header.find(END)
    if start < 0 or end < 0 or header[start:end + len(END)] != text:
        print(f"{HEADER} does not hold this script's constants; paste its output there",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
