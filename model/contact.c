// contact.c — contacts between hands and objects (1999 paper §3.1-3.2, Fig. 2, Fig. 4).
//
// Everything is computed in the object's body frame, whose origin is G, against each convex part:
//  (A) a check point that reached the part this frame touches the face it crossed along its path
//      relative to the object (also when it has come out again: swept detection);
//  (B) a check line crossing the part touches an edge when it enters and leaves through the two
//      faces that meet at that edge; the contact normal is the pseudo-normal from G to the edge.
//      A line through two faces that do not meet presses the face nearest to its middle; a line
//      that swept across the part during the frame touches where it first met it.
// A part already inside is drawn back to the surface (§3.2 rectification) when it touched last
// frame or the object came onto it, and touches nothing when it started inside (docs/model.md §3,
// "Swept detection, rectification and contact hysteresis"). paper_contacts keeps [H]'s letter.
#include "clip.h"
#include "contact.h"
#include "hand_sweep.h"
#include "hgrid.h"
#include "inline.h"
#include "push.h"

#include "lanes2.h"
#include "lanes4.h"
#include "part_box.h"

#if defined(HS_SELFCHECK)
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#endif

// Grasp when n_i · n_j <= cos(threshold) + eps: with a bare comparison rounding would decide the
// 90 deg case (two adjoining cube faces) and two builds could disagree (docs/model.md §3).
#define HS_GRASP_EPS 1e-9

// m: what the bounds that test a finger segment for its four lines add for rounding, far above it
// for coordinates up to HS_MAX_COORDINATE (1e6 m, where a double's step is 1.2e-10 m)
#define HS_CULL_SLACK 1e-6

// The per-line distance tests and the frame changes are inlined (HS_FORCE_INLINE): called apart,
// their vectors (passed by value) went through the stack on every call.
//
// An object's pose as a position and a rotation matrix: detection moves up to 140 hand points
// into each object's frame every frame.
typedef struct frame {
	hs_vec3 pos;
	hs_mat3 rot;
} frame;

static frame frame_of(const hs_body *body) {
	frame f = {body->pos, hs_mat3_from_quat(body->rot)};
	return f;
}
static HS_FORCE_INLINE hs_vec3 to_body(const frame *f, hs_vec3 p) { return hs_mat3_tmul(f->rot, hs_sub(p, f->pos)); }
// Both ends of a line: out[k] = to_body(f, p[k]). With SSE2 one end per lane, each doing
// to_body's subtractions, products and sums in its order (the same bits).
static HS_FORCE_INLINE void line_to_body(const frame *f, const hs_vec3 p[2], hs_vec3 out[2]) {
#if defined(__SSE2__)
	const hs_mat3 *m = &f->rot;
	hs_lanes2 in = hs_lanes2_load(&p[0], &p[1]);
	__m128d vx = _mm_sub_pd(in.x, _mm_set1_pd(f->pos.x));
	__m128d vy = _mm_sub_pd(in.y, _mm_set1_pd(f->pos.y));
	__m128d vz = _mm_sub_pd(in.z, _mm_set1_pd(f->pos.z));
	__m128d ox = _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_set1_pd(m->r0.x), vx), _mm_mul_pd(_mm_set1_pd(m->r1.x), vy)),
	                        _mm_mul_pd(_mm_set1_pd(m->r2.x), vz));
	__m128d oy = _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_set1_pd(m->r0.y), vx), _mm_mul_pd(_mm_set1_pd(m->r1.y), vy)),
	                        _mm_mul_pd(_mm_set1_pd(m->r2.y), vz));
	__m128d oz = _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_set1_pd(m->r0.z), vx), _mm_mul_pd(_mm_set1_pd(m->r1.z), vy)),
	                        _mm_mul_pd(_mm_set1_pd(m->r2.z), vz));
	hs_lanes2_store((hs_lanes2){ox, oy, oz}, &out[0], &out[1]);
#else
	out[0] = to_body(f, p[0]);
	out[1] = to_body(f, p[1]);
#endif
}
static HS_FORCE_INLINE hs_vec3 to_world(const frame *f, hs_vec3 p) { return hs_add(f->pos, hs_mat3_mul(f->rot, p)); }

// Many-faced parts (HS_FACE_TREE_MIN_FACES or more) are searched through their normal-cone tree
// (face_tree.h: the faces near the point, with the scan's answers), out of line (HS_NOINLINE); the
// others are scanned inline, as they were.
static const hs_face_tree *tree_of(const hs_world *world, const hs_shape *shape) {
	return &world->face_trees[shape - world->shapes];
}

static inline bool scan_inside(const hs_shape *shape, const hs_part *part, hs_vec3 p, double grow) {
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f)
		if (hs_dot(shape->faces[f].normal, p) >= shape->faces[f].offset + grow)
			return false;
	return true;
}

static inline int scan_nearest(const hs_shape *shape, const hs_part *part, hs_vec3 p) {
	int best = part->first_face;
	double best_depth = INFINITY;
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f) {
		double depth = shape->faces[f].offset - hs_dot(shape->faces[f].normal, p);
		if (depth < best_depth) {
			best_depth = depth;
			best = f;
		}
	}
	return best;
}

// True when the four points lie beyond one face of the part by more than `margin`.
static inline bool scan_beyond(const hs_shape *shape, const hs_part *part, const hs_vec3 q[4], double margin) {
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f)
		if (hs_face_beyond_by(&shape->faces[f], q, margin))
			return true;
	return false;
}

static HS_NOINLINE bool inside_many(const hs_world *world, const hs_shape *shape, const hs_part *part, hs_vec3 p,
                                    double grow) {
	const hs_face_tree *tree = tree_of(world, shape);
	int root = hs_face_tree_root(tree, shape, part);
	return root >= 0 ? hs_face_tree_inside(tree, root, shape, p, grow) : scan_inside(shape, part, p, grow);
}

static HS_NOINLINE int nearest_many(const hs_world *world, const hs_shape *shape, const hs_part *part, hs_vec3 p) {
	const hs_face_tree *tree = tree_of(world, shape);
	int root = hs_face_tree_root(tree, shape, part);
	return root >= 0 ? hs_face_tree_nearest(tree, root, shape, part->first_face, p) : scan_nearest(shape, part, p);
}

#if defined(HS_SELFCHECK)
// Sanitizer builds: a box part's queries return what the scan of its faces returns.
static bool box_inside(const hs_shape *shape, const hs_part *part, hs_vec3 p, double grow) {
	bool inside = hs_part_box_inside(part, p, grow);
	if (inside != scan_inside(shape, part, p, grow)) {
		fprintf(stderr, "selfcheck: the box's inside test differs from the scan's\n");
		abort();
	}
	return inside;
}
static bool box_apart(const hs_shape *shape, const hs_part *part, hs_vec3 a, hs_vec3 b, double grow) {
	bool apart = hs_part_box_apart(part, a, b, grow, HS_CULL_SLACK);
	if (apart && hs_clip_segment(shape, part, a, b, grow).hit) {
		fprintf(stderr, "selfcheck: a segment the box test put beyond a face meets the part\n");
		abort();
	}
	return apart;
}
static int box_nearest(const hs_shape *shape, const hs_part *part, hs_vec3 p) {
	int face = hs_part_box_nearest(part, p);
	if (face != scan_nearest(shape, part, p)) {
		fprintf(stderr, "selfcheck: the box's nearest face differs from the scan's\n");
		abort();
	}
	return face;
}
#else
static inline int box_nearest(const hs_shape *shape, const hs_part *part, hs_vec3 p) {
	(void)shape;
	return hs_part_box_nearest(part, p);
}
static inline bool box_inside(const hs_shape *shape, const hs_part *part, hs_vec3 p, double grow) {
	(void)shape;
	return hs_part_box_inside(part, p, grow);
}
static inline bool box_apart(const hs_shape *shape, const hs_part *part, hs_vec3 a, hs_vec3 b, double grow) {
	(void)shape;
	return hs_part_box_apart(part, a, b, grow, HS_CULL_SLACK);
}
#endif

// Inside the part grown by `grow` (m; 0: the part itself).
static inline bool inside_part(const hs_world *world, const hs_shape *shape, const hs_part *part, hs_vec3 p, double grow) {
	if (part->face_count >= HS_FACE_TREE_MIN_FACES)
		return inside_many(world, shape, part, p, grow);
	if (hs_part_is_box(part) && hs_part_box_takes(p))
		return box_inside(shape, part, p, grow);
	return scan_inside(shape, part, p, grow);
}

