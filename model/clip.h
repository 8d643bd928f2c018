// clip.h — Cyrus-Beck clipping of a segment against one convex part of a shape. Shape geometry
// only: used by the hand contacts (contact.c, 1999 paper §3.2 (B)) and the support mode (support.c).
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

// When it misses (hit false) the other fields are not final: it stops at the face that shows it.
hs_clip hs_clip_segment(const hs_shape *shape, const hs_part *part, hs_vec3 a, hs_vec3 b, double grow);
// The same over every face: the fields as the whole loop leaves them, also on a miss.
hs_clip hs_clip_segment_all(const hs_shape *shape, const hs_part *part, hs_vec3 a, hs_vec3 b, double grow);

#endif
