// contact_cull.h — the contact tests' bounding tests (contact_cull.c): what detection may pass over
// before the 1999 paper's narrow tests (§3.2, Fig. 2), each giving the plain test's answer.
// Private to contact_*.c.
#ifndef HS_CONTACT_CULL_H
#define HS_CONTACT_CULL_H

#include <stdint.h>

#include "contact_part.h"
#include "contact_pass.h"
#include "lanes4.h"

// The first check point of finger segment s (finger s / 3, segment s % 3): 4 (s / 3) + s % 3.
static inline int hs_segment_first_point(int s) {
	static const int first[15] = {0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, 16, 17, 18};
	return first[s];
}

// Where check point i is at piece boundary k of its path (0: a frame ago, steps: now).
static inline hs_vec3 hs_contact_path_point(const hs_hand *hand, int i, int k, int steps) {
	return k == 0 ? hand->cache.prev_points[i] : k == steps ? hand->cache.points[i] : hand->cache.path_points[k - 1][i];
}

// True when check point i's path through the frame comes within sqrt(r_sq) of c.
static inline bool hs_contact_path_near(const hs_hand *hand, int i, int steps, hs_vec3 c, double r_sq) {
	if (steps == 1) // one piece (most frames): read straight, not through path_point
		return segment_distance_sq(c, hand->cache.prev_points[i], hand->cache.points[i]) <= r_sq;
	for (int k = 0; k < steps; ++k)
		if (segment_distance_sq(c, hs_contact_path_point(hand, i, k, steps), hs_contact_path_point(hand, i, k + 1, steps)) <= r_sq)
			return true;
	return false;
}

// A line with an end inside the part is the check points' business (detect_lines); so is one
// with an end off the surface by less than grasp_release_mm at a check point that touches (it
// touched last frame, the hysteresis of detect_points, or touches the part now), at the end of
// the frame or at its start (a finger lifting off sweeps its side past the face it leaves): a fingertip resting on a top face 1 cm from its edge, its prism's
// side 2 mm from the edge, swept that side across the edge under glove noise (±6 mm a frame) and
// pushed the object sideways while the tip itself held still.
static inline bool hs_contact_end_touches(const hs_world_model *model, uint32_t touching, int point, const hs_shape *shape,
                                          const hs_part *part, const hs_vec3 p[2]) { // the line runs beside point and point + 1
	double margin = model->def.grasp_release_mm * 1e-3;
	for (int k = 0; k < 2; ++k)
		if ((touching >> (point + k) & 1u) && inside_part(model, shape, part, p[k], margin))
			return true;
	return false;
}

typedef struct hs_deep_memo {
	uint32_t known, deep; // the check points tested so far, and those found deep
} hs_deep_memo;


// What detect_lines tests a finger segment by, for a part's bounding sphere of radius r. A
// segment's 4 check lines lie finger_radius from its axis (joint to joint), at every point of the
// path: when the axis is further than rs = r + finger_radius from the part, all four are, and none
// is tested one by one (the same lines culled, fewer distances taken). Where the paths count, a
// line's piece of path has its corners' mean within finger_radius of the axis' and its sphere at
// most 2 finger_radius wider: when the axis' misses rp = r + 3 finger_radius, the lines' miss r.
// An axis within ri = r - finger_radius has all four lines within r: none is tested alone. A
// touching check point inside the part grown by deep = margin - finger_radius has the segment's
// line ends beside it inside the part grown by the margin: end_touches holds for all four lines.
typedef struct hs_segment_bounds {
	double rs, rp, ri, deep;
} hs_segment_bounds;

static inline hs_segment_bounds hs_contact_segment_bounds(const hs_world_model *model, const hs_hand *hand, double r) {
	double rf = hand->model.def.finger_radius;
	hs_segment_bounds b = {r + rf + HS_CULL_SLACK, r + 3.0 * rf + HS_CULL_SLACK, r - rf - HS_CULL_SLACK,
	                    model->def.grasp_release_mm * 1e-3 - rf - HS_CULL_SLACK};
	return b;
}

// The turn from a hand's wrist frame (mirrored for a left hand) into a held object's body frame,
// scaled by finger_radius: body rot^T · place_m · diag(1, ±1, 1) · finger_radius, as its three
// columns; made once per detection, at the first segment held_lines_clear looks at.
typedef struct hs_held_turn {
	bool ready;
	hs_vec3 c[3];
} hs_held_turn;


