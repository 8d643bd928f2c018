// clip.c — Cyrus-Beck clipping of a segment against a convex part (Cyrus & Beck 1978): the hand's
// check lines against an object's parts (1999 paper §3.2 (B)) and edges against supports (support.c).
#include "clip.h"

// `to_the_end`: every face, even once the segment is known to miss (t_in > t_out, which no later
// face can undo: t_in only grows and t_out only shrinks).
static inline hs_clip clip(const hs_shape *shape, const hs_part *part, hs_vec3 a, hs_vec3 b, double grow,
                           bool to_the_end) {
	hs_clip c = {0.0, 1.0, -1, -1, false};
	hs_vec3 d = hs_sub(b, a);
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f) {
		if (!hs_clip_face(&c, &shape->faces[f], f, a, d, grow))
			return c; // parallel and outside this face's plane
		if (!to_the_end && c.t_in > c.t_out)
			return c; // misses
	}
	c.hit = c.t_in <= c.t_out;
	return c;
}

hs_clip hs_clip_segment(const hs_shape *shape, const hs_part *part, hs_vec3 a, hs_vec3 b, double grow) {
	return clip(shape, part, a, b, grow, false);
}

hs_clip hs_clip_segment_all(const hs_shape *shape, const hs_part *part, hs_vec3 a, hs_vec3 b, double grow) {
	return clip(shape, part, a, b, grow, true);
}
