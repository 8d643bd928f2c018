// test_face_tree.c — the normal-cone trees (model/geometry/face_tree.c) answer every query exactly as the
// scan of all faces in index order does: inside, nearest face (ties to the lower index), the
// Cyrus-Beck clip (every field when it hits) and the four-points-beyond test, on many-faced
// balls and stretched balls, for random points near and far, points on the surface and at the
// centre (where faces tie), and NaN.
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clip.h"
#include "face_tree.h"
#include "test_scans.h"
#include "test_util.h"

// A UV ball of slices × stacks faces (fans at the poles, planar trapezoids between), its vertices
// scaled by `stretch` (an affine map keeps faces planar).
static hs_shape *uv_ball(int slices, int stacks, double r, hs_vec3 stretch) {
	int nv = 2 + slices * (stacks - 1), nf = slices * stacks;
	hs_vec3 *v = malloc((size_t)nv * sizeof *v);
	int *fv = malloc((size_t)nf * 4 * sizeof *fv), *fs = malloc((size_t)nf * sizeof *fs);
	assert_non_null(v);
	assert_non_null(fv);
	assert_non_null(fs);
	int n = 0, m = 0, f = 0;
	v[n++] = hs_v3(0.0, 0.0, r * stretch.z);
	for (int j = 1; j < stacks; ++j)
		for (int i = 0; i < slices; ++i) {
			double th = HS_PI * j / stacks, ph = 2.0 * HS_PI * i / slices;
			v[n++] = hs_v3(r * stretch.x * sin(th) * cos(ph), r * stretch.y * sin(th) * sin(ph), r * stretch.z * cos(th));
		}
	v[n++] = hs_v3(0.0, 0.0, -r * stretch.z);
	for (int j = 0; j < stacks; ++j)
		for (int i = 0; i < slices; ++i) {
			int i1 = (i + 1) % slices, top = 1 + (j - 1) * slices, low = top + slices;
			if (j == 0) {
				fv[m++] = 0, fv[m++] = 1 + i, fv[m++] = 1 + i1, fs[f++] = 3;
			} else if (j == stacks - 1) {
				fv[m++] = n - 1, fv[m++] = top + i1, fv[m++] = top + i, fs[f++] = 3;
			} else {
				fv[m++] = top + i, fv[m++] = low + i, fv[m++] = low + i1, fv[m++] = top + i1, fs[f++] = 4;
			}
		}
	char why[128] = "";
	hs_status st;
	hs_shape *s = hs_shape_polyhedron(v, n, fv, fs, f, why, sizeof why, &st);
	if (!s)
		fail_msg("ball of %d faces: %s", f, why);
	free(v);
	free(fv);
	free(fs);
	return s;
}

// The sweep's scan, as contact_swept.c writes it (the reference; the others are in test_scans.h).
static bool scan_beyond(const hs_shape *s, const hs_part *part, const hs_vec3 q[4]) {
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f) {
		hs_vec3 n = s->faces[f].normal;
		double o = s->faces[f].offset;
		if (hs_dot(n, q[0]) > o && hs_dot(n, q[1]) > o && hs_dot(n, q[2]) > o && hs_dot(n, q[3]) > o)
			return true;
	}
	return false;
}

static double unit(uint64_t *state) { // [-1, 1), a fixed LCG
	*state = *state * 6364136223846793005ull + 1442695040888963407ull;
	return (double)(*state >> 11) / (double)(1ull << 52) - 1.0;
}

// A point of one of four kinds: anywhere near the ball, just inside or outside a vertex, on a face
// (a vertex average), or the centre.
static hs_vec3 sample(const hs_shape *s, uint64_t *rng, double r) {
	int kind = (int)((unit(rng) + 1.0) * 2.0);
	int v = (int)((unit(rng) + 1.0) * 0.5 * s->vertex_count) % s->vertex_count;
	switch (kind) {
	case 0: {
		double scale = (unit(rng) + 1.0) * 1.5 * r; // 0 .. 3 r
		return hs_v3(scale * unit(rng), scale * unit(rng), scale * unit(rng));
	}
	case 1:
		return hs_scale(s->vertices[v], 1.0 + 1e-6 * unit(rng));
	case 2: {
		const hs_face *f = &s->faces[v % s->face_count];
		hs_vec3 c = hs_v3(0, 0, 0);
		for (int k = 0; k < f->index_count; ++k)
			c = hs_add(c, s->vertices[s->face_vertices[f->first_index + k]]);
		return hs_scale(c, 1.0 / f->index_count);
	}
	default:
		return hs_v3(0.0, 0.0, 0.0);
	}
}

