// contact_cull.c — the bounding tests that pass check points, finger segments and check lines over
// before the 1999 paper's narrow tests (§3.2, Fig. 2: "after boundary checking"), with SSE2 and
// AVX lanes that give the scalar code's bits; in self-check builds each is compared with the plain
// test it stands for (docs/model.md §3).
#if defined(HS_SELFCHECK)
#include <string.h>
#endif

#include "contact_cull.h"
#include "contact_swept.h"
#include "lanes4.h"

#if HS_LANES4
// The hand's check points i to i + 3 in the four lanes (from its point rows).
HS_AVX static inline hs_lanes4 point_lanes(const hs_hand *hand, int i) {
	return hs_lanes4_rows(&hand->cache.point_rows[0][i], HS_HAND_POINTS + 4);
}

// points_near four points at a time (AVX).
HS_AVX static uint32_t points_near_avx(const hs_hand *hand, hs_vec3 c, double r_sq, double keep_sq, uint32_t *kept) {
	uint32_t near = 0, within = 0;
	for (int i = 0; i < HS_HAND_POINTS; i += 4) {
		__m256d d = hs_lanes4_distance_sq(point_lanes(hand, i), c);
		near |= hs_lanes4_not_above(d, r_sq) << i;
		within |= hs_lanes4_not_above(d, keep_sq) << i;
	}
	*kept = within;
	return near;
}
#endif

// The check points (bit i) not further than sqrt(r_sq) from c now, as the cull reads it:
// !(|p_i - c|^2 > r_sq), NaN near; in *kept those not further than sqrt(keep_sq). With AVX four
// points at a time, with SSE2 two, each lane doing hs_length_sq(hs_sub(p, c))'s operations in its
// order (the same bits).
uint32_t hs_contact_points_near(const hs_hand *hand, hs_vec3 c, double r_sq, double keep_sq, uint32_t *kept) {
	const hs_vec3 *p = hand->cache.points;
	uint32_t near = 0, within = 0;
	int i = 0;
#if HS_LANES4
	if (hs_cpu_has_avx()) {
		near = points_near_avx(hand, c, r_sq, keep_sq, &within);
		i = HS_HAND_POINTS;
	}
#endif
#if defined(__SSE2__)
	const __m128d cx = _mm_set1_pd(c.x), cy = _mm_set1_pd(c.y), cz = _mm_set1_pd(c.z), r = _mm_set1_pd(r_sq),
	              kr = _mm_set1_pd(keep_sq);
	for (; i + 1 < HS_HAND_POINTS; i += 2) {
		hs_lanes2 in = hs_lanes2_load(&p[i], &p[i + 1]);
		__m128d dx = _mm_sub_pd(in.x, cx), dy = _mm_sub_pd(in.y, cy), dz = _mm_sub_pd(in.z, cz);
		__m128d d = _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz));
		near |= (uint32_t)_mm_movemask_pd(_mm_cmpngt_pd(d, r)) << i;
		within |= (uint32_t)_mm_movemask_pd(_mm_cmpngt_pd(d, kr)) << i;
	}
#endif
	for (; i < HS_HAND_POINTS; ++i) {
		double d = hs_length_sq(hs_sub(p[i], c));
		near |= (uint32_t)!(d > r_sq) << i;
		within |= (uint32_t)!(d > keep_sq) << i;
	}
	*kept = within;
#if defined(HS_SELFCHECK)
	for (int k = 0; k < HS_HAND_POINTS; ++k) {
		const double row[3] = {hand->cache.point_rows[0][k], hand->cache.point_rows[1][k], hand->cache.point_rows[2][k]};
		const double point[3] = {p[k].x, p[k].y, p[k].z};
		if (memcmp(row, point, sizeof row) != 0) {
			fprintf(stderr, "selfcheck: the hand's point rows differ from its points\n");
			abort();
		}
	}
	for (int k = 0; k < HS_HAND_POINTS; ++k)
		if ((near >> k & 1u) != !(hs_length_sq(hs_sub(p[k], c)) > r_sq) ||
		    (within >> k & 1u) != !(hs_length_sq(hs_sub(p[k], c)) > keep_sq)) {
			fprintf(stderr, "selfcheck: points_near differs from the scalar cull\n");
			abort();
		}