static inline int nearest_face(const hs_world *world, const hs_shape *shape, const hs_part *part, hs_vec3 p) {
	if (part->face_count >= HS_FACE_TREE_MIN_FACES)
		return nearest_many(world, shape, part, p);
	if (hs_part_is_box(part) && hs_part_box_takes(p))
		return box_nearest(shape, part, p);
	return scan_nearest(shape, part, p);
}

// hs_clip_segment, through the tree for a many-faced part: the same clip whenever it hits.
static inline hs_clip clip_part(const hs_world *world, const hs_shape *shape, const hs_part *part, hs_vec3 a, hs_vec3 b,
                         double grow) {
	if (part->face_count >= HS_FACE_TREE_MIN_FACES) {
		const hs_face_tree *tree = tree_of(world, shape);
		int root = hs_face_tree_root(tree, shape, part);
		if (root >= 0)
			return hs_face_tree_clip(tree, root, shape, a, b, grow);
	}
	if (hs_part_is_box(part) && hs_part_box_takes(a) && hs_part_box_takes(b) && box_apart(shape, part, a, b, grow)) {
		hs_clip miss = {0.0, 1.0, -1, -1, false};
		return miss;
	}
	return hs_clip_segment(shape, part, a, b, grow);
}

// The part's first edge (in index order) between faces f1 and f2, or -1: among f1's own edges
// (hs_face_edges), a cost that does not grow with the part's face count.
static int edge_between(const hs_world *world, int shape_index, const hs_part *part, int f1, int f2) {
	const hs_shape *shape = &world->shapes[shape_index];
	const hs_face_edges *index = &world->face_edges[shape_index];
	for (int k = index->first[f1]; k < index->first[f1 + 1]; ++k) {
		int e = index->edges[k];
		const hs_edge *edge = &shape->edges[e];
		if (e >= part->first_edge && e < part->first_edge + part->edge_count &&
		    ((edge->faces[0] == f1 && edge->faces[1] == f2) || (edge->faces[0] == f2 && edge->faces[1] == f1)))
			return e;
	}
	return -1;
}

// Closest point on segment a-b to segment c-d (both in the same frame).
static hs_vec3 closest_on_first(hs_vec3 a, hs_vec3 b, hs_vec3 c, hs_vec3 d) {
	hs_vec3 u = hs_sub(b, a), v = hs_sub(d, c), w = hs_sub(a, c);
	double uu = hs_dot(u, u), uv = hs_dot(u, v), vv = hs_dot(v, v), uw = hs_dot(u, w), vw = hs_dot(v, w);
	double den = uu * vv - uv * uv;
	double s = den > 0.0 ? (uv * vw - vv * uw) / den : 0.0;
	s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
	return hs_mul_add(a, s, u);
}

// Where a part touching the surface at C with normal n drives C (B, eq. 1-2), when its own
// position, or its motion since it touched (a part drawn back to the surface, §3.2
// rectification), would take C to C + d. The fingertip holds the surface by Coulomb friction
// (docs/model.md §3, "Friction at the fingertip"): it pushes by how far it goes in along -n and
// drags C sideways by at most μ times that, as a finger sliding over the face; a part not going
// in (leaving, or moving along the face) drives nothing. [H]'s eq. 1-2 take C to the finger
// wherever it went (a sticky contact): under glove noise a fingertip resting on a face dragged
// it by its jitter. How deep a part sank never moves the object (d is its motion, not its depth).
static hs_vec3 friction_finger(hs_vec3 c, hs_vec3 d, hs_vec3 n) {
	double in = -hs_dot(d, n);
	if (!(in > 0.0))
		return c;
	hs_vec3 tan = hs_mul_add(d, in, n);
	double t = hs_length(tan), cap = HS_PUSH_FRICTION * in;
	return hs_add(c, hs_mul_add(t > cap ? hs_scale(tan, cap / t) : tan, -in, n));
}

// A contact found in the body frame `f`: C = `point` on the surface, B = `finger` where the part
// drives it (eq. 1-2), `normal` the face normal or the edge's pseudo-normal.
static void push_contact(hs_world *world, int object, int hand, int part, bool edge, int feature, const frame *f,
                         hs_vec3 point, hs_vec3 normal, hs_vec3 finger, double t) {
	if (world->contact_count >= world->contact_capacity) {
		world->counters.dropped_contacts++;
		return;
	}
	hs_contact *c = &world->contacts[world->contact_count++];
	c->object = hs_object_handle(world, object);
	c->hand = hs_hand_handle(world, hand);
	c->part = part;
	c->edge = edge;
	c->feature = feature;
	c->point = to_world(f, point);
	c->normal = hs_mat3_mul(f->rot, normal);
	if (!world->def.paper_contacts)
		finger = friction_finger(point, hs_sub(finger, point), normal);
	c->finger = to_world(f, finger);
	c->t = t;
}

// Squared distance from c to the segment p0-p1.
static HS_FORCE_INLINE double segment_distance_sq(hs_vec3 c, hs_vec3 p0, hs_vec3 p1) {
	return hs_length_sq(hs_sub(hs_segment_closest(p0, p1, c), c));
}

// The pseudo-normal of edge e: the unit vector from G (the body origin) to the foot of the
// perpendicular from G onto the edge line.
static hs_vec3 edge_normal(const hs_shape *shape, int e) {
	hs_vec3 ea = shape->vertices[shape->edges[e].a], eb = shape->vertices[shape->edges[e].b];
	hs_vec3 dir = hs_normalize(hs_sub(eb, ea));
	return hs_normalize(hs_mul_add(ea, -hs_dot(ea, dir), dir));
}

// Where a part that lies in, or passed through, a convex part of the object now got there
// (docs/model.md §3, "Rectification and swept detection"):
//  - entered this frame (its path relative to the object crosses the surface): C where it
//    crossed, B where it is now - also when it has come out again (swept detection: a fast
//    fingertip at 12 frames/s does not pass through an object);
//  - already inside a frame ago and touching then: sunk in, drawn back to the surface;
//  - already inside and not touching: it started inside (or the object came onto it) and
//    touches nothing: no flinging, no grabbing.
// `grow` > 0: against the part grown by that much (the grasp's release margin, docs/model.md §3);
// swept detection runs for the part itself only. `moved`: the object moved since the last frame
// (a held object): points are culled where they end (their motion relative to it is small).
// The object's pose a frame ago (before the last step moved it).
static frame frame_before_last_step(const hs_body *body) {
	frame f = {body->prev, hs_mat3_from_quat(body->rot_prev)};
	return f;
}

// A part inside the object now and a frame ago, that touched nothing then, lay outside it before
// the object's last move: the object came onto the finger (pushed by another, or falling). It
// touches, drawn back to the surface like a finger that sank in. Else the part started inside
// (a hand placed inside an object): it touches nothing until it has come out.
static bool came_onto(const hs_world *world, int object, const hs_part *part, hs_vec3 prev_point, double grow) {
	if (world->frame == 0)
		return false; // nothing has moved yet (an object's pose a frame ago is its initial parabola's)
	const hs_body *body = &world->bodies[object];
	frame last = frame_before_last_step(body);
	return !inside_part(world, &world->shapes[body->shape], part, to_body(&last, prev_point), grow);
}

static bool line_came_onto(const hs_world *world, int object, const hs_part *part, const hs_vec3 prev[2], double grow) {
	if (world->frame == 0)
		return false;
	const hs_body *body = &world->bodies[object];
	frame last = frame_before_last_step(body);
	return !clip_part(world, &world->shapes[body->shape], part, to_body(&last, prev[0]), to_body(&last, prev[1]), grow).hit;
}

// Where check point i is at piece boundary k of its path (0: a frame ago, steps: now).
static hs_vec3 path_point(const hs_hand *hand, int i, int k, int steps) {
	return k == 0 ? hand->prev_points[i] : k == steps ? hand->points[i] : hand->path_points[k - 1][i];
}

// True when check point i's path through the frame comes within sqrt(r_sq) of c.
static bool path_near(const hs_hand *hand, int i, int steps, hs_vec3 c, double r_sq) {
	if (steps == 1) // one piece (most frames): read straight, not through path_point
		return segment_distance_sq(c, hand->prev_points[i], hand->points[i]) <= r_sq;
	for (int k = 0; k < steps; ++k)
		if (segment_distance_sq(c, path_point(hand, i, k, steps), path_point(hand, i, k + 1, steps)) <= r_sq)
			return true;
	return false;
}

