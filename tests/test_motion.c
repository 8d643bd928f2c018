// test_motion.c — free motion (eq. 3), the floor hull, stability and tipping (1999 paper §4.1-4.2).
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "hs_bench.h"
#include "motion.h"
#include "world_internal.h"
#include "test_util.h"

static hs_world *make_world(double dt, bool skip) {
	hs_world_def def = hs_default_world_def();
	def.dt = dt;
	hs_status st;
	hs_world *w = hs_world_create(&def, &st);
	assert_non_null(w);
	hs_world_set_skip_work(w, skip);
	assert_int_equal(st, HS_OK);
	return w;
}

static hs_shape_id add_box(hs_world *w, double x, double y, double z) {
	hs_status st;
	hs_shape *box = hs_shape_box(hs_v3(x, y, z), &st);
	assert_non_null(box);
	hs_shape_id id = hs_world_add_shape(w, box, &st);
	hs_shape_destroy(box); // the world keeps its own copy
	assert_int_equal(st, HS_OK);
	return id;
}

static hs_object_id add_object(hs_world *w, hs_shape_id shape, hs_vec3 pos, hs_quat rot, hs_vec3 vel) {
	hs_object_def def = hs_default_object_def();
	def.shape = shape;
	def.position = pos;
	def.orientation = rot;
	def.velocity = vel;
	hs_status st;
	hs_object_id id = hs_world_add_object(w, &def, &st);
	assert_int_equal(st, HS_OK);
	assert_int_not_equal(id.index1, 0);
	return id;
}

static hs_object_state state_of(hs_world *w, hs_object_id id) {
	hs_object_state s;
	assert_int_equal(hs_world_object_state(w, id, &s), HS_OK);
	return s;
}

// Eq. 3 started on the exact parabola reproduces P0 + v t + g t²/2 at every frame.
static void test_verlet_matches_closed_form(void **state) {
	(void)state;
	double dts[] = {1.0 / 12, 1.0 / 60, 1.0 / 1000};
	for (int k = 0; k < 3; ++k) {
		double dt = dts[k];
		hs_world *w = make_world(dt, true);
		hs_vec3 p0 = hs_v3(0.5, -1, 1000), v0 = hs_v3(1, 2, 3);
		hs_object_id id = add_object(w, add_box(w, 0.1, 0.1, 0.1), p0, hs_quat_identity(), v0);
		for (int n = 1; n <= 120; ++n) {
			hs_world_step(w);
			double t = n * dt;
			hs_vec3 exact = hs_v3(p0.x + v0.x * t, p0.y + v0.y * t, p0.z + v0.z * t - 0.5 * 9.81 * t * t);
			// exact in real arithmetic; round-off in 2P - P' grows as n² ε |P|
			assert_vec3_near(state_of(w, id).position, exact, (double)(n * n) * 2.3e-16 * 1000);
		}
		hs_world_destroy(w);
	}
}

// §4.1: a released object keeps rotating by its last relative rotation per frame.
static void test_spin_carries_over(void **state) {
	(void)state;
	hs_world *w = make_world(1.0 / 60, true);
	hs_object_def def = hs_default_object_def();
	def.shape = add_box(w, 0.1, 0.1, 0.1);
	def.position = hs_v3(0, 0, 50);
	def.angular_velocity = hs_v3(0, 0, HS_PI / 2); // 90 deg/s about z
	hs_object_id id = hs_world_add_object(w, &def, NULL);
	for (int n = 0; n < 60; ++n)
		hs_world_step(w);
	hs_object_state s = state_of(w, id);
	assert_near(hs_quat_angle(s.orientation), HS_PI / 2, 1e-12);
	assert_vec3_near(hs_quat_rotate(s.orientation, hs_v3(1, 0, 0)), hs_v3(0, 1, 0), 1e-12);
	hs_world_destroy(w);
}