#endif
	return near;
}

#if HS_LANES4
// points_to_body four points at a time (AVX), from the point rows.
HS_AVX static void points_to_body_avx(const hs_hand *hand, const hs_frame *f, hs_body_points *out) {
	const hs_mat3 *m = &f->rot;
	const __m256d px = _mm256_set1_pd(f->pos.x), py = _mm256_set1_pd(f->pos.y), pz = _mm256_set1_pd(f->pos.z);
	for (int i = 0; i < HS_HAND_POINTS; i += 4) {
		hs_lanes4 p = point_lanes(hand, i);
		__m256d vx = _mm256_sub_pd(p.x, px), vy = _mm256_sub_pd(p.y, py), vz = _mm256_sub_pd(p.z, pz);
		_mm256_storeu_pd(&out->x[i], _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(m->r0.x), vx),
		                                                         _mm256_mul_pd(_mm256_set1_pd(m->r1.x), vy)),
		                                           _mm256_mul_pd(_mm256_set1_pd(m->r2.x), vz)));
		_mm256_storeu_pd(&out->y[i], _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(m->r0.y), vx),
		                                                         _mm256_mul_pd(_mm256_set1_pd(m->r1.y), vy)),
		                                           _mm256_mul_pd(_mm256_set1_pd(m->r2.y), vz)));
		_mm256_storeu_pd(&out->z[i], _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(m->r0.z), vx),
		                                                         _mm256_mul_pd(_mm256_set1_pd(m->r1.z), vy)),
		                                           _mm256_mul_pd(_mm256_set1_pd(m->r2.z), vz)));
	}
}
#endif

// Each check point's to_body(f, p): hs_mat3_tmul(rot, p - pos), its subtractions, products and sums
// in their order in each lane (the same bits; self-check builds compare).
void hs_contact_points_to_body(const hs_hand *hand, const hs_frame *f, hs_body_points *out) {
	int i = 0;
#if HS_LANES4
	if (hs_cpu_has_avx()) {
		points_to_body_avx(hand, f, out);
		i = HS_HAND_POINTS;
	}
#endif
	for (; i < HS_HAND_POINTS; ++i) {
		hs_vec3 b = to_body(f, hand->cache.points[i]);
		out->x[i] = b.x, out->y[i] = b.y, out->z[i] = b.z;
	}
#if defined(HS_SELFCHECK)
	for (int k = 0; k < HS_HAND_POINTS; ++k) {
		hs_vec3 b = to_body(f, hand->cache.points[k]);
		const double want[3] = {b.x, b.y, b.z}, got[3] = {out->x[k], out->y[k], out->z[k]};
		if (memcmp(want, got, sizeof want) != 0) {
			fprintf(stderr, "selfcheck: the check points' body rows differ from to_body\n");
			abort();
		}
	}
#endif
}

// True when check line j's path through the frame may come within r of c: each piece's quad.
bool hs_contact_line_path_near(const hs_hand *hand, int j, int steps, hs_vec3 c, double r) {
	for (int k = 0; k < steps; ++k) {
		const hs_vec3 *m = k == 0 ? hand->cache.prev_lines[j] : hand->cache.path_lines[k - 1][j];
		const hs_vec3 *l = k + 1 == steps ? hand->cache.lines[j] : hand->cache.path_lines[k][j];
		if (quad_near(&m[0], &m[1], &l[0], &l[1], c, r))
			return true;
	}
	return false;
}

#if defined(HS_SELFCHECK)
// Sanitizer builds: what sweep_clear_of_a_face skipped would have found nothing.
static void check_clear(const hs_contact_pass *cp, const hs_shape *shape, const hs_part *part, const hs_vec3 q[2],
                        const hs_vec3 p[2]) {
	if (clip_part(cp->model, shape, part, p[0], p[1], 0.0).hit || clip_part(cp->model, shape, part, q[0], q[1], 0.0).hit ||
	    !hs_contact_sweep_beyond_a_face(cp->model, shape, part, q, p)) {
		fprintf(stderr, "handspring: a line's sweep passed over as clear of a face touches the part (frame %ld)\n",
		        cp->frame);
		abort();
	}
}
#endif