// The first piece of check point i's path (relative to the object: body frame) that crosses into
// the part; false when none does. `inside`: the point ends inside (the last piece may end there).
static bool path_enters(const hs_world *world, const hs_shape *shape, const hs_part *part, const hs_hand *hand, int i, int steps,
                        const frame *body, hs_vec3 a, bool inside, hs_clip *hit, hs_vec3 *from, hs_vec3 *to,
                        double *when) {
	for (int k = 1; k <= steps; ++k) {
		hs_vec3 b = k == steps ? to_body(body, hand->points[i]) : to_body(body, hand->path_points[k - 1][i]);
		hs_clip c = clip_part(world, shape, part, a, b, 0.0);
		if (c.face_in >= 0 && c.hit && (c.t_in < c.t_out || (k == steps && inside))) {
			*hit = c;
			*from = a;
			*to = b;
			*when = (k - 1 + c.t_in) / steps;
			return true;
		}
		a = b;
	}
	return false;
}

// [H]'s letter (paper_contacts): a check point inside the part where it ends the frame touches the
// face it entered through along its motion, or the nearest face when it was inside already, and
// drives C to where it is.
static void paper_point(hs_world *world, int object, int h, int i, const hs_part *part, const frame *body,
                        hs_vec3 a, hs_vec3 b, double grow) {
	const hs_shape *shape = &world->shapes[world->bodies[object].shape];
	hs_clip c = hs_clip_segment_all(shape, part, a, b, grow); // face_in read on a miss too
	if (c.face_in >= 0) {
		push_contact(world, object, h, i, false, c.face_in, body, hs_lerp(a, b, c.t_in), shape->faces[c.face_in].normal,
		             b, c.t_in);
		return;
	}
	int face = nearest_face(world, shape, part, b);
	const hs_face *f = &shape->faces[face];
	push_contact(world, object, h, i, false, face, body, hs_mul_add(b, f->offset - hs_dot(f->normal, b), f->normal),
	             f->normal, b, 0.0);
}

// The object did not move last frame (its pose equals the one before: asleep, or held still).
static bool same_pose(const hs_body *b) {
	return b->pos.x == b->prev.x && b->pos.y == b->prev.y && b->pos.z == b->prev.z && b->rot.w == b->rot_prev.w &&
	       b->rot.x == b->rot_prev.x && b->rot.y == b->rot_prev.y && b->rot.z == b->rot_prev.z;
}

