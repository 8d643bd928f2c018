// shape.c — the built-in shapes (box, square pyramid, L-block, UV ellipsoid, sphere) and user
// polyhedra, all made by the one builder of shape_build.c (which also releases them).
#include <stdlib.h>

#include "shape_build.h"

static bool valid_size(double x) { return isfinite(x) && x > 0.0; }
static bool valid_size3(hs_vec3 s) { return valid_size(s.x) && valid_size(s.y) && valid_size(s.z); }

// Box part over [lo, hi]: vertex i = (x bit 0, y bit 1, z bit 2) of i, faces wound outward.
static const int box_face_vertices[24] = {
    0, 2, 3, 1, // z = lo
    4, 5, 7, 6, // z = hi
    0, 1, 5, 4, // y = lo
    2, 6, 7, 3, // y = hi
    0, 4, 6, 2, // x = lo
    1, 3, 7, 5, // x = hi
};
static const int box_face_sizes[6] = {4, 4, 4, 4, 4, 4};

static void box_vertices(hs_vec3 lo, hs_vec3 hi, hs_vec3 out[8]) {
	for (int i = 0; i < 8; i++)
		out[i] = hs_v3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
}

static part_src box_src(const hs_vec3 vertices[8]) {
	part_src src = {vertices, 8, box_face_vertices, box_face_sizes, 6};
	return src;
}