// True when the line's sweep through the frame, q to p (one piece), lies beyond one face of a
// scanned part by more than HS_CULL_SLACK (far above the rounding of body-frame coordinates within
// HS_MAX_COORDINATE): then the clips of p and of q miss and sweep_beyond_a_face holds, so
// swept_path finds nothing, and the line is passed over before them.
bool hs_contact_sweep_clear_of_a_face(const hs_contact_pass *cp, const hs_shape *shape, const hs_part *part, const hs_vec3 q[2],
                                      const hs_vec3 p[2]) {
	const hs_vec3 ends[4] = {q[0], q[1], p[0], p[1]};
	if (part->face_count >= HS_FACE_TREE_MIN_FACES || !scan_beyond(shape, part, ends, HS_CULL_SLACK))
		return false;
#if defined(HS_SELFCHECK)
	check_clear(cp, shape, part, q, p);
#endif
	(void)cp;
	return true;
}

#if defined(HS_SELFCHECK)
// Sanitizer builds: each line of a segment passed over as clear would have been passed over alone.
void hs_contact_check_segment_clear(const hs_contact_pass *cp, int h, int a, const hs_frame *body, const hs_frame *before,
                                    const hs_shape *shape, const hs_part *part) {
	int s = a - a / 4; // the segment of first check point a (hs_segment_first_point)
	hs_hand *hand = (hs_hand *)&cp->hands[h]; // placing lines changes no result (hand_internal.h)
	hs_hand_ready_segment(hand, s);
	for (int j = 4 * s; j < 4 * s + 4; ++j) {
		hs_vec3 p[2], q[2];
		line_to_body(body, hand->cache.lines[j], p);
		line_to_body(before, hand->cache.prev_lines[j], q);
		if (!hs_contact_sweep_clear_of_a_face(cp, shape, part, q, p)) {
			fprintf(stderr, "handspring: a segment passed over as clear of a face has line %d near the part\n", j);
			abort();
		}
	}
}
#endif

#if defined(HS_SELFCHECK)
// Sanitizer builds: each line of a segment passed over as clear of a box face through its path lies
// beyond one box face by the slack at each piece (its two positions) and misses the part at the end.
void hs_contact_check_segment_path_clear(const hs_contact_pass *cp, int h, int a, const hs_frame *body, const hs_frame *before,
                                         const hs_part_cache *pc, int steps) {
	int s = a - a / 4; // the segment of first check point a (hs_segment_first_point)
	hs_hand *hand = (hs_hand *)&cp->hands[h]; // placing lines changes no result (hand_internal.h)
	hs_hand_ready_segment(hand, s);
	for (int j = 4 * s; j < 4 * s + 4; ++j) {
		hs_vec3 e[4];
		line_to_body(before, hand->cache.prev_lines[j], e);
		bool clear = true;
		for (int k = 1; k <= steps; ++k) {
			const hs_vec3 *l = k == steps ? hand->cache.lines[j] : hand->cache.path_lines[k - 1][j];
			line_to_body(body, l, &e[2]);
			clear = clear && hs_part_box_beyond4(pc, e, HS_CULL_SLACK);
			e[0] = e[2], e[1] = e[3];
		}
		if (!clear) {
			fprintf(stderr, "selfcheck: a segment passed over as clear of a box face through its path has line %d near the part\n", j);
			abort();
		}
	}
}
#endif