#if HS_LANES4
// The hand's check points i to i + 3 in the four lanes (from its point rows).
HS_AVX static inline hs_lanes4 point_lanes(const hs_hand *hand, int i) {
	return hs_lanes4_rows(&hand->point_rows[0][i], HS_HAND_POINTS + 4);
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
static uint32_t points_near(const hs_hand *hand, hs_vec3 c, double r_sq, double keep_sq, uint32_t *kept) {
	const hs_vec3 *p = hand->points;
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
		const double row[3] = {hand->point_rows[0][k], hand->point_rows[1][k], hand->point_rows[2][k]};
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

// The check points near the part now: within r, its sphere grown by `grow` (its corners reach
// further: part_reach.h); and, in the swept test, a point that touched (or started inside) within
// the sphere grown further by the release margin (or twice it), where it still counts.
static uint32_t points_near_part(const hs_world *world, const hs_hand *hand, const hs_part *part, hs_vec3 center,
                                 double r, bool swept) {
	double keep = r + part->grow_reach * hs_contact_keep(world, hand);
	uint32_t within = 0, near = points_near(hand, center, r * r, keep * keep, &within);
	return swept ? near | (within & (hand->touch_points | hand->embed_points)) : near;
}

// The finger segments (bit s) with an embedded check line: such a line stays so within twice the
// margin of the part, beyond its sphere (detect_lines), so its segment is not culled.
static uint32_t segments_embedded(const hs_hand *hand) {
	uint32_t segments = 0;
	if (hand->embed_lines)
		for (int k = 0; k < HS_HAND_LINES / 4; ++k)
			segments |= (uint32_t)((hand->embed_lines >> (4 * k) & 0xFu) != 0) << k;
	return segments;
}

static void detect_points(hs_world *world, int object, int h, const hs_part *part, const frame *body,
                          const frame *before, bool moved, bool cull, double grow, unsigned far) {
	const hs_shape *shape = &world->shapes[world->bodies[object].shape];
	const hs_hand *hand = &world->hands[h];
	hs_vec3 center = to_world(body, part->center); // cull before the transform
	double r = part->radius + part->grow_reach * grow, r_sq = r * r; // grown: its corners reach further
	bool paper = world->def.paper_contacts, swept = grow == 0.0 && !paper;
	int steps = moved ? 1 : hand->path_steps; // a held object moves with the hand: chords suffice
	bool still = !moved && same_pose(&world->bodies[object]);
	// passed over: far fingers' points (far_fingers), and those beyond the sphere now unless paths count
	uint32_t todo = ((1u << HS_HAND_POINTS) - 1u) & ~hs_finger_parts(far, 4);
	uint32_t near = cull ? points_near_part(world, hand, part, center, r, swept) : todo;
	double margin = world->def.grasp_release_mm * 1e-3;
	if (!swept || moved)
		todo &= near;
	for (; todo; todo &= todo - 1u) {
		int i = hs_lowest_bit(todo);
		if (!(near >> i & 1u) && !path_near(hand, i, steps, center, r_sq))
			continue;
		hs_vec3 b = to_body(body, hand->points[i]);
		bool inside = inside_part(world, shape, part, b, grow);
		if (paper) {
			if (inside)
				paper_point(world, object, h, i, part, body, to_body(before, hand->prev_points[i]), b, grow);
			continue;
		}
		bool touched = swept && (hand->touch_points >> i & 1u);
		if (swept && (hand->embed_points >> i & 1u)) { // started inside: touches nothing until clear
			if (inside_part(world, shape, part, b, 2.0 * margin))
				world->hands[h].embed_points_next |= 1u << i;
			continue;
		}
		if (!inside && touched && inside_part(world, shape, part, b, margin)) {
			world->hands[h].near_points |= 1u << i; // off the surface, within the margin: still touching
			if (moved)
				continue;
			const hs_face *f = &shape->faces[nearest_face(world, shape, part, b)];
			hs_vec3 on = hs_mul_add(b, f->offset - hs_dot(f->normal, b), f->normal);
			// on an object that moved, only beside a part of its hand that pushes it (keep_hovering)
			push_contact(world, object, h, i, false, (int)(f - shape->faces), body, on, f->normal, on, still ? 0.0 : -1.0);
			continue;
		}
		if (!inside && (!swept || moved))
			continue; // a held object moves with the hand: nothing passes through it unseen
		hs_vec3 a = to_body(before, hand->prev_points[i]); // where it was
		hs_clip c;
		hs_vec3 from = a, to = b; // (path_enters sets them when it enters: read only then)
		bool entered = false;
		double when = 0.0;
		if (touched) {
			// the entry is read only for a point that did not touch: not sought
		} else if (grow > 0.0 || steps == 1) {
			c = clip_part(world, shape, part, a, b, grow);
			from = a;
			to = b;
			entered = c.face_in >= 0 && c.hit && (inside || c.t_in < c.t_out);
			when = c.t_in;
		} else {
			entered = path_enters(world, shape, part, hand, i, steps, body, a, inside, &c, &from, &to, &when);
		}
		if (entered && !touched) { // reached the surface this frame
			push_contact(world, object, h, i, false, c.face_in, body, hs_lerp(from, to, c.t_in),
			             shape->faces[c.face_in].normal, b, when);
		} else if (inside && !touched && !inside_part(world, shape, part, a, grow)) { // from on the surface (the clip's t = 0)
			int face = nearest_face(world, shape, part, a);
			push_contact(world, object, h, i, false, face, body, a, shape->faces[face].normal, b, 0.0);
		} else if (inside && (grow > 0.0 || touched || came_onto(world, object, part, hand->prev_points[i], grow))) {
			// sunk in (or back in, within the margin), or the object came onto it; or within the grown
			// part (the margin counts every part)
			int face = nearest_face(world, shape, part, a);
			const hs_face *f = &shape->faces[face];
			hs_vec3 point = hs_mul_add(a, f->offset - hs_dot(f->normal, a), f->normal);
			hs_vec3 start = inside_part(world, shape, part, a, grow) ? a : point; // back in: from the surface
			push_contact(world, object, h, i, false, face, body, point, f->normal,
			             hs_add(point, hs_sub(b, start)), 0.0);
		} else if (inside && swept) { // in it since before it touched anything: started inside
			world->hands[h].embed_points_next |= 1u << i;
		}
	}
}

// A check line across the part now (entering and leaving through two faces): an edge contact
// when the faces meet at an edge (§3.2 (B)), else the face nearest its middle. `d`: NULL when
// the line reached the object this frame (B = the line's point nearest C), else its motion
// relative to the object since it touched last frame (sunk in).
static void line_across(hs_world *world, int object, int h, int j, const hs_part *part, const frame *body,
                        hs_vec3 p0, hs_vec3 p1, hs_clip c, const hs_vec3 *d) {
	const hs_shape *shape = &world->shapes[world->bodies[object].shape];
	int feature = edge_between(world, world->bodies[object].shape, part, c.face_in, c.face_out);
	bool edge = feature >= 0;
	hs_vec3 point, normal;
	if (edge) {
		point = closest_on_first(shape->vertices[shape->edges[feature].a], shape->vertices[shape->edges[feature].b],
		                         p0, p1);
		normal = edge_normal(shape, feature);
	} else {
		hs_vec3 mid = hs_lerp(p0, p1, 0.5 * (c.t_in + c.t_out));
		feature = nearest_face(world, shape, part, mid);
		const hs_face *f = &shape->faces[feature];
		point = hs_mul_add(mid, f->offset - hs_dot(f->normal, mid), f->normal);
		normal = f->normal;
	}
	hs_vec3 finger = d ? hs_add(point, *d) : hs_segment_closest(p0, p1, point);
	push_contact(world, object, h, HS_HAND_POINTS + j, edge, feature, body, point, normal, finger, 0.0);
}

static bool across(hs_clip c) { return c.hit && c.face_in >= 0 && c.face_out >= 0; }

// Where the segment a-b meets the triangle v0 v1 v2 (Möller-Trumbore): the segment's parameter
// *t and the barycentric weights *beta (of v1) and *gamma (of v2). False when it misses or lies in
// the triangle's plane (a line that did not move sweeps no area).
static bool segment_triangle(hs_vec3 a, hs_vec3 b, hs_vec3 v0, hs_vec3 v1, hs_vec3 v2, double *t, double *beta,
                             double *gamma) {
	hs_vec3 e1 = hs_sub(v1, v0), e2 = hs_sub(v2, v0), d = hs_sub(b, a);
	hs_vec3 pv = hs_cross(d, e2);
	double det = hs_dot(e1, pv);
	if (det == 0.0)
		return false;
	hs_vec3 tv = hs_sub(a, v0), qv = hs_cross(tv, e1);
	double u = hs_dot(tv, pv) / det, v = hs_dot(d, qv) / det, s = hs_dot(e2, qv) / det;
	if (!(u >= 0.0 && v >= 0.0 && u + v <= 1.0 && s >= 0.0 && s <= 1.0))
		return false;
	*t = s;
	*beta = u;
	*gamma = v;
	return true;
}

// Where an edge of the part meets the surface a line sweeps from q0-q1 to p0-p1 (the triangles
// q0 q1 p1 and q0 p1 p0): the earliest, as *u (0 at q, 1 at p), *s along the line, *t along the
// edge. False when none does.
static bool edge_through_sweep(hs_vec3 ea, hs_vec3 eb, const hs_vec3 q[2], const hs_vec3 p[2], double *u, double *s,
                               double *t) {
	double t1 = 0.0, b1 = 0.0, g1 = 0.0, t2 = 0.0, b2 = 0.0, g2 = 0.0; // set where read (gcc -O3 cannot see it)
	bool first = segment_triangle(ea, eb, q[0], q[1], p[1], &t1, &b1, &g1);
	bool second = segment_triangle(ea, eb, q[0], p[1], p[0], &t2, &b2, &g2);
	if (first && (!second || g1 <= b2 + g2)) {
		*u = g1;
		*s = b1 + g1;
		*t = t1;
		return true;
	}
	if (second) {
		*u = b2 + g2;
		*s = b2;
		*t = t2;
	}
	return second;
}

// True when all four ends lie beyond one face plane of the part: the swept surface misses it.
static bool sweep_beyond_a_face(const hs_world *world, const hs_shape *shape, const hs_part *part, const hs_vec3 q[2],
                                const hs_vec3 p[2]) {
	const hs_vec3 ends[4] = {q[0], q[1], p[0], p[1]};
	if (part->face_count >= HS_FACE_TREE_MIN_FACES) {
		const hs_face_tree *tree = tree_of(world, shape);
		int root = hs_face_tree_root(tree, shape, part);
		if (root >= 0)
			return hs_face_tree_beyond(tree, root, shape, ends);
	}
	return scan_beyond(shape, part, ends, 0.0);
}

// The earliest feature a swept line meets so far (swept_line): its place u along the sweep, the
// face or edge, where on the part and where on the line.
typedef struct swept_hit {
	double best;
	int feature;
	bool edge;
	hs_vec3 point, finger;
} swept_hit;

// Edge e against the surface a line sweeps from q0-q1 to n0-n1 (ends p0-p1 now): kept when it meets
// it earlier than the best so far (the first in the order tried on a tie).
static inline void try_edge(const hs_shape *shape, int e, const hs_vec3 q[2], const hs_vec3 n[2], const hs_vec3 p[2],
                            swept_hit *hit) {
	hs_vec3 ea = shape->vertices[shape->edges[e].a], eb = shape->vertices[shape->edges[e].b];
	double u, s, t;
	if (edge_through_sweep(ea, eb, q, n, &u, &s, &t) && u < hit->best) {
		hit->best = u;
		hit->feature = e;
		hit->edge = true;
		hit->point = hs_lerp(ea, eb, t);
		hit->finger = hs_lerp(p[0], p[1], s);
	}
}

// A many-faced part's edges against the sweep: only those of the faces whose planes the sweep
// reaches (face_tree.h), in index order; any other edge lies on faces the sweep stays inside of,
// so it misses, and the result is the loop over every edge's. -1 (nothing tried) when the part
// has no tree.
static HS_NOINLINE int sweep_edges(hs_world *world, const hs_shape *shape, const hs_part *part, const hs_vec3 q[2],
                                   const hs_vec3 n[2], const hs_vec3 p[2], swept_hit *hit) {
	const hs_face_tree *tree = tree_of(world, shape);
	int root = hs_face_tree_root(tree, shape, part);
	if (root < 0)
		return -1;
	const hs_vec3 ends[4] = {q[0], q[1], n[0], n[1]};
	int faces = hs_face_tree_reached(tree, root, (int)(part - shape->parts), shape, ends, world->face_pick);
	const hs_face_edges *index = &world->face_edges[shape - world->shapes];
	int count = 0;
	for (int k = 0; k < faces; ++k)
		for (int j = index->first[world->face_pick[k]]; j < index->first[world->face_pick[k] + 1]; ++j) {
			int e = index->edges[j];
			if (e >= part->first_edge && e < part->first_edge + part->edge_count && !world->edge_mark[e]) {
				world->edge_mark[e] = 1;
				world->edge_pick[count++] = e;
			}
		}
	for (int k = 0; k < count; ++k)
		world->edge_mark[world->edge_pick[k]] = 0;
	hs_sort_indices(world->edge_pick, count);
	for (int k = 0; k < count; ++k)
		try_edge(shape, world->edge_pick[k], q, n, p, hit);
	return count;
}

// The first contact of a check line that misses the part at both ends of a piece of its path but
// swept across it (from q0-q1 to n0-n1): an end of the line passing through a face, or an edge of
// the part through the swept surface. A convex part meets that surface in one of these two ways
// only. C where they met, B the line's point at the same place along it at the end of the frame
// (p); the piece spans [t0, t0 + span] of the frame. False when it did not meet the part.
static bool swept_line(hs_world *world, int object, int h, int j, const hs_part *part, const frame *body,
                       const hs_vec3 q[2], const hs_vec3 n[2], const hs_vec3 p[2], double t0, double span) {
	const hs_shape *shape = &world->shapes[world->bodies[object].shape];
	if (sweep_beyond_a_face(world, shape, part, q, n))
		return false;
	swept_hit hit = {INFINITY, -1, false, q[0], p[0]};
	for (int k = 0; k < 2; ++k) {
		hs_clip c = clip_part(world, shape, part, q[k], n[k], 0.0);
		if (c.hit && c.face_in >= 0 && c.t_in < c.t_out && c.t_in < hit.best) {
			hit.best = c.t_in;
			hit.feature = c.face_in;
			hit.point = hs_lerp(q[k], n[k], c.t_in);
			hit.finger = p[k];
		}
	}
	// a many-faced part: only the edges of faces the sweep reaches; else every edge, in index order
	if (part->face_count < HS_FACE_TREE_MIN_FACES || sweep_edges(world, shape, part, q, n, p, &hit) < 0)
		for (int e = part->first_edge; e < part->first_edge + part->edge_count; ++e)
			try_edge(shape, e, q, n, p, &hit);
	if (hit.feature < 0)
		return false;
	push_contact(world, object, h, HS_HAND_POINTS + j, hit.edge, hit.feature, body, hit.point,
	             hit.edge ? edge_normal(shape, hit.feature) : shape->faces[hit.feature].normal, hit.finger,
	             t0 + hit.best * span);
	return true;
}

// A check line that misses the part now (p, body frame): the first piece of its path through the
// frame that swept across the part makes the contact. Touching it at the start of a piece, it
// had reached it before and left again: nothing. `start`: the line a frame ago, in the frame of the
// object's pose before the step (transformed once, by detect_lines).
static void swept_path(hs_world *world, int object, int h, int j, const hs_part *part, const frame *body,
                       int steps, const hs_vec3 start[2], const hs_vec3 p[2]) {
	const hs_shape *shape = &world->shapes[world->bodies[object].shape];
	const hs_hand *hand = &world->hands[h];
	hs_vec3 q[2] = {start[0], start[1]};
	for (int k = 1; k <= steps; ++k) {
		if (clip_part(world, shape, part, q[0], q[1], 0.0).hit)
			return;
		hs_vec3 n[2] = {p[0], p[1]};
		if (k < steps) {
			n[0] = to_body(body, hand->path_lines[k - 1][j][0]);
			n[1] = to_body(body, hand->path_lines[k - 1][j][1]);
		}
		if (swept_line(world, object, h, j, part, body, q, n, p, (double)(k - 1) / steps, 1.0 / steps))
			return;
		q[0] = n[0];
		q[1] = n[1];
	}
}

// fmax(a, b), NaN included, without the library call
static double larger(double a, double b) { return a >= b || b != b ? a : b; }

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

// True when check line j's path through the frame may come within r of c: each piece's quad.
static bool line_path_near(const hs_hand *hand, int j, int steps, hs_vec3 c, double r) {
	for (int k = 0; k < steps; ++k) {
		const hs_vec3 *m = k == 0 ? hand->prev_lines[j] : hand->path_lines[k - 1][j];
		const hs_vec3 *l = k + 1 == steps ? hand->lines[j] : hand->path_lines[k][j];
		if (quad_near(&m[0], &m[1], &l[0], &l[1], c, r))
			return true;
	}
	return false;
}

// The same for the axis of a finger segment, check points a to a + 1.
static bool axis_path_near(const hs_hand *hand, int a, int steps, hs_vec3 c, double r) {
	if (steps == 1) // one piece (most frames): read straight, not through path_point
		return quad_near(&hand->prev_points[a], &hand->prev_points[a + 1], &hand->points[a], &hand->points[a + 1], c, r);
	for (int k = 0; k < steps; ++k) {
		hs_vec3 m0 = path_point(hand, a, k, steps), m1 = path_point(hand, a + 1, k, steps);
		hs_vec3 l0 = path_point(hand, a, k + 1, steps), l1 = path_point(hand, a + 1, k + 1, steps);
		if (quad_near(&m0, &m1, &l0, &l1, c, r))
			return true;
	}
	return false;
}

// The first check point of finger segment s (finger s / 3, segment s % 3): 4 (s / 3) + s % 3.
static const int SEGMENT_FIRST_POINT[15] = {0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, 16, 17, 18};

#if defined(HS_SELFCHECK)
// Sanitizer builds: what sweep_clear_of_a_face skipped would have found nothing.
static void check_clear(const hs_world *world, const hs_shape *shape, const hs_part *part, const hs_vec3 q[2],
                        const hs_vec3 p[2]) {
	if (clip_part(world, shape, part, p[0], p[1], 0.0).hit || clip_part(world, shape, part, q[0], q[1], 0.0).hit ||
	    !sweep_beyond_a_face(world, shape, part, q, p)) {
		fprintf(stderr, "handspring: a line's sweep passed over as clear of a face touches the part (frame %ld)\n",
		        world->frame);
		abort();
	}
}
#endif

// True when the line's sweep through the frame, q to p (one piece), lies beyond one face of a
// scanned part by more than HS_CULL_SLACK (far above the rounding of body-frame coordinates within
// HS_MAX_COORDINATE): then the clips of p and of q miss and sweep_beyond_a_face holds, so
// swept_path finds nothing, and the line is passed over before them.
static bool sweep_clear_of_a_face(const hs_world *world, const hs_shape *shape, const hs_part *part, const hs_vec3 q[2],
                                  const hs_vec3 p[2]) {
	const hs_vec3 ends[4] = {q[0], q[1], p[0], p[1]};
	if (part->face_count >= HS_FACE_TREE_MIN_FACES || !scan_beyond(shape, part, ends, HS_CULL_SLACK))
		return false;
#if defined(HS_SELFCHECK)
	check_clear(world, shape, part, q, p);
#endif
	(void)world;
	return true;
}

#if defined(HS_SELFCHECK)
// Sanitizer builds: each line of a segment passed over as clear would have been passed over alone.
static void check_segment_clear(const hs_world *world, int h, int a, const frame *body, const frame *before,
                                const hs_shape *shape, const hs_part *part) {
	int s = a - a / 4; // the segment of first check point a (SEGMENT_FIRST_POINT)
	hs_hand *hand = (hs_hand *)&world->hands[h]; // placing lines changes no result (hand_internal.h)
	hs_hand_ready_segment(hand, s);
	for (int j = 4 * s; j < 4 * s + 4; ++j) {
		hs_vec3 p[2], q[2];
		line_to_body(body, hand->lines[j], p);
		line_to_body(before, hand->prev_lines[j], q);
		if (!sweep_clear_of_a_face(world, shape, part, q, p)) {
			fprintf(stderr, "handspring: a segment passed over as clear of a face has line %d near the part\n", j);
			abort();
		}
	}
}
#endif

// The same for a whole finger segment, before its lines are placed: its axis now and a frame ago
// (check points a and a + 1) beyond one face by more than finger_radius + 2 HS_CULL_SLACK. Each of
// its check lines lies finger_radius from that axis, so its ends now and a frame ago lie beyond
// the face by more than HS_CULL_SLACK (the rounding of placing and transforming them is far below
// the other HS_CULL_SLACK): sweep_clear_of_a_face would pass each one over.
static bool segment_clear_of_a_face(const hs_world *world, int h, int a, const frame *body, const frame *before,
                                    const hs_shape *shape, const hs_part *part) {
	const hs_hand *hand = &world->hands[h];
	if (part->face_count >= HS_FACE_TREE_MIN_FACES)
		return false;
	const hs_vec3 e[4] = {to_body(body, hand->points[a]), to_body(body, hand->points[a + 1]),
	                      to_body(before, hand->prev_points[a]), to_body(before, hand->prev_points[a + 1])};
	if (!scan_beyond(shape, part, e, hand->def.finger_radius + 2.0 * HS_CULL_SLACK))
		return false;
#if defined(HS_SELFCHECK)
	check_segment_clear(world, h, a, body, before, shape, part);
#endif
	return true;
}

// A line with an end inside the part is the check points' business (detect_lines); so is one
// with an end off the surface by less than grasp_release_mm at a check point that touches (it
// touched last frame, the hysteresis of detect_points, or touches the part now), at the end of
// the frame or at its start (a finger lifting off sweeps its side past the face it leaves): a fingertip resting on a top face 1 cm from its edge, its prism's
// side 2 mm from the edge, swept that side across the edge under glove noise (±6 mm a frame) and
// pushed the object sideways while the tip itself held still.
static bool end_touches(const hs_world *world, uint32_t touching, int point, const hs_shape *shape,
                        const hs_part *part, const hs_vec3 p[2]) { // the line runs beside point and point + 1
	double margin = world->def.grasp_release_mm * 1e-3;
	for (int k = 0; k < 2; ++k)
		if ((touching >> (point + k) & 1u) && inside_part(world, shape, part, p[k], margin))
			return true;
	return false;
}

typedef struct deep_memo {
	uint32_t known, deep; // the check points tested so far, and those found deep
} deep_memo;

// True when check point a or a + 1 touches (`touching`) and lies inside the part grown by `grow`
// now (the check points of a segment's line ends, end_touches). `memo` keeps each point's answer
// for the rest of the part's lines.
static bool ends_deep(const hs_world *world, const hs_hand *hand, uint32_t touching, int a, const frame *body, const hs_shape *shape,
                      const hs_part *part, double grow, deep_memo *memo) {
	for (uint32_t ends = touching & 3u << a; ends; ends &= ends - 1u) { // a, then a + 1
		int i = hs_lowest_bit(ends);
		uint32_t bit = 1u << i;
		if (!(memo->known & bit)) { // a check point ends two segments: tested once
			memo->known |= bit;
			if (inside_part(world, shape, part, to_body(body, hand->points[i]), grow))
				memo->deep |= bit;
		}
		if (memo->deep & bit)
			return true;
	}
	return false;
}

// What detect_lines tests a finger segment by, for a part's bounding sphere of radius r. A
// segment's 4 check lines lie finger_radius from its axis (joint to joint), at every point of the
// path: when the axis is further than rs = r + finger_radius from the part, all four are, and none
// is tested one by one (the same lines culled, fewer distances taken). Where the paths count, a
// line's piece of path has its corners' mean within finger_radius of the axis' and its sphere at
// most 2 finger_radius wider: when the axis' misses rp = r + 3 finger_radius, the lines' miss r.
// An axis within ri = r - finger_radius has all four lines within r: none is tested alone. A
// touching check point inside the part grown by deep = margin - finger_radius has the segment's
// line ends beside it inside the part grown by the margin: end_touches holds for all four lines.
typedef struct segment_bounds {
	double rs, rp, ri, deep;
} segment_bounds;

static segment_bounds segment_bounds_of(const hs_world *world, const hs_hand *hand, double r) {
	double rf = hand->def.finger_radius;
	segment_bounds b = {r + rf + HS_CULL_SLACK, r + 3.0 * rf + HS_CULL_SLACK, r - rf - HS_CULL_SLACK,
	                    world->def.grasp_release_mm * 1e-3 - rf - HS_CULL_SLACK};
	return b;
}

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
static uint32_t axes_near(const hs_hand *hand, hs_vec3 c, double r_sq, double d[16]) {
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
		int a0 = SEGMENT_FIRST_POINT[s], a1 = SEGMENT_FIRST_POINT[s + 1];
		__m128d dist = segment_distance_sq2(hs_lanes2_load(&hand->points[a0], &hand->points[a1]),
		                                    hs_lanes2_load(&hand->points[a0 + 1], &hand->points[a1 + 1]), c);
		_mm_storel_pd(&d[s], dist);
		_mm_storeh_pd(&d[s + 1], dist);
		near |= (uint32_t)_mm_movemask_pd(_mm_cmpngt_pd(dist, _mm_set1_pd(r_sq))) << s;
	}
#endif
	for (; s < 15; ++s) {
		int a = SEGMENT_FIRST_POINT[s];
		d[s] = segment_distance_sq(c, hand->points[a], hand->points[a + 1]);
		if (!(d[s] > r_sq))
			near |= 1u << s;
	}
#if defined(HS_SELFCHECK)
	for (int k = 0; k < 15; ++k) {
		double e = segment_distance_sq(c, hand->points[SEGMENT_FIRST_POINT[k]], hand->points[SEGMENT_FIRST_POINT[k] + 1]);
		if (memcmp(&e, &d[k], sizeof e) != 0 || (near >> k & 1u) != !(e > r_sq)) {
			fprintf(stderr, "selfcheck: axes_near differs from segment_distance_sq\n");
			abort();
		}
	}
#endif
	return near;
}

// The check lines of segment s (bit k: line 4 s + k) not further than sqrt(r_sq) from c now, as
// the line cull reads segment_distance_sq: !(d > r_sq), NaN near; two at a time with SSE2.
static unsigned lines_near(const hs_hand *hand, int s, hs_vec3 c, double r_sq) {
	unsigned near = 0;
	const hs_vec3(*l)[2] = &hand->lines[4 * s];
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
			fprintf(stderr, "selfcheck: lines_near differs from segment_distance_sq\n");
			abort();
		}
#endif
	return near;
}

