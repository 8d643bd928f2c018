// detmath.h — the exact building blocks of the deterministic elementary functions (detmath.c,
// detmath_exp.c): bit access, powers of two, and sums and products as unevaluated hi + lo pairs.
#ifndef HS_DETMATH_H
#define HS_DETMATH_H

#include <stdint.h>
#include <string.h>

#include "hs_math.h"

typedef struct dd {
	double hi, lo; // value hi + lo, |lo| <= ulp(hi) / 2 unless said otherwise
} dd;

#define SHIFT 0x1.8p52 // (v + SHIFT) - SHIFT rounds v to an integer for |v| < 2^51
#define MANT_MASK 0x000fffffffffffffULL

static inline uint64_t bits_of(double x) {
	uint64_t u;
	memcpy(&u, &x, sizeof u);
	return u;
}
static inline double from_bits(uint64_t u) {
	double x;
	memcpy(&x, &u, sizeof x);
	return x;
}
// 2^m for -1022 <= m <= 1023
static inline double pow2i(int m) { return from_bits((uint64_t)(m + 1023) << 52); }

// a + b exactly (Knuth)
static inline dd two_sum(double a, double b) {
	double s = a + b, bb = s - a;
	dd r = {s, (a - (s - bb)) + (b - bb)};
	return r;
}
// a + b exactly when |a| >= |b| (Dekker)
static inline dd fast_two_sum(double a, double b) {
	double s = a + b;
	dd r = {s, b - (s - a)};
	return r;
}
// a * b exactly (Dekker with Veltkamp splitting: no FMA, so every CPU agrees); |a|, |b| < 2^995
static inline dd two_prod(double a, double b) {
	double ca = 134217729.0 * a, cb = 134217729.0 * b;
	double ah = ca - (ca - a), al = a - ah;
	double bh = cb - (cb - b), bl = b - bh;
	double p = a * b;
	dd r = {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
	return r;
}

#endif