#if defined(__SSE2__)
// segment_distance_sq(c, a, b) of both lanes: hs_segment_param's and the distance's operations in
// their order, the division too (the same bits).
static inline __m128d segment_distance_sq2(hs_lanes2 a, hs_lanes2 b, hs_vec3 c) {
	const __m128d cx = _mm_set1_pd(c.x), cy = _mm_set1_pd(c.y), cz = _mm_set1_pd(c.z), zero = _mm_setzero_pd(),
	              one = _mm_set1_pd(1.0);
	__m128d ex = _mm_sub_pd(b.x, a.x), ey = _mm_sub_pd(b.y, a.y), ez = _mm_sub_pd(b.z, a.z);
	__m128d len_sq = _mm_add_pd(_mm_add_pd(_mm_mul_pd(ex, ex), _mm_mul_pd(ey, ey)), _mm_mul_pd(ez, ez));
	__m128d dot = _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_sub_pd(cx, a.x), ex), _mm_mul_pd(_mm_sub_pd(cy, a.y), ey)),
	                         _mm_mul_pd(_mm_sub_pd(cz, a.z), ez));
	__m128d u = _mm_and_pd(_mm_cmpgt_pd(len_sq, zero), _mm_div_pd(dot, len_sq)); // 0 for a point segment
	u = _mm_andnot_pd(_mm_cmplt_pd(u, zero), u);                                  // u < 0: 0 (NaN kept)
	__m128d above = _mm_cmpgt_pd(u, one);
	u = _mm_or_pd(_mm_and_pd(above, one), _mm_andnot_pd(above, u)); // u > 1: 1
	__m128d dx = _mm_sub_pd(_mm_add_pd(a.x, _mm_mul_pd(u, ex)), cx);
	__m128d dy = _mm_sub_pd(_mm_add_pd(a.y, _mm_mul_pd(u, ey)), cy);
	__m128d dz = _mm_sub_pd(_mm_add_pd(a.z, _mm_mul_pd(u, ez)), cz);
	return _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz));
}
#endif

#if HS_LANES4
// axes_near a finger at a time (AVX): lanes 0-2 its three segments (check points 4 f + k to
// 4 f + k + 1, from the point rows), lane 3 nothing (its distance is overwritten or spare; d has
// 16 places).
HS_AVX static uint32_t axes_near_avx(const hs_hand *hand, hs_vec3 c, double r_sq, double d[16]) {
	uint32_t near = 0;
	for (int f = 0; f < 5; ++f) {
		__m256d dist = hs_lanes4_segment_distance_sq(point_lanes(hand, 4 * f), point_lanes(hand, 4 * f + 1), c);
		_mm256_storeu_pd(&d[3 * f], dist);
		near |= (hs_lanes4_not_above(dist, r_sq) & 7u) << (3 * f);
	}
	return near;
}
#endif

// The squared distance from c to each finger segment's axis (check points a to a + 1) now,
// segment_distance_sq's bits, four segments at a time with AVX, two with SSE2. Returns the
// segments (bit s) whose axis is not further than sqrt(r_sq): !(d > r_sq), NaN near.
uint32_t hs_contact_axes_near(const hs_hand *hand, hs_vec3 c, double r_sq, double d[16]) {
	uint32_t near = 0;
	int s = 0;
#if HS_LANES4
	if (hs_cpu_has_avx()) {
		near = axes_near_avx(hand, c, r_sq, d);
		s = 15;
	}
#endif
#if defined(__SSE2__)
	for (; s + 1 < 15; s += 2) {
		int a0 = hs_segment_first_point(s), a1 = hs_segment_first_point(s + 1);
		__m128d dist = segment_distance_sq2(hs_lanes2_load(&hand->cache.points[a0], &hand->cache.points[a1]),
		                                    hs_lanes2_load(&hand->cache.points[a0 + 1], &hand->cache.points[a1 + 1]), c);
		_mm_storel_pd(&d[s], dist);
		_mm_storeh_pd(&d[s + 1], dist);
		near |= (uint32_t)_mm_movemask_pd(_mm_cmpngt_pd(dist, _mm_set1_pd(r_sq))) << s;
	}
#endif
	for (; s < 15; ++s) {
		int a = hs_segment_first_point(s);
		d[s] = segment_distance_sq(c, hand->cache.points[a], hand->cache.points[a + 1]);
		if (!(d[s] > r_sq))
			near |= 1u << s;
	}
#if defined(HS_SELFCHECK)
	for (int k = 0; k < 15; ++k) {
		double e = segment_distance_sq(c, hand->cache.points[hs_segment_first_point(k)], hand->cache.points[hs_segment_first_point(k) + 1]);
		if (memcmp(&e, &d[k], sizeof e) != 0 || (near >> k & 1u) != !(e > r_sq)) {
			fprintf(stderr, "selfcheck: hs_contact_axes_near differs from segment_distance_sq\n");
			abort();
		}
	}
#endif
	return near;
}