#if defined(HS_SELFCHECK)
// Sanitizer builds: each line of a segment held_lines_clear passed over, placed and moved into
// the body frame, lies beside a touching check point or misses the part.
static void check_held_clear(hs_world *world, int h, int s, int a, const frame *body, const hs_shape *shape,
                             const hs_part *part, uint32_t touching, double grow) {
	hs_hand_ready_segment(&world->hands[h], s);
	for (int j = 4 * s; j < 4 * s + 4; ++j) {
		hs_vec3 p[2];
		line_to_body(body, world->hands[h].lines[j], p);
		if (!end_touches(world, touching, a, shape, part, p) && clip_part(world, shape, part, p[0], p[1], grow).hit) {
			fprintf(stderr, "selfcheck: a held object's line passed over as clear touches the part\n");
			abort();
		}
	}
}
#else
static inline void check_held_clear(hs_world *world, int h, int s, int a, const frame *body, const hs_shape *shape,
                                    const hs_part *part, uint32_t touching, double grow) {
	(void)world, (void)h, (void)s, (void)a, (void)body, (void)shape, (void)part, (void)touching, (void)grow;
}
#endif

// The turn from a hand's wrist frame (mirrored for a left hand) into a held object's body frame,
// scaled by finger_radius: body rot^T · place_m · diag(1, ±1, 1) · finger_radius, as its three
// columns; made once per detection, at the first segment held_lines_clear looks at.
typedef struct held_turn {
	bool ready;
	hs_vec3 c[3];
} held_turn;

