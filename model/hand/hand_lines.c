// hand_lines.c — the 60 check lines of the 1999 paper §3.1 (Fig. 1): each finger segment's four
// long edges of the square prism around its axis, from the segment's ends and frame (the glove's
// kinematics, hand.c, and the joint-driven hands, hand_joints.c, both place them so).
#include <string.h>
#if defined(HS_SELFCHECK)
#include <stdio.h>
#include <stdlib.h>
#endif

#include "hand_internal.h"
#include "lanes2.h"
#include "lanes4.h"

static hs_vec3 mirror_if(bool left, hs_vec3 v) { return left ? hs_v3(v.x, -v.y, v.z) : v; }

// A segment's 4 check lines from its ends a, b and its frame q: line e runs from a + off to b + off,
// off = hs_quat_rotate(q, v[e]) for the offsets v of a finger of radius rad, mirrored for a left
// hand. With SSE2, two lines at a time, one per lane: each lane does hs_quat_rotate's products and
// sums, then the additions, in their order (the same bits); the mirror is the sign of y.
static void segment_lines(hs_quat q, double rad, hs_vec3 a, hs_vec3 b, bool left, hs_vec3 out[4][2]) {
	const hs_vec3 v[4] = {{0.0, rad, 0.0}, {0.0, -rad, 0.0}, {0.0, 0.0, rad}, {0.0, 0.0, -rad}};
	int e = 0;
#if defined(__SSE2__)
	const __m128d flip = _mm_set1_pd(left ? -0.0 : 0.0);
	for (; e < 4; e += 2) {
		hs_lanes2 off = hs_lanes2_rotate(q, hs_lanes2_load(&v[e], &v[e + 1]));
		__m128d ox = off.x, oy = off.y, oz = off.z;
		hs_lanes2 from = {_mm_add_pd(_mm_set1_pd(a.x), ox), _mm_xor_pd(_mm_add_pd(_mm_set1_pd(a.y), oy), flip),
		                  _mm_add_pd(_mm_set1_pd(a.z), oz)};
		hs_lanes2 to = {_mm_add_pd(_mm_set1_pd(b.x), ox), _mm_xor_pd(_mm_add_pd(_mm_set1_pd(b.y), oy), flip),
		                _mm_add_pd(_mm_set1_pd(b.z), oz)};
		hs_lanes2_store(from, &out[e][0], &out[e + 1][0]);
		hs_lanes2_store(to, &out[e][1], &out[e + 1][1]);
	}
#endif
	for (; e < 4; e++) {
		hs_vec3 off = hs_quat_rotate(q, v[e]);
		out[e][0] = mirror_if(left, hs_add(a, off));
		out[e][1] = mirror_if(left, hs_add(b, off));
	}
}

#if HS_LANES4
// segment_lines with the 4 offsets of a finger of radius rad (hs_hand_segment_lines) in the 4 lanes
// of AVX registers: each lane does the scalar code's operations in its order (the same bits;
// selfcheck builds compare them with the two-lane path).
HS_AVX static void segment_lines_avx(const hs_quat *q, double rad, const hs_vec3 *a, const hs_vec3 *b, bool left,
                                     hs_vec3 out[4][2]) {
	const __m256d flip = _mm256_set1_pd(left ? -0.0 : 0.0);
	hs_lanes4 v = {_mm256_setzero_pd(), _mm256_set_pd(0.0, 0.0, -rad, rad), _mm256_set_pd(-rad, rad, 0.0, 0.0)};
	hs_lanes4 off = hs_lanes4_rotate(*q, v);
	hs_lanes4 from = {_mm256_add_pd(_mm256_set1_pd(a->x), off.x), _mm256_xor_pd(_mm256_add_pd(_mm256_set1_pd(a->y), off.y), flip),
	                  _mm256_add_pd(_mm256_set1_pd(a->z), off.z)};
	hs_lanes4 to = {_mm256_add_pd(_mm256_set1_pd(b->x), off.x), _mm256_xor_pd(_mm256_add_pd(_mm256_set1_pd(b->y), off.y), flip),
	                _mm256_add_pd(_mm256_set1_pd(b->z), off.z)};
	hs_lanes4_store_each(from, &out[0][0], &out[1][0], &out[2][0], &out[3][0]);
	hs_lanes4_store_each(to, &out[0][1], &out[1][1], &out[2][1], &out[3][1]);
}
#endif

#if HS_LANES4 && defined(HS_SELFCHECK)
// Sanitizer builds: the four lanes' lines have the bits of the two-lane path's.
static void check_four_lanes(hs_quat q, double rad, hs_vec3 a, hs_vec3 b, bool left, const hs_vec3 out[4][2]) {
	hs_vec3 two_lanes[4][2];
	segment_lines(q, rad, a, b, left, two_lanes);
	if (memcmp(two_lanes, out, sizeof two_lanes) != 0) {
		fprintf(stderr, "selfcheck: a segment's check lines in four lanes differ from the two-lane path\n");
		abort();
	}
}
#else
static inline void check_four_lanes(hs_quat q, double rad, hs_vec3 a, hs_vec3 b, bool left, const hs_vec3 out[4][2]) {
	(void)q, (void)rad, (void)a, (void)b, (void)left, (void)out;
}
#endif

// Check lines (§3.1) of segment s: the 4 long edges of a square prism around it, edge e offset from
// the axis by r along the segment's local +y, −y, +z, −z. Its ends are the check points mirrored
// back (a sign: exact).
void hs_hand_segment_lines(const hs_hand_def *def, const hs_vec3 points[HS_HAND_POINTS], const hs_quat segment[15],
                           int s, hs_vec3 out[4][2]) {
	double rad = def->finger_radius;
	int i = 4 * (s / 3) + s % 3;
	hs_vec3 a = mirror_if(def->left, points[i]), b = mirror_if(def->left, points[i + 1]);
#if HS_LANES4
	if (hs_cpu_has_avx()) {
		segment_lines_avx(&segment[s], rad, &a, &b, def->left, out);
		check_four_lanes(segment[s], rad, a, b, def->left, (const hs_vec3(*)[2])out);
		return;
	}
#endif
	segment_lines(segment[s], rad, a, b, def->left, out);
}
