// face_edges.h — a shape's edges listed by face, so that the edge between two faces is found
// among one face's few edges, not by a scan of every edge (the hand's check lines across an
// edge, contact_rules.c, and a swept line's edges, contact_swept.c). Built with the world's copy
// of each shape (world_core.c).
#ifndef HS_FACE_EDGES_H
#define HS_FACE_EDGES_H

#include <stdbool.h>

#include "handspring.h"

// Face f's edges are edges[first[f] .. first[f + 1]), in index order.
typedef struct hs_face_edges {
	int *first; // face_count + 1
	int *edges; // 2 x edge_count
} hs_face_edges;

// Lists the shape's edges by face; false (and *out empty) when out of memory.
bool hs_face_edges_build(hs_face_edges *out, const hs_shape *shape);
// Frees the lists and empties *index.
void hs_face_edges_free(hs_face_edges *index);

#endif