static void compare_on(hs_shape *s, double r, int samples) {
	hs_face_tree tree;
	assert_true(hs_face_tree_build(&tree, s));
	const hs_part *part = &s->parts[0];
	int root = hs_face_tree_root(&tree, s, part);
	assert_true(root >= 0); // a many-faced part has its tree
	uint64_t rng = 12345;
	const double grows[3] = {0.0, 1e-3, 2e-3};
	int hits = 0, inside = 0, beyond = 0;
	for (int k = 0; k < samples; ++k) {
		hs_vec3 a = sample(s, &rng, r), b = sample(s, &rng, r);
		double grow = grows[k % 3];
		bool in = scan_inside(s, part, a, grow);
		inside += in;
		assert_int_equal(hs_face_tree_inside(&tree, root, s, a, grow), in);
		assert_int_equal(hs_face_tree_nearest(&tree, root, s, part->first_face, a), scan_nearest(s, part, a));
		hs_clip want = hs_clip_segment(s, part, a, b, grow), got = hs_face_tree_clip(&tree, root, s, a, b, grow);
		assert_int_equal(got.hit, want.hit);
		if (want.hit) {
			hits++;
			assert_true(got.t_in == want.t_in && got.t_out == want.t_out);
			assert_int_equal(got.face_in, want.face_in);
			assert_int_equal(got.face_out, want.face_out);
		}
		hs_vec3 q[4] = {a, b, sample(s, &rng, r), sample(s, &rng, r)};
		if (k % 2) // a small swept quad about a: beyond a face when a is well outside
			for (int i = 1; i < 4; ++i)
				q[i] = hs_add(a, hs_v3(0.1 * r * unit(&rng), 0.1 * r * unit(&rng), 0.1 * r * unit(&rng)));
		bool far = scan_beyond(s, part, q);
		beyond += far;
		assert_int_equal(hs_face_tree_beyond(&tree, root, s, q), far);
	}
	// the samples reach every answer
	print_message("%d samples: %d hits, %d inside, %d beyond\n", samples, hits, inside, beyond);
	assert_true(hits > samples / 20 && hits < samples);
	assert_true(inside > samples / 20 && inside < samples);
	assert_true(beyond > samples / 50 && beyond < samples);
	hs_vec3 nan = hs_v3(NAN, 0.0, 0.0);
	assert_int_equal(hs_face_tree_inside(&tree, root, s, nan, 0.0), scan_inside(s, part, nan, 0.0));
	assert_int_equal(hs_face_tree_nearest(&tree, root, s, part->first_face, nan), scan_nearest(s, part, nan));
	hs_clip want = hs_clip_segment(s, part, nan, hs_v3(0, 0, 0), 0.0), got = hs_face_tree_clip(&tree, root, s, nan, hs_v3(0, 0, 0), 0.0);
	assert_int_equal(got.hit, want.hit);
	hs_face_tree_free(&tree);
}

static void test_ball_128(void **state) {
	(void)state;
	hs_shape *s = uv_ball(16, 8, 0.025, hs_v3(1, 1, 1));
	compare_on(s, 0.025, 60000);
	hs_shape_destroy(s);
}

static void test_ball_512(void **state) {
	(void)state;
	hs_shape *s = uv_ball(32, 16, 0.025, hs_v3(1, 1, 1));
	compare_on(s, 0.025, 60000);
	hs_shape_destroy(s);
}

// Stretched: plane offsets differ from face to face and normals crowd at the flat sides.
static void test_stretched_ball(void **state) {
	(void)state;
	hs_shape *s = uv_ball(24, 12, 0.5, hs_v3(1.0, 0.3, 0.05));
	compare_on(s, 0.5, 60000);
	hs_shape_destroy(s);
}