hs_shape *hs_shape_box(hs_vec3 size, hs_status *status) {
	if (!valid_size3(size)) {
		hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	hs_vec3 v[8];
	hs_vec3 half = hs_scale(size, 0.5);
	box_vertices(hs_neg(half), half, v);
	part_src src = box_src(v);
	return hs_shape_build(HS_SHAPE_BOX, &src, 1, 0.0, NULL, 0, status);
}

hs_shape *hs_shape_pyramid(double base, double height, hs_status *status) {
	if (!valid_size(base) || !valid_size(height)) {
		hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	double h = 0.5 * base;
	// base on z = 0, apex above its centre; the builder moves the origin to G (h/4 up)
	hs_vec3 v[5] = {hs_v3(-h, -h, 0.0), hs_v3(h, -h, 0.0), hs_v3(h, h, 0.0), hs_v3(-h, h, 0.0),
	                hs_v3(0.0, 0.0, height)};
	static const int fv[16] = {0, 3, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
	static const int fs[5] = {4, 3, 3, 3, 3};
	part_src src = {v, 5, fv, fs, 5};
	return hs_shape_build(HS_SHAPE_PYRAMID, &src, 1, 0.0, NULL, 0, status);
}

hs_shape *hs_shape_l_block(hs_vec3 size, double thickness, hs_status *status) {
	if (!valid_size3(size) || !valid_size(thickness) || !(thickness < size.x) || !(thickness < size.z)) {
		hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	// two convex boxes in the x–z plane (the L-block is not convex): foot, then upright
	hs_vec3 foot[8], upright[8];
	box_vertices(hs_v3(0.0, 0.0, 0.0), hs_v3(size.x, size.y, thickness), foot);
	box_vertices(hs_v3(0.0, 0.0, thickness), hs_v3(thickness, size.y, size.z), upright);
	part_src src[2] = {box_src(foot), box_src(upright)};
	return hs_shape_build(HS_SHAPE_L_BLOCK, src, 2, 0.0, NULL, 0, status);
}

// cos(k · 22.5°) from square roots only, so that no libm trigonometry (which the compiler may
// fold at compile time with another rounding) can make two builds differ.
static double cos16(int k) {
	double q[5] = {1.0, 0.5 * sqrt(2.0 + sqrt(2.0)), sqrt(0.5), 0.5 * sqrt(2.0 - sqrt(2.0)), 0.0};
	k = ((k % 16) + 16) % 16;
	if (k <= 4)
		return q[k];
	if (k <= 8)
		return -q[8 - k];
	if (k <= 12)
		return -q[k - 8];
	return q[16 - k];
}
static double sin16(int k) { return cos16(k - 4); }

// Largest UV polyhedron built here (the sphere's 16 slices × 8 stacks).
#define UV_MAX_VERTICES (2 + 16 * 7)
#define UV_MAX_FACES (16 * 8)
#define UV_MAX_FACE_VERTICES (16 * 3 * 2 + 16 * 6 * 4)

// UV polyhedron with semi-axes `axes`: `slices` around z, `stacks` from pole to pole (both divide
// 16 and 8 steps of 22.5°). Vertex 0 is the north pole, then rings top to bottom, then the south pole.
static hs_shape *uv_shape(hs_shape_kind kind, hs_vec3 axes, int slices, int stacks, double exact_sphere,
                          hs_status *status) {
	hs_vec3 v[UV_MAX_VERTICES];
	int fv[UV_MAX_FACE_VERTICES], fs[UV_MAX_FACES];
	int ds = 16 / slices, dt = 8 / stacks, nv = 0, nfv = 0, nf = 0;
	v[nv++] = hs_v3(0.0, 0.0, axes.z);
	for (int j = 1; j < stacks; j++) {
		double st = sin16(j * dt), ct = cos16(j * dt);
		for (int i = 0; i < slices; i++)
			v[nv++] = hs_v3(axes.x * st * cos16(i * ds), axes.y * st * sin16(i * ds), axes.z * ct);
	}
	v[nv++] = hs_v3(0.0, 0.0, -axes.z);
	int south = nv - 1;
	// ring j (1-based) slice i is vertex 1 + (j - 1) * slices + i
	for (int i = 0; i < slices; i++) { // north cap
		int i1 = (i + 1) % slices;
		fv[nfv++] = 0;
		fv[nfv++] = 1 + i;
		fv[nfv++] = 1 + i1;
		fs[nf++] = 3;
	}
	for (int j = 1; j + 1 < stacks; j++) { // planar trapezoids between rings j and j + 1
		for (int i = 0; i < slices; i++) {
			int i1 = (i + 1) % slices, top = 1 + (j - 1) * slices, low = top + slices;
			fv[nfv++] = top + i;
			fv[nfv++] = low + i;
			fv[nfv++] = low + i1;
			fv[nfv++] = top + i1;
			fs[nf++] = 4;
		}
	}
	int last = 1 + (stacks - 2) * slices;
	for (int i = 0; i < slices; i++) { // south cap
		int i1 = (i + 1) % slices;
		fv[nfv++] = south;
		fv[nfv++] = last + i1;
		fv[nfv++] = last + i;
		fs[nf++] = 3;
	}
	part_src src = {v, nv, fv, fs, nf};
	return hs_shape_build(kind, &src, 1, exact_sphere, NULL, 0, status);
}

hs_shape *hs_shape_ellipsoid(hs_vec3 semi_axes, hs_status *status) {
	if (!valid_size3(semi_axes)) {
		hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	// 1999 paper, Exp. 3: "an ellipsoid of 32 faces and 56 edges" = 8 slices × 4 stacks
	return uv_shape(HS_SHAPE_ELLIPSOID, semi_axes, 8, 4, 0.0, status);
}

hs_shape *hs_shape_sphere(double radius, hs_status *status) {
	if (!valid_size(radius)) {
		hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	// exact sphere for the spring model's masses and collisions; the inscribed 16 × 8
	// polyhedron (poles on the sphere) serves display and floor contact
	return uv_shape(HS_SHAPE_SPHERE, hs_v3(radius, radius, radius), 16, 8, radius, status);
}

hs_shape *hs_shape_polyhedron(const hs_vec3 *vertices, int vertex_count, const int *face_vertices,
                              const int *face_sizes, int face_count, char *why, size_t why_size,
                              hs_status *status) {
	if (vertex_count < 0 || face_count < 0) {
		hs_shape_why(why, why_size, "negative count");
		hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	if ((vertex_count > 0 && !vertices) || (face_count > 0 && (!face_sizes || !face_vertices))) {
		hs_shape_why(why, why_size, "null pointer");
		hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	for (int v = 0; v < vertex_count; v++) {
		if (!hs_vec3_is_finite(vertices[v])) {
			hs_shape_why(why, why_size, "vertex %d is not finite", v);
			hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
			return NULL;
		}
	}
	part_src src = {vertices, vertex_count, face_vertices, face_sizes, face_count};
	return hs_shape_build(HS_SHAPE_POLYHEDRON, &src, 1, 0.0, why, why_size, status);
}
