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

// Four vectors in a row, v[0] .. v[3] (12 doubles: 3 loads of two and 3 of two into the high
// halves, then 3 shuffles).
HS_AVX static inline hs_lanes4 hs_lanes4_load(const hs_vec3 *v) {
	__m256d a = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(&v[0].x)), _mm_loadu_pd(&v[2].x), 1); // x0 y0 | x2 y2
	__m256d b = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(&v[0].z)), _mm_loadu_pd(&v[2].z), 1); // z0 x1 | z2 x3
	__m256d c = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(&v[1].y)), _mm_loadu_pd(&v[3].y), 1); // y1 z1 | y3 z3
	hs_lanes4 l = {_mm256_shuffle_pd(a, b, 0xA), _mm256_shuffle_pd(a, c, 0x5), _mm256_shuffle_pd(b, c, 0xA)};
	return l;
}

// The four lanes into v[0] .. v[3], in a row: hs_lanes4_load's shuffles backwards.
HS_AVX static inline void hs_lanes4_store(hs_lanes4 l, hs_vec3 *v) {
	__m256d a = _mm256_shuffle_pd(l.x, l.y, 0x0), b = _mm256_shuffle_pd(l.z, l.x, 0xA), c = _mm256_shuffle_pd(l.y, l.z, 0xF);
	_mm_storeu_pd(&v[0].x, _mm256_castpd256_pd128(a));
	_mm_storeu_pd(&v[0].z, _mm256_castpd256_pd128(b));
	_mm_storeu_pd(&v[1].y, _mm256_castpd256_pd128(c));
	_mm_storeu_pd(&v[2].x, _mm256_extractf128_pd(a, 1));
	_mm_storeu_pd(&v[2].z, _mm256_extractf128_pd(b, 1));
	_mm_storeu_pd(&v[3].y, _mm256_extractf128_pd(c, 1));
}

// The four lanes into *p0 .. *p3, wherever they are.
HS_AVX static inline void hs_lanes4_store_each(hs_lanes4 l, hs_vec3 *p0, hs_vec3 *p1, hs_vec3 *p2, hs_vec3 *p3) {
	__m256d even = _mm256_shuffle_pd(l.x, l.y, 0x0), odd = _mm256_shuffle_pd(l.x, l.y, 0xF); // x0 y0 | x2 y2, x1 y1 | x3 y3
	__m128d z01 = _mm256_castpd256_pd128(l.z), z23 = _mm256_extractf128_pd(l.z, 1);
	_mm_storeu_pd(&p0->x, _mm256_castpd256_pd128(even));
	_mm_storel_pd(&p0->z, z01);
	_mm_storeu_pd(&p1->x, _mm256_castpd256_pd128(odd));
	_mm_storeh_pd(&p1->z, z01);
	_mm_storeu_pd(&p2->x, _mm256_extractf128_pd(even, 1));
	_mm_storel_pd(&p2->z, z23);
	_mm_storeu_pd(&p3->x, _mm256_extractf128_pd(odd, 1));
	_mm_storeh_pd(&p3->z, z23);
}

// hs_quat_rotate(q, v) of each lane: t = 2 (u x v), then (v + w t) + u x t, in its order (lanes2.h's
// hs_lanes2_rotate four wide).
HS_AVX static inline hs_lanes4 hs_lanes4_rotate(hs_quat q, hs_lanes4 v) {
	const __m256d ux = _mm256_set1_pd(q.x), uy = _mm256_set1_pd(q.y), uz = _mm256_set1_pd(q.z), w = _mm256_set1_pd(q.w),
	              two = _mm256_set1_pd(2.0);
	__m256d tx = _mm256_mul_pd(_mm256_sub_pd(_mm256_mul_pd(uy, v.z), _mm256_mul_pd(uz, v.y)), two);
	__m256d ty = _mm256_mul_pd(_mm256_sub_pd(_mm256_mul_pd(uz, v.x), _mm256_mul_pd(ux, v.z)), two);
	__m256d tz = _mm256_mul_pd(_mm256_sub_pd(_mm256_mul_pd(ux, v.y), _mm256_mul_pd(uy, v.x)), two);
	hs_lanes4 o = {
	    _mm256_add_pd(_mm256_add_pd(v.x, _mm256_mul_pd(tx, w)), _mm256_sub_pd(_mm256_mul_pd(uy, tz), _mm256_mul_pd(uz, ty))),
	    _mm256_add_pd(_mm256_add_pd(v.y, _mm256_mul_pd(ty, w)), _mm256_sub_pd(_mm256_mul_pd(uz, tx), _mm256_mul_pd(ux, tz))),
	    _mm256_add_pd(_mm256_add_pd(v.z, _mm256_mul_pd(tz, w)), _mm256_sub_pd(_mm256_mul_pd(ux, ty), _mm256_mul_pd(uy, tx)))};
	return o;
}

// w + m v of each lane: hs_add(w, hs_mat3_mul(m, v))'s products and sums in their order.
HS_AVX static inline hs_lanes4 hs_lanes4_place(hs_mat3 m, hs_vec3 w, hs_lanes4 v) {
	hs_lanes4 o = {
	    _mm256_add_pd(_mm256_set1_pd(w.x), _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(m.r0.x), v.x),
	                                                                   _mm256_mul_pd(_mm256_set1_pd(m.r0.y), v.y)),
	                                                     _mm256_mul_pd(_mm256_set1_pd(m.r0.z), v.z))),
	    _mm256_add_pd(_mm256_set1_pd(w.y), _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(m.r1.x), v.x),
	                                                                   _mm256_mul_pd(_mm256_set1_pd(m.r1.y), v.y)),
	                                                     _mm256_mul_pd(_mm256_set1_pd(m.r1.z), v.z))),
	    _mm256_add_pd(_mm256_set1_pd(w.z), _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(m.r2.x), v.x),
	                                                                   _mm256_mul_pd(_mm256_set1_pd(m.r2.y), v.y)),
	                                                     _mm256_mul_pd(_mm256_set1_pd(m.r2.z), v.z)))};
	return o;
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