// The check lines of segment s (bit k: line 4 s + k) not further than sqrt(r_sq) from c now, as
// the line cull reads segment_distance_sq: !(d > r_sq), NaN near; two at a time with SSE2.
unsigned hs_contact_lines_near(const hs_hand *hand, int s, hs_vec3 c, double r_sq) {
	unsigned near = 0;
	const hs_vec3(*l)[2] = (const hs_vec3(*)[2])&hand->cache.lines[4 * s];
#if defined(__SSE2__)
	for (int k = 0; k < 4; k += 2) {
		__m128d dist = segment_distance_sq2(hs_lanes2_load(&l[k][0], &l[k + 1][0]), hs_lanes2_load(&l[k][1], &l[k + 1][1]), c);
		near |= (unsigned)_mm_movemask_pd(_mm_cmpngt_pd(dist, _mm_set1_pd(r_sq))) << k;
	}
#else
	for (int k = 0; k < 4; ++k)
		if (!(segment_distance_sq(c, l[k][0], l[k][1]) > r_sq))
			near |= 1u << k;
#endif
#if defined(HS_SELFCHECK)
	for (int k = 0; k < 4; ++k)
		if ((near >> k & 1u) != !(segment_distance_sq(c, l[k][0], l[k][1]) > r_sq)) {
			fprintf(stderr, "selfcheck: hs_contact_lines_near differs from segment_distance_sq\n");
			abort();
		}
#endif
	return near;
}

#if defined(HS_SELFCHECK)
// Sanitizer builds: each line of a segment held_lines_clear passed over, placed and moved into
// the body frame, lies beside a touching check point or misses the part.
static void check_held_clear(const hs_contact_pass *cp, int h, int s, int a, const hs_frame *body, const hs_shape *shape,
                             const hs_part *part, uint32_t touching, double grow) {
	hs_hand_ready_segment(&cp->hands[h], s);
	for (int j = 4 * s; j < 4 * s + 4; ++j) {
		hs_vec3 p[2];
		line_to_body(body, cp->hands[h].cache.lines[j], p);
		if (!hs_contact_end_touches(cp->model, touching, a, shape, part, p) && clip_part(cp->model, shape, part, p[0], p[1], grow).hit) {
			fprintf(stderr, "selfcheck: a held object's line passed over as clear touches the part\n");
			abort();
		}
	}
}
#else
static inline void check_held_clear(const hs_contact_pass *cp, int h, int s, int a, const hs_frame *body, const hs_shape *shape,
                                    const hs_part *part, uint32_t touching, double grow) {
	(void)cp, (void)h, (void)s, (void)a, (void)body, (void)shape, (void)part, (void)touching, (void)grow;
}
#endif

static HS_NOINLINE void held_turn_make(hs_held_turn *t, const hs_frame *body, const hs_hand *hand) {
	hs_mat3 p = hand->cache.place_m;
	double rf = hand->model.def.finger_radius, ry = hand->model.def.left ? -rf : rf;
	t->c[0] = hs_mat3_tmul(body->rot, hs_v3(rf * p.r0.x, rf * p.r1.x, rf * p.r2.x));
	t->c[1] = hs_mat3_tmul(body->rot, hs_v3(ry * p.r0.y, ry * p.r1.y, ry * p.r2.y));
	t->c[2] = hs_mat3_tmul(body->rot, hs_v3(rf * p.r0.z, rf * p.r1.z, rf * p.r2.z));
	t->ready = true;
}

static HS_FORCE_INLINE hs_vec3 held_turn_apply(const hs_held_turn *t, hs_vec3 v) {
	return hs_add(hs_add(hs_scale(t->c[0], v.x), hs_scale(t->c[1], v.y)), hs_scale(t->c[2], v.z));
}

