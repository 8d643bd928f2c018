// test_shape.c — built-in shapes and the polyhedron constructor against hand-computed values.
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "test_util.h"

#define SQRT2 1.41421356237309504880

// ---------------------------------------------------------------------------------------------
// Invariants every shape must satisfy, checked without trusting the library's own numbers.

// Volume and centroid by the test's own divergence sum: tetrahedra fanned from the part's
// first vertex (the library uses the vertex mean), so the two computations are independent.
static void part_mass(const hs_shape *s, const hs_part *p, double *volume, hs_vec3 *centroid) {
	hs_vec3 r = s->vertices[p->first_vertex];
	double v6 = 0.0;
	hs_vec3 m = hs_v3(0, 0, 0);
	for (int f = p->first_face; f < p->first_face + p->face_count; f++) {
		const int *idx = s->face_vertices + s->faces[f].first_index;
		int k = s->faces[f].index_count;
		for (int i = 1; i + 1 < k; i++) {
			hs_vec3 a = hs_sub(s->vertices[idx[0]], r), b = hs_sub(s->vertices[idx[i]], r),
			        c = hs_sub(s->vertices[idx[i + 1]], r);
			double t = hs_dot(a, hs_cross(b, c));
			v6 += t;
			m = hs_mul_add(m, t, hs_add(hs_add(a, b), c));
		}
	}
	*volume = v6 / 6.0;
	*centroid = hs_add(r, hs_scale(m, 1.0 / (4.0 * v6)));
}

static bool face_has_step(const hs_shape *s, int f, int a, int b) {
	const int *idx = s->face_vertices + s->faces[f].first_index;
	int k = s->faces[f].index_count;
	for (int i = 0; i < k; i++)
		if (idx[i] == a && idx[(i + 1) % k] == b)
			return true;
	return false;
}

static void check_invariants(const hs_shape *s) {
	assert_non_null(s);
	double eps = 1e-12 * (1.0 + s->radius);
	int v_sum = 0, f_sum = 0, e_sum = 0;
	double volume = 0.0;
	hs_vec3 moment = hs_v3(0, 0, 0);
	for (int p = 0; p < s->part_count; p++) {
		const hs_part *part = &s->parts[p];
		// contiguous ranges, concatenated in part order
		assert_int_equal(part->first_vertex, v_sum);
		assert_int_equal(part->first_face, f_sum);
		assert_int_equal(part->first_edge, e_sum);
		v_sum += part->vertex_count;
		f_sum += part->face_count;
		e_sum += part->edge_count;
		// Euler: every convex part is a topological sphere
		assert_int_equal(part->vertex_count - part->edge_count + part->face_count, 2);
		for (int v = part->first_vertex; v < part->first_vertex + part->vertex_count; v++) {
			assert_true(hs_distance(s->vertices[v], part->center) <= part->radius + eps);
			assert_true(hs_length(s->vertices[v]) <= s->radius + eps);
		}
		for (int f = part->first_face; f < part->first_face + part->face_count; f++) {
			const hs_face *face = &s->faces[f];
			assert_int_equal(face->part, p);
			assert_true(face->index_count >= 3);
			assert_near(hs_length(face->normal), 1.0, 1e-12);
			const int *idx = s->face_vertices + face->first_index;
			hs_vec3 mean = hs_v3(0, 0, 0), newell = hs_v3(0, 0, 0);
			for (int i = 0; i < face->index_count; i++) {
				// vertices of a face belong to its part and lie on its plane
				assert_true(idx[i] >= part->first_vertex && idx[i] < part->first_vertex + part->vertex_count);
				assert_near(hs_dot(face->normal, s->vertices[idx[i]]), face->offset, eps);
				mean = hs_add(mean, s->vertices[idx[i]]);
				hs_vec3 a = s->vertices[idx[i]], b = s->vertices[idx[(i + 1) % face->index_count]];
				newell = hs_add(newell, hs_cross(a, b));
			}
			mean = hs_scale(mean, 1.0 / face->index_count);
			assert_near(hs_dot(face->normal, mean), face->offset, eps);
			// counter-clockwise seen from outside: the winding's own normal agrees with `normal`
			assert_true(hs_dot(hs_normalize(newell), face->normal) > 1.0 - 1e-9);
			// outward, convex: every vertex of the part behind the plane, the part centre strictly
			for (int v = part->first_vertex; v < part->first_vertex + part->vertex_count; v++)
				assert_true(hs_dot(face->normal, s->vertices[v]) <= face->offset + eps);
			assert_true(hs_dot(face->normal, part->center) < face->offset - 1e-6 * part->radius);
		}
		for (int e = part->first_edge; e < part->first_edge + part->edge_count; e++) {
			const hs_edge *edge = &s->edges[e];
			assert_true(edge->a != edge->b);
			for (int i = 0; i < 2; i++)
				assert_true(edge->faces[i] >= part->first_face &&
				            edge->faces[i] < part->first_face + part->face_count);
			assert_true(edge->faces[0] != edge->faces[1]);
			// both faces contain the edge, run a -> b and b -> a respectively
			assert_true(face_has_step(s, edge->faces[0], edge->a, edge->b));
			assert_true(face_has_step(s, edge->faces[1], edge->b, edge->a));
		}
		double pv;
		hs_vec3 pc;
		part_mass(s, part, &pv, &pc);
		assert_true(pv > 0.0);
		volume += pv;
		moment = hs_mul_add(moment, pv, pc);
	}
	assert_int_equal(v_sum, s->vertex_count);
	assert_int_equal(f_sum, s->face_count);
	assert_int_equal(e_sum, s->edge_count);
	// every face-vertex slot used once, faces in order
	int fv = 0;
	for (int f = 0; f < s->face_count; f++) {
		assert_int_equal(s->faces[f].first_index, fv);
		fv += s->faces[f].index_count;
	}
	assert_int_equal(fv, s->face_vertex_count);
	// each edge's length sum: 2E = sum of face sizes
	assert_int_equal(2 * s->edge_count, s->face_vertex_count);
	if (s->kind != HS_SHAPE_SPHERE) {
		assert_near(volume, s->volume, 1e-12 * s->volume);
		// the body frame's origin is G
		assert_vec3_near(hs_scale(moment, 1.0 / volume), hs_v3(0, 0, 0), eps);
	}
}

