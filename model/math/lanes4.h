// lanes4.h — four vectors in the four lanes of three AVX registers (x, y and z), lanes2.h's twice
// as wide: each lane does the scalar code's operations in its order, so the bits are the scalar
// code's (AVX has the same IEEE operations as SSE2; no fused multiply-add is asked for). Only
// functions compiled for AVX (HS_AVX) may call these, and only where the CPU has AVX
// (hs_cpu_has_avx): the library's own flags stay those of every x86-64. -DHS_NO_AVX leaves them
// out (the determinism matrix's gcc-noavx build: the SSE2 paths on this CPU).
#ifndef HS_LANES4_H
#define HS_LANES4_H

#if defined(__x86_64__) && defined(__GNUC__) && !defined(HS_NO_AVX)
#define HS_LANES4 1
#include <immintrin.h>
#include <stdbool.h>

#include "hs_math.h"

#define HS_AVX __attribute__((target("avx")))

typedef struct hs_lanes4 {
	__m256d x, y, z;
} hs_lanes4;

static inline bool hs_cpu_has_avx(void) { return __builtin_cpu_supports("avx"); }

// Four vectors kept as rows of x, y and z `stride` apart (hand.c, point_rows): x[0 .. 3],
// x[stride ..], x[2 stride ..].
HS_AVX static inline hs_lanes4 hs_lanes4_rows(const double *x, int stride) {
	hs_lanes4 l = {_mm256_loadu_pd(x), _mm256_loadu_pd(x + stride), _mm256_loadu_pd(x + 2 * stride)};
	return l;
}

// !(d > r) of each lane as bits 0 .. 3: NaN near (SSE2's cmpngt).
HS_AVX static inline unsigned hs_lanes4_not_above(__m256d d, double r) {
	return (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(d, _mm256_set1_pd(r), _CMP_NGT_US));
}

// |p - c|^2 of each lane, hs_length_sq(hs_sub(p, c))'s operations in their order.
HS_AVX static inline __m256d hs_lanes4_distance_sq(hs_lanes4 p, hs_vec3 c) {
	__m256d dx = _mm256_sub_pd(p.x, _mm256_set1_pd(c.x)), dy = _mm256_sub_pd(p.y, _mm256_set1_pd(c.y)),
	        dz = _mm256_sub_pd(p.z, _mm256_set1_pd(c.z));
	return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
}

// The squared distance from c to each lane's segment a-b: hs_segment_param's and the distance's
// operations in their order, the division too (contact_part.h, segment_distance_sq).
HS_AVX static inline __m256d hs_lanes4_segment_distance_sq(hs_lanes4 a, hs_lanes4 b, hs_vec3 c) {
	const __m256d cx = _mm256_set1_pd(c.x), cy = _mm256_set1_pd(c.y), cz = _mm256_set1_pd(c.z),
	              zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
	__m256d ex = _mm256_sub_pd(b.x, a.x), ey = _mm256_sub_pd(b.y, a.y), ez = _mm256_sub_pd(b.z, a.z);
	__m256d len_sq = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ex, ex), _mm256_mul_pd(ey, ey)), _mm256_mul_pd(ez, ez));
	__m256d dot = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_sub_pd(cx, a.x), ex), _mm256_mul_pd(_mm256_sub_pd(cy, a.y), ey)),
	                            _mm256_mul_pd(_mm256_sub_pd(cz, a.z), ez));
	__m256d u = _mm256_and_pd(_mm256_cmp_pd(len_sq, zero, _CMP_GT_OS), _mm256_div_pd(dot, len_sq)); // 0: a point
	u = _mm256_andnot_pd(_mm256_cmp_pd(u, zero, _CMP_LT_OS), u);                                     // u < 0: 0 (NaN kept)
	__m256d above = _mm256_cmp_pd(u, one, _CMP_GT_OS);
	u = _mm256_or_pd(_mm256_and_pd(above, one), _mm256_andnot_pd(above, u)); // u > 1: 1
	__m256d dx = _mm256_sub_pd(_mm256_add_pd(a.x, _mm256_mul_pd(u, ex)), cx);
	__m256d dy = _mm256_sub_pd(_mm256_add_pd(a.y, _mm256_mul_pd(u, ey)), cy);
	__m256d dz = _mm256_sub_pd(_mm256_add_pd(a.z, _mm256_mul_pd(u, ez)), cz);
	return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
}
#else
#define HS_LANES4 0
#endif

#endif