// A held segment's check lines as held_lines_clear tests them: line k from e0 + off[k] to
// e1 + off[k], off = y, -y, z, -z; an end beside a touching check point (touch0, touch1) within
// `margin` of the box, both beyond one face by grow + 2 HS_CULL_SLACK, or the line further than
// r from the part's centre: clear.
typedef struct held_ends {
	hs_vec3 e0, e1, y, z;
	bool touch0, touch1;
	double margin, grow, r;
} held_ends;

static inline bool held_each_clear(const hs_part *part, const hs_part_cache *pc, const held_ends *l) {
	const hs_vec3 off[4] = {l->y, hs_scale(l->y, -1.0), l->z, hs_scale(l->z, -1.0)};
	for (int k = 0; k < 4; ++k) {
		hs_vec3 p0 = hs_add(l->e0, off[k]), p1 = hs_add(l->e1, off[k]);
		if ((l->touch0 && hs_part_box_inside(pc, p0, l->margin)) || (l->touch1 && hs_part_box_inside(pc, p1, l->margin)) ||
		    hs_part_box_apart(pc, p0, p1, l->grow, 2.0 * HS_CULL_SLACK) ||
		    segment_distance_sq(part->center, p0, p1) > l->r * l->r)
			continue;
		return false;
	}
	return true;
}

#if HS_LANES4
// The six coordinates the box's faces compare, in face order: p.x, -p.x, p.y, -p.y, p.z, -p.z
// (-p: the sign flipped alone, as unary minus).
HS_AVX static inline void box_coords4(hs_lanes4 p, __m256d out[6]) {
	const __m256d sign = _mm256_set1_pd(-0.0);
	out[0] = p.x, out[1] = _mm256_xor_pd(p.x, sign);
	out[2] = p.y, out[3] = _mm256_xor_pd(p.y, sign);
	out[4] = p.z, out[5] = _mm256_xor_pd(p.z, sign);
}

// The lanes (bits 0-3) whose point (coordinates v, box_coords4) is not inside the box grown by
// g: some face with v[f] >= o[f] + g, as hs_part_box_inside compares.
HS_AVX static inline unsigned box_outside4(const double o[6], const __m256d v[6], double g) {
	__m256d out = _mm256_setzero_pd();
#pragma GCC unroll 6 // rolled, these two loops cost 160 instructions a frame
	for (int f = 0; f < 6; ++f)
		out = _mm256_or_pd(out, _mm256_cmp_pd(v[f], _mm256_set1_pd(o[f] + g), _CMP_GE_OQ));
	return (unsigned)_mm256_movemask_pd(out);
}

// The lanes whose two points (a, b) both lie beyond one face of the box grown by g: a[f] > o[f] + g
// and b[f] > o[f] + g for some face, as hs_part_box_apart compares.
HS_AVX static inline unsigned box_apart4(const double o[6], const __m256d a[6], const __m256d b[6], double g) {
	__m256d apart = _mm256_setzero_pd();
#pragma GCC unroll 6
	for (int f = 0; f < 6; ++f) {
		__m256d bound = _mm256_set1_pd(o[f] + g);
		apart = _mm256_or_pd(apart, _mm256_and_pd(_mm256_cmp_pd(a[f], bound, _CMP_GT_OQ), _mm256_cmp_pd(b[f], bound, _CMP_GT_OQ)));
	}
	return (unsigned)_mm256_movemask_pd(apart);
}

