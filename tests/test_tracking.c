// test_tracking.c — a hand the tracker loses and finds again, through the public API
// (model/hand/tracking.c; docs/model.md §3 "Tracking loss").
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "handspring.h"
#include "test_util.h"

// A 5 cm cube on the floor at the origin and a right hand (rpy 0) whose grasp posture is set to
// `width` with its grip point (hs_hand_grip) at `grip`.
typedef struct rig {
	hs_world *w;
	hs_object_id cube;
	hs_hand_id hand;
	hs_hand_def def;
} rig;

static rig make_rig(void) {
	rig r;
	hs_world_def wd = hs_default_world_def();
	r.w = hs_world_create(&wd, NULL);
	assert_non_null(r.w);
	hs_object_def od = hs_default_object_def();
	hs_shape *cube = hs_shape_box(hs_v3(0.05, 0.05, 0.05), NULL);
	od.shape = hs_world_add_shape(r.w, cube, NULL);
	hs_shape_destroy(cube);
	od.position = hs_v3(0, 0, 0.025);
	r.cube = hs_world_add_object(r.w, &od, NULL);
	r.def = hs_default_hand_def();
	r.hand = hs_world_add_hand(r.w, &r.def, NULL);
	return r;
}

static void set_grip(rig *r, hs_vec3 grip, double width, bool tracked) {
	uint8_t s[HS_GLOVE_SENSORS];
	assert_int_equal(hs_hand_posture(&r->def, HS_POSTURE_GRASP, width, s), HS_OK);
	hs_vec3 center, axis;
	hs_hand_grip(&r->def, s, &center, &axis);
	assert_int_equal(hs_world_set_hand(r->w, r->hand, hs_sub(grip, center), hs_quat_identity(), s), HS_OK);
	assert_int_equal(hs_world_set_hand_tracked(r->w, r->hand, tracked), HS_OK);
	assert_int_equal(hs_world_step(r->w), HS_OK);
}

static hs_object_state cube_state(const rig *r) {
	hs_object_state st;
	assert_int_equal(hs_world_object_state(r->w, r->cube, &st), HS_OK);
	return st;
}

// Open above the cube, down beside it, close on it (a grasp), lift it 0.2 m.
static void grasp_and_lift(rig *r) {
	for (int k = 0; k <= 30; ++k)
		set_grip(r, hs_v3(0.004, 0, 0.193 - 0.15 * k / 30.0), 0.12, true);
	for (int k = 1; k <= 6; ++k)
		set_grip(r, hs_v3(0.004 - 0.004 * k / 6.0, 0, 0.043), 0.12 - 0.085 * k / 6.0, true);
	assert_int_equal(cube_state(r).contact, HS_CONTACT_GRASP);
	for (int k = 1; k <= 30; ++k)
		set_grip(r, hs_v3(0, 0, 0.043 + 0.2 * k / 30.0), 0.035, true);
	assert_true(cube_state(r).position.z > 0.2); // lifted with the hand
}

// Lost for 0.2 s (12 frames at 60 frames/s) the hand, held where it was last seen, keeps the
// cube; the 13th frame lost it lets it go in place: it drops straight down (no fling) and lands
// where it was, the hand touching nothing (its fingers are still around it).
static void test_lost_hand_keeps_then_drops(void **state) {
	(void)state;
	rig r = make_rig();
	grasp_and_lift(&r);
	hs_vec3 at = cube_state(&r).position;
	for (int k = 1; k <= 12; ++k) {
		set_grip(&r, hs_v3(0, 0, 0.243), 0.035, false);
		assert_int_equal(cube_state(&r).contact, HS_CONTACT_GRASP);
	}
	set_grip(&r, hs_v3(0, 0, 0.243), 0.035, false);
	hs_object_state st = cube_state(&r);
	assert_int_equal(st.contact, HS_CONTACT_NONE);
	assert_near(st.velocity.x, 0.0, 1e-12);
	assert_near(st.velocity.y, 0.0, 1e-12);
	for (int k = 0; k < 60; ++k)
		set_grip(&r, hs_v3(0, 0, 0.243), 0.035, false);
	st = cube_state(&r); // straight down: held a little tilted, it settles flat, G moving < 1 mm
	assert_near(st.position.x, at.x, 1e-3);
	assert_near(st.position.y, at.y, 1e-3);
	assert_near(st.position.z, 0.025, 1e-9);
	assert_true(st.resting);
	hs_world_destroy(r.w);
}

// Grasps and lifts the cube, loses the hand for 5 frames where it was last seen, finds it again
// with its grip at `found`; returns where the cube was before the loss in *at.
static hs_object_state lost_and_found(rig *r, hs_vec3 found, hs_vec3 *at) {
	grasp_and_lift(r);
	*at = cube_state(r).position;
	for (int k = 1; k <= 5; ++k)
		set_grip(r, hs_v3(0, 0, 0.243), 0.035, false);
	set_grip(r, found, 0.035, true);
	return cube_state(r);
}

// Lost for 5 frames and found 20 cm away (beyond 5 cm + 0.5 m/s x 0.1 s): the grasp it kept is
// let go in place (the cube would have jumped with it), and the jump drags and flings nothing.
static void test_found_far_lets_go_in_place(void **state) {
	(void)state;
	rig r = make_rig();
	hs_vec3 at;
	hs_object_state st = lost_and_found(&r, hs_v3(0.2, 0, 0.243), &at);
	assert_int_not_equal(st.contact, HS_CONTACT_GRASP);
	assert_near(st.position.x, at.x, 1e-12);
	assert_near(st.velocity.x, 0.0, 1e-12);
	hs_world_destroy(r.w);
}

// Found again near where it was lost, within the hold: the grasp goes on.
static void test_found_near_keeps(void **state) {
	(void)state;
	rig r = make_rig();
	hs_vec3 at;
	hs_object_state st = lost_and_found(&r, hs_v3(0.01, 0, 0.243), &at);
	assert_int_equal(st.contact, HS_CONTACT_GRASP);
	assert_near(st.position.x, at.x + 0.01, 1e-9);
	hs_world_destroy(r.w);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_lost_hand_keeps_then_drops),
	    cmocka_unit_test(test_found_far_lets_go_in_place),
	    cmocka_unit_test(test_found_near_keeps),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
