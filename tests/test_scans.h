// test_scans.h — the face scans of a convex part, written as contact_part.h writes them: the reference
// the coordinate tests of a box (test_part_box.c) and the face tree (test_face_tree.c) must answer
// as, bit for bit.
#ifndef HS_TEST_SCANS_H
#define HS_TEST_SCANS_H

#include <math.h>
#include <stdbool.h>

#include "handspring.h"

// No face has dot(normal, p) >= offset + grow.
static inline bool scan_inside(const hs_shape *s, const hs_part *part, hs_vec3 p, double grow) {
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f)
		if (hs_dot(s->faces[f].normal, p) >= s->faces[f].offset + grow)
			return false;
	return true;
}

// The first face (in face order) of the least depth offset - dot(normal, p).
static inline int scan_nearest(const hs_shape *s, const hs_part *part, hs_vec3 p) {
	int best = part->first_face;
	double best_depth = INFINITY;
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f) {
		double depth = s->faces[f].offset - hs_dot(s->faces[f].normal, p);
		if (depth < best_depth) {
			best_depth = depth;
			best = f;
		}
	}
	return best;
}

#endif
