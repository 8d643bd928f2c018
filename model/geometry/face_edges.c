// face_edges.c — a shape's edges by face (face_edges.h): counted, then filled in edge order.
#include <stdlib.h>

#include "face_edges.h"

static bool face_in_range(const hs_shape *shape, int f) { return f >= 0 && f < shape->face_count; }

bool hs_face_edges_build(hs_face_edges *out, const hs_shape *shape) {
	out->first = calloc((size_t)shape->face_count + 1, sizeof *out->first);
	out->edges = malloc((size_t)(2 * shape->edge_count > 0 ? 2 * shape->edge_count : 1) * sizeof *out->edges);
	if (!out->first || !out->edges) {
		hs_face_edges_free(out);
		return false;
	}
	for (int e = 0; e < shape->edge_count; ++e)
		for (int k = 0; k < 2; ++k)
			if (face_in_range(shape, shape->edges[e].faces[k]))
				out->first[shape->edges[e].faces[k] + 1]++;
	for (int f = 0; f < shape->face_count; ++f)
		out->first[f + 1] += out->first[f];
	int *fill = out->first; // advanced per face while filling, then moved back
	for (int e = 0; e < shape->edge_count; ++e)
		for (int k = 0; k < 2; ++k)
			if (face_in_range(shape, shape->edges[e].faces[k]))
				out->edges[fill[shape->edges[e].faces[k]]++] = e;
	for (int f = shape->face_count; f > 0; --f)
		fill[f] = fill[f - 1];
	fill[0] = 0;
	return true;
}

void hs_face_edges_free(hs_face_edges *index) {
	free(index->first);
	free(index->edges);
	index->first = index->edges = NULL;
}
