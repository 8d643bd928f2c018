// part_cache.h — what the library derives from a convex part of a shape for the hand check, kept by
// the world beside its copy of the shape (one per part, made by hs_world_add_shape) so that a
// user's hs_part holds only what the user sets: whether the part is a box with axis-aligned faces
// (part_box.h) and how far it reaches once grown (part_reach.h).
#ifndef HS_PART_CACHE_H
#define HS_PART_CACHE_H

typedef struct hs_part_cache {
	// a part of six faces whose normals are exactly +x, -x, +y, -y, +z, -z has box_face[k] = the
	// index of the face of normal k, in that order, and box_offset[k] its offset; box_face[0] = -1
	// for any other part
	int box_face[6];
	double box_offset[6];
	// and the normal k of each of its faces in face order (box_axis[f - first_face]), as the clip visits them
	int box_axis[6];
	// the part with its faces moved out by g lies within radius + g · grow_reach of its centre
	// (√3 for a box: its corners move out diagonally)
	double grow_reach;
} hs_part_cache;

#endif
