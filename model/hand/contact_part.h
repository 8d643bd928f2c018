// contact_part.h — a convex part's queries in the object's body frame, for the contact tests of
// the 1999 paper §3.2 (A)-(B): inside, nearest face, segment clip, beyond a face. The scan of the
// part's face planes is the rule; a box's tests and a many-faced part's face tree are fast paths,
// each compared with the scan in self-check builds (docs/model.md §3). Private to contact_*.c.
#ifndef HS_CONTACT_PART_H
#define HS_CONTACT_PART_H

#include <math.h>
#include <stdbool.h>
#if defined(HS_SELFCHECK)
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#endif

#include "clip.h"
#include "inline.h"
#include "lanes2.h"
#include "part_box.h"
#include "world_internal.h"

// m: what the bounds that test a finger segment for its four lines add for rounding, far above it
// for coordinates up to HS_MAX_COORDINATE (1e6 m, where a double's step is 1.2e-10 m)
#define HS_CULL_SLACK 1e-6

// The per-line distance tests and the frame changes are inlined (HS_FORCE_INLINE): called apart,
// their vectors (passed by value) went through the stack on every call.
//
// An object's pose as a position and a rotation matrix: detection moves up to 140 hand points
// into each object's frame every frame.
typedef struct hs_frame {
	hs_vec3 pos;
	hs_mat3 rot;
} hs_frame;

static inline hs_frame frame_of(const hs_body *body) {
	hs_frame f = {body->pos, hs_mat3_from_quat(body->rot)};
	return f;
}
static HS_FORCE_INLINE hs_vec3 to_body(const hs_frame *f, hs_vec3 p) { return hs_mat3_tmul(f->rot, hs_sub(p, f->pos)); }
// Both ends of a line: out[k] = to_body(f, p[k]). With SSE2 one end per lane, each doing
// to_body's subtractions, products and sums in its order (the same bits).
static HS_FORCE_INLINE void line_to_body(const hs_frame *f, const hs_vec3 p[2], hs_vec3 out[2]) {
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
static HS_FORCE_INLINE hs_vec3 to_world(const hs_frame *f, hs_vec3 p) { return hs_add(f->pos, hs_mat3_mul(f->rot, p)); }

// The object's pose a frame ago (before the last step moved it).
static inline hs_frame frame_before_last_step(const hs_body *body) {
	hs_frame f = {body->prev, hs_mat3_from_quat(body->rot_prev)};
	return f;
}

// Squared distance from c to the segment p0-p1.
static HS_FORCE_INLINE double segment_distance_sq(hs_vec3 c, hs_vec3 p0, hs_vec3 p1) {
	return hs_length_sq(hs_sub(hs_segment_closest(p0, p1, c), c));
}

// Many-faced parts (HS_FACE_TREE_MIN_FACES or more) are searched through their normal-cone tree
// (face_tree.h: the faces near the point, with the scan's answers), out of line (contact_part.c);
// the others are scanned inline.
static inline const hs_face_tree *tree_of(const hs_world_model *model, const hs_shape *shape) {
	return &model->face_trees[shape - model->shapes];
}

// The rule ([H] §3.2 (A)): a point is in a convex part when it lies behind every face plane, here
// of the part grown by `grow` (m; 0: the part itself).
static inline bool scan_inside(const hs_shape *shape, const hs_part *part, hs_vec3 p, double grow) {
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f)
		if (hs_dot(shape->faces[f].normal, p) >= shape->faces[f].offset + grow)
			return false;
	return true;
}

// The face of least depth under a point (the one it is drawn back to, §3.2 rectification): the
// first in face order on a tie.
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

// The same through the part's face tree (contact_part.c), out of line.
bool hs_contact_inside_many(const hs_world_model *model, const hs_shape *shape, const hs_part *part, hs_vec3 p, double grow);
int hs_contact_nearest_many(const hs_world_model *model, const hs_shape *shape, const hs_part *part, hs_vec3 p);