static void test_hull(void **state) {
	(void)state;
	hs_vec2 pts[8] = {{1, 1}, {0, 0}, {0.5, 0.5}, {1, 0}, {0, 1}, {0, 0}, {0.5, 0}, {0.2, 0.7}};
	hs_vec2 hull[9];
	int n = hs_hull_build(pts, 8, hull);
	assert_int_equal(n, 4); // interior, duplicate and collinear points dropped
	double area = 0;
	for (int i = 0; i < n; ++i)
		area += hull[i].x * hull[(i + 1) % n].y - hull[(i + 1) % n].x * hull[i].y;
	assert_near(area / 2, 1.0, 0); // counter-clockwise: positive area
	assert_true(hs_hull_contains(hull, n, (hs_vec2){0.5, 0.5}, 1e-12));
	assert_true(hs_hull_contains(hull, n, (hs_vec2){1.0, 0.5}, 1e-12)); // on the boundary counts
	assert_false(hs_hull_contains(hull, n, (hs_vec2){1.0 + 1e-9, 0.5}, 1e-12));
	int e = hs_hull_nearest_edge(hull, n, (hs_vec2){0.5, -3});
	assert_near(hull[e].y, 0, 0);
	assert_near(hull[(e + 1) % n].y, 0, 0);

	hs_vec2 line[3] = {{2, 2}, {0, 0}, {1, 1}};
	assert_int_equal(hs_hull_build(line, 3, hull), 2); // collinear: a segment
	assert_false(hs_hull_contains(hull, 2, (hs_vec2){1, 1}, 1e-12)); // a segment supports nothing
	hs_vec2 one[2] = {{3, 3}, {3, 3}};
	assert_int_equal(hs_hull_build(one, 2, hull), 1);
}

// Lands in the first frame whose Verlet step reaches the floor, rectified flat, and stops.
static void test_drop_lands_and_sleeps(void **state) {
	(void)state;
	double dt = 1.0 / 60, h = 1.0;
	hs_world *w = make_world(dt, true);
	hs_object_id id = add_object(w, add_box(w, 0.1, 0.1, 0.1), hs_v3(0, 0, h + 0.05), hs_quat_identity(),
	                             hs_v3(0, 0, 0));
	long expected = (long)ceil(sqrt(2 * h / 9.81) / dt); // 28 at 60 frames/s
	long landed = -1;
	for (long n = 1; n <= 60; ++n) {
		hs_world_step(w);
		if (landed < 0 && state_of(w, id).floor_contacts > 0)
			landed = n;
	}
	assert_int_equal(landed, expected);
	hs_object_state s = state_of(w, id);
	assert_int_equal(s.floor_contacts, 4);
	assert_true(s.resting);
	assert_near(s.position.z, 0.05, 1e-15);
	assert_near(s.velocity.z, 0, 0);
	hs_world_counters c = hs_world_get_counters(w);
	assert_true(c.sleeping_skips >= 60 - expected - 1); // asleep after landing: no work
	hs_world_destroy(w);
}

// A box thrown level at 2.5 m/s from 0.5 m lands where its path through the landing frame met the
// floor (docs/model.md §5 "Landing"): x0 + vx (n - f) dt, f the part of frame n's fall that lay
// below the floor; with paper_landing, lifted straight up from where frame n left it, x0 + vx n dt.
static void test_landing_on_the_path(void **state) {
	(void)state;
	const double dt = 1.0 / 12, vx = 2.5, z0 = 0.55, g = 9.81;
	for (int paper = 0; paper <= 1; ++paper) {
		hs_world_def def = hs_default_world_def();
		def.dt = dt;
		def.paper_landing = paper;
		hs_world *w = hs_world_create(&def, NULL);
		assert_non_null(w);
		hs_object_id id = add_object(w, add_box(w, 0.1, 0.1, 0.1), hs_v3(0, 0, z0), hs_quat_identity(), hs_v3(vx, 0, 0));
		int n = 0;
		double z = z0, before = z0;
		while (z - 0.05 >= 0.0) { // the closed form's landing frame
			++n;
			before = z;
			z = z0 - 0.5 * g * (n * dt) * (n * dt);
		}
		for (int k = 0; k < n; ++k)
			assert_int_equal(hs_world_step(w), HS_OK);
		hs_object_state st = state_of(w, id);
		double f = (z - 0.05) / (z - before);
		assert_int_equal(st.floor_contacts, 4);
		assert_near(st.position.x, paper ? vx * n * dt : vx * (n - f) * dt, 1e-12);
		assert_near(st.position.z, 0.05, 1e-15);
		hs_world_destroy(w);
	}
}