// held_each_clear's four lines in the four lanes (AVX), each comparison the scalar one's (the
// same answers; the ends are finite, held_lines_clear): the touching ends first, as there.
HS_AVX static bool held_four_clear(const hs_part *part, const hs_part_cache *pc, const held_ends *l) {
	const hs_vec3 y = l->y, z = l->z;
	const __m256d ox = _mm256_set_pd(-z.x, z.x, -y.x, y.x), oy = _mm256_set_pd(-z.y, z.y, -y.y, y.y),
	              oz = _mm256_set_pd(-z.z, z.z, -y.z, y.z);
	hs_lanes4 p0 = {_mm256_add_pd(_mm256_set1_pd(l->e0.x), ox), _mm256_add_pd(_mm256_set1_pd(l->e0.y), oy),
	                _mm256_add_pd(_mm256_set1_pd(l->e0.z), oz)};
	hs_lanes4 p1 = {_mm256_add_pd(_mm256_set1_pd(l->e1.x), ox), _mm256_add_pd(_mm256_set1_pd(l->e1.y), oy),
	                _mm256_add_pd(_mm256_set1_pd(l->e1.z), oz)};
	__m256d v0[6], v1[6];
	box_coords4(p0, v0);
	box_coords4(p1, v1);
	const double *o = pc->box_offset;
	unsigned clear = 0;
	if (l->touch0)
		clear |= ~box_outside4(o, v0, l->margin) & 0xFu;
	if (l->touch1)
		clear |= ~box_outside4(o, v1, l->margin) & 0xFu;
	if (clear == 0xFu)
		return true;
	clear |= box_apart4(o, v0, v1, l->grow + 2.0 * HS_CULL_SLACK);
	if (clear == 0xFu)
		return true;
	__m256d d = hs_lanes4_segment_distance_sq(p0, p1, part->center);
	clear |= (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(d, _mm256_set1_pd(l->r * l->r), _CMP_GT_OQ));
	return clear == 0xFu;
}
#endif

// A held object's finger segment whose 4 check lines would all find nothing, decided from its
// check points and frame before the lines are placed. A line end is its check point plus the
// segment's y or z axis times finger_radius (hand_lines.c, segment_lines; mirrored for a left hand):
// the axes read off the segment's quaternion and taken into the body frame by one turn
// (held_turn), it differs from the placed and moved end by rounding alone, far below
// HS_CULL_SLACK. Each line must, by that slack, lie beside a touching check point inside the
// part grown by the margin (end_touches), have both ends beyond one face of the box (clip_part's
// miss), or lie outside the part's bounding sphere. Box parts only (hs_part_is_box); the lines are
// not embedded.
static HS_FORCE_INLINE bool held_lines_clear_in(const hs_contact_pass *cp, int h, int s, int a, const hs_frame *body,
                                                const hs_body_points *bp, const hs_shape *shape, const hs_part *part,
                                                uint32_t touching, double grow, hs_held_turn *turn, bool four) {
	const hs_hand *hand = &cp->hands[h];
	hs_vec3 e0 = hs_body_point(bp, hand, body, a), e1 = hs_body_point(bp, hand, body, a + 1);
	if (!hs_part_box_takes(e0) || !hs_part_box_takes(e1))
		return false;
	hs_quat q = hand->cache.local->segment[s]; // its y and z axes: the rotation's second and third columns
	hs_vec3 y = hs_v3(2.0 * (q.x * q.y - q.w * q.z), 1.0 - 2.0 * (q.x * q.x + q.z * q.z), 2.0 * (q.y * q.z + q.w * q.x));
	hs_vec3 z = hs_v3(2.0 * (q.x * q.z + q.w * q.y), 2.0 * (q.y * q.z - q.w * q.x), 1.0 - 2.0 * (q.x * q.x + q.y * q.y));
	if (!turn->ready)
		held_turn_make(turn, body, hand);
	y = held_turn_apply(turn, y);
	z = held_turn_apply(turn, z);
	// the offsets are finite and a few finger radii long: added to ends whose coordinates and sum are
	// finite, they cannot make one overflow (that takes an addend near 2^970), so the line ends take
	// the box's path whenever e0 and e1 do
	if (!hs_part_box_takes(y) || !hs_part_box_takes(z))
		return false;
	const hs_part_cache *pc = hs_part_cache_of(cp->model, shape, part);
	held_ends ends = {e0, e1, y, z, touching >> a & 1u, touching >> (a + 1) & 1u,
	                  cp->model->def.grasp_release_mm * 1e-3 - HS_CULL_SLACK, grow, part->radius + pc->grow_reach * grow + HS_CULL_SLACK};
#if HS_LANES4
	bool clear = four ? held_four_clear(part, pc, &ends) : held_each_clear(part, pc, &ends);
#else
	(void)four;
	bool clear = held_each_clear(part, pc, &ends);
#endif
#if defined(HS_SELFCHECK)
	if (clear != held_each_clear(part, pc, &ends)) {
		fprintf(stderr, "selfcheck: held_lines_clear's lanes differ from its loop\n");
		abort();
	}
#endif
	if (!clear)
		return false;
	check_held_clear(cp, h, s, a, body, shape, part, touching, grow);
	return true;
}