static HS_NOINLINE void held_turn_make(held_turn *t, const frame *body, const hs_hand *hand) {
	hs_mat3 p = hand->place_m;
	double rf = hand->def.finger_radius, ry = hand->def.left ? -rf : rf;
	t->c[0] = hs_mat3_tmul(body->rot, hs_v3(rf * p.r0.x, rf * p.r1.x, rf * p.r2.x));
	t->c[1] = hs_mat3_tmul(body->rot, hs_v3(ry * p.r0.y, ry * p.r1.y, ry * p.r2.y));
	t->c[2] = hs_mat3_tmul(body->rot, hs_v3(rf * p.r0.z, rf * p.r1.z, rf * p.r2.z));
	t->ready = true;
}

static HS_FORCE_INLINE hs_vec3 held_turn_apply(const held_turn *t, hs_vec3 v) {
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

static inline bool held_each_clear(const hs_part *part, const held_ends *l) {
	const hs_vec3 off[4] = {l->y, hs_scale(l->y, -1.0), l->z, hs_scale(l->z, -1.0)};
	for (int k = 0; k < 4; ++k) {
		hs_vec3 p0 = hs_add(l->e0, off[k]), p1 = hs_add(l->e1, off[k]);
		if ((l->touch0 && hs_part_box_inside(part, p0, l->margin)) || (l->touch1 && hs_part_box_inside(part, p1, l->margin)) ||
		    hs_part_box_apart(part, p0, p1, l->grow, 2.0 * HS_CULL_SLACK) ||
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
HS_AVX static bool held_four_clear(const hs_part *part, const held_ends *l) {
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
	const double *o = part->box_offset;
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
// segment's y or z axis times finger_radius (hand.c, segment_lines; mirrored for a left hand):
// the axes read off the segment's quaternion and taken into the body frame by one turn
// (held_turn), it differs from the placed and moved end by rounding alone, far below
// HS_CULL_SLACK. Each line must, by that slack, lie beside a touching check point inside the
// part grown by the margin (end_touches), have both ends beyond one face of the box (clip_part's
// miss), or lie outside the part's bounding sphere. Box parts only (hs_part_is_box); the lines are
// not embedded.
static HS_FORCE_INLINE bool held_lines_clear_in(hs_world *world, int h, int s, int a, const frame *body,
                                                const hs_shape *shape, const hs_part *part, uint32_t touching, double grow,
                                                held_turn *turn, bool four) {
	const hs_hand *hand = &world->hands[h];
	hs_vec3 e0 = to_body(body, hand->points[a]), e1 = to_body(body, hand->points[a + 1]);
	if (!hs_part_box_takes(e0) || !hs_part_box_takes(e1))
		return false;
	hs_quat q = hand->local.segment[s]; // its y and z axes: the rotation's second and third columns
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
	held_ends ends = {e0, e1, y, z, touching >> a & 1u, touching >> (a + 1) & 1u,
	                  world->def.grasp_release_mm * 1e-3 - HS_CULL_SLACK, grow, part->radius + part->grow_reach * grow + HS_CULL_SLACK};
#if HS_LANES4
	bool clear = four ? held_four_clear(part, &ends) : held_each_clear(part, &ends);
#else
	(void)four;
	bool clear = held_each_clear(part, &ends);
#endif
#if defined(HS_SELFCHECK)
	if (clear != held_each_clear(part, &ends)) {
		fprintf(stderr, "selfcheck: held_lines_clear's lanes differ from its loop\n");
		abort();
	}
#endif
	if (!clear)
		return false;
	check_held_clear(world, h, s, a, body, shape, part, touching, grow);
	return true;
}

static bool held_lines_clear(hs_world *world, int h, int s, int a, const frame *body, const hs_shape *shape,
                             const hs_part *part, uint32_t touching, double grow, held_turn *turn) {
	return held_lines_clear_in(world, h, s, a, body, shape, part, touching, grow, turn, false);
}

#if HS_LANES4
HS_AVX static bool held_lines_clear_avx(hs_world *world, int h, int s, int a, const frame *body, const hs_shape *shape,
                                        const hs_part *part, uint32_t touching, double grow, held_turn *turn) {
	return held_lines_clear_in(world, h, s, a, body, shape, part, touching, grow, turn, true);
}
#define HELD_LINES_CLEAR (hs_cpu_has_avx() ? held_lines_clear_avx : held_lines_clear)
#else
#define HELD_LINES_CLEAR held_lines_clear
#endif

// (B) check lines against the part: across it now (reached it this frame, sunk in, or across it
// since before it touched anything, as the check points in detect_points), or swept across it
// during the frame. A line with an end inside is the check points' business.
static void detect_lines(hs_world *world, int object, int h, const hs_part *part, const frame *body,
                         const frame *before, bool moved, bool cull, double grow, uint32_t touching, unsigned far) {
	const hs_shape *shape = &world->shapes[world->bodies[object].shape];
	const hs_hand *hand = &world->hands[h];
	hs_vec3 center = to_world(body, part->center);
	double r = part->radius + part->grow_reach * grow; // grown: its corners reach further
	bool paper = world->def.paper_contacts, swept = grow == 0.0 && !paper;
	int steps = moved ? 1 : hand->path_steps; // a held object moves with the hand: chords suffice
	segment_bounds sb = segment_bounds_of(world, hand, r);
	deep_memo memo = {0, 0};
	held_turn turn = {.ready = false};
	// passed over: far fingers' segments (far_fingers), and those beyond rs now unless paths count
	double d_axis[16]; // axes_near's AVX path fills a 16th
	uint32_t segments = HS_HAND_ALL_SEGMENTS & ~hs_finger_parts(far, 3);
	uint32_t near = (cull ? axes_near(hand, center, sb.rs * sb.rs, d_axis) : segments) | (swept ? segments_embedded(hand) : 0);
	if (!swept || moved)
		segments &= near;
	for (; segments; segments &= segments - 1u) {
		int s = hs_lowest_bit(segments), a = SEGMENT_FIRST_POINT[s]; // a: the segment's first check point
		double d_sq = cull ? d_axis[s] : 0.0;
		bool plain = swept && !(hand->embed_lines >> (4 * s) & 0xFu); // none of its lines embedded
		if ((!(near >> s & 1u) && !axis_path_near(hand, a, steps, center, sb.rp)) ||
		    (swept && ends_deep(world, hand, touching, a, body, shape, part, sb.deep, &memo)) ||
		    (plain && !moved && steps == 1 && segment_clear_of_a_face(world, h, a, body, before, shape, part)) ||
		    (plain && moved && hs_part_is_box(part) && HELD_LINES_CLEAR(world, h, s, a, body, shape, part, touching, grow, &turn)))
			continue; // far, each line beside a touching point, or clear (seen before it is placed)
		hs_hand_ready_segment(&world->hands[h], s); // its lines are read from here on
		bool all_near = (sb.ri > 0.0 && d_sq <= sb.ri * sb.ri) || (swept && !plain); // all within r now
		unsigned lines = cull && !all_near ? lines_near(hand, s, center, r * r) : 0xFu;
		for (int j = 4 * s; j < 4 * s + 4; ++j) {
			const hs_vec3 *l = hand->lines[j], *m = hand->prev_lines[j];
			if (!(lines >> (j - 4 * s) & 1u) && (!swept || moved || !line_path_near(hand, j, steps, center, r)))
				continue;
			hs_vec3 p[2];
			line_to_body(body, l, p);
			bool embedded = swept && (hand->embed_lines >> j & 1u);
			// where no path is swept (a held object; the grown and paper tests) a line that misses the part
			// now is done: clipped before the line a frame ago is transformed (most lines end here)
			bool miss_ends = (moved || !swept) && !embedded;
			if (swept && end_touches(world, touching, a, shape, part, p))
				continue; // beside a touching check point at the frame's end
			hs_clip c = miss_ends ? clip_part(world, shape, part, p[0], p[1], grow) : (hs_clip){0.0, 1.0, -1, -1, false};
			if (miss_ends && !c.hit)
				continue;
			hs_vec3 q[2]; // the line a frame ago
			line_to_body(before, m, q);
			if (swept && !moved && !embedded && steps == 1 && sweep_clear_of_a_face(world, shape, part, q, p))
				continue; // missed it at both ends and swept nothing of it
			if (swept && end_touches(world, hand->touch_points, a, shape, part, q))
				continue; // or at its start
			if (embedded) { // started inside: touches nothing until clear
				if (clip_part(world, shape, part, p[0], p[1], 2.0 * world->def.grasp_release_mm * 1e-3).hit)
					world->hands[h].embed_lines_next |= (uint64_t)1 << j;
				continue;
			}
			if (!miss_ends)
				c = clip_part(world, shape, part, p[0], p[1], grow);
			if (!c.hit) {
				if (swept && !moved) // a held object moves with the hand: nothing passes through it unseen
					swept_path(world, object, h, j, part, body, steps, q, p);
				continue;
			}
			if (!across(c))
				continue; // an end is inside
			if (paper) { // [H]'s letter: across where it ends the frame
				line_across(world, object, h, j, part, body, p[0], p[1], c, NULL);
				continue;
			}
			if (!clip_part(world, shape, part, q[0], q[1], grow).hit) { // reached it this frame
				line_across(world, object, h, j, part, body, p[0], p[1], c, NULL);
			} else if (grow > 0.0 || (hand->touch_lines >> j & 1u) || line_came_onto(world, object, part, m, grow)) {
				// in it a frame ago too: sunk in (touching), or the object came onto it
				hs_vec3 d = hs_scale(hs_add(hs_sub(p[0], q[0]), hs_sub(p[1], q[1])), 0.5);
				line_across(world, object, h, j, part, body, p[0], p[1], c, &d);
			} else if (swept) { // in it since before it touched anything: started inside, touches nothing
				world->hands[h].embed_lines_next |= (uint64_t)1 << j;
			}
		}
	}
}

hs_vec3 hs_contact_rectify(const hs_world *world, hs_vec3 p) {
	for (int i = 0; i < world->object_count; ++i) {
		const hs_body *body = &world->bodies[i];
		const hs_shape *shape = &world->shapes[body->shape];
		if (hs_length_sq(hs_sub(p, body->pos)) > shape->radius * shape->radius)
			continue;
		frame f = frame_of(body);
		hs_vec3 b = to_body(&f, p);
		for (int k = 0; k < shape->part_count; ++k) {
			const hs_part *part = &shape->parts[k];
			if (!inside_part(world, shape, part, b, 0.0))
				continue;
			const hs_face *face = &shape->faces[nearest_face(world, shape, part, b)];
			return to_world(&f, hs_mul_add(b, face->offset - hs_dot(face->normal, b), face->normal));
		}
	}
	return p;
}

int hs_contact_detect(hs_world *world, int object, const hs_pose *before) {
	return hs_contact_detect_grown(world, object, before, 0.0);
}

static int finger_of(int part);

// How far contact c drives C in along its normal (friction_finger: the depth it pushes).
static double push_depth(const hs_contact *c) { return -hs_dot(hs_sub(c->finger, c->point), c->normal); }

static bool touched_before(const hs_world *world, const hs_contact *c) {
	const hs_hand *hand = &world->hands[c->hand.index1 - 1];
	return c->part < HS_HAND_POINTS ? (hand->touch_points >> c->part & 1u)
	                                : (hand->touch_lines >> (c->part - HS_HAND_POINTS) & 1u);
}

// A part that reached a face this frame behind a part of the same finger that already touched
// that face, or reached it earlier in this frame (swept detection's t), and drives it further in
// is set aside: the face, pushed by the leading part, is still ahead of it. Detection tests the parts against the object's pose at the start of the frame; at
// 12 frames/s a fingertip pushing at 0.3 m/s moves the face 2.5 cm a frame and its DIP, 1.7 cm
// behind the tip, "reached" the face the tip was pushing away (`hand/push_off_centre`: state 3,
// no more turn). A finger that curls or lies down onto the face goes in further than the part
// already there and still touches.
static int drop_trailing(hs_world *world, int first) {
	int kept = first;
	for (int k = first; k < world->contact_count; ++k) {
		const hs_contact *c = &world->contacts[k];
		bool trails = false;
		for (int m = first; m < world->contact_count && !trails && !c->edge && !touched_before(world, c); ++m) {
			const hs_contact *l = &world->contacts[m];
			trails = m != k && !l->edge && l->hand.index1 == c->hand.index1 && finger_of(l->part) == finger_of(c->part) &&
			         l->feature == c->feature && (touched_before(world, l) || (l->t >= 0.0 && l->t < c->t)) &&
			         push_depth(l) > push_depth(c);
		}
		if (!trails && kept++ != k) // (kept in place: no copy)
			world->contacts[kept - 1] = *c;
	}
	world->contact_count = kept;
	return kept - first;
}

// A touching check point hovering within the margin over an object that moved last frame
// (marked t < 0 by detect_points) is a contact while another part of its hand drives the object
// this frame: two fingertips pushing a box, one of them lifted off by glove noise, still push at
// several points (3) rather than at one (1, which turns the box by eq. 2). Alone, it is none: the
// object goes on by eq. 3 (a finger drawn back after a push does not stop what it pushed).
static int keep_hovering(hs_world *world, int first, int n) {
	int kept = first;
	for (int k = first; k < first + n; ++k) {
		const hs_contact *c = &world->contacts[k];
		bool keep = !(c->t < 0.0);
		for (int m = first; m < first + n && !keep; ++m) {
			const hs_contact *l = &world->contacts[m];
			keep = !(l->t < 0.0) && l->hand.index1 == c->hand.index1 && push_depth(l) > 0.0;
		}
		if (!keep)
			continue;
		hs_contact *to = &world->contacts[kept++]; // a copy only when it moves (the one left behind
		if (to != c)                               // keeps its t for the later contacts' tests)
			*to = *c;
		to->t = to->t < 0.0 ? 0.0 : to->t;
	}
	world->contact_count = kept;
	return kept - first;
}

// The fingers (bit f) whose spheres through the frame (hs_hand_finger_spheres) lie further than
// `reach` from c, the centre of a part's bounding sphere (its radius and HS_CULL_SLACK for
// rounding) — further by the part's keep (hs_contact_keep × grow_reach) for a finger with a
// touching or embedded check point — none of whose check lines is embedded; for the ungrown
// test. Such a finger's check points lie where the points' own cull passes them over; its lines and their sweeps miss the part the sphere holds, so the line tests find no
// contact (end_touches, a test with a margin, only passes a line over). An embedded line answers
// to the part grown by twice the margin, which reaches past the sphere at a box's corner (by
// (sqrt 3 - 1) times the growth): a finger with one keeps its tests.
static unsigned far_fingers(const hs_world *world, const hs_hand *hand, const hs_part *part, hs_vec3 c, double reach) {
	unsigned far = 0;
	uint32_t kept = hand->touch_points | hand->embed_points; // counted beyond the sphere (detect_points)
	double keep = part->grow_reach * hs_contact_keep(world, hand);
	for (int f = 0; f < 5; ++f) {
		double r = hand->finger_reach[f] + reach + (kept >> (4 * f) & 0xFu ? keep : 0.0);
		if (!(hand->embed_lines >> (12 * f) & 0xFFFu) && hs_length_sq(hs_sub(hand->finger_center[f], c)) > r * r)
			far |= 1u << f;
	}
	return far;
}

#if defined(HS_SELFCHECK)
// Sanitizer builds: every check point of a finger far_fingers passes over, and every placed check
// line, now and a frame ago, lies further than `reach` from c.
static void check_far(const hs_hand *hand, unsigned far, hs_vec3 c, double reach) {
	bool near = false;
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		if (far >> (i / 4) & 1u)
			near |= hs_length_sq(hs_sub(hand->points[i], c)) <= reach * reach ||
			        hs_length_sq(hs_sub(hand->prev_points[i], c)) <= reach * reach;
	for (int j = 0; j < HS_HAND_LINES; ++j)
		if (far >> (j / 12) & 1u)
			near |= (hand->lines_ready >> (j / 4) & 1u && segment_distance_sq(c, hand->lines[j][0], hand->lines[j][1]) <= reach * reach) ||
			        (hand->prev_lines_ready >> (j / 4) & 1u &&
			         segment_distance_sq(c, hand->prev_lines[j][0], hand->prev_lines[j][1]) <= reach * reach);
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

int hs_contact_detect_grown(hs_world *world, int object, const hs_pose *before, double grow) {
	int first = world->contact_count;
	const hs_body *body = &world->bodies[object];
	const hs_shape *shape = &world->shapes[body->shape];
	int h = 0; // the first hand near the object: only then are its poses made matrices
	while (h < world->hand_count && !hs_contact_hand_near(world, body, &world->hands[h], grow))
		++h;
	if (h == world->hand_count)
		return 0;
	frame now = frame_of(body), then = now;
	if (before)
		then = (frame){before->pos, hs_mat3_from_quat(before->rot)};
	for (; h < world->hand_count; ++h) {
		const hs_hand *hand = &world->hands[h];
		if (!hs_contact_hand_near(world, body, hand, grow))
			continue; // bounding-volume rejection before the narrow tests (Fig. 2)
		if (grow == 0.0) // the grown test repeats a held object's: counted once
			world->counters.hand_tests++;
		// finger by finger for an object the hand did not carry, in the ungrown test (a carried one
		// has them all near, and its points and lines are passed over by cheaper tests)
		bool fingers = world->def.skip_work && !before && grow == 0.0;
		if (fingers)
			hs_hand_finger_spheres(&world->hands[h]);
		for (int p = 0; p < shape->part_count; ++p) {
			const hs_part *part = &shape->parts[p];
			unsigned far = 0;
			if (world->def.skip_work) {
				hs_vec3 c = to_world(&now, part->center);
				if (!hs_contact_sphere_near(world, hand, c, part->radius, part->grow_reach, grow))
					continue;
				if (fingers) {
					far = far_fingers(world, hand, part, c, part->radius + HS_CULL_SLACK);
					check_far(hand, far, c, part->radius + HS_CULL_SLACK);
				}
			}
			int from = world->contact_count;
			detect_points(world, object, h, part, &now, &then, before != NULL, world->def.skip_work, grow, far);
			uint32_t touching = hand->touch_points; // touched last frame, or touch this part now
			for (int k = from; k < world->contact_count; ++k)
				touching |= 1u << world->contacts[k].part;
			detect_lines(world, object, h, part, &now, &then, before != NULL, world->def.skip_work, grow, touching, far);
		}
	}
	if (grow == 0.0 && !world->def.paper_contacts)
		return keep_hovering(world, first, drop_trailing(world, first));
	return world->contact_count - first;
}

double hs_grasp_limit(double grasp_threshold_deg) {
	return hs_cos(grasp_threshold_deg * (HS_PI / 180.0)) + HS_GRASP_EPS;
}

hs_contact_state hs_contact_classify(const hs_contact *contacts, int count, double grasp_limit, bool any_contacts) {
	if (count == 0)
		return HS_CONTACT_NONE;
	if (count == 1)
		return HS_CONTACT_PUSH_ONE;
	return hs_contact_grasps(contacts, count, 0, grasp_limit, any_contacts) ? HS_CONTACT_GRASP : HS_CONTACT_PUSH_MANY;
}

// The finger of a contact's part: check point i is on finger i / 4, check line j on j / 12 (§3.1).
static int finger_of(int part) {
	return part < HS_HAND_POINTS ? part / 4 : (part - HS_HAND_POINTS) / 12;
}

// Two contacts may make a grasp when they lie on different hands or different fingers
// (docs/model.md §3 "Two fingers make a grasp": two points of one finger sunk into an object are
// not a grasp), or with the paper's "any two contacts" rule (§3.2 (2)).
static bool may_grasp(const hs_contact *a, const hs_contact *b, bool any_contacts) {
	return any_contacts || a->hand.index1 != b->hand.index1 || finger_of(a->part) != finger_of(b->part);
}

bool hs_contact_grasps(const hs_contact *contacts, int count, uint32_t hand1, double grasp_limit, bool any_contacts) {
	for (int i = 0; i < count; ++i) {
		if (hand1 && contacts[i].hand.index1 != hand1)
			continue;
		for (int j = i + 1; j < count; ++j)
			if ((!hand1 || contacts[j].hand.index1 == hand1) && may_grasp(&contacts[i], &contacts[j], any_contacts) &&
			    hs_dot(contacts[i].normal, contacts[j].normal) <= grasp_limit)
				return true; // two normals at >= the threshold (§3.2 (2))
	}
	return false;
}