#if defined(HS_SELFCHECK)
// Sanitizer builds: a box part's queries return what the scan of its faces returns.
static inline bool box_inside(const hs_shape *shape, const hs_part *part, const hs_part_cache *pc, hs_vec3 p, double grow) {
	bool inside = hs_part_box_inside(pc, p, grow);
	if (inside != scan_inside(shape, part, p, grow)) {
		fprintf(stderr, "selfcheck: the box's inside test differs from the scan's\n");
		abort();
	}
	return inside;
}
static inline bool box_apart(const hs_shape *shape, const hs_part *part, const hs_part_cache *pc, hs_vec3 a, hs_vec3 b,
                             double grow) {
	bool apart = hs_part_box_apart(pc, a, b, grow, HS_CULL_SLACK);
	if (apart && hs_clip_segment(shape, part, a, b, grow).hit) {
		fprintf(stderr, "selfcheck: a segment the box test put beyond a face meets the part\n");
		abort();
	}
	return apart;
}
static inline hs_clip box_clip(const hs_shape *shape, const hs_part *part, const hs_part_cache *pc, hs_vec3 a, hs_vec3 b,
                               double grow) {
	hs_clip c = hs_part_box_clip(pc, part->first_face, a, b, grow), s = hs_clip_segment(shape, part, a, b, grow);
	if (c.hit != s.hit || c.face_in != s.face_in || c.face_out != s.face_out || memcmp(&c.t_in, &s.t_in, sizeof c.t_in) != 0 ||
	    memcmp(&c.t_out, &s.t_out, sizeof c.t_out) != 0) {
		fprintf(stderr, "selfcheck: the box's clip differs from the scan's\n");
		abort();
	}
	return c;
}
static inline int box_nearest(const hs_shape *shape, const hs_part *part, const hs_part_cache *pc, hs_vec3 p) {
	int face = hs_part_box_nearest(pc, p);
	if (face != scan_nearest(shape, part, p)) {
		fprintf(stderr, "selfcheck: the box's nearest face differs from the scan's\n");
		abort();
	}
	return face;
}
#else
static inline hs_clip box_clip(const hs_shape *shape, const hs_part *part, const hs_part_cache *pc, hs_vec3 a, hs_vec3 b,
                               double grow) {
	(void)shape;
	return hs_part_box_clip(pc, part->first_face, a, b, grow);
}
static inline int box_nearest(const hs_shape *shape, const hs_part *part, const hs_part_cache *pc, hs_vec3 p) {
	(void)shape, (void)part;
	return hs_part_box_nearest(pc, p);
}
static inline bool box_inside(const hs_shape *shape, const hs_part *part, const hs_part_cache *pc, hs_vec3 p, double grow) {
	(void)shape, (void)part;
	return hs_part_box_inside(pc, p, grow);
}
static inline bool box_apart(const hs_shape *shape, const hs_part *part, const hs_part_cache *pc, hs_vec3 a, hs_vec3 b,
                             double grow) {
	(void)shape, (void)part;
	return hs_part_box_apart(pc, a, b, grow, HS_CULL_SLACK);
}
#endif

// Inside the part grown by `grow` (m; 0: the part itself); pc: the part's cache (part_cache.h).
static inline bool inside_part_with(const hs_world_model *model, const hs_shape *shape, const hs_part *part,
                                    const hs_part_cache *pc, hs_vec3 p, double grow) {
	if (part->face_count >= HS_FACE_TREE_MIN_FACES)
		return hs_contact_inside_many(model, shape, part, p, grow);
	if (hs_part_is_box(pc) && hs_part_box_takes(p))
		return box_inside(shape, part, pc, p, grow);
	return scan_inside(shape, part, p, grow);
}

static inline int nearest_face_with(const hs_world_model *model, const hs_shape *shape, const hs_part *part,
                                    const hs_part_cache *pc, hs_vec3 p) {
	if (part->face_count >= HS_FACE_TREE_MIN_FACES)
		return hs_contact_nearest_many(model, shape, part, p);
	if (hs_part_is_box(pc) && hs_part_box_takes(p))
		return box_nearest(shape, part, pc, p);
	return scan_nearest(shape, part, p);
}

// hs_clip_segment, through the tree for a many-faced part: the same clip whenever it hits.
static inline hs_clip clip_part_with(const hs_world_model *model, const hs_shape *shape, const hs_part *part,
                                     const hs_part_cache *pc, hs_vec3 a, hs_vec3 b, double grow) {
	if (part->face_count >= HS_FACE_TREE_MIN_FACES) {
		const hs_face_tree *tree = tree_of(model, shape);
		int root = hs_face_tree_root(tree, shape, part);
		if (root >= 0)
			return hs_face_tree_clip(tree, root, shape, a, b, grow);
	}
	if (hs_part_is_box(pc) && hs_part_box_takes(a) && hs_part_box_takes(b)) {
		if (box_apart(shape, part, pc, a, b, grow)) {
			hs_clip miss = {0.0, 1.0, -1, -1, false};
			return miss;
		}
		if (hs_part_box_takes(hs_sub(b, a)))
			return box_clip(shape, part, pc, a, b, grow);
	}
	return hs_clip_segment(shape, part, a, b, grow);
}

// The same three, the part's cache found from the model (where a caller does not hold it).
static inline bool inside_part(const hs_world_model *model, const hs_shape *shape, const hs_part *part, hs_vec3 p, double grow) {
	return inside_part_with(model, shape, part, hs_part_cache_of(model, shape, part), p, grow);
}
static inline int nearest_face(const hs_world_model *model, const hs_shape *shape, const hs_part *part, hs_vec3 p) {
	return nearest_face_with(model, shape, part, hs_part_cache_of(model, shape, part), p);
}
static inline hs_clip clip_part(const hs_world_model *model, const hs_shape *shape, const hs_part *part, hs_vec3 a, hs_vec3 b,
                                double grow) {
	return clip_part_with(model, shape, part, hs_part_cache_of(model, shape, part), a, b, grow);
}

#endif
