// shape_build.h — the one builder every shape goes through (shape_build.c), for the built-ins
// (shape.c) and user polyhedra.
#ifndef HS_SHAPE_BUILD_H
#define HS_SHAPE_BUILD_H

#include <stddef.h>

#include "handspring.h"

// One convex part as given: vertices and faces (lists of indices into `vertices`, any winding).
typedef struct part_src {
	const hs_vec3 *vertices;
	int vertex_count;
	const int *face_vertices; // concatenated, face_sizes[f] entries per face
	const int *face_sizes;
	int face_count;
} part_src;

static inline void hs_set_status(hs_status *status, hs_status value) {
	if (status)
		*status = value;
}

// Writes a printf-style reason into why (may be NULL).
void hs_shape_why(char *why, size_t why_size, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

// Validates and assembles a shape from convex parts, then moves the body frame to G.
// `exact_sphere` > 0 makes an HS_SHAPE_SPHERE: G stays at the given origin and the volume is exact.
hs_shape *hs_shape_build(hs_shape_kind kind, const part_src *parts, int part_count, double exact_sphere,
                         char *why, size_t why_size, hs_status *status);

#endif