// ---------------------------------------------------------------------------------------------
// Built-ins

static void test_box(void **state) {
	(void)state;
	hs_status st = HS_ERR_NO_MEMORY;
	hs_shape *s = hs_shape_box(hs_v3(0.1, 0.2, 0.3), &st);
	assert_int_equal(st, HS_OK);
	assert_int_equal(s->kind, HS_SHAPE_BOX);
	assert_int_equal(s->part_count, 1);
	assert_int_equal(s->vertex_count, 8);
	assert_int_equal(s->edge_count, 12);
	assert_int_equal(s->face_count, 6);
	check_invariants(s);
	assert_near(s->volume, 0.1 * 0.2 * 0.3, 1e-15);
	assert_vec3_near(s->centroid_shift, hs_v3(0, 0, 0), 1e-15);
	// half-diagonal
	assert_near(s->radius, 0.5 * sqrt(0.01 + 0.04 + 0.09), 1e-15);
	assert_near(s->sphere_radius, 0.0, 0.0);
	// every vertex at (±0.05, ±0.1, ±0.15)
	for (int v = 0; v < 8; v++) {
		assert_near(fabs(s->vertices[v].x), 0.05, 1e-15);
		assert_near(fabs(s->vertices[v].y), 0.1, 1e-15);
		assert_near(fabs(s->vertices[v].z), 0.15, 1e-15);
	}
	hs_shape_destroy(s);
}

static void test_pyramid(void **state) {
	(void)state;
	double b = 0.2, h = 0.3;
	hs_status st;
	hs_shape *s = hs_shape_pyramid(b, h, &st);
	assert_int_equal(st, HS_OK);
	assert_int_equal(s->vertex_count, 5);
	assert_int_equal(s->edge_count, 8);
	assert_int_equal(s->face_count, 5);
	check_invariants(s);
	assert_near(s->volume, b * b * h / 3.0, 1e-15);
	// G of a pyramid is a quarter of the height above the base
	assert_vec3_near(s->centroid_shift, hs_v3(0, 0, h / 4.0), 1e-15);
	double zmin = INFINITY, zmax = -INFINITY;
	for (int v = 0; v < 5; v++) {
		zmin = fmin(zmin, s->vertices[v].z);
		zmax = fmax(zmax, s->vertices[v].z);
	}
	assert_near(zmin, -h / 4.0, 1e-15);
	assert_near(zmax, 3.0 * h / 4.0, 1e-15);
	// the base face points straight down, at z = -h/4
	int down = 0;
	for (int f = 0; f < 5; f++) {
		if (s->faces[f].normal.z < -1.0 + 1e-12) {
			down++;
			assert_near(s->faces[f].offset, h / 4.0, 1e-15);
			assert_int_equal(s->faces[f].index_count, 4);
		}
	}
	assert_int_equal(down, 1);
	hs_shape_destroy(s);
}

