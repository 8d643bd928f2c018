// test_cull_keep.c — the hand's bounding-volume culls (contact_cull.c, skip_work) pass over no finger
// part that still counts beyond an object's part: a check point that touched stays touching within
// the release margin, a point or line that started inside stays so within twice it, and at a box's
// corner both reach past the part's bounding sphere. A hand whose check point k starts just inside
// a cube's top corner and backs out along the corner's diagonal, or rests on it and lifts off it,
// gives the same bits every frame with skip_work on and off.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>

#include "hs_bench.h"
#include "handspring.h"
#include "test_util.h"

#define FRAMES 50

static hs_world *cube_world(bool skip_work) {
	hs_world_def def = hs_default_world_def();
	hs_world *w = hs_world_create(&def, NULL);
	assert_non_null(w);
	hs_world_set_skip_work(w, skip_work);
	hs_shape *shape = hs_shape_box(hs_v3(0.05, 0.05, 0.05), NULL);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(w, shape, NULL);
	hs_shape_destroy(shape);
	od.position = hs_v3(0, 0, 0.025);
	assert_int_not_equal(hs_world_add_object(w, &od, NULL).index1, 0);
	hs_hand_def hd = hs_default_hand_def();
	assert_int_not_equal(hs_world_add_hand(w, &hd, NULL).index1, 0);
	return w;
}

// How far check point k is out of the corner along its diagonal at frame f (negative: inside):
// embedded, from 2 mm inside out by 0.4 mm a frame (embedded until 10 mm clear); touching, from
// 3 mm outside in by 0.4 mm a frame for 10 frames, then out again (touching until 5 mm clear).
static double out_at(bool embedded, int f) {
	if (embedded)
		return -0.002 + 0.0004 * f;
	return f < 10 ? 0.003 - 0.0004 * f : -0.001 + 0.0004 * (f - 10);
}

// Check point k near the corner (sx, sy) of the cube's top, moving along the corner's diagonal.
static void corner_run(int k, double sx, double sy, bool embedded, const uint8_t *sensors) {
	hs_world *on = cube_world(true), *off = cube_world(false), *probe = cube_world(true);
	hs_hand_id hand = hs_world_hand_at(probe, 0);
	hs_quat turn = hs_quat_from_rpy(0.0, 0.3, 0.0); // tipped down a little
	assert_int_equal(hs_world_set_hand(probe, hand, hs_v3(0, 0, 0), turn, sensors), HS_OK);
	hs_vec3 points[HS_HAND_POINTS];
	assert_int_equal(hs_world_hand_points(probe, hand, points), HS_OK);
	hs_world_destroy(probe);
	hs_vec3 out = hs_scale(hs_v3(sx, sy, 1.0), 1.0 / sqrt(3.0)), corner = hs_v3(0.025 * sx, 0.025 * sy, 0.05);
	hs_vec3 wrist0 = hs_sub(corner, points[k]);
	hs_world *w[2] = {on, off};
	for (int f = 0; f < FRAMES; ++f) {
		hs_vec3 wrist = hs_mul_add(wrist0, out_at(embedded, f), out);
		for (int i = 0; i < 2; ++i) {
			assert_int_equal(hs_world_set_hand(w[i], hs_world_hand_at(w[i], 0), wrist, turn, sensors), HS_OK);
			assert_int_equal(hs_world_step(w[i]), HS_OK);
		}
		if (hs_world_hash(on) != hs_world_hash(off))
			fail_msg("point %d, corner (%g, %g), %s, frame %d: skip_work on and off differ", k, sx, sy,
			         embedded ? "embedded" : "touching", f + 1);
	}
	hs_world_destroy(on);
	hs_world_destroy(off);
}

static void each_point(bool embedded) {
	hs_hand_def hd = hs_default_hand_def();
	uint8_t sensors[HS_GLOVE_SENSORS];
	assert_int_equal(hs_hand_posture(&hd, HS_POSTURE_GRASP, 0.06, sensors), HS_OK);
	for (int k = 0; k < HS_HAND_POINTS; ++k)
		for (int c = 0; c < 4; ++c)
			corner_run(k, c & 1 ? 1.0 : -1.0, c & 2 ? 1.0 : -1.0, embedded, sensors);
}

static void test_embedded_backing_out_of_a_corner(void **state) {
	(void)state;
	each_point(true);
}

static void test_touching_lifting_off_a_corner(void **state) {
	(void)state;
	each_point(false);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_embedded_backing_out_of_a_corner),
	    cmocka_unit_test(test_touching_lifting_off_a_corner),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