// The hand's check points in an object's body frame, as rows: to_body of each, the same bits (a
// held object's detection reads most of them, several times: made once, four at a time with AVX).
typedef struct hs_body_points {
	double x[HS_HAND_POINTS], y[HS_HAND_POINTS], z[HS_HAND_POINTS];
} hs_body_points;

void hs_contact_points_to_body(const hs_hand *hand, const hs_frame *f, hs_body_points *out);

// Check point i in the body frame: from the rows when made (bp), else transformed now.
static HS_FORCE_INLINE hs_vec3 hs_body_point(const hs_body_points *bp, const hs_hand *hand, const hs_frame *f, int i) {
	return bp ? hs_v3(bp->x[i], bp->y[i], bp->z[i]) : to_body(f, hand->cache.points[i]);
}

// The check points (bit i) within sqrt(r_sq) of c now, and in *kept those within sqrt(keep_sq).
uint32_t hs_contact_points_near(const hs_hand *hand, hs_vec3 c, double r_sq, double keep_sq, uint32_t *kept);
// Check line j's path through the frame may come within r of c.
bool hs_contact_line_path_near(const hs_hand *hand, int j, int steps, hs_vec3 c, double r);
// A line's sweep (q to p, one piece) clear of one face of a scanned part.
bool hs_contact_sweep_clear_of_a_face(const hs_contact_pass *cp, const hs_shape *shape, const hs_part *part,
                                      const hs_vec3 q[2], const hs_vec3 p[2]);
#if defined(HS_SELFCHECK)
// Self-check builds: each line of a segment passed over as clear of a face is so alone; through
// the path, each line's every piece and its end (hs_contact_segment_path_clear_of_a_box_face).
void hs_contact_check_segment_clear(const hs_contact_pass *cp, int h, int a, const hs_frame *body, const hs_frame *before,
                                    const hs_shape *shape, const hs_part *part);
void hs_contact_check_segment_path_clear(const hs_contact_pass *cp, int h, int a, const hs_frame *body, const hs_frame *before,
                                         const hs_part_cache *pc, int steps);
#endif
// The finger segments whose axis, and segment s's check lines whose line, lie within sqrt(r_sq) of c.
uint32_t hs_contact_axes_near(const hs_hand *hand, hs_vec3 c, double r_sq, double d[16]);
unsigned hs_contact_lines_near(const hs_hand *hand, int s, hs_vec3 c, double r_sq);
// A held object's finger segment s whose four check lines would find nothing (box parts): four
// lines in four AVX lanes, or one by one.
bool hs_contact_held_lines_clear_plain(const hs_contact_pass *cp, int h, int s, int a, const hs_frame *body, const hs_body_points *bp,
                                       const hs_shape *shape, const hs_part *part, uint32_t touching, double grow, hs_held_turn *turn);
#if HS_LANES4
bool hs_contact_held_lines_clear_avx(const hs_contact_pass *cp, int h, int s, int a, const hs_frame *body, const hs_body_points *bp,
                                     const hs_shape *shape, const hs_part *part, uint32_t touching, double grow, hs_held_turn *turn);
#endif
static inline bool hs_contact_held_lines_clear(const hs_contact_pass *cp, int h, int s, int a, const hs_frame *body,
                                               const hs_body_points *bp, const hs_shape *shape, const hs_part *part,
                                               uint32_t touching, double grow, hs_held_turn *turn) {
#if HS_LANES4
	if (hs_cpu_has_avx())
		return hs_contact_held_lines_clear_avx(cp, h, s, a, body, bp, shape, part, touching, grow, turn);
#endif
	return hs_contact_held_lines_clear_plain(cp, h, s, a, body, bp, shape, part, touching, grow, turn);
}
// The fingers (bit f) far from a part's bounding sphere (centre c, radius `reach`) through the frame.
// grow_reach: the part's (part_cache.h).
unsigned hs_contact_far_fingers(const hs_hand *hand, double grow_reach, hs_vec3 c, double reach, double hand_keep);

// The check points near the part now: within r, its sphere grown by `grow` (its corners reach
// further: part_reach.h); and, in the swept test, a point that touched (or started inside) within
// the sphere grown further by the release margin (or twice it), where it still counts.
static inline uint32_t hs_contact_points_near_part(const hs_hand *hand, double grow_reach, hs_vec3 center, double r, bool swept,
                                                   double hand_keep) {
	double keep = r + grow_reach * hand_keep;
	uint32_t within = 0, near = hs_contact_points_near(hand, center, r * r, keep * keep, &within);
	return swept ? near | (within & (hand->state.touch_points | hand->state.embed_points)) : near;
}

