// part_reach.c — the growth factor of part_reach.h.
//
// Why it bounds: the grown part P_g = {x : n_f·x ≤ d_f + g} has support h_g(u) ≤ h_0(u) + g·Λ(u),
// Λ(u) = max{u·w : n_f·w ≤ 1 for all f} (LP duality: any multipliers that bound u·x on P_0 bound
// it on P_g with g added per unit of weight). Each unit u lies in the normal cone of a vertex v,
// where keeping only v's own faces gives Λ(u) ≤ max{u·w : n_f·w ≤ 1, f at v}, reached at a
// vertex w of that cone: three of v's faces with n_f·w = 1 and the others ≤ 1. So K = the largest
// |w| over the vertices' cones bounds |x - c| ≤ radius + g·K for every g, not only small ones.
#include <math.h>

#include "part_reach.h"

// The part's faces through vertex index v (up to `max`).
static int faces_at(const hs_shape *shape, const hs_part *part, int v, int *out, int max) {
	int n = 0;
	for (int f = part->first_face; f < part->first_face + part->face_count && n < max; ++f) {
		const hs_face *face = &shape->faces[f];
		for (int k = 0; k < face->index_count; ++k)
			if (shape->face_vertices[face->first_index + k] == v) {
				out[n++] = f;
				break;
			}
	}
	return n;
}

// The largest |w| over the vertices of {w : n_f·w ≤ 1, f in faces}; 0 when it has none.
static double cone_reach(const hs_shape *shape, const int *faces, int n) {
	double best = 0.0;
	for (int a = 0; a < n; ++a)
		for (int b = a + 1; b < n; ++b)
			for (int c = b + 1; c < n; ++c) {
				hs_vec3 na = shape->faces[faces[a]].normal, nb = shape->faces[faces[b]].normal,
				        nc = shape->faces[faces[c]].normal;
				hs_vec3 bc = hs_cross(nb, nc), ca = hs_cross(nc, na), ab = hs_cross(na, nb);
				double det = hs_dot(na, bc);
				if (!(fabs(det) > 1e-12))
					continue; // three normals in a plane: no vertex
				hs_vec3 w = hs_scale(hs_add(hs_add(bc, ca), ab), 1.0 / det);
				bool inside = true;
				for (int k = 0; k < n && inside; ++k)
					inside = hs_dot(shape->faces[faces[k]].normal, w) <= 1.0 + 1e-9;
				if (inside)
					best = fmax(best, hs_length(w));
			}
	return best;
}

double hs_part_grow_reach(const hs_shape *shape, const hs_part *part) {
	enum { MAX_AT = 64 }; // faces through one vertex looked at (more: the bound below)
	int faces[MAX_AT];
	double k = 1.0;
	for (int v = part->first_vertex; v < part->first_vertex + part->vertex_count; ++v) {
		int n = faces_at(shape, part, v, faces, MAX_AT);
		double r = n >= 3 && n < MAX_AT ? cone_reach(shape, faces, n) : 0.0;
		if (!(r > 0.0) || !isfinite(r))
			return 1e6; // a vertex whose cone could not be bounded: no cull reaches past the part
		k = fmax(k, r);
	}
	return k * (1.0 + 1e-9) + 1e-9;
}
