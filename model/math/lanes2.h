// lanes2.h — two vectors in the two lanes of three SSE2 registers (x, y and z), for the speed work's
// hand-written loops (hand.c, contact_part.h, contact_cull.c): each lane then does the scalar code's operations in its
// order, so the bits are the scalar code's. Without SSE2 those loops take the scalar path.
#ifndef HS_LANES2_H
#define HS_LANES2_H

#if defined(__SSE2__)
#include <emmintrin.h>

#include "hs_math.h"

typedef struct hs_lanes2 {
	__m128d x, y, z;
} hs_lanes2;

// a in the low lane, b in the high one.
static inline hs_lanes2 hs_lanes2_load(const hs_vec3 *a, const hs_vec3 *b) {
	hs_lanes2 l = {_mm_set_pd(b->x, a->x), _mm_set_pd(b->y, a->y), _mm_set_pd(b->z, a->z)};
	return l;
}

// hs_quat_rotate(q, v) of both lanes: t = 2 (u x v), then (v + w t) + u x t, in its order.
static inline hs_lanes2 hs_lanes2_rotate(hs_quat q, hs_lanes2 v) {
	const __m128d ux = _mm_set1_pd(q.x), uy = _mm_set1_pd(q.y), uz = _mm_set1_pd(q.z), w = _mm_set1_pd(q.w),
	              two = _mm_set1_pd(2.0);
	__m128d tx = _mm_mul_pd(_mm_sub_pd(_mm_mul_pd(uy, v.z), _mm_mul_pd(uz, v.y)), two);
	__m128d ty = _mm_mul_pd(_mm_sub_pd(_mm_mul_pd(uz, v.x), _mm_mul_pd(ux, v.z)), two);
	__m128d tz = _mm_mul_pd(_mm_sub_pd(_mm_mul_pd(ux, v.y), _mm_mul_pd(uy, v.x)), two);
	hs_lanes2 o = {_mm_add_pd(_mm_add_pd(v.x, _mm_mul_pd(tx, w)), _mm_sub_pd(_mm_mul_pd(uy, tz), _mm_mul_pd(uz, ty))),
	               _mm_add_pd(_mm_add_pd(v.y, _mm_mul_pd(ty, w)), _mm_sub_pd(_mm_mul_pd(uz, tx), _mm_mul_pd(ux, tz))),
	               _mm_add_pd(_mm_add_pd(v.z, _mm_mul_pd(tz, w)), _mm_sub_pd(_mm_mul_pd(ux, ty), _mm_mul_pd(uy, tx)))};
	return o;
}

static inline void hs_lanes2_store(hs_lanes2 l, hs_vec3 *a, hs_vec3 *b) {
	_mm_storel_pd(&a->x, l.x);
	_mm_storel_pd(&a->y, l.y);
	_mm_storel_pd(&a->z, l.z);
	_mm_storeh_pd(&b->x, l.x);
	_mm_storeh_pd(&b->y, l.y);
	_mm_storeh_pd(&b->z, l.z);
}
#endif

#endif