static void test_l_block(void **state) {
	(void)state;
	hs_status st;
	// bounding box 3 × 1 × 2, arms 1 thick: foot 3 × 1 × 1 (centroid (1.5, 0.5, 0.5)),
	// upright 1 × 1 × 1 on top of its end (centroid (0.5, 0.5, 1.5)); G = (3·foot + 1·upright) / 4
	hs_shape *s = hs_shape_l_block(hs_v3(3, 1, 2), 1, &st);
	assert_int_equal(st, HS_OK);
	assert_int_equal(s->kind, HS_SHAPE_L_BLOCK);
	assert_int_equal(s->part_count, 2);
	assert_int_equal(s->vertex_count, 16);
	assert_int_equal(s->edge_count, 24);
	assert_int_equal(s->face_count, 12);
	check_invariants(s);
	assert_near(s->volume, 4.0, 1e-14);
	assert_vec3_near(s->centroid_shift, hs_v3(1.25, 0.5, 0.75), 1e-14);
	// the foot spans x in [0, 3] given, [-1.25, 1.75] in the body frame
	double xmin = INFINITY, xmax = -INFINITY;
	for (int v = 0; v < 8; v++) {
		xmin = fmin(xmin, s->vertices[v].x);
		xmax = fmax(xmax, s->vertices[v].x);
	}
	assert_near(xmin, -1.25, 1e-14);
	assert_near(xmax, 1.75, 1e-14);
	// part centres: the boxes' centres, shifted
	assert_vec3_near(s->parts[0].center, hs_v3(0.25, 0, -0.25), 1e-14);
	assert_vec3_near(s->parts[1].center, hs_v3(-0.75, 0, 0.75), 1e-14);
	assert_near(s->parts[0].radius, 0.5 * sqrt(11.0), 1e-14);
	assert_near(s->parts[1].radius, 0.5 * sqrt(3.0), 1e-14);
	// the parts' vertex boxes (collide.c's cheap rejection): the foot 3 × 1 × 1 about its centre,
	// the upright 1 × 1 × 1 about its own
	assert_vec3_near(s->parts[0].box_center, hs_v3(0.25, 0, -0.25), 1e-14);
	assert_vec3_near(s->parts[0].box_half, hs_v3(1.5, 0.5, 0.5), 1e-14);
	assert_vec3_near(s->parts[1].box_center, hs_v3(-0.75, 0, 0.75), 1e-14);
	assert_vec3_near(s->parts[1].box_half, hs_v3(0.5, 0.5, 0.5), 1e-14);
	// farthest vertex from G: (3, y, 0) given → (1.75, ±0.5, -0.75)
	assert_near(s->radius, sqrt(1.75 * 1.75 + 0.25 + 0.75 * 0.75), 1e-14);
	hs_shape_destroy(s);

	// a thin one in metres: foot 0.3 × 0.1 × 0.05 (1.5e-3 m³), upright 0.05 × 0.1 × 0.15 (7.5e-4 m³)
	s = hs_shape_l_block(hs_v3(0.3, 0.1, 0.2), 0.05, &st);
	assert_int_equal(st, HS_OK);
	check_invariants(s);
	assert_near(s->volume, 2.25e-3, 1e-17);
	assert_vec3_near(s->centroid_shift, hs_v3(13.0 / 120.0, 0.05, 7.0 / 120.0), 1e-15);
	hs_shape_destroy(s);
}

