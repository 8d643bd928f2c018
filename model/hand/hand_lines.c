// hand_lines.c — the 60 check lines of the 1999 paper §3.1 (Fig. 1): each finger segment's four
// long edges of the square prism around its axis, from the segment's ends and frame (the glove's
// kinematics, hand.c, and the joint-driven hands, hand_joints.c, both place them so).
#include "hand_internal.h"
#include "lanes2.h"

static hs_vec3 mirror_if(bool left, hs_vec3 v) { return left ? hs_v3(v.x, -v.y, v.z) : v; }

// A segment's 4 check lines from its ends a, b and its frame q: line e runs from a + off to b + off,
// off = hs_quat_rotate(q, v[e]), mirrored for a left hand. With SSE2, two lines at a time, one per
// lane: each lane does hs_quat_rotate's products and sums, then the additions, in their order
// (the same bits); the mirror is the sign of y.
static void segment_lines(hs_quat q, const hs_vec3 v[4], hs_vec3 a, hs_vec3 b, bool left, hs_vec3 out[4][2]) {
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

// Check lines (§3.1) of segment s: the 4 long edges of a square prism around it, edge e offset from
// the axis by r along the segment's local +y, −y, +z, −z. Its ends are the check points mirrored
// back (a sign: exact).
void hs_hand_segment_lines(const hs_hand_def *def, const hs_vec3 points[HS_HAND_POINTS], const hs_quat segment[15],
                           int s, hs_vec3 out[4][2]) {
	double rad = def->finger_radius;
	const hs_vec3 offsets[4] = {{0.0, rad, 0.0}, {0.0, -rad, 0.0}, {0.0, 0.0, rad}, {0.0, 0.0, -rad}};
	int a = 4 * (s / 3) + s % 3;
	segment_lines(segment[s], offsets, mirror_if(def->left, points[a]), mirror_if(def->left, points[a + 1]), def->left,
	              out);
}