// The finger segments (bit s) with an embedded check line: such a line stays so within twice the
// margin of the part, beyond its sphere (detect_lines), so its segment is not culled.
static inline uint32_t hs_contact_segments_embedded(const hs_hand *hand) {
	uint32_t segments = 0;
	for (uint64_t lines = hand->state.embed_lines; lines;) { // one turn per embedded segment, not per segment
		uint32_t low = (uint32_t)lines;
		int s = (low ? hs_lowest_bit(low) : 32 + hs_lowest_bit((uint32_t)(lines >> 32))) / 4;
		segments |= 1u << s;
		lines &= ~((uint64_t)0xFu << (4 * s));
	}
	return segments;
}

// True when check point a or a + 1 touches (`touching`) and lies inside the part grown by `grow`
// now (the check points of a segment's line ends, end_touches). `memo` keeps each point's answer
// for the rest of the part's lines.
static inline bool hs_contact_ends_deep(const hs_world_model *model, const hs_hand *hand, uint32_t touching, int a,
                                        const hs_frame *body, const hs_body_points *bp, const hs_shape *shape, const hs_part *part,
                                        double grow, hs_deep_memo *memo) {
	for (uint32_t ends = touching & 3u << a; ends; ends &= ends - 1u) { // a, then a + 1
		int i = hs_lowest_bit(ends);
		uint32_t bit = 1u << i;
		if (!(memo->known & bit)) { // a check point ends two segments: tested once
			memo->known |= bit;
			if (inside_part(model, shape, part, hs_body_point(bp, hand, body, i), grow))
				memo->deep |= bit;
		}
		if (memo->deep & bit)
			return true;
	}
	return false;
}

// fmax(a, b), NaN included, without the library call
static inline double larger(double a, double b) { return a >= b || b != b ? a : b; }

// True when the quad a segment sweeps from m0-m1 to l0-l1 may come within r of c: its bounding
// sphere about the corners' mean. With SSE2, the two ends a frame ago in one lane and the two ends
// now in the other: each lane does the scalar code's sums, products and `larger` in its order
// (the same bits), the lanes meeting where the scalar code joins the two halves.
static HS_FORCE_INLINE bool quad_near(const hs_vec3 *m0, const hs_vec3 *m1, const hs_vec3 *l0, const hs_vec3 *l1, hs_vec3 c,
                                      double r) {
#if defined(__SSE2__)
	hs_lanes2 a = hs_lanes2_load(m0, l0), b = hs_lanes2_load(m1, l1);
	__m128d sx = _mm_add_pd(a.x, b.x), sy = _mm_add_pd(a.y, b.y), sz = _mm_add_pd(a.z, b.z); // m0 + m1 | l0 + l1
	const __m128d quarter = _mm_set_sd(0.25);
	__m128d mx = _mm_mul_sd(_mm_add_sd(sx, _mm_unpackhi_pd(sx, sx)), quarter);
	__m128d my = _mm_mul_sd(_mm_add_sd(sy, _mm_unpackhi_pd(sy, sy)), quarter);
	__m128d mz = _mm_mul_sd(_mm_add_sd(sz, _mm_unpackhi_pd(sz, sz)), quarter);
	mx = _mm_unpacklo_pd(mx, mx);
	my = _mm_unpacklo_pd(my, my);
	mz = _mm_unpacklo_pd(mz, mz);
	__m128d ax = _mm_sub_pd(a.x, mx), ay = _mm_sub_pd(a.y, my), az = _mm_sub_pd(a.z, mz);
	__m128d bx = _mm_sub_pd(b.x, mx), by = _mm_sub_pd(b.y, my), bz = _mm_sub_pd(b.z, mz);
	__m128d da = _mm_add_pd(_mm_add_pd(_mm_mul_pd(ax, ax), _mm_mul_pd(ay, ay)), _mm_mul_pd(az, az)); // m0 | l0
	__m128d db = _mm_add_pd(_mm_add_pd(_mm_mul_pd(bx, bx), _mm_mul_pd(by, by)), _mm_mul_pd(bz, bz)); // m1 | l1
	__m128d keep = _mm_or_pd(_mm_cmpge_pd(da, db), _mm_cmpunord_pd(db, db)); // larger(da, db), lane by lane
	__m128d most = _mm_or_pd(_mm_and_pd(keep, da), _mm_andnot_pd(keep, db));
	double lanes[2];
	_mm_storeu_pd(lanes, most);
	double rad = sqrt(larger(lanes[0], lanes[1]));
	hs_vec3 mid = hs_v3(_mm_cvtsd_f64(mx), _mm_cvtsd_f64(my), _mm_cvtsd_f64(mz));
#else
	hs_vec3 mid = hs_scale(hs_add(hs_add(*m0, *m1), hs_add(*l0, *l1)), 0.25);
	double rad = sqrt(larger(larger(hs_length_sq(hs_sub(*m0, mid)), hs_length_sq(hs_sub(*m1, mid))),
	                         larger(hs_length_sq(hs_sub(*l0, mid)), hs_length_sq(hs_sub(*l1, mid)))));
#endif
	return hs_length_sq(hs_sub(c, mid)) <= (r + rad) * (r + rad);
}