static void test_ellipsoid(void **state) {
	(void)state;
	hs_status st;
	hs_shape *s = hs_shape_ellipsoid(hs_v3(1, 2, 3), &st);
	assert_int_equal(st, HS_OK);
	assert_int_equal(s->kind, HS_SHAPE_ELLIPSOID);
	// 1999 paper, Exp. 3: 32 faces and 56 edges
	assert_int_equal(s->vertex_count, 26);
	assert_int_equal(s->edge_count, 56);
	assert_int_equal(s->face_count, 32);
	check_invariants(s);
	int triangles = 0, quads = 0;
	for (int f = 0; f < s->face_count; f++) {
		triangles += s->faces[f].index_count == 3;
		quads += s->faces[f].index_count == 4;
	}
	assert_int_equal(triangles, 16);
	assert_int_equal(quads, 16);
	// unit sphere: two octagonal frustums (h = √2/2, areas 2√2 and √2) and two pyramids
	// (h = 1 - √2/2, base √2): 2 (1 + √2/3 + (√2 - 1)/3) = (4/3)(1 + √2); scaled by abc
	assert_near(s->volume, 6.0 * (4.0 / 3.0) * (1.0 + SQRT2), 1e-13);
	assert_vec3_near(s->centroid_shift, hs_v3(0, 0, 0), 1e-15);
	// the poles and the equator are on the ellipsoid: radius = the largest semi-axis
	assert_near(s->radius, 3.0, 1e-15);
	for (int v = 0; v < s->vertex_count; v++) {
		hs_vec3 p = s->vertices[v];
		assert_near(p.x * p.x + p.y * p.y / 4.0 + p.z * p.z / 9.0, 1.0, 1e-14);
	}
	hs_shape_destroy(s);
}

static void test_sphere(void **state) {
	(void)state;
	hs_status st;
	double r = 0.05;
	hs_shape *s = hs_shape_sphere(r, &st);
	assert_int_equal(st, HS_OK);
	assert_int_equal(s->kind, HS_SHAPE_SPHERE);
	assert_near(s->sphere_radius, r, 0.0);
	// exact, not the polyhedron's: the spring model needs the exact mass
	assert_near(s->volume, 4.0 / 3.0 * HS_PI * r * r * r, 1e-18);
	assert_near(s->radius, r, 0.0);
	assert_vec3_near(s->centroid_shift, hs_v3(0, 0, 0), 0.0);
	assert_vec3_near(s->parts[0].center, hs_v3(0, 0, 0), 0.0);
	assert_near(s->parts[0].radius, r, 0.0);
	// 16 slices × 8 stacks: 2 + 16·7 vertices, 16·8 faces, 16·7 + 16·8 edges
	assert_int_equal(s->vertex_count, 114);
	assert_int_equal(s->face_count, 128);
	assert_int_equal(s->edge_count, 240);
	check_invariants(s);
	double zmin = INFINITY;
	for (int v = 0; v < s->vertex_count; v++) {
		assert_near(hs_length(s->vertices[v]), r, 1e-16);
		zmin = fmin(zmin, s->vertices[v].z);
	}
	// the south pole is the floor contact of a resting sphere
	assert_near(zmin, -r, 0.0);
	hs_shape_destroy(s);
}

static void test_cube_is_box(void **state) {
	(void)state;
	hs_shape *s = hs_shape_box(hs_v3(0.05, 0.05, 0.05), NULL); // status may be NULL
	assert_non_null(s);
	check_invariants(s);
	assert_near(s->volume, 1.25e-4, 1e-18);
	for (int f = 0; f < 6; f++)
		assert_near(s->faces[f].offset, 0.025, 1e-17);
	hs_shape_destroy(s);
	hs_shape_destroy(NULL);
}

static void test_deterministic(void **state) {
	(void)state;
	for (int kind = 0; kind < 3; kind++) {
		hs_shape *a = kind == 0 ? hs_shape_ellipsoid(hs_v3(0.1, 0.07, 0.05), NULL)
		              : kind == 1 ? hs_shape_l_block(hs_v3(0.3, 0.1, 0.2), 0.05, NULL)
		                          : hs_shape_sphere(0.3, NULL);
		hs_shape *b = kind == 0 ? hs_shape_ellipsoid(hs_v3(0.1, 0.07, 0.05), NULL)
		              : kind == 1 ? hs_shape_l_block(hs_v3(0.3, 0.1, 0.2), 0.05, NULL)
		                          : hs_shape_sphere(0.3, NULL);
		assert_non_null(a);
		assert_non_null(b);
		assert_memory_equal(a->vertices, b->vertices, sizeof *a->vertices * (size_t)a->vertex_count);
		assert_memory_equal(a->faces, b->faces, sizeof *a->faces * (size_t)a->face_count);
		assert_memory_equal(a->edges, b->edges, sizeof *a->edges * (size_t)a->edge_count);
		assert_memory_equal(&a->volume, &b->volume, sizeof a->volume);
		hs_shape_destroy(a);
		hs_shape_destroy(b);
	}
}