// Few faces: no tree (the scan is cheaper); a shape of several parts gets a root per part.
static void test_few_faces_are_scanned(void **state) {
	(void)state;
	hs_status st;
	hs_shape *cube = hs_shape_box(hs_v3(0.05, 0.05, 0.05), &st);
	hs_shape *ellipsoid = hs_shape_ellipsoid(hs_v3(0.05, 0.03, 0.02), &st);
	hs_shape *l = hs_shape_l_block(hs_v3(0.1, 0.05, 0.1), 0.02, &st);
	hs_shape *shapes[3] = {cube, ellipsoid, l};
	assert_int_equal(hs_face_tree_root(NULL, cube, &cube->parts[0]), -1);
	for (int k = 0; k < 3; ++k) {
		hs_face_tree tree;
		assert_true(hs_face_tree_build(&tree, shapes[k]));
		assert_int_equal(tree.part_count, shapes[k]->part_count);
		for (int p = 0; p < shapes[k]->part_count; ++p)
			assert_int_equal(hs_face_tree_root(&tree, shapes[k], &shapes[k]->parts[p]), -1);
		hs_face_tree_free(&tree);
		hs_shape_destroy(shapes[k]);
	}
}

// A segment meets a triangle (loosely: barycentrics within 1e-9 of their bounds count).
static bool segment_meets_triangle(hs_vec3 a, hs_vec3 b, hs_vec3 v0, hs_vec3 v1, hs_vec3 v2) {
	hs_vec3 e1 = hs_sub(v1, v0), e2 = hs_sub(v2, v0), d = hs_sub(b, a), pv = hs_cross(d, e2);
	double det = hs_dot(e1, pv);
	if (det == 0.0)
		return false;
	hs_vec3 tv = hs_sub(a, v0), qv = hs_cross(tv, e1);
	double u = hs_dot(tv, pv) / det, v = hs_dot(d, qv) / det, s = hs_dot(e2, qv) / det, e = 1e-9;
	return u >= -e && v >= -e && u + v <= 1.0 + e && s >= -e && s <= 1.0 + e;
}

// The faces a swept quad reaches hold every edge the quad's two triangles meet (contact_swept.c tries
// only their edges), and leave most faces out when the quad passes close by.
static void test_reached_faces_hold_every_edge_hit(void **state) {
	(void)state;
	hs_shape *s = uv_ball(32, 16, 0.025, hs_v3(1.0, 0.8, 0.6));
	hs_face_tree tree;
	assert_true(hs_face_tree_build(&tree, s));
	int root = hs_face_tree_root(&tree, s, &s->parts[0]);
	int *faces = malloc((size_t)s->face_count * sizeof *faces);
	bool *listed = malloc((size_t)s->face_count * sizeof *listed);
	assert_non_null(faces);
	assert_non_null(listed);
	uint64_t rng = 777;
	long hits = 0, listed_total = 0;
	const int quads = 4000;
	for (int k = 0; k < quads; ++k) {
		// a check line (length 2 cm) near the surface, moved by up to 2 cm
		hs_vec3 c = sample(s, &rng, 0.025);
		hs_vec3 dir = hs_v3(unit(&rng), unit(&rng), unit(&rng)), move = hs_v3(unit(&rng), unit(&rng), unit(&rng));
		hs_vec3 q[4] = {hs_sub(c, hs_scale(dir, 0.01)), hs_add(c, hs_scale(dir, 0.01)), {0, 0, 0}, {0, 0, 0}};
		q[2] = hs_add(q[0], hs_scale(move, 0.02)); // n0
		q[3] = hs_add(q[1], hs_scale(move, 0.02)); // n1
		int count = hs_face_tree_reached(&tree, root, 0, s, q, faces);
		listed_total += count;
		memset(listed, 0, (size_t)s->face_count * sizeof *listed);
		for (int j = 0; j < count; ++j)
			listed[faces[j]] = true;
		for (int e = 0; e < s->edge_count; ++e) {
			hs_vec3 ea = s->vertices[s->edges[e].a], eb = s->vertices[s->edges[e].b];
			if (!segment_meets_triangle(ea, eb, q[0], q[1], q[3]) && !segment_meets_triangle(ea, eb, q[0], q[3], q[2]))
				continue;
			hits++;
			assert_true(listed[s->edges[e].faces[0]] && listed[s->edges[e].faces[1]]);
		}
	}
	print_message("%d quads: %ld edge hits, %.1f of %d faces listed a quad\n", quads, hits, (double)listed_total / quads,
	              s->face_count);
	assert_true(hits > quads / 4);
	assert_true(listed_total < (long)quads * s->face_count / 2); // the tree leaves most faces out
	free(faces);
	free(listed);
	hs_face_tree_free(&tree);
	hs_shape_destroy(s);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_ball_128),
	    cmocka_unit_test(test_ball_512),
	    cmocka_unit_test(test_stretched_ball),
	    cmocka_unit_test(test_few_faces_are_scanned),
	    cmocka_unit_test(test_reached_faces_hold_every_edge_hit),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
