// test_joint_hand.c — hands driven by tracked joint positions (docs/model.md §1 "Joint-driven
// hands"): the check points are the joints given, a thumb and an index fingertip closing on a 2 cm
// cube from opposite faces grasp it, carry it and let it go; the state saves and loads with the
// joints; the calls refuse what does not fit the hand.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "hs_harness.h"
#include "test_util.h"

static hs_hand_def joint_def(void) {
	hs_hand_def d = hs_default_hand_def();
	d.joint_driven = true;
	return d;
}

// Points k = 0..3 of a straight chain from b to t.
static void chain(hs_vec3 *p, hs_vec3 b, hs_vec3 t) {
	for (int k = 0; k < 4; ++k)
		p[k] = hs_lerp(b, t, k / 3.0);
}

// A pinching hand in world coordinates, its wrist at `wrist`, the thumb tip `gap` m off the 2 cm
// cube's -x face and the index tip `gap` off its +x face (at the cube's centre height, the cube's
// centre `up` m above (0, 0, 0.01)); the other three fingers well above and beside the cube.
static void pinch_points(double gap, double up, hs_vec3 wrist, hs_vec3 local[HS_HAND_POINTS]) {
	hs_vec3 p[HS_HAND_POINTS], c = hs_v3(0.0, 0.0, 0.01 + up);
	chain(&p[0], hs_add(c, hs_v3(-0.06, 0.0, 0.07)), hs_add(c, hs_v3(-0.01 - gap, 0.0, 0.0)));
	chain(&p[4], hs_add(c, hs_v3(0.06, 0.0, 0.07)), hs_add(c, hs_v3(0.01 + gap, 0.0, 0.0)));
	for (int f = 2; f < 5; ++f)
		chain(&p[4 * f], hs_add(c, hs_v3(0.0, 0.03 + 0.02 * f, 0.08)), hs_add(c, hs_v3(0.02, 0.03 + 0.02 * f, 0.05)));
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		local[i] = hs_sub(p[i], wrist);
}

typedef struct pinch_run {
	hs_world *world;
	hs_hand_id hand;
	hs_object_id cube;
} pinch_run;

static pinch_run pinch_world(void) {
	pinch_run r;
	hs_world_def wd = hs_default_world_def();
	r.world = hs_world_create(&wd, NULL);
	assert_non_null(r.world);
	hs_shape *cube = hs_shape_box(hs_v3(0.02, 0.02, 0.02), NULL);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(r.world, cube, NULL);
	hs_shape_destroy(cube);
	od.position = hs_v3(0.0, 0.0, 0.01);
	r.cube = hs_world_add_object(r.world, &od, NULL);
	hs_hand_def hd = joint_def();
	r.hand = hs_world_add_hand(r.world, &hd, NULL);
	assert_int_not_equal(r.hand.index1, 0);
	return r;
}

// Frame f of the script: close (0-29: gap 20 mm to -1 mm), hold (30-44), lift 5 cm (45-74),
// open in place (75-89: gap back to 20 mm), hold (90-119).
static void pinch_frame(const pinch_run *r, int f) {
	double gap = f < 30 ? 0.02 - 0.021 * f / 29.0 : f < 75 ? -0.001 : f < 90 ? -0.001 + 0.021 * (f - 75) / 14.0 : 0.02;
	double up = f < 45 ? 0.0 : f < 75 ? 0.05 * (f - 45) / 29.0 : 0.05;
	hs_vec3 wrist = hs_v3(-0.1, 0.0, 0.12 + up), local[HS_HAND_POINTS];
	pinch_points(gap, up, wrist, local);
	assert_int_equal(hs_world_set_hand_joints(r->world, r->hand, wrist, hs_quat_identity(), local), HS_OK);
	assert_int_equal(hs_world_step(r->world), HS_OK);
}

static hs_object_state cube_state(const pinch_run *r) {
	hs_object_state s;
	assert_int_equal(hs_world_object_state(r->world, r->cube, &s), HS_OK);
	return s;
}

// The tips close on the cube's side faces: a grasp; the lift carries it 5 cm; the tips opening
// let it go and it falls back to the floor, upright where it was.
static void test_joint_pinch_grasps_carries_releases(void **state) {
	(void)state;
	pinch_run r = pinch_world();
	int grasped_from = -1;
	for (int f = 0; f < 120; ++f) {
		pinch_frame(&r, f);
		hs_object_state s = cube_state(&r);
		if (grasped_from < 0 && s.contact == HS_CONTACT_GRASP)
			grasped_from = f;
		if (f == 74) {
			assert_int_equal(s.contact, HS_CONTACT_GRASP);
			assert_near(s.position.z, 0.06, 1e-9);
		}
	}
	assert_true(grasped_from > 20 && grasped_from < 30); // the tips reach the faces at frame 27
	hs_object_state s = cube_state(&r);
	assert_int_equal(s.contact, HS_CONTACT_NONE);
	assert_near(s.position.z, 0.01, 1e-9);
	assert_near(s.position.x, 0.0, 1e-9);
	assert_true(s.resting);
	hs_world_destroy(r.world);
}

