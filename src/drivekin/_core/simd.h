/* Array forms of the transcendental functions drivekin.batch needs, in two builds.
 *
 * Default: plain loops over libm's sin, cos and atan2, so the batch module performs the same
 * operations, in the same order, as the per-call kernels (bit-identical results).
 *
 * DRIVEKIN_SIMD (setup.py's DRIVEKIN_SIMD=1, compiled with -mavx2 -mfma, linked with -lmvec):
 * four values per call to glibc's libmvec AVX2 variants. They are not correctly rounded
 * (glibc documents at most 4 ulp for these), so results differ from the default build in
 * the last bits; NaN and infinities still propagate as libm's do.
 *
 * A ragged tail goes through the same vector function (padded with zeros), so a value's
 * result does not depend on where it sits in the array.
 */
#ifndef DRIVEKIN_SIMD_H
#define DRIVEKIN_SIMD_H

#include <math.h>
#include <stddef.h>

#ifdef DRIVEKIN_SIMD
#include <immintrin.h>

#define DK_SIMD 1

/* The instructions this build uses are available on the running CPU. */
static inline int dk_cpu_ok(void) {
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

/* libmvec's x86_64 vector ABI: the 'd' ISA class (AVX2) takes and returns ymm registers,
 * which is exactly how gcc passes __m256d under -mavx2. (libmvec's sincos takes a vector of
 * output pointers and measured slower here than a sin and a cos.) */
extern __m256d _ZGVdN4v_sin(__m256d x);
extern __m256d _ZGVdN4v_cos(__m256d x);
extern __m256d _ZGVdN4vv_atan2(__m256d y, __m256d x);

/* s[i] = sin(x[i]), c[i] = cos(x[i]) for i < n. */
static inline void dk_sincos_n(ptrdiff_t n, const double* x, double* s, double* c) {
    ptrdiff_t i = 0, k;
    double xt[4] = {0.0, 0.0, 0.0, 0.0}, st[4], ct[4];
    __m256d v;
    for (; i + 4 <= n; i += 4) {
        v = _mm256_loadu_pd(x + i);
        _mm256_storeu_pd(s + i, _ZGVdN4v_sin(v));
        _mm256_storeu_pd(c + i, _ZGVdN4v_cos(v));
    }
    if (i < n) {
        for (k = 0; i + k < n; k++)
            xt[k] = x[i + k];
        v = _mm256_loadu_pd(xt);
        _mm256_storeu_pd(st, _ZGVdN4v_sin(v));
        _mm256_storeu_pd(ct, _ZGVdN4v_cos(v));
        for (k = 0; i + k < n; k++) {
            s[i + k] = st[k];
            c[i + k] = ct[k];
        }
    }
}

/* r[i] = atan2(y[i], x[i]) for i < n. */
static inline void dk_atan2_n(ptrdiff_t n, const double* y, const double* x, double* r) {
    ptrdiff_t i = 0, k;
    double yt[4] = {0.0, 0.0, 0.0, 0.0}, xt[4] = {1.0, 1.0, 1.0, 1.0}, rt[4];
    for (; i + 4 <= n; i += 4)
        _mm256_storeu_pd(r + i, _ZGVdN4vv_atan2(_mm256_loadu_pd(y + i), _mm256_loadu_pd(x + i)));
    if (i < n) {
        for (k = 0; i + k < n; k++) {
            yt[k] = y[i + k];
            xt[k] = x[i + k];
        }
        _mm256_storeu_pd(rt, _ZGVdN4vv_atan2(_mm256_loadu_pd(yt), _mm256_loadu_pd(xt)));
        for (k = 0; i + k < n; k++)
            r[i + k] = rt[k];
    }
}

#else  /* scalar libm: the per-call kernels' exact operations */

#define DK_SIMD 0

static inline int dk_cpu_ok(void) { return 1; }

static inline void dk_sincos_n(ptrdiff_t n, const double* x, double* s, double* c) {
    ptrdiff_t i;
    for (i = 0; i < n; i++) {
        /* cos before sin, as rot_rad does (gcc fuses the pair into one sincos either way). */
        c[i] = cos(x[i]);
        s[i] = sin(x[i]);
    }
}

static inline void dk_atan2_n(ptrdiff_t n, const double* y, const double* x, double* r) {
    ptrdiff_t i;
    for (i = 0; i < n; i++)
        r[i] = atan2(y[i], x[i]);
}

#endif
#endif