static void test_invalid_sizes(void **state) {
	(void)state;
	const double bad[] = {0.0, -1.0, NAN, INFINITY, -INFINITY};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		double x = bad[i];
		hs_status st = HS_OK;
		assert_null(hs_shape_box(hs_v3(x, 1, 1), &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_box(hs_v3(1, 1, x), &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_pyramid(x, 1, &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_pyramid(1, x, &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_l_block(hs_v3(3, x, 2), 1, &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_l_block(hs_v3(3, 1, 2), x, &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_ellipsoid(hs_v3(1, x, 1), &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		st = HS_OK;
		assert_null(hs_shape_sphere(x, &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
		assert_null(hs_shape_sphere(x, NULL));
	}
	// the arms must leave a notch: thickness below both the length and the height
	hs_status st = HS_OK;
	assert_null(hs_shape_l_block(hs_v3(3, 1, 2), 2, &st));
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	st = HS_OK;
	assert_null(hs_shape_l_block(hs_v3(1, 1, 2), 1, &st));
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	// but a thin, tall one is fine
	hs_shape *s = hs_shape_l_block(hs_v3(1, 1, 2), 0.999, &st);
	assert_int_equal(st, HS_OK);
	hs_shape_destroy(s);
}

static void test_status_string(void **state) {
	(void)state;
	assert_string_equal(hs_status_string(HS_OK), "ok");
	assert_string_equal(hs_status_string(HS_ERR_INVALID_ARGUMENT), "invalid argument");
	assert_string_equal(hs_status_string(HS_ERR_DEGENERATE), "degenerate shape");
	assert_string_equal(hs_status_string(HS_ERR_CAPACITY), "capacity exceeded");
	assert_string_equal(hs_status_string(HS_ERR_NO_MEMORY), "out of memory");
	assert_string_equal(hs_status_string((hs_status)99), "unknown status");
}

// ---------------------------------------------------------------------------------------------
// hs_shape_polyhedron

static const hs_vec3 tet_v[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

static void test_polyhedron_tetrahedron(void **state) {
	(void)state;
	// windings mixed on purpose: face 1 is listed inward, the others outward
	const int fv[12] = {0, 2, 1, 0, 3, 1, 1, 2, 3, 0, 3, 2};
	const int fs[4] = {3, 3, 3, 3};
	char why[64] = "untouched";
	hs_status st;
	hs_shape *s = hs_shape_polyhedron(tet_v, 4, fv, fs, 4, why, sizeof why, &st);
	assert_int_equal(st, HS_OK);
	assert_string_equal(why, "");
	assert_int_equal(s->kind, HS_SHAPE_POLYHEDRON);
	assert_int_equal(s->edge_count, 6);
	check_invariants(s);
	assert_near(s->volume, 1.0 / 6.0, 1e-15);
	assert_vec3_near(s->centroid_shift, hs_v3(0.25, 0.25, 0.25), 1e-15);
	// faces keep their input order; face 1 (y = 0 plane) points along -y, face 2 away from the origin
	assert_vec3_near(s->faces[0].normal, hs_v3(0, 0, -1), 1e-15);
	assert_vec3_near(s->faces[1].normal, hs_v3(0, -1, 0), 1e-15);
	assert_vec3_near(s->faces[2].normal, hs_v3(1 / sqrt(3.0), 1 / sqrt(3.0), 1 / sqrt(3.0)), 1e-15);
	assert_vec3_near(s->faces[3].normal, hs_v3(-1, 0, 0), 1e-15);
	// plane x + y + z = 1 given, G at 1/4 each: offset (1 - 3/4)/√3 in the body frame
	assert_near(s->faces[2].offset, 0.25 / sqrt(3.0), 1e-15);
	hs_shape_destroy(s);
}

// unit cube, vertex i = (x bit 0, y bit 1, z bit 2), placed at (2, 3, 4)
static void cube_vertices(hs_vec3 v[8]) {
	for (int i = 0; i < 8; i++)
		v[i] = hs_v3(2.0 + (i & 1), 3.0 + ((i >> 1) & 1), 4.0 + ((i >> 2) & 1));
}
// z=0, z=1, y=0, y=1, x=0, x=1 — faces 1, 2 and 4 listed inward
static const int cube_fv[24] = {0, 2, 3, 1, 4, 6, 7, 5, 0, 4, 5, 1, 2, 6, 7, 3, 0, 2, 6, 4, 1, 3, 7, 5};
static const int cube_fs[6] = {4, 4, 4, 4, 4, 4};

static void test_polyhedron_cube(void **state) {
	(void)state;
	hs_vec3 v[8];
	cube_vertices(v);
	hs_status st;
	hs_shape *s = hs_shape_polyhedron(v, 8, cube_fv, cube_fs, 6, NULL, 0, &st);
	assert_int_equal(st, HS_OK);
	assert_int_equal(s->vertex_count, 8);
	assert_int_equal(s->edge_count, 12);
	assert_int_equal(s->face_count, 6);
	check_invariants(s);
	assert_near(s->volume, 1.0, 1e-14);
	assert_vec3_near(s->centroid_shift, hs_v3(2.5, 3.5, 4.5), 1e-14);
	const hs_vec3 normals[6] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
	for (int f = 0; f < 6; f++) {
		assert_vec3_near(s->faces[f].normal, normals[f], 1e-15);
		assert_near(s->faces[f].offset, 0.5, 1e-14);
	}
	assert_near(s->radius, 0.5 * sqrt(3.0), 1e-14);
	hs_shape_destroy(s);
}

// Rejects `input`, status `expected`, reason exactly `reason`.
static void expect_rejected(const hs_vec3 *v, int nv, const int *fv, const int *fs, int nf, hs_status expected,
                            const char *reason) {
	char why[128] = "";
	hs_status st = HS_OK;
	hs_shape *s = hs_shape_polyhedron(v, nv, fv, fs, nf, why, sizeof why, &st);
	if (s || st != expected || strcmp(why, reason) != 0)
		print_error("expected %d \"%s\", got %d \"%s\"\n", (int)expected, reason, (int)st, why);
	assert_null(s);
	assert_int_equal(st, expected);
	assert_string_equal(why, reason);
	// status and why may be NULL
	assert_null(hs_shape_polyhedron(v, nv, fv, fs, nf, NULL, 0, NULL));
}

static void test_polyhedron_rejects_counts(void **state) {
	(void)state;
	const int tet_fv[12] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
	const int tet_fs[4] = {3, 3, 3, 3};
	expect_rejected(tet_v, 3, tet_fv, tet_fs, 4, HS_ERR_DEGENERATE, "fewer than 4 vertices");
	expect_rejected(NULL, 0, NULL, NULL, 0, HS_ERR_DEGENERATE, "fewer than 4 vertices");
	expect_rejected(tet_v, 4, tet_fv, tet_fs, 3, HS_ERR_DEGENERATE, "fewer than 4 faces");
	const int fs2[4] = {3, 3, 3, 2};
	expect_rejected(tet_v, 4, tet_fv, fs2, 4, HS_ERR_DEGENERATE, "face 3 has fewer than 3 vertices");
	const int fs5[4] = {3, 5, 3, 1};
	expect_rejected(tet_v, 4, tet_fv, fs5, 4, HS_ERR_DEGENERATE, "face 1 has more vertices than the shape");
	const int out_of_range[12] = {0, 2, 1, 0, 1, 3, 1, 2, 9, 0, 3, 2};
	expect_rejected(tet_v, 4, out_of_range, tet_fs, 4, HS_ERR_DEGENERATE, "vertex index 9 out of range");
	const int negative[12] = {0, 2, 1, -1, 1, 3, 1, 2, 3, 0, 3, 2};
	expect_rejected(tet_v, 4, negative, tet_fs, 4, HS_ERR_DEGENERATE, "vertex index -1 out of range");
	const int repeat[12] = {0, 2, 1, 0, 1, 3, 1, 2, 1, 0, 3, 2};
	expect_rejected(tet_v, 4, repeat, tet_fs, 4, HS_ERR_DEGENERATE, "face 2 repeats vertex 1");
	expect_rejected(tet_v, -1, tet_fv, tet_fs, 4, HS_ERR_INVALID_ARGUMENT, "negative count");
	expect_rejected(NULL, 4, tet_fv, tet_fs, 4, HS_ERR_INVALID_ARGUMENT, "null pointer");
	expect_rejected(tet_v, 4, NULL, tet_fs, 4, HS_ERR_INVALID_ARGUMENT, "null pointer");
	expect_rejected(tet_v, 4, tet_fv, NULL, 4, HS_ERR_INVALID_ARGUMENT, "null pointer");
	const hs_vec3 nan_v[4] = {{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}, {0, 0, 1}};
	expect_rejected(nan_v, 4, tet_fv, tet_fs, 4, HS_ERR_INVALID_ARGUMENT, "vertex 2 is not finite");
	const hs_vec3 inf_v[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -INFINITY}};
	expect_rejected(inf_v, 4, tet_fv, tet_fs, 4, HS_ERR_INVALID_ARGUMENT, "vertex 3 is not finite");
}

static void test_polyhedron_rejects_topology(void **state) {
	(void)state;
	hs_vec3 v[9];
	cube_vertices(v);
	v[8] = hs_v3(9, 9, 9);
	// an extra point no face uses
	expect_rejected(v, 9, cube_fv, cube_fs, 6, HS_ERR_DEGENERATE, "vertex 8 is unused");
	// the z = 0 face left out: its edges have one face; the lowest is 0-1
	expect_rejected(v, 8, cube_fv + 4, cube_fs, 5, HS_ERR_DEGENERATE, "edge 0-1 is not shared by exactly two faces");
	// the same face twice: its edges have three faces
	int twice[28];
	memcpy(twice, cube_fv, sizeof cube_fv);
	memcpy(twice + 24, cube_fv, 4 * sizeof(int));
	const int fs7[7] = {4, 4, 4, 4, 4, 4, 4};
	expect_rejected(v, 8, twice, fs7, 7, HS_ERR_DEGENERATE, "edge 0-1 is not shared by exactly two faces");
	// two disjoint tetrahedra: closed, but V - E + F = 8 - 12 + 8
	const hs_vec3 two[8] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1}};
	const int two_fv[24] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2, 4, 6, 5, 4, 5, 7, 5, 6, 7, 4, 7, 6};
	const int two_fs[8] = {3, 3, 3, 3, 3, 3, 3, 3};
	expect_rejected(two, 8, two_fv, two_fs, 8, HS_ERR_DEGENERATE, "v - e + f is 4, not 2");
}

static void test_polyhedron_rejects_geometry(void **state) {
	(void)state;
	hs_vec3 v[8];
	cube_vertices(v);
	// corner 7 lifted by 0.1: faces 1 (z = 1), 3 (y = 1) and 5 (x = 1) bend; face 1 is met first
	v[7].z += 0.1;
	expect_rejected(v, 8, cube_fv, cube_fs, 6, HS_ERR_DEGENERATE, "face 1 is not planar");
	// lifted by far less than the 1e-9 relative tolerance: accepted
	cube_vertices(v);
	v[7].z += 1e-12;
	hs_shape *s = hs_shape_polyhedron(v, 8, cube_fv, cube_fs, 6, NULL, 0, NULL);
	assert_non_null(s);
	hs_shape_destroy(s);

	// a tetrahedron whose four points lie in one plane
	const hs_vec3 flat[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
	const int tet_fv[12] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
	const int tet_fs[4] = {3, 3, 3, 3};
	expect_rejected(flat, 4, tet_fv, tet_fs, 4, HS_ERR_DEGENERATE, "shape has no volume");
	// face 0 = points 0, 2, 1 on one line
	const hs_vec3 line[4] = {{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {0, 1, 1}};
	expect_rejected(line, 4, tet_fv, tet_fs, 4, HS_ERR_DEGENERATE, "face 0 has no area");

	// unit cube with its top dented: four triangles to (0.5, 0.5, 0.8)
	hs_vec3 dent[9];
	for (int i = 0; i < 8; i++)
		dent[i] = hs_v3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
	dent[8] = hs_v3(0.5, 0.5, 0.8);
	const int dent_fv[32] = {0, 2, 3, 1, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5,
	                         4, 5, 8, 5, 7, 8, 7, 6, 8, 6, 4, 8};
	const int dent_fs[9] = {4, 4, 4, 4, 4, 3, 3, 3, 3};
	expect_rejected(dent, 9, dent_fv, dent_fs, 9, HS_ERR_DEGENERATE, "shape is not convex");
	// the same bump pushed outward (z = 1.2) is a convex roof
	dent[8].z = 1.2;
	s = hs_shape_polyhedron(dent, 9, dent_fv, dent_fs, 9, NULL, 0, NULL);
	assert_non_null(s);
	check_invariants(s);
	// cube + pyramid of height 0.2 on a unit base
	assert_near(s->volume, 1.0 + 0.2 / 3.0, 1e-14);
	hs_shape_destroy(s);

	// a 2 × 2 × 1 slab whose top is an L-shaped hexagon (face 5, reflex at (1, 1, 1)) plus a square
	const hs_vec3 lt[11] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 1}, {2, 0, 1},
	                        {2, 1, 1}, {1, 1, 1}, {1, 2, 1}, {0, 2, 1}, {2, 2, 1}};
	const int lt_fv[32] = {0, 1, 2, 3, 0, 1, 5, 4, 1, 2, 10, 6, 5, 2, 3, 9, 8, 10,
	                       3, 0, 4, 9, 4, 5, 6, 7, 8, 9, 7, 6, 10, 8};
	const int lt_fs[7] = {4, 4, 5, 5, 4, 6, 4};
	expect_rejected(lt, 11, lt_fv, lt_fs, 7, HS_ERR_DEGENERATE, "face 5 is not convex");
}

static void test_polyhedron_why_truncated(void **state) {
	(void)state;
	const int tet_fv[12] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
	const int tet_fs[4] = {3, 3, 3, 3};
	char why[8];
	memset(why, 'x', sizeof why);
	hs_status st;
	assert_null(hs_shape_polyhedron(tet_v, 2, tet_fv, tet_fs, 4, why, sizeof why, &st));
	assert_int_equal(st, HS_ERR_DEGENERATE);
	assert_string_equal(why, "fewer t"); // 7 characters and the terminator, never more
}

static void test_polyhedron_far_from_origin(void **state) {
	(void)state;
	// a 5 cm cube 1 km away: tolerances are relative to the part's size, not its position
	hs_vec3 v[8];
	for (int i = 0; i < 8; i++)
		v[i] = hs_v3(1000.0 + 0.05 * (i & 1), -1000.0 + 0.05 * ((i >> 1) & 1), 0.05 * ((i >> 2) & 1));
	hs_status st;
	hs_shape *s = hs_shape_polyhedron(v, 8, cube_fv, cube_fs, 6, NULL, 0, &st);
	assert_int_equal(st, HS_OK);
	check_invariants(s);
	assert_near(s->volume, 1.25e-4, 1e-14);
	assert_vec3_near(s->centroid_shift, hs_v3(1000.025, -999.975, 0.025), 1e-11);
	hs_shape_destroy(s);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_box),
	    cmocka_unit_test(test_pyramid),
	    cmocka_unit_test(test_l_block),
	    cmocka_unit_test(test_ellipsoid),
	    cmocka_unit_test(test_sphere),
	    cmocka_unit_test(test_cube_is_box),
	    cmocka_unit_test(test_deterministic),
	    cmocka_unit_test(test_invalid_sizes),
	    cmocka_unit_test(test_status_string),
	    cmocka_unit_test(test_polyhedron_tetrahedron),
	    cmocka_unit_test(test_polyhedron_cube),
	    cmocka_unit_test(test_polyhedron_rejects_counts),
	    cmocka_unit_test(test_polyhedron_rejects_topology),
	    cmocka_unit_test(test_polyhedron_rejects_geometry),
	    cmocka_unit_test(test_polyhedron_why_truncated),
	    cmocka_unit_test(test_polyhedron_far_from_origin),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