// The check points are the joints given, placed by the wrist pose: the same bits as the glove
// hand's kinematics when given that hand's own points.
static void test_joint_points_are_the_joints(void **state) {
	(void)state;
	hs_world_def wd = hs_default_world_def();
	hs_world *w = hs_world_create(&wd, NULL);
	hs_hand_def glove = hs_default_hand_def(), joints = joint_def();
	hs_hand_id g = hs_world_add_hand(w, &glove, NULL), j = hs_world_add_hand(w, &joints, NULL);
	uint8_t s[HS_GLOVE_SENSORS];
	assert_int_equal(hs_hand_posture(&glove, HS_POSTURE_PINCH, 0.6, s), HS_OK);
	hs_vec3 local[HS_HAND_POINTS], wrist = hs_v3(0.1, -0.2, 0.3), a[HS_HAND_POINTS], b[HS_HAND_POINTS];
	hs_quat rot = hs_quat_from_rpy(0.1, -0.4, 0.7);
	hs_hand_kinematics(&glove, hs_v3(0, 0, 0), hs_quat_identity(), s, local, NULL);
	assert_int_equal(hs_world_set_hand(w, g, wrist, rot, s), HS_OK);
	assert_int_equal(hs_world_set_hand_joints(w, j, wrist, rot, local), HS_OK);
	assert_int_equal(hs_world_hand_points(w, g, a), HS_OK);
	assert_int_equal(hs_world_hand_points(w, j, b), HS_OK);
	assert_memory_equal(a, b, sizeof a);
	hs_world_destroy(w);
}

// Saved mid-carry and loaded into a fresh world built the same way, the run goes on to the same
// bits; a glove hand's world refuses the state.
static void test_joint_state_round_trip(void **state) {
	(void)state;
	pinch_run a = pinch_world(), b = pinch_world();
	for (int f = 0; f < 60; ++f)
		pinch_frame(&a, f);
	size_t n = hs_world_state_size(a.world);
	void *buf = malloc(n);
	assert_non_null(buf);
	assert_int_equal(hs_world_save_state(a.world, buf, n), HS_OK);
	assert_int_equal(hs_world_load_state(b.world, buf, n), HS_OK);
	assert_int_equal(hs_world_hash(a.world), hs_world_hash(b.world));
	for (int f = 60; f < 120; ++f) {
		pinch_frame(&a, f);
		pinch_frame(&b, f);
	}
	assert_int_equal(hs_world_hash(a.world), hs_world_hash(b.world));
	hs_world_def wd = hs_default_world_def();
	hs_world *glove = hs_world_create(&wd, NULL);
	hs_shape *cube = hs_shape_box(hs_v3(0.02, 0.02, 0.02), NULL);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(glove, cube, NULL);
	hs_shape_destroy(cube);
	od.position = hs_v3(0.0, 0.0, 0.01);
	hs_world_add_object(glove, &od, NULL);
	hs_hand_def hd = hs_default_hand_def();
	hs_world_add_hand(glove, &hd, NULL);
	assert_int_not_equal(hs_world_load_state(glove, buf, n), HS_OK);
	free(buf);
	hs_world_destroy(glove);
	hs_world_destroy(a.world);
	hs_world_destroy(b.world);
}

static void test_joint_invalid_arguments(void **state) {
	(void)state;
	pinch_run r = pinch_world();
	hs_vec3 local[HS_HAND_POINTS], wrist = hs_v3(-0.1, 0.0, 0.12);
	pinch_points(0.02, 0.0, wrist, local);
	uint8_t s[HS_GLOVE_SENSORS] = {0};
	assert_int_equal(hs_world_set_hand(r.world, r.hand, wrist, hs_quat_identity(), s), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_hand_joints(r.world, r.hand, wrist, hs_quat_identity(), NULL), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_set_hand_joints(r.world, r.hand, wrist, hs_q(2, 0, 0, 0), local), HS_ERR_INVALID_ARGUMENT);
	local[7].x = NAN;
	assert_int_equal(hs_world_set_hand_joints(r.world, r.hand, wrist, hs_quat_identity(), local), HS_ERR_INVALID_ARGUMENT);
	local[7].x = 2.0 * HS_MAX_COORDINATE;
	assert_int_equal(hs_world_set_hand_joints(r.world, r.hand, wrist, hs_quat_identity(), local), HS_ERR_INVALID_ARGUMENT);
	hs_hand_def glove = hs_default_hand_def();
	hs_hand_id g = hs_world_add_hand(r.world, &glove, NULL);
	pinch_points(0.02, 0.0, wrist, local);
	assert_int_equal(hs_world_set_hand_joints(r.world, g, wrist, hs_quat_identity(), local), HS_ERR_INVALID_ARGUMENT);
	hs_world_destroy(r.world);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_joint_pinch_grasps_carries_releases),
	    cmocka_unit_test(test_joint_points_are_the_joints),
	    cmocka_unit_test(test_joint_state_round_trip),
	    cmocka_unit_test(test_joint_invalid_arguments),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
