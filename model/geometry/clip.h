// clip.h — Cyrus-Beck clipping of a segment against one convex part of a shape. Shape geometry
// only: used by the hand contacts (contact_part.h, 1999 paper §3.2 (B)) and the support mode (support.c).
#ifndef HS_CLIP_H
#define HS_CLIP_H

#include <stdbool.h>

#include "handspring.h"

// Where the segment a → b (in the shape's body frame) enters and leaves a convex part whose faces
// are pushed out by `grow` (m), and through which faces (-1 where that end is already inside).
typedef struct hs_clip {
	double t_in, t_out;
	int face_in, face_out;
	bool hit;
} hs_clip;

// One face of the clip: the segment a -> a + d against face f's plane pushed out by `grow`. False
// when the segment runs parallel outside that plane (it misses). Ties go to the lower face index,
// so any order of the faces gives the index order's clip (face_tree.c visits them out of order).
static inline bool hs_clip_face(hs_clip *c, const hs_face *face, int f, hs_vec3 a, hs_vec3 d, double grow) {
	double num = face->offset + grow - hs_dot(face->normal, a);
	double den = hs_dot(face->normal, d);
	if (den == 0.0)
		return num > 0.0;
	double t = num / den;
	if (den < 0.0) { // entering through this face
		if (t > c->t_in || (t == c->t_in && f < c->face_in)) {
			c->t_in = t;
			c->face_in = f;
		}
	} else if (t < c->t_out || (t == c->t_out && f < c->face_out)) {
		c->t_out = t;
		c->face_out = f;
	}
	return true;
}

// When it misses (hit false) the other fields are not final: it stops at the face that shows it.
hs_clip hs_clip_segment(const hs_shape *shape, const hs_part *part, hs_vec3 a, hs_vec3 b, double grow);
// The same over every face: the fields as the whole loop leaves them, also on a miss.
hs_clip hs_clip_segment_all(const hs_shape *shape, const hs_part *part, hs_vec3 a, hs_vec3 b, double grow);

#endif