bool hs_contact_held_lines_clear_plain(const hs_contact_pass *cp, int h, int s, int a, const hs_frame *body, const hs_body_points *bp,
                                       const hs_shape *shape, const hs_part *part, uint32_t touching, double grow, hs_held_turn *turn) {
	return held_lines_clear_in(cp, h, s, a, body, bp, shape, part, touching, grow, turn, false);
}

#if HS_LANES4
HS_AVX bool hs_contact_held_lines_clear_avx(const hs_contact_pass *cp, int h, int s, int a, const hs_frame *body,
                                            const hs_body_points *bp, const hs_shape *shape, const hs_part *part, uint32_t touching,
                                            double grow, hs_held_turn *turn) {
	return held_lines_clear_in(cp, h, s, a, body, bp, shape, part, touching, grow, turn, true);
}
#endif

#if defined(HS_SELFCHECK)
// Sanitizer builds: every check point of a finger far_fingers passes over, and every placed check
// line, now and a frame ago, lies further than `reach` from c.
static void check_far(const hs_hand *hand, unsigned far, hs_vec3 c, double reach) {
	bool near = false;
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		if (far >> (i / 4) & 1u)
			near |= hs_length_sq(hs_sub(hand->cache.points[i], c)) <= reach * reach ||
			        hs_length_sq(hs_sub(hand->cache.prev_points[i], c)) <= reach * reach;
	for (int j = 0; j < HS_HAND_LINES; ++j)
		if (far >> (j / 12) & 1u)
			near |= (hand->cache.lines_ready >> (j / 4) & 1u && segment_distance_sq(c, hand->cache.lines[j][0], hand->cache.lines[j][1]) <= reach * reach) ||
			        (hand->cache.prev_lines_ready >> (j / 4) & 1u &&
			         segment_distance_sq(c, hand->cache.prev_lines[j][0], hand->cache.prev_lines[j][1]) <= reach * reach);
	if (near) {
		fprintf(stderr, "selfcheck: a finger passed over as far from a part comes near it\n");
		abort();
	}
}
#else
static inline void check_far(const hs_hand *hand, unsigned far, hs_vec3 c, double reach) {
	(void)hand, (void)far, (void)c, (void)reach;
}
#endif

// The fingers (bit f) whose spheres through the frame (hs_hand_finger_spheres) lie further than
// `reach` from c, the centre of a part's bounding sphere (its radius and HS_CULL_SLACK for
// rounding) — further by the part's keep (hs_contact_keep × grow_reach) for a finger with a
// touching or embedded check point — none of whose check lines is embedded; for the ungrown
// test. Such a finger's check points lie where the points' own cull passes them over; its lines and their sweeps miss the part the sphere holds, so the line tests find no
// contact (end_touches, a test with a margin, only passes a line over). An embedded line answers
// to the part grown by twice the margin, which reaches past the sphere at a box's corner (by
// (sqrt 3 - 1) times the growth): a finger with one keeps its tests.
unsigned hs_contact_far_fingers(const hs_hand *hand, double grow_reach, hs_vec3 c, double reach, double hand_keep) {
	unsigned far = 0;
	uint32_t kept = hand->state.touch_points | hand->state.embed_points; // counted beyond the sphere (detect_points)
	double keep = grow_reach * hand_keep;
	for (int f = 0; f < 5; ++f) {
		double r = hand->cache.finger_reach[f] + reach + (kept >> (4 * f) & 0xFu ? keep : 0.0);
		if (!(hand->state.embed_lines >> (12 * f) & 0xFFFu) && hs_length_sq(hs_sub(hand->cache.finger_center[f], c)) > r * r)
			far |= 1u << f;
	}
	check_far(hand, far, c, reach);
	return far;
}

