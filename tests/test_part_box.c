// test_part_box.c — a part that is a box with axis-aligned faces (model/geometry/part_box.h): which
// parts are found to be such boxes, the coordinate inside test and nearest face answer as the
// scans of the faces do (on faces, at ±0, grown, NaN, ties), and two ends beyond one face by more than the slack make the
// Cyrus-Beck clip miss, while ends beyond by less do not count as apart; the box's clip is the
// clip's, bit for bit, and four ends beyond one face make every segment between them miss.
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "clip.h"
#include "face_tree.h"
#include "part_box.h"
#include "part_reach.h"
#include "world_internal.h"
#include "test_scans.h"
#include "test_util.h"

#define SLACK 1e-6 // contact_part.h's HS_CULL_SLACK

static double unit(uint64_t *state) { // [-1, 1), a fixed LCG
	*state = *state * 6364136223846793005ull + 1442695040888963407ull;
	return (double)(*state >> 11) / (double)(1ull << 52) - 1.0;
}

// A coordinate of one of four kinds: anywhere within the span lo..hi widened by its length on
// each side, exactly lo or hi, just off one of them by less than the slack, or a zero of either
// sign.
static double coordinate(uint64_t *rng, double lo, double hi) {
	int kind = (int)((unit(rng) + 1.0) * 2.0);
	bool high = unit(rng) >= 0.0;
	switch (kind) {
	case 0:
		return 0.5 * (lo + hi) + 1.5 * (hi - lo) * unit(rng);
	case 1:
		return high ? hi : lo;
	case 2:
		return (high ? hi : lo) + 0.5 * SLACK * unit(rng);
	default:
		return high ? 0.0 : -0.0;
	}
}

// What the world finds of a part of a shape (hs_world_add_shape does the same in its copy).
static hs_part_cache cache_of(const hs_shape *shape, int p) {
	hs_part_cache pc;
	hs_part_box_find(shape, &shape->parts[p], &pc);
	return pc;
}

// A point about the part's box grown by `grow`, its coordinates each of coordinate's kinds.
static hs_vec3 sample(uint64_t *rng, const hs_part_cache *pc, double grow) {
	const double *o = pc->box_offset;
	return hs_v3(coordinate(rng, -(o[1] + grow), o[0] + grow), coordinate(rng, -(o[3] + grow), o[2] + grow),
	             coordinate(rng, -(o[5] + grow), o[4] + grow));
}