// The same for the axis of a finger segment, check points a to a + 1.
static inline bool hs_contact_axis_path_near(const hs_hand *hand, int a, int steps, hs_vec3 c, double r) {
	if (steps == 1) // one piece (most frames): read straight, not through path_point
		return quad_near(&hand->cache.prev_points[a], &hand->cache.prev_points[a + 1], &hand->cache.points[a], &hand->cache.points[a + 1], c, r);
	for (int k = 0; k < steps; ++k) {
		hs_vec3 m0 = hs_contact_path_point(hand, a, k, steps), m1 = hs_contact_path_point(hand, a + 1, k, steps);
		hs_vec3 l0 = hs_contact_path_point(hand, a, k + 1, steps), l1 = hs_contact_path_point(hand, a + 1, k + 1, steps);
		if (quad_near(&m0, &m1, &l0, &l1, c, r))
			return true;
	}
	return false;
}

// The same for a whole finger segment, before its lines are placed: its axis now and a frame ago
// (check points a and a + 1) beyond one face by more than finger_radius + 2 HS_CULL_SLACK. Each of
// its check lines lies finger_radius from that axis, so its ends now and a frame ago lie beyond
// the face by more than HS_CULL_SLACK (the rounding of placing and transforming them is far below
// the other HS_CULL_SLACK): sweep_clear_of_a_face would pass each one over.
static inline bool hs_contact_segment_clear_of_a_face(const hs_contact_pass *cp, int h, int a, const hs_frame *body,
                                                      const hs_frame *before, const hs_shape *shape,
                                                      const hs_part *part) {
	const hs_hand *hand = &cp->hands[h];
	if (part->face_count >= HS_FACE_TREE_MIN_FACES)
		return false;
	const hs_vec3 e[4] = {to_body(body, hand->cache.points[a]), to_body(body, hand->cache.points[a + 1]),
	                      to_body(before, hand->cache.prev_points[a]), to_body(before, hand->cache.prev_points[a + 1])};
	if (!scan_beyond(shape, part, e, hand->model.def.finger_radius + 2.0 * HS_CULL_SLACK))
		return false;
#if defined(HS_SELFCHECK)
	hs_contact_check_segment_clear(cp, h, a, body, before, shape, part);
#endif
	return true;
}

// The same for a box part through every pose of the frame's path (a frame ago, the path's pieces,
// now: any number of pieces): the segment's axis beyond one face of the box by more than
// finger_radius + 2 HS_CULL_SLACK at each of them, so each of its check lines at each pose lies beyond
// that face by more than HS_CULL_SLACK: its clips miss at the frame's end, and every piece of its path
// is clear of that face (swept_path's piece_clear_of_a_box_face), so detect_lines finds nothing.
// 1: clear; 0: not (nor would segment_clear_of_a_face find it so: the box's coordinates are its
// faces' dots); -1: a coordinate is not finite, the scan decides.
static inline int hs_contact_segment_path_clear_of_a_box_face(const hs_contact_pass *cp, int h, int a, const hs_frame *body,
                                                              const hs_frame *before, const hs_part_cache *pc, int steps) {
	const hs_hand *hand = &cp->hands[h];
	hs_vec3 e[2 * (HS_HAND_PATH_MAX + 1)];
	e[0] = to_body(before, hand->cache.prev_points[a]);
	e[1] = to_body(before, hand->cache.prev_points[a + 1]);
	for (int k = 1; k <= steps; ++k) {
		const hs_vec3 *p = k == steps ? hand->cache.points : hand->cache.path_points[k - 1];
		e[2 * k] = to_body(body, p[a]);
		e[2 * k + 1] = to_body(body, p[a + 1]);
	}
	int clear = hs_part_box_beyond_n(pc, e, 2 * (steps + 1), hand->model.def.finger_radius + 2.0 * HS_CULL_SLACK);
#if defined(HS_SELFCHECK)
	if (clear == 1)
		hs_contact_check_segment_path_clear(cp, h, a, body, before, pc, steps);
#endif
	return clear;
}

#endif
