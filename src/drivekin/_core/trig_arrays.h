/* Array forms of dkmath.h's sin/cos and atan2 for drivekin.batch, vectorised by the compiler
 * from the scalar source: each loop runs the branch-free core on every element, then a
 * second pass sends the rare |x| >= 2^20 (and non-finite) elements through the scalar
 * huge-argument path, so every element gets exactly what dk_sincos / dk_atan2 give it,
 * whatever the vector width and wherever it sits in the array.
 *
 * x86_64: the baseline (SSE2, two doubles a vector) is built as is, and the same loops are
 * built again for AVX2 (four) and AVX-512; the first call picks the best the CPU has.
 * None contracts to FMA (-ffp-contract=off), so all give the same bits.
 * aarch64: NEON is baseline, so there is one build.
 *
 * The outputs must not overlap the inputs (restrict). Per-call loops over a drivetrain's
 * modules use these too (the same bits as one dk_sincos / dk_atan2 per module, fewer
 * instructions).
 */
#ifndef DRIVEKIN_TRIG_ARRAYS_H
#define DRIVEKIN_TRIG_ARRAYS_H

#include <stddef.h>
#include "dkmath.h"

#define DK_SINCOS_LOOP(n, x, s, c)                                                     \
    do {                                                                               \
        ptrdiff_t i_;                                                                  \
        for (i_ = 0; i_ < (n); i_++)                                                   \
            dk_sincos_core((x)[i_], &(s)[i_], &(c)[i_]);                               \
        for (i_ = 0; i_ < (n); i_++)                                                   \
            if (!dk_trig_common((x)[i_]))                                              \
                dk_sincos_huge((x)[i_], &(s)[i_], &(c)[i_]);                           \
    } while (0)

#define DK_ATAN2_LOOP(n, y, x, r)                                                      \
    do {                                                                               \
        ptrdiff_t i_;                                                                  \
        for (i_ = 0; i_ < (n); i_++)                                                   \
            (r)[i_] = dk_atan2_core((y)[i_], (x)[i_]);                                 \
    } while (0)

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(__AVX2__)
/* Not every module that includes this uses every function. */
#define DK_MAYBE_UNUSED __attribute__((unused))

/* One loop pair per instruction set, from the same source. AVX-512 (F, DQ, VL) keeps
 * 256-bit vectors but gains mask registers and 32 of them: measured 1.7x AVX2's speed on
 * an AMD EPYC (Zen 4). */
#define DK_LOOPS(suffix, attrs)                                                        \
    attrs static void dk_sincos_n_##suffix(ptrdiff_t n, const double* __restrict x,      \
                                           double* __restrict s, double* __restrict c) { \
        DK_SINCOS_LOOP(n, x, s, c);                                                    \
    }                                                                                  \
    attrs static void dk_atan2_n_##suffix(ptrdiff_t n, const double* __restrict y,       \
                                          const double* __restrict x,                  \
                                          double* __restrict r) {                      \
        DK_ATAN2_LOOP(n, y, x, r);                                                     \
    }

DK_LOOPS(base, DK_MAYBE_UNUSED)
DK_LOOPS(avx2, __attribute__((target("avx2"), unused)))
DK_LOOPS(avx512, __attribute__((target("avx512f,avx512dq,avx512vl"), unused)))

/* The instruction set in use: 0 SSE2, 1 AVX2, 2 AVX-512, -1 not yet decided. Decided by
 * the first call (every thread that races there writes the same value), changed only by
 * the test hook dk_trig_use. */
static int dk_isa = -1;
static const char* const dk_isa_names[3] = {"SSE2", "AVX2", "AVX-512"};

static int dk_isa_supported(int isa) {
    __builtin_cpu_init();
    if (isa == 2)
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq")
               && __builtin_cpu_supports("avx512vl");
    if (isa == 1)
        return __builtin_cpu_supports("avx2");
    return isa == 0;
}

DK_MAYBE_UNUSED static int dk_trig_init(void) {
    dk_isa = dk_isa_supported(2) ? 2 : (dk_isa_supported(1) ? 1 : 0);
    return 0;
}

DK_MAYBE_UNUSED static const char* dk_trig_isa(void) {
    if (dk_isa < 0)
        dk_trig_init();
    return dk_isa_names[dk_isa];
}

/* Select an instruction set by name (for tests): 0 if done, -1 if unknown or unsupported. */
DK_MAYBE_UNUSED static int dk_trig_use(const char* name) {
    int isa;
    for (isa = 0; isa < 3; isa++) {
        if (strcmp(name, dk_isa_names[isa]) == 0 && dk_isa_supported(isa)) {
            dk_isa = isa;
            return 0;
        }
    }
    return -1;
}

DK_CALL static void dk_sincos_n(ptrdiff_t n, const double* x, double* s, double* c) {
    if (dk_isa < 0)
        dk_trig_init();
    if (dk_isa == 2)
        dk_sincos_n_avx512(n, x, s, c);
    else if (dk_isa == 1)
        dk_sincos_n_avx2(n, x, s, c);
    else
        dk_sincos_n_base(n, x, s, c);
}

DK_CALL static void dk_atan2_n(ptrdiff_t n, const double* y, const double* x, double* r) {
    if (dk_isa < 0)
        dk_trig_init();
    if (dk_isa == 2)
        dk_atan2_n_avx512(n, y, x, r);
    else if (dk_isa == 1)
        dk_atan2_n_avx2(n, y, x, r);
    else
        dk_atan2_n_base(n, y, x, r);
}

#else /* one build: what the compiler targets */

static inline int dk_trig_init(void) { return 0; }

static inline const char* dk_trig_isa(void) {
#if defined(__AVX2__)
    return "AVX2";
#elif defined(__x86_64__) || defined(__SSE2__)
    return "SSE2";
#elif defined(__ARM_NEON) || defined(__aarch64__)
    return "NEON";
#else
    return "scalar";
#endif
}

static inline int dk_trig_use(const char* name) { return strcmp(name, dk_trig_isa()) == 0 ? 0 : -1; }

DK_CALL static void dk_sincos_n(ptrdiff_t n, const double* __restrict x,
                                double* __restrict s, double* __restrict c) {
    DK_SINCOS_LOOP(n, x, s, c);
}

DK_CALL static void dk_atan2_n(ptrdiff_t n, const double* __restrict y,
                               const double* __restrict x, double* __restrict r) {
    DK_ATAN2_LOOP(n, y, x, r);
}

#endif
#endif