// Skipping (bounding spheres, sleeping) saves work but never changes a result.
static void test_skipping_changes_nothing(void **state) {
	(void)state;
	uint64_t hashes[2][200];
	long skipped[2];
	for (int skip = 0; skip < 2; ++skip) {
		hs_world *w = make_world(1.0 / 60, skip != 0);
		hs_shape_id cube = add_box(w, 0.05, 0.05, 0.05), tall = add_box(w, 0.1, 0.1, 0.2);
		for (int i = 0; i < 5; ++i)
			add_object(w, cube, hs_v3(0.1 * i, 0, 0.025), hs_quat_identity(), hs_v3(0, 0, 0));
		add_object(w, cube, hs_v3(0, 1, 0.5), hs_quat_from_rpy(0.3, 0.2, 0.1), hs_v3(1, 0, 0));
		add_object(w, tall, hs_v3(0, 2, 0.1116026), hs_quat_from_rpy(0, 30 * HS_PI / 180, 0), hs_v3(0, 0, 0));
		for (int n = 0; n < 200; ++n) {
			hs_world_step(w);
			hashes[skip][n] = hs_world_hash(w);
		}
		skipped[skip] = hs_world_get_counters(w).sleeping_skips;
		hs_world_destroy(w);
	}
	for (int n = 0; n < 200; ++n)
		assert_true(hashes[0][n] == hashes[1][n]);
	assert_int_equal(skipped[0], 0);
	assert_true(skipped[1] > 5 * 190);
}

static double tip_box(double pitch_deg, hs_vec3 *up_axis_out) {
	hs_world *w = make_world(1.0 / 60, true);
	double p = pitch_deg * HS_PI / 180;
	double z = 0.05 * sin(p) + 0.1 * cos(p); // lowest edge on the floor
	hs_object_id id =
	    add_object(w, add_box(w, 0.1, 0.1, 0.2), hs_v3(0, 0, z), hs_quat_from_rpy(0, p, 0), hs_v3(0, 0, 0));
	assert_int_equal(state_of(w, id).floor_contacts, 2); // set down on an edge
	for (int n = 0; n < 120; ++n)
		hs_world_step(w);
	hs_object_state s = state_of(w, id);
	assert_true(s.resting);
	assert_int_equal(s.floor_contacts, 4);
	*up_axis_out = hs_quat_rotate(s.orientation, hs_v3(0, 0, 1));
	hs_world_destroy(w);
	return s.position.z;
}

// §4.2 rule (2): short of the balance angle atan(w/h) it settles back, past it it falls over.
static void test_tipping_about_an_edge(void **state) {
	(void)state;
	double balance = atan(0.5) * 180 / HS_PI; // 26.565 deg
	hs_vec3 up;
	assert_near(tip_box(balance - 3, &up), 0.1, 1e-9);
	assert_vec3_near(up, hs_v3(0, 0, 1), 1e-9); // standing again
	assert_near(tip_box(balance + 3, &up), 0.05, 1e-9);
	assert_vec3_near(up, hs_v3(1, 0, 0), 1e-9); // lying on its side, top toward +x
}

// A box tipping forward on one corner of its far edge (pitched 20 deg, 6 deg short of its balance
// angle, and rolled 2 deg so one vertex is lowest), G moving over that edge at 0.3 m/s: rule (1)
// turns it about the corner until the edge's second vertex comes down, and it goes on turning about
// the edge (rule (2)) over its balance angle, onto its side. Stopped at that second vertex it
// would settle back upright. Without the motion it settles back upright either way.
static hs_vec3 tip_on_corner(double speed) {
	hs_world *w = make_world(1.0 / 60, true);
	hs_quat rot = hs_quat_mul(hs_quat_from_axis_angle(hs_v3(1, 0, 0), 2 * HS_PI / 180),
	                          hs_quat_from_axis_angle(hs_v3(0, 1, 0), 20 * HS_PI / 180));
	hs_object_id id = add_object(w, add_box(w, 0.1, 0.1, 0.2), hs_v3(0, 0, 0.5), rot, hs_v3(0, 0, 0));
	hs_body *b = &w->state.bodies[0];
	b->pos.z -= hs_motion_pose_vertices(&w->model, &w->scratch, b); // its lowest vertex on the floor
	hs_motion_keep_above_floor(&w->model, &w->scratch, b);
	assert_int_equal(b->floor_contacts, 1);
	hs_vec3 edge = hs_v3(0.05, 0, -0.1), g_dir = hs_normalize(hs_cross(hs_v3(0, 1, 0), hs_quat_rotate(rot, hs_neg(edge))));
	b->prev = hs_sub(b->pos, hs_scale(g_dir, speed / 60)); // G turning about +y over the far edge
	b->grounded = 1;
	b->asleep = 0;
	for (int n = 0; n < 180; ++n)
		hs_world_step(w);
	hs_object_state s = state_of(w, id);
	assert_true(s.resting);
	assert_true(s.floor_contacts >= 3);
	hs_vec3 up = hs_quat_rotate(s.orientation, hs_v3(0, 0, 1));
	hs_world_destroy(w);
	return up;
}

