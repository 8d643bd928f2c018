// lanes2.h — two vectors in the two lanes of three SSE2 registers (x, y and z), for the speed work's
// hand-written loops (hand.c, contact.c): each lane then does the scalar code's operations in its
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
