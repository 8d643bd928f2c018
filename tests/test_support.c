// test_support.c — objects on objects: the paper's §4.3 mode and the 'support' mode of DESIGN.md.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "test_util.h"

static hs_world *world_with(hs_stacking stacking) {
	hs_world_def def = hs_default_world_def();
	def.stacking = stacking;
	hs_world *w = hs_world_create(&def, NULL);
	assert_non_null(w);
	return w;
}

static hs_object_id add_box(hs_world *w, hs_vec3 size, hs_vec3 pos) {
	hs_shape *shape = hs_shape_box(size, NULL);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(w, shape, NULL);
	hs_shape_destroy(shape);
	od.position = pos;
	hs_object_id id = hs_world_add_object(w, &od, NULL);
	assert_int_not_equal(id.index1, 0);
	return id;
}

static hs_object_state run(hs_world *w, hs_object_id id, int frames) {
	for (int i = 0; i < frames; ++i)
		hs_world_step(w);
	hs_object_state s;
	assert_int_equal(hs_world_object_state(w, id, &s), HS_OK);
	return s;
}

// Support mode: a cube dropped on a bigger one is rectified onto its top face (§4.2 on a support)
// and rests there exactly: 0.1 + 0.01 = 0.11 m.
static void test_support_rests_on_top(void **state) {
	(void)state;
	hs_world *w = world_with(HS_STACKING_SUPPORT);
	add_box(w, hs_v3(0.1, 0.1, 0.1), hs_v3(0.3, 0, 0.05));
	hs_object_id small = add_box(w, hs_v3(0.02, 0.02, 0.02), hs_v3(0.3, 0, 0.3));
	hs_object_state s = run(w, small, 120);
	assert_true(s.resting);
	assert_near(s.position.z, 0.11, 1e-12);
	assert_near(s.position.x, 0.3, 0);
	hs_world_destroy(w);
}

// Support mode: a plank whose G is over the support rests on it although it overhangs: the
// contact region's corners include edge-edge crossings.
static void test_support_overhang_short_of_edge(void **state) {
	(void)state;
	hs_world *w = world_with(HS_STACKING_SUPPORT);
	add_box(w, hs_v3(0.1, 0.1, 0.1), hs_v3(0.6, 0, 0.05)); // top spans x 0.55..0.65
	hs_object_id plank = add_box(w, hs_v3(0.12, 0.04, 0.02), hs_v3(0.63, 0, 0.3));
	hs_object_state s = run(w, plank, 120);
	assert_true(s.resting);
	assert_near(s.position.z, 0.11, 1e-12);
	assert_near(hs_quat_angle(s.orientation), 0, 0);
	hs_world_destroy(w);
}

// Support mode: G beyond the support's edge: it tips over the edge (rule (2)) and ends leaning on
// the floor and the edge, lower than the top.
static void test_support_overhang_past_edge_tips(void **state) {
	(void)state;
	hs_world *w = world_with(HS_STACKING_SUPPORT);
	add_box(w, hs_v3(0.1, 0.1, 0.1), hs_v3(0.6, 0, 0.05));
	hs_object_id plank = add_box(w, hs_v3(0.12, 0.04, 0.02), hs_v3(0.68, 0, 0.15));
	hs_object_state s = run(w, plank, 180);
	assert_true(s.resting);
	assert_true(s.position.z < 0.1);
	assert_int_equal(s.floor_contacts, 2);
	assert_true(hs_quat_angle(s.orientation) > 30 * HS_PI / 180);
	hs_world_destroy(w);
}

// Paper mode (§4.3): a falling object stops at its first interference with another and, being
// untouched by the hand, ignores gravity from then on: it hangs, sunk by at most one frame's fall.
static void test_paper_mode_stops_at_interference(void **state) {
	(void)state;
	hs_world *w = world_with(HS_STACKING_PAPER);
	add_box(w, hs_v3(0.1, 0.1, 0.1), hs_v3(0.3, 0, 0.05));
	hs_object_id small = add_box(w, hs_v3(0.02, 0.02, 0.02), hs_v3(0.3, 0, 0.3));
	hs_object_state s = run(w, small, 120);
	double v_land = sqrt(2 * 9.81 * (0.3 - 0.11)); // speed when it reaches the top
	assert_true(s.position.z < 0.11);
	assert_true(s.position.z > 0.11 - (v_land + 9.81 / 60) / 60);
	assert_true(s.resting);
	hs_world_destroy(w);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_support_rests_on_top),
	    cmocka_unit_test(test_support_overhang_short_of_edge),
	    cmocka_unit_test(test_support_overhang_past_edge_tips),
	    cmocka_unit_test(test_paper_mode_stops_at_interference),
	};
	return cmocka_run_group_tests_name("support", tests, NULL, NULL);
}