static void test_corner_landing_keeps_turning_about_edge(void **state) {
	(void)state;
	hs_vec3 up = tip_on_corner(0.3);
	assert_true(up.x > 0.99); // on its side, top toward +x
	up = tip_on_corner(0.0);
	assert_true(up.z > 0.99); // upright
}

// §4.2 rule (1): Gm parallel to CG is the well-balanced state: an upright pyramid on its apex stays.
static void test_balanced_on_apex_stays(void **state) {
	(void)state;
	hs_world *w = make_world(1.0 / 60, true);
	hs_status st;
	hs_shape *pyr = hs_shape_pyramid(0.1, 0.1, &st);
	hs_shape_id sid = hs_world_add_shape(w, pyr, &st);
	hs_shape_destroy(pyr);
	hs_quat flip = hs_q(0, 1, 0, 0); // exactly upside down: apex straight below G
	hs_object_id id = add_object(w, sid, hs_v3(0, 0, 0.075), flip, hs_v3(0, 0, 0));
	for (int n = 0; n < 30; ++n)
		hs_world_step(w);
	hs_object_state s = state_of(w, id);
	assert_true(s.resting);
	assert_int_equal(s.floor_contacts, 1);
	assert_near(s.position.z, 0.075, 0);
	hs_world_destroy(w);
}

// A pyramid tilted on its apex falls by rules (1)-(2) and ends on a face.
static void test_pyramid_falls_onto_a_face(void **state) {
	(void)state;
	hs_world *w = make_world(1.0 / 60, true);
	hs_shape *pyr = hs_shape_pyramid(0.1, 0.1, NULL);
	hs_shape_id sid = hs_world_add_shape(w, pyr, NULL);
	hs_shape_destroy(pyr);
	double tilt = 10 * HS_PI / 180;
	hs_object_id id = add_object(w, sid, hs_v3(0, 0, 0.075 * cos(tilt)), hs_quat_from_rpy(HS_PI + tilt, 0, 0),
	                             hs_v3(0, 0, 0));
	for (int n = 0; n < 180; ++n)
		hs_world_step(w);
	hs_object_state s = state_of(w, id);
	assert_true(s.resting);
	assert_true(s.floor_contacts >= 3);
	hs_world_destroy(w);
}

static void test_invalid_input_rejected(void **state) {
	(void)state;
	hs_world_def def = hs_default_world_def();
	def.dt = -1;
	hs_status st;
	assert_null(hs_world_create(&def, &st));
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	def = hs_default_world_def();
	def.gravity.z = NAN;
	assert_null(hs_world_create(&def, &st));
	hs_world *w = make_world(1.0 / 60, true);
	hs_object_def od = hs_default_object_def();
	assert_int_equal(hs_world_add_object(w, &od, &st).index1, 0); // null shape handle
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	od.shape = add_box(w, 1, 1, 1);
	od.position.x = INFINITY;
	assert_int_equal(hs_world_add_object(w, &od, &st).index1, 0);
	od.position.x = 0;
	od.orientation = hs_q(2, 0, 0, 0); // not a unit quaternion
	assert_int_equal(hs_world_add_object(w, &od, &st).index1, 0);
	hs_object_state s;
	hs_object_id bogus = {7, 0, 0};
	assert_int_equal(hs_world_object_state(w, bogus, &s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_step(NULL), HS_ERR_INVALID_ARGUMENT);
	hs_world_destroy(w);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_verlet_matches_closed_form),
	    cmocka_unit_test(test_spin_carries_over),
	    cmocka_unit_test(test_hull),
	    cmocka_unit_test(test_drop_lands_and_sleeps),
	    cmocka_unit_test(test_landing_on_the_path),
	    cmocka_unit_test(test_skipping_changes_nothing),
	    cmocka_unit_test(test_tipping_about_an_edge),
	    cmocka_unit_test(test_corner_landing_keeps_turning_about_edge),
	    cmocka_unit_test(test_balanced_on_apex_stays),
	    cmocka_unit_test(test_pyramid_falls_onto_a_face),
	    cmocka_unit_test(test_invalid_input_rejected),
	};
	return cmocka_run_group_tests_name("motion", tests, NULL, NULL);
}
