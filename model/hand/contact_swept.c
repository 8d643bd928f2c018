// contact_swept.c — where a check point's or check line's path through the frame first met a part
// (the 1999 paper §3.2 (A)-(B), Fig. 2, followed along the path: docs/model.md §3, "Rectification
// and swept detection"): a point's path crossing a face; a line's ends through a face, or an edge
// of the part through the surface the line sweeps.
#include "contact_rules.h"
#include "contact_swept.h"

// The first piece of check point i's path (relative to the object: body frame) that crosses into
// the part; false when none does. `inside`: the point ends inside (the last piece may end there).
bool hs_contact_path_enters(const hs_world_model *model, const hs_shape *shape, const hs_part *part, const hs_hand *hand, int i, int steps,
                            const hs_frame *body, hs_vec3 a, bool inside, hs_clip *hit, hs_vec3 *from, hs_vec3 *to,
                            double *when) {
	for (int k = 1; k <= steps; ++k) {
		hs_vec3 b = k == steps ? to_body(body, hand->cache.points[i]) : to_body(body, hand->cache.path_points[k - 1][i]);
		hs_clip c = clip_part(model, shape, part, a, b, 0.0);
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
bool hs_contact_sweep_beyond_a_face(const hs_world_model *model, const hs_shape *shape, const hs_part *part, const hs_vec3 q[2],
                                    const hs_vec3 p[2]) {
	const hs_vec3 ends[4] = {q[0], q[1], p[0], p[1]};
	if (part->face_count >= HS_FACE_TREE_MIN_FACES) {
		const hs_face_tree *tree = tree_of(model, shape);
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
static HS_NOINLINE int sweep_edges(const hs_contact_pass *cp, const hs_shape *shape, const hs_part *part, const hs_vec3 q[2],
                                   const hs_vec3 n[2], const hs_vec3 p[2], swept_hit *hit) {
	const hs_face_tree *tree = tree_of(cp->model, shape);
	int root = hs_face_tree_root(tree, shape, part);
	if (root < 0)
		return -1;
	const hs_vec3 ends[4] = {q[0], q[1], n[0], n[1]};
	int faces = hs_face_tree_reached(tree, root, (int)(part - shape->parts), shape, ends, cp->scratch->face_pick);
	const hs_face_edges *index = &cp->model->face_edges[shape - cp->model->shapes];
	int count = 0;
	for (int k = 0; k < faces; ++k)
		for (int j = index->first[cp->scratch->face_pick[k]]; j < index->first[cp->scratch->face_pick[k] + 1]; ++j) {
			int e = index->edges[j];
			if (e >= part->first_edge && e < part->first_edge + part->edge_count && !cp->scratch->edge_mark[e]) {
				cp->scratch->edge_mark[e] = 1;
				cp->scratch->edge_pick[count++] = e;
			}
		}
	for (int k = 0; k < count; ++k)
		cp->scratch->edge_mark[cp->scratch->edge_pick[k]] = 0;
	hs_sort_indices(cp->scratch->edge_pick, count);
	for (int k = 0; k < count; ++k)
		try_edge(shape, cp->scratch->edge_pick[k], q, n, p, hit);
	return count;
}

// The first contact of a check line that misses the part at both ends of a piece of its path but
// swept across it (from q0-q1 to n0-n1): an end of the line passing through a face, or an edge of
// the part through the swept surface. A convex part meets that surface in one of these two ways
// only. C where they met, B the line's point at the same place along it at the end of the frame
// (p); the piece spans [t0, t0 + span] of the frame. False when it did not meet the part.
static bool swept_line(const hs_contact_pass *cp, int object, int h, int j, const hs_part *part, const hs_frame *body,
                       const hs_vec3 q[2], const hs_vec3 n[2], const hs_vec3 p[2], double t0, double span) {
	const hs_shape *shape = &cp->model->shapes[cp->bodies[object].shape];
	if (hs_contact_sweep_beyond_a_face(cp->model, shape, part, q, n))
		return false;
	swept_hit hit = {INFINITY, -1, false, q[0], p[0]};
	for (int k = 0; k < 2; ++k) {
		hs_clip c = clip_part(cp->model, shape, part, q[k], n[k], 0.0);
		if (c.hit && c.face_in >= 0 && c.t_in < c.t_out && c.t_in < hit.best) {
			hit.best = c.t_in;
			hit.feature = c.face_in;
			hit.point = hs_lerp(q[k], n[k], c.t_in);
			hit.finger = p[k];
		}
	}
	// a many-faced part: only the edges of faces the sweep reaches; else every edge, in index order
	if (part->face_count < HS_FACE_TREE_MIN_FACES || sweep_edges(cp, shape, part, q, n, p, &hit) < 0)
		for (int e = part->first_edge; e < part->first_edge + part->edge_count; ++e)
			try_edge(shape, e, q, n, p, &hit);
	if (hit.feature < 0)
		return false;
	hs_contact_push(cp, object, h, HS_HAND_POINTS + j, hit.edge, hit.feature, body, hit.point,
	                hit.edge ? hs_contact_edge_normal(shape, hit.feature) : shape->faces[hit.feature].normal, hit.finger,
	                t0 + hit.best * span);
	return true;
}

// True when a piece of a line's path, q0-q1 to n0-n1, lies beyond one face of a box part by more
// than HS_CULL_SLACK (most pieces of a fast finger's path past a cube): then the line a piece ago
// misses the part (its clip) and the piece sweeps clear of that face (swept_line finds nothing),
// so neither is asked; the two are compared with this in self-check builds.
static inline bool piece_clear_of_a_box_face(const hs_contact_pass *cp, const hs_shape *shape, const hs_part *part,
                                             const hs_part_cache *pc, const hs_vec3 q[2], const hs_vec3 n[2]) {
	const hs_vec3 ends[4] = {q[0], q[1], n[0], n[1]};
	if (!hs_part_is_box(pc) || !hs_part_box_beyond4(pc, ends, HS_CULL_SLACK))
		return false;
#if defined(HS_SELFCHECK)
	if (clip_part(cp->model, shape, part, q[0], q[1], 0.0).hit || !hs_contact_sweep_beyond_a_face(cp->model, shape, part, q, n)) {
		fprintf(stderr, "selfcheck: a piece of a line's path clear of a box face meets the part\n");
		abort();
	}
#else
	(void)cp, (void)shape, (void)part;
#endif
	return true;
}

// A check line that misses the part now (p, body frame): the first piece of its path through the
// frame that swept across the part makes the contact. Touching it at the start of a piece, it
// had reached it before and left again: nothing. `start`: the line a frame ago, in the frame of the
// object's pose before the step (transformed once, by detect_lines).
void hs_contact_swept_path(const hs_contact_pass *cp, int object, int h, int j, const hs_part *part, const hs_frame *body,
                           int steps, const hs_vec3 start[2], const hs_vec3 p[2]) {
	const hs_shape *shape = &cp->model->shapes[cp->bodies[object].shape];
	const hs_hand *hand = &cp->hands[h];
	const hs_part_cache *pc = hs_part_cache_of(cp->model, shape, part);
	hs_vec3 q[2] = {start[0], start[1]};
	for (int k = 1; k <= steps; ++k) {
		hs_vec3 n[2] = {p[0], p[1]};
		if (k < steps) {
			n[0] = to_body(body, hand->cache.path_lines[k - 1][j][0]);
			n[1] = to_body(body, hand->cache.path_lines[k - 1][j][1]);
		}
		if (!piece_clear_of_a_box_face(cp, shape, part, pc, q, n)) {
			if (clip_part_with(cp->model, shape, part, pc, q[0], q[1], 0.0).hit)
				return;
			if (swept_line(cp, object, h, j, part, body, q, n, p, (double)(k - 1) / steps, 1.0 / steps))
				return;
		}
		q[0] = n[0];
		q[1] = n[1];
	}
}
