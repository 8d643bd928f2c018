// test_rig.h — a world of one object and one hand whose check points and lines are parked far
// away, for the tests that place single finger parts themselves (test_contact, test_push).
// Reaches into the world's insides (world_internal.h): model tests only.
#ifndef HS_TEST_RIG_H
#define HS_TEST_RIG_H

#include "test_util.h"
#include "world_internal.h"

#define RIG_FAR hs_v3(100, 100, 100)

// The world of `def` with one object of `shape` (destroyed here) at `position` and one hand,
// placed, its parts at RIG_FAR, its bounding sphere about `hand_center` and its finger radius so
// large that the bounding tests never decide (they are not what these tests are about).
static inline hs_world *rig_world(const hs_world_def *def, hs_shape *shape, hs_vec3 position, hs_vec3 hand_center) {
	// the rig's parts are put in place one by one, not by a hand that closes: a grasp here needs no
	// closing (grasp_close_mm 0); test_grasp_start tests the closing rule with whole hands
	hs_world_def rig = *def;
	rig.grasp_close_mm = 0.0;
	hs_world *w = hs_world_create(&rig, NULL);
	assert_non_null(w);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(w, shape, NULL);
	hs_shape_destroy(shape);
	od.position = position;
	assert_int_equal(hs_world_add_object(w, &od, NULL).index1, 1);
	hs_hand_def hd = hs_default_hand_def();
	assert_int_equal(hs_world_add_hand(w, &hd, NULL).index1, 1);
	hs_hand *hand = &w->state.hands[0];
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		hand->cache.points[i] = hand->cache.prev_points[i] = RIG_FAR;
	hs_hand_points_moved(hand);
	for (int j = 0; j < HS_HAND_LINES; ++j)
		hand->cache.lines[j][0] = hand->cache.lines[j][1] = hand->cache.prev_lines[j][0] = hand->cache.prev_lines[j][1] = RIG_FAR;
	hand->cache.center = hand->cache.prev_center = hand->cache.sweep_center = hand_center;
	hand->cache.radius = hand->cache.prev_radius = hand->cache.sweep_radius = 1000;
	hand->cache.path_steps = 1; // straight paths: hs_hand_sweep (run by hs_manipulate) keeps it so
	// the tests place lines without their segment's check points (a hand's lie finger_radius from
	// them, which contact_cull.c's per-segment culling relies on): a radius so large that it never decides
	hand->model.def.finger_radius = 1000;
	hand->state.placed = true;
	return w;
}

#endif