static void test_finds_boxes(void **state) {
	(void)state;
	hs_shape *box = hs_shape_box(hs_v3(0.3, 0.1, 0.2), NULL);
	assert_non_null(box);
	hs_part_cache pc = cache_of(box, 0);
	assert_true(hs_part_is_box(&pc));
	const hs_vec3 axis[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
	const double half[3] = {0.15, 0.05, 0.1};
	for (int k = 0; k < 6; ++k) {
		const hs_face *f = &box->faces[pc.box_face[k]];
		assert_vec3_near(f->normal, axis[k], 0.0);
		assert_true(pc.box_offset[k] == f->offset);
		assert_near(pc.box_offset[k], half[k / 2], 1e-15);
	}
	hs_shape_destroy(box);

	// both parts of the L-block, though one lies beside G (its near face's offset is negative)
	hs_shape *l = hs_shape_l_block(hs_v3(3, 1, 2), 1, NULL);
	assert_non_null(l);
	hs_part_cache l0 = cache_of(l, 0), l1 = cache_of(l, 1);
	assert_true(hs_part_is_box(&l0));
	assert_true(hs_part_is_box(&l1));
	bool negative = false;
	for (int k = 0; k < 6; ++k)
		negative |= l1.box_offset[k] < 0.0;
	assert_true(negative);

	// the world finds them in its copy, beside it (the caller's hs_part has no such field)
	hs_world_def def = hs_default_world_def();
	hs_world *w = hs_world_create(&def, NULL);
	assert_non_null(w);
	hs_shape_id id = hs_world_add_shape(w, l, NULL);
	const hs_shape *copy = hs_world_shape(w, id);
	assert_non_null(copy);
	const hs_part_cache *kept = hs_part_cache_of(&w->model, copy, &copy->parts[1]);
	assert_true(hs_part_is_box(hs_part_cache_of(&w->model, copy, &copy->parts[0])));
	assert_true(kept->box_offset[0] == l1.box_offset[0]);
	assert_true(kept->grow_reach == hs_part_grow_reach(l, &l->parts[1]));
	assert_near(kept->grow_reach, sqrt(3.0), 1e-6);
	hs_world_destroy(w);
	hs_shape_destroy(l);

	// a turned cube and a many-faced ellipsoid are not
	hs_shape *e = hs_shape_ellipsoid(hs_v3(0.1, 0.1, 0.1), NULL);
	assert_non_null(e);
	hs_part_cache ec = cache_of(e, 0);
	assert_false(hs_part_is_box(&ec));
	hs_shape_destroy(e);
	const double c = cos(0.3), s = sin(0.3);
	hs_vec3 v[8];
	int fv[24] = {0, 1, 3, 2, 4, 6, 7, 5, 0, 4, 5, 1, 2, 3, 7, 6, 0, 2, 6, 4, 1, 5, 7, 3};
	int fs[6] = {4, 4, 4, 4, 4, 4};
	for (int i = 0; i < 8; ++i) {
		double x = i & 1 ? 0.1 : -0.1, y = i & 2 ? 0.1 : -0.1, z = i & 4 ? 0.1 : -0.1;
		v[i] = hs_v3(c * x - s * y, s * x + c * y, z);
	}
	char why[128] = "";
	hs_shape *turned = hs_shape_polyhedron(v, 8, fv, fs, 6, why, sizeof why, NULL);
	assert_non_null(turned);
	assert_int_equal(turned->parts[0].face_count, 6);
	hs_part_cache tc = cache_of(turned, 0);
	assert_false(hs_part_is_box(&tc));
	hs_shape_destroy(turned);
}

// The inside test against the scan for points about the part, grown by 0, 1 and 2 mm.
static void inside_as_the_scan(const hs_shape *shape, int part_index, uint64_t seed) {
	const hs_part *part = &shape->parts[part_index];
	hs_part_cache pc = cache_of(shape, part_index);
	const double grows[3] = {0.0, 1e-3, 2e-3};
	uint64_t rng = seed;
	int inside = 0, on_a_face = 0;
	for (int k = 0; k < 100000; ++k) {
		double grow = grows[k % 3];
		hs_vec3 p = sample(&rng, &pc, grow);
		assert_true(hs_part_box_takes(p));
		bool want = scan_inside(shape, part, p, grow);
		assert_int_equal(hs_part_box_inside(&pc, p, grow), want);
		inside += want;
		on_a_face += p.x == pc.box_offset[0] + grow;
	}
	assert_in_range(inside, 1000, 99000); // both answers are common
	assert_true(on_a_face > 1000);
}

static void test_inside_matches_the_scan(void **state) {
	(void)state;
	hs_shape *box = hs_shape_box(hs_v3(0.3, 0.1, 0.2), NULL);
	hs_shape *l = hs_shape_l_block(hs_v3(3, 1, 2), 1, NULL);
	assert_non_null(box);
	assert_non_null(l);
	inside_as_the_scan(box, 0, 2026);
	inside_as_the_scan(l, 1, 11); // a box beside G
	// a coordinate that is not finite goes to the scan
	assert_false(hs_part_box_takes(hs_v3(NAN, 0.0, 0.0)));
	assert_false(hs_part_box_takes(hs_v3(0.0, INFINITY, 0.0)));
	assert_false(hs_part_box_takes(hs_v3(1e308, 1e308, 0.0))); // the sum overflows
	hs_shape_destroy(box);
	hs_shape_destroy(l);
}

// The nearest face against the scan for points about the part (inside and out, on faces, at ±0);
// returns how many had two faces or more at the least depth (ties, settled by the face index).
static int nearest_as_the_scan(const hs_shape *shape, int part_index, uint64_t seed) {
	const hs_part *part = &shape->parts[part_index];
	hs_part_cache pc = cache_of(shape, part_index);
	uint64_t rng = seed;
	int ties = 0;
	for (int k = 0; k < 100000; ++k) {
		hs_vec3 p = sample(&rng, &pc, 0.0);
		int want = scan_nearest(shape, part, p);
		assert_int_equal(hs_part_box_nearest(&pc, p), want);
		int least = 0;
		for (int f = part->first_face; f < part->first_face + part->face_count; ++f)
			least += shape->faces[f].offset - hs_dot(shape->faces[f].normal, p) ==
			         shape->faces[want].offset - hs_dot(shape->faces[want].normal, p);
		ties += least > 1;
	}
	return ties;
}

static void test_nearest_matches_the_scan(void **state) {
	(void)state;
	hs_shape *box = hs_shape_box(hs_v3(0.3, 0.1, 0.2), NULL);
	hs_shape *cube = hs_shape_box(hs_v3(0.2, 0.2, 0.2), NULL);
	hs_shape *l = hs_shape_l_block(hs_v3(3, 1, 2), 1, NULL);
	assert_non_null(box);
	assert_non_null(cube);
	assert_non_null(l);
	assert_true(nearest_as_the_scan(box, 0, 2027) > 100);
	assert_true(nearest_as_the_scan(cube, 0, 5) > 100);
	assert_true(nearest_as_the_scan(l, 1, 12) > 100);
	// a cube's centre is as deep under all six faces: the first of them; off it along +x, the +x face
	const hs_part *c = &cube->parts[0];
	hs_part_cache cc = cache_of(cube, 0);
	assert_int_equal(hs_part_box_nearest(&cc, hs_v3(0.0, 0.0, 0.0)), c->first_face);
	assert_int_equal(hs_part_box_nearest(&cc, hs_v3(-0.0, -0.0, -0.0)), c->first_face);
	assert_int_equal(hs_part_box_nearest(&cc, hs_v3(0.01, 0.0, 0.0)), cc.box_face[0]);
	assert_int_equal(hs_part_box_nearest(&cc, hs_v3(0.0, 0.0, -0.09)), cc.box_face[5]);
	// on the +x/+y edge's diagonal: the lower of the two faces' indices
	int xy = cc.box_face[0] < cc.box_face[2] ? cc.box_face[0] : cc.box_face[2];
	assert_int_equal(hs_part_box_nearest(&cc, hs_v3(0.05, 0.05, 0.0)), xy);
	assert_int_equal(scan_nearest(cube, c, hs_v3(0.05, 0.05, 0.0)), xy);
	hs_shape_destroy(box);
	hs_shape_destroy(cube);
	hs_shape_destroy(l);
}

static void test_apart_means_the_clip_misses(void **state) {
	(void)state;
	hs_shape *box = hs_shape_box(hs_v3(0.3, 0.1, 0.2), NULL);
	assert_non_null(box);
	const hs_part *part = &box->parts[0];
	hs_part_cache pc = cache_of(box, 0);
	uint64_t rng = 77;
	int apart = 0, hits = 0;
	for (int k = 0; k < 200000; ++k) {
		double grow = k % 2 ? 0.0 : 1e-3;
		hs_vec3 a = sample(&rng, &pc, grow), b = sample(&rng, &pc, grow);
		hs_clip c = hs_clip_segment(box, part, a, b, grow);
		if (hs_part_box_apart(&pc, a, b, grow, SLACK)) {
			++apart;
			assert_false(c.hit);
		}
		hits += c.hit;
	}
	assert_true(apart > 5000);
	assert_true(hits > 20000);
	// beyond the +x face by 1 mm at both ends: apart; by less than the slack: not (the clip decides)
	hs_vec3 a = hs_v3(0.151, -0.2, 0.0), b = hs_v3(0.151, 0.2, 0.0);
	assert_true(hs_part_box_apart(&pc, a, b, 0.0, SLACK));
	assert_false(hs_part_box_apart(&pc, a, b, 2e-3, SLACK)); // grown past them
	a.x = b.x = 0.15 + 0.5 * SLACK;
	assert_false(hs_part_box_apart(&pc, a, b, 0.0, SLACK));
	assert_false(hs_clip_segment(box, part, a, b, 0.0).hit);
	// one end beyond -y, the other across: not apart, and it hits
	a = hs_v3(0.0, -0.2, 0.0);
	b = hs_v3(0.0, 0.2, 0.0);
	assert_false(hs_part_box_apart(&pc, a, b, 0.0, SLACK));
	assert_true(hs_clip_segment(box, part, a, b, 0.0).hit);
	hs_shape_destroy(box);
}

// The box's clip against hs_clip_segment on n segments about part p: every field the same, bit for
// bit (the sampled ends sit on faces, at ±0 and parallel to faces often). Returns the hits.
static int clips_as_the_scan(const hs_shape *shape, int p, uint64_t seed, int n) {
	const hs_part *part = &shape->parts[p];
	hs_part_cache pc = cache_of(shape, p);
	assert_true(hs_part_is_box(&pc));
	uint64_t rng = seed;
	int hits = 0, parallel = 0;
	for (int k = 0; k < n; ++k) {
		double grow = k % 3 == 0 ? 1e-3 : 0.0;
		hs_vec3 a = sample(&rng, &pc, grow), b = k % 5 == 0 ? hs_v3(a.x, sample(&rng, &pc, grow).y, a.z) : sample(&rng, &pc, grow);
		hs_clip want = hs_clip_segment(shape, part, a, b, grow), got = hs_part_box_clip(&pc, part->first_face, a, b, grow);
		assert_int_equal(got.hit, want.hit);
		assert_int_equal(got.face_in, want.face_in);
		assert_int_equal(got.face_out, want.face_out);
		assert_memory_equal(&got.t_in, &want.t_in, sizeof got.t_in);
		assert_memory_equal(&got.t_out, &want.t_out, sizeof got.t_out);
		hits += want.hit;
		parallel += a.x == b.x || a.y == b.y || a.z == b.z;
	}
	assert_true(parallel > n / 10);
	return hits;
}

static void test_clip_matches_the_scan(void **state) {
	(void)state;
	hs_shape *box = hs_shape_box(hs_v3(0.3, 0.1, 0.2), NULL);
	hs_shape *l = hs_shape_l_block(hs_v3(3, 1, 2), 1, NULL);
	assert_non_null(box);
	assert_non_null(l);
	assert_true(clips_as_the_scan(box, 0, 91, 100000) > 10000);
	assert_true(clips_as_the_scan(l, 1, 92, 100000) > 10000); // a part whose faces do not start at 0
	// through the +x and -x faces along the x axis: in at -x, out at +x, at the box's own t
	const hs_part *part = &box->parts[0];
	hs_part_cache pc = cache_of(box, 0);
	hs_clip c = hs_part_box_clip(&pc, part->first_face, hs_v3(-0.3, 0.0, 0.0), hs_v3(0.3, 0.0, 0.0), 0.0);
	assert_true(c.hit);
	assert_int_equal(c.face_in, pc.box_face[1]);
	assert_int_equal(c.face_out, pc.box_face[0]);
	assert_true(c.t_in == 0.25 && c.t_out == 0.75);
	// parallel to the +y face, outside it: a miss at that face
	assert_false(hs_part_box_clip(&pc, part->first_face, hs_v3(-0.3, 0.06, 0.0), hs_v3(0.3, 0.06, 0.0), 0.0).hit);
	hs_shape_destroy(box);
	hs_shape_destroy(l);
}

// Four ends beyond one face by more than the slack: every segment between two of them misses and the
// face's beyond test holds; by less, or with a coordinate that is not finite, they are not beyond.
static void test_four_beyond_a_face(void **state) {
	(void)state;
	hs_shape *box = hs_shape_box(hs_v3(0.3, 0.1, 0.2), NULL);
	assert_non_null(box);
	const hs_part *part = &box->parts[0];
	hs_part_cache pc = cache_of(box, 0);
	uint64_t rng = 93;
	int beyond = 0;
	for (int k = 0; k < 100000; ++k) {
		hs_vec3 q[4], shift = hs_v3(0.0, 0.0, 0.0); // most sets moved off the box along an axis: many beyond
		double *axis = k % 4 == 0 ? &shift.x : k % 4 == 1 ? &shift.y : &shift.z;
		*axis = k % 8 < 4 ? 0.2 : -0.2;
		for (int e = 0; e < 4; ++e)
			q[e] = hs_add(sample(&rng, &pc, 0.0), k % 3 ? shift : hs_v3(0.0, 0.0, 0.0));
		bool any = false;
		for (int f = part->first_face; f < part->first_face + part->face_count; ++f)
			any = any || hs_face_beyond_by(&box->faces[f], q, SLACK);
		assert_int_equal(hs_part_box_beyond4(&pc, q, SLACK), any);
		if (!any)
			continue;
		++beyond;
		for (int i = 0; i < 4; ++i)
			for (int j = i + 1; j < 4; ++j)
				assert_false(hs_clip_segment(box, part, q[i], q[j], 0.0).hit);
	}
	assert_true(beyond > 1000);
	hs_vec3 q[4] = {{0.16, 0.0, 0.0}, {0.16, 0.3, 0.0}, {0.2, -0.3, 0.1}, {0.16, 0.0, -0.4}};
	assert_true(hs_part_box_beyond4(&pc, q, SLACK)); // beyond +x by 1 cm
	q[2].x = 0.15 + 0.5 * SLACK;
	assert_false(hs_part_box_beyond4(&pc, q, SLACK)); // one of them by less than the slack
	q[2].x = 0.2;
	q[3].y = NAN;
	assert_false(hs_part_box_beyond4(&pc, q, SLACK)); // not finite: the caller's scan decides
	assert_int_equal(hs_part_box_beyond_n(&pc, q, 4, SLACK), -1);
	q[3].y = 0.0;
	assert_int_equal(hs_part_box_beyond_n(&pc, q, 4, SLACK), 1);
	assert_int_equal(hs_part_box_beyond_n(&pc, q, 2, SLACK), 1); // the first two alone
	q[1].x = 0.0;
	assert_int_equal(hs_part_box_beyond_n(&pc, q, 4, SLACK), 0); // one of them inside the +x face's plane
	hs_shape_destroy(box);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_finds_boxes),
	    cmocka_unit_test(test_inside_matches_the_scan),
	    cmocka_unit_test(test_nearest_matches_the_scan),
	    cmocka_unit_test(test_apart_means_the_clip_misses),
	    cmocka_unit_test(test_clip_matches_the_scan),
	    cmocka_unit_test(test_four_beyond_a_face),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
