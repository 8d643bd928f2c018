// test_push.c — a push at one point on an object lying on the floor (1999 paper eq. 1-2
// under §4.2, docs/model.md §4 "Pushing an object on the floor"), against closed forms.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "manipulate.h"
#include "motion.h"
#include "push.h"
#include "world_internal.h"
#include "test_rig.h"

#define FAR RIG_FAR

// A box of the given size flat on the floor (G at half its height) and one hand whose parts are
// all far away until a test puts one of them somewhere.
static hs_world *box_world(hs_vec3 size) {
	hs_world_def def = hs_default_world_def();
	def.dt = 1.0 / 60;
	hs_world *w = rig_world(&def, hs_shape_box(size, NULL), hs_v3(0, 0, 0.5 * size.z), hs_v3(0, 0, 0));
	hs_motion_keep_above_floor(&w->model, &w->scratch, &w->state.bodies[0]); // floor contacts of the initial pose
	return w;
}

// Free motion's parts of w, for the push functions (made at each call: one world at a time).
static const hs_motion_pass *motion_of(hs_world *w) {
	static hs_motion_pass m;
	m = hs_motion_pass_of(w);
	return &m;
}

static double lowest_z(hs_world *w) { return hs_motion_pose_vertices(&w->model, &w->scratch, &w->state.bodies[0]); }

// (a) A still fingertip 1 mm into the top of a 10 cm box on the floor (it came down onto it in the
// first frame), at several offsets from the centre, for 30 frames through the whole hand pass (detection, classification, push, §4.2
// rectification): the pose keeps its bits (off both axes, eq. 2's yaw about the vertical is
// rounding, 1e-16 rad, and G moves by 1e-20 m). Eq. 1-2 alone would turn the box about G (checked).
static void test_press_down_leaves_box(void **state) {
	(void)state;
	const double offsets[][2] = {{0, 0}, {0.04, 0}, {0, -0.03}, {0.04, 0.03}, {-0.049, 0.02}};
	for (size_t k = 0; k < sizeof offsets / sizeof offsets[0]; ++k) {
		hs_world *w = box_world(hs_v3(0.1, 0.1, 0.1));
		hs_body *b = &w->state.bodies[0];
		hs_vec3 tip = hs_v3(offsets[k][0], offsets[k][1], 0.099);
		for (int frame = 0; frame < 30; ++frame) { // it came down onto the box in frame 0, then stays
			w->state.hands[0].cache.prev_points[7] = frame == 0 ? hs_add(tip, hs_v3(0, 0, 0.01)) : tip;
			w->state.hands[0].cache.points[7] = tip;
			hs_hand_points_moved(&w->state.hands[0]);
			hs_manipulate(w);
			assert_int_equal(b->contact, HS_CONTACT_PUSH_ONE);
			assert_vec3_near(b->pos, hs_v3(0, 0, 0.05), 1e-18); // off both axes: rounding of the yaw
			assert_near(hs_quat_angle(b->rot), 0.0, 1e-15);
			assert_true(b->pos.z == 0.05);                      // never lifted, never sunk
			if (offsets[k][0] == 0.0 || offsets[k][1] == 0.0) { // on an axis: the bits stay
				assert_true(b->pos.x == 0.0 && b->pos.y == 0.0);
				assert_true(b->rot.w == 1.0 && b->rot.x == 0.0 && b->rot.y == 0.0 && b->rot.z == 0.0);
			}
			assert_int_equal(b->floor_contacts, 4);
		}
		hs_world_destroy(w);
	}
	hs_world *w = box_world(hs_v3(0.1, 0.1, 0.1)); // a fingertip that starts there touches nothing
	w->state.hands[0].cache.prev_points[7] = w->state.hands[0].cache.points[7] = hs_v3(0.04, 0, 0.099);
	hs_hand_points_moved(&w->state.hands[0]);
	hs_manipulate(w);
	assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_NONE);
	hs_world_destroy(w);
	hs_body free_box = {.pos = hs_v3(0, 0, 0.05), .rot = hs_quat_identity()};
	hs_push_at_one_point(&free_box, hs_v3(0.04, 0, 0.1), hs_v3(0.04, 0, 0.099));
	assert_true(hs_quat_angle(free_box.rot) > 1e-3); // what the floor rule prevents
}

// (b) A horizontal push at the side below G: eq. 2's turn would sink the near bottom edge (the
// push's torque about it does not lift the box), so the box slides by the finger's horizontal
// motion: G + (d, 0, 0), z and orientation unchanged to the bit.
static void test_push_low_slides(void **state) {
	(void)state;
	const double heights[] = {0.001, 0.01, 0.02, 0.035, 0.049};
	for (size_t k = 0; k < sizeof heights / sizeof heights[0]; ++k) {
		hs_world *w = box_world(hs_v3(0.1, 0.1, 0.1));
		hs_body *b = &w->state.bodies[0];
		double d = 0.002;
		for (int frame = 1; frame <= 10; ++frame) {
			hs_vec3 c = hs_v3(b->pos.x - 0.05, 0, heights[k]);
			assert_true(hs_push_on_floor(motion_of(w), b, c, hs_add(c, hs_v3(d, 0, 0))));
			assert_near(b->pos.x, frame * d, 1e-15);
			assert_true(b->pos.y == 0.0 && b->pos.z == 0.05);
			assert_true(b->rot.w == 1.0 && b->rot.x == 0.0 && b->rot.y == 0.0 && b->rot.z == 0.0);
		}
		hs_world_destroy(w);
	}
}

// (c) A horizontal push high on the side of a tall box (0.1 x 0.1 x 0.3, G = (0, 0, 0.15)) at
// C = (-0.05, 0, 0.25), CB = (d, 0, 0). Eq. 1: CG = (0.05, 0, -0.1), T = (CB·CG/|CG|²) CG,
// R = CB - T; eq. 2's turn about R x CG ∥ +y would sink the far (+x) bottom edge; the push's
// torque about that edge, (PC x CB)·y = 0.25 d > 0, lifts the box, so it tips about that edge
// (after T's horizontal part slid it) by θ = atan(((PC x R)·y) / |PC|²), PC = (-0.1, 0, 0.25)
// from the edge to C: eq. 2's form atan(|R'| / |PC|) about the edge.
static void test_push_high_tips(void **state) {
	(void)state;
	hs_world *w = box_world(hs_v3(0.1, 0.1, 0.3));
	hs_body *b = &w->state.bodies[0];
	double d = 0.002;
	hs_vec3 c = hs_v3(-0.05, 0, 0.25), cg = hs_v3(0.05, 0, -0.1);
	hs_vec3 t = hs_scale(cg, d * 0.05 / 0.0125);
	hs_vec3 r = hs_sub(hs_v3(d, 0, 0), t);
	double theta = atan((0.25 * r.x + 0.1 * r.z) / 0.0725);
	assert_true(hs_push_on_floor(motion_of(w), b, c, hs_add(c, hs_v3(d, 0, 0))));
	hs_vec3 pivot = hs_v3(0.05 + t.x, 0, 0);
	hs_vec3 g = hs_add(pivot, hs_v3(-0.05 * cos(theta) + 0.15 * sin(theta), 0,
	                                0.05 * sin(theta) + 0.15 * cos(theta)));
	assert_vec3_near(b->pos, g, 1e-15);
	assert_near(hs_quat_angle(b->rot), theta, 1e-14);
	assert_true(b->rot.y > 0.0 && b->rot.x == 0.0 && b->rot.z == 0.0); // about +y: the top goes forward
	assert_true(lowest_z(w) >= -1e-15);                                 // the far edge stays on the floor
	assert_near(lowest_z(w), 0.0, 1e-15);
	// keep pushing: it goes on tipping about the same edge, never below the floor
	double last = hs_quat_angle(b->rot);
	for (int frame = 0; frame < 20; ++frame) {
		hs_vec3 top = hs_add(b->pos, hs_quat_rotate(b->rot, hs_v3(-0.05, 0, 0.1)));
		assert_true(hs_push_on_floor(motion_of(w), b, top, hs_add(top, hs_v3(d, 0, 0))));
		hs_motion_keep_above_floor(&w->model, &w->scratch, b);
		assert_true(lowest_z(w) >= -1e-12);
		assert_true(hs_quat_angle(b->rot) > last);
		last = hs_quat_angle(b->rot);
	}
	hs_world_destroy(w);
}

// Off the floor the rule does not apply: eq. 1-2 for a free object.
// (e) The floor's friction cone: a push that presses a box on the floor down at least 1/μ times as
// much as it drives it sideways leaves it (pose to the bit), at one point and at several; outside
// the cone the one point rule above applies and the several points slide it along the floor.
static void test_press_within_floor_cone_holds(void **state) {
	(void)state;
	assert_true(HS_PUSH_FRICTION == 1.0);
	hs_world *w = box_world(hs_v3(0.1, 0.1, 0.1));
	hs_body *b = &w->state.bodies[0];
	hs_vec3 c = hs_v3(0.04, 0.01, 0.1);
	assert_true(hs_push_on_floor(motion_of(w), b, c, hs_add(c, hs_v3(0.0012, -0.0009, -0.0015)))); // |h| = 0.0015
	assert_true(b->pos.x == 0.0 && b->pos.y == 0.0 && b->pos.z == 0.05);
	assert_true(b->rot.w == 1.0 && b->rot.x == 0.0 && b->rot.y == 0.0 && b->rot.z == 0.0);
	hs_push_many(motion_of(w), b, hs_v3(0.001, 0, -0.002));
	assert_true(b->pos.x == 0.0 && b->pos.y == 0.0 && b->pos.z == 0.05);
	hs_push_many(motion_of(w), b, hs_v3(0.003, 0, -0.002));
	assert_true(b->pos.x == 0.003 && b->pos.y == 0.0 && b->pos.z == 0.05);
	assert_true(hs_push_on_floor(motion_of(w), b, c, hs_add(c, hs_v3(0.002, 0, -0.001))));
	assert_true(b->pos.x != 0.003 || hs_quat_angle(b->rot) > 0.0); // outside the cone it acts
	hs_world_destroy(w);
}

// (f) A push at one point that began in the frame moved the object over the part of the frame
// after the finger reached it (hs_contact.t): the pose a frame ago that eq. 3 continues from makes
// the velocity that motion over that time, and the spin that turn over it (1 / (1 - t), at most
// 4), so a flick flies on at the finger's speed at any frame rate. An object already moving is
// remembered as pushed (pos - prev is the push).
static void test_push_remembers_finger_speed(void **state) {
	(void)state;
	const double from[] = {-0.06, -0.0675, -0.0695, -0.06};
	const double speedup[] = {2.0, 8.0, 10.0, 2.0}; // reached at t = 0.5, 0.875, 0.975 (capped), off centre
	for (int k = 0; k < 4; ++k) {
		hs_world *w = box_world(hs_v3(0.1, 0.1, 0.1));
		hs_body *b = &w->state.bodies[0];
		b->prev = b->pos; // at rest
		double y = k == 3 ? 0.03 : 0.0;
		w->state.hands[0].cache.prev_points[7] = hs_v3(from[k], y, 0.05); // at G's height: slides, no swing
		w->state.hands[0].cache.points[7] = hs_v3(from[k] + 0.02, y, 0.05);
		hs_hand_points_moved(&w->state.hands[0]);
		hs_manipulate(w);
		assert_int_equal(b->contact, HS_CONTACT_PUSH_ONE);
		hs_vec3 moved = hs_sub(b->pos, hs_v3(0, 0, 0.05));
		assert_true(moved.x > 0.0);
		assert_vec3_near(hs_sub(b->pos, b->prev), hs_scale(moved, speedup[k]), 1e-15);
		double turn = hs_quat_angle(b->rot), spin = hs_quat_angle(hs_quat_mul(b->rot, hs_quat_conj(b->rot_prev)));
		assert_near(spin, speedup[k] * turn, 1e-12);
		assert_true(k < 3 ? turn == 0.0 : turn > 0.01);
		hs_world_destroy(w);
	}
	hs_world *w = box_world(hs_v3(0.1, 0.1, 0.1)); // moving already: pos - prev is the push
	hs_body *b = &w->state.bodies[0];
	b->prev = hs_v3(-0.001, 0, 0.05);
	w->state.hands[0].cache.prev_points[7] = hs_v3(-0.06, 0, 0.05);
	w->state.hands[0].cache.points[7] = hs_v3(-0.04, 0, 0.05);
	hs_hand_points_moved(&w->state.hands[0]);
	hs_manipulate(w);
	assert_vec3_near(b->prev, hs_v3(0, 0, 0.05), 0.0);
	hs_world_destroy(w);
}

// (g) An object touching the floor at one vertex lies on it: a push at several points with an
// upward part slides it along the floor, never lifts it (it used to fly off on the push's rise).
static void test_push_on_a_corner_keeps_floor(void **state) {
	(void)state;
	hs_world *w = box_world(hs_v3(0.1, 0.1, 0.1));
	hs_body *b = &w->state.bodies[0];
	hs_quat tilt = hs_quat_mul(hs_quat_from_axis_angle(hs_v3(1, 0, 0), 0.1), hs_quat_from_axis_angle(hs_v3(0, 1, 0), 0.1));
	b->rot = hs_quat_normalize(tilt);
	b->pos = hs_v3(0, 0, 0.2);
	b->pos.z -= hs_motion_pose_vertices(&w->model, &w->scratch, b); // its lowest vertex on the floor
	hs_motion_keep_above_floor(&w->model, &w->scratch, b);
	assert_int_equal(b->floor_contacts, 1);
	hs_vec3 at = b->pos;
	hs_push_many(motion_of(w), b, hs_v3(0.002, 0.001, 0.003));
	assert_true(b->pos.x == at.x + 0.002 && b->pos.y == at.y + 0.001 && b->pos.z == at.z);
	hs_world_destroy(w);
}

// (g2) A push above G that also yaws the box (C off the centre line, eq. 2's yaw about the vertical)
// tips it about the floor edge it stands on after that yaw, not about eq. 2's horizontal axis
// through its furthest floor vertex, which lies a few degrees off that edge: both vertices of the
// far edge stay on the floor (two floor contacts, the lowest exactly on it) frame after frame.
static void test_skewed_push_tips_about_floor_edge(void **state) {
	(void)state;
	hs_world *w = box_world(hs_v3(0.1, 0.1, 0.3));
	hs_body *b = &w->state.bodies[0];
	for (int frame = 0; frame < 10; ++frame) {
		hs_vec3 c = hs_add(b->pos, hs_quat_rotate(b->rot, hs_v3(-0.05, 0.03, 0.1)));
		assert_true(hs_push_on_floor(motion_of(w), b, c, hs_add(c, hs_v3(0.002, 0.0, 0.0))));
		hs_motion_keep_above_floor(&w->model, &w->scratch, b);
		assert_int_equal(b->floor_contacts, 2);
		assert_near(lowest_z(w), 0.0, 1e-15);
	}
	hs_vec3 up = hs_quat_rotate(b->rot, hs_v3(0, 0, 1));
	assert_true(up.x > 0.05);                    // tipped forward about its far edge
	assert_true(hs_quat_rotate(b->rot, hs_v3(1, 0, 0)).y < 0.0); // and yawed: the pushed +y side went ahead
	hs_world_destroy(w);
}

// (h) A push that ends leaves an object lying stable on the floor where it is ([H] §4.1: no
// sliding; §4.2 judged as on landing): a box slid 1 mm a frame at G's height (G' 1.8 cm ahead of G
// with Gm = (0.001, 0, -g dt²), inside its base) stops when the tip draws back, instead of flying
// on a frame by eq. 3. A box standing on an edge (G' beyond its one-edge hull) is not stopped.
static void test_push_end_stops_on_floor(void **state) {
	(void)state;
	hs_world *w = box_world(hs_v3(0.1, 0.1, 0.1));
	hs_body *b = &w->state.bodies[0];
	b->prev = hs_v3(-0.001, 0, 0.05); // moving already: no speed-up of the remembered motion
	w->state.hands[0].cache.prev_points[7] = hs_v3(-0.0505, 0, 0.05);
	w->state.hands[0].cache.points[7] = hs_v3(-0.049, 0, 0.05);
	hs_hand_points_moved(&w->state.hands[0]);
	hs_manipulate(w);
	assert_int_equal(b->contact, HS_CONTACT_PUSH_ONE);
	assert_vec3_near(b->pos, hs_v3(0.001, 0, 0.05), 1e-15);
	hs_vec3 at = b->pos;
	w->state.hands[0].cache.prev_points[7] = w->state.hands[0].cache.points[7];
	w->state.hands[0].cache.points[7] = hs_v3(-0.08, 0, 0.05); // drawn back
	hs_hand_points_moved(&w->state.hands[0]);
	hs_manipulate(w);
	assert_int_equal(b->contact, HS_CONTACT_NONE);
	assert_true(b->pos.x == at.x && b->pos.y == at.y && b->pos.z == at.z);
	assert_true(b->prev.x == at.x && b->prev.y == at.y && b->prev.z == at.z); // no inertia left
	assert_true(b->grounded == 1 && b->asleep == 1);
	assert_near(hs_quat_angle(b->spin), 0.0, 0.0);
	hs_world_destroy(w);

	w = box_world(hs_v3(0.1, 0.1, 0.1)); // on its edge x = 0.05, G over x = 0.05 - 0.0707 sin(45 - 20 deg)
	b = &w->state.bodies[0];
	b->rot = hs_quat_from_axis_angle(hs_v3(0, 1, 0), -0.349);
	b->pos = hs_v3(0, 0, 0.2);
	b->pos.z -= hs_motion_pose_vertices(&w->model, &w->scratch, b);
	hs_motion_keep_above_floor(&w->model, &w->scratch, b);
	assert_int_equal(b->floor_contacts, 2);
	b->prev = b->pos;
	assert_false(hs_push_release_on_floor(motion_of(w), b, false)); // after a one-point push: eq. 3 carries it on
	hs_world_destroy(w);
}

// (h2) A push at several points that ends with the box a hair up on its floor edge (tilted 0.004
// deg about y, moving 1 cm a frame along +x) leaves it on the floor: rules (1)-(3) turn it back onto
// its face where it is, turned about that edge, with no slide (the push's motion across the edge
// turns it, its part along the floor is the floor's). After a one-point push it would fly a frame on.
static void test_push_many_end_stays_on_floor(void **state) {
	(void)state;
	hs_world *w = box_world(hs_v3(0.1, 0.2, 0.06));
	hs_body *b = &w->state.bodies[0];
	b->rot = hs_quat_from_axis_angle(hs_v3(0, 1, 0), -7e-5); // the -x edge a hair up: on its +x edge
	b->pos = hs_v3(0, 0, 0.2);
	b->pos.z -= hs_motion_pose_vertices(&w->model, &w->scratch, b);
	hs_motion_keep_above_floor(&w->model, &w->scratch, b);
	assert_int_equal(b->floor_contacts, 2);
	hs_vec3 at = b->pos;
	b->prev = hs_sub(at, hs_v3(0.01, 0, 0));
	assert_true(hs_push_release_on_floor(motion_of(w), b, true));
	assert_true(b->grounded == 1);
	assert_true(hs_motion_pose_vertices(&w->model, &w->scratch, b) >= -1e-15);
	assert_true(fabs(b->pos.x - at.x) < 1e-4 && b->pos.y == at.y); // turned about its edge, not slid
	hs_motion_pass motion = hs_motion_pass_of(w);
	for (int n = 0; n < 30 && !b->asleep; ++n) // §4.2 on the floor from here on
		hs_motion_step(&motion, b);
	assert_true(b->asleep);
	assert_int_equal(b->floor_contacts, 4);
	assert_true(fabs(b->pos.x - at.x) < 1e-4 && fabs(b->pos.z - 0.03) < 1e-12);
	hs_world_destroy(w);
}

// (i) A sunk fingertip that leaves a moving object (it drives nothing, B = C) neither moves it nor
// takes its motion away: pos - prev stays the motion it had (eq. 3 goes on from it when the contact
// ends). On an object at rest nothing changes either.
static void test_leaving_part_keeps_motion(void **state) {
	(void)state;
	for (int moving = 0; moving < 2; ++moving) {
		hs_world *w = box_world(hs_v3(0.1, 0.1, 0.1));
		hs_body *b = &w->state.bodies[0];
		hs_vec3 prev = moving ? hs_v3(-0.001, 0, 0.05) : b->pos;
		b->prev = prev;
		w->state.hands[0].state.touch_points = 1u << 7;                 // touching last frame, 1 mm in
		w->state.hands[0].cache.prev_points[7] = hs_v3(-0.049, 0, 0.05);
		w->state.hands[0].cache.points[7] = hs_v3(-0.0495, 0, 0.05);    // drawn back, still inside
		hs_hand_points_moved(&w->state.hands[0]);
		hs_manipulate(w);
		assert_int_equal(b->contact, HS_CONTACT_PUSH_ONE);
		assert_true(b->pos.x == 0.0 && b->pos.y == 0.0 && b->pos.z == 0.05);
		assert_true(b->prev.x == prev.x && b->prev.y == prev.y && b->prev.z == prev.z);
		hs_world_destroy(w);
	}
}

static void test_free_object_untouched(void **state) {
	(void)state;
	hs_world *w = box_world(hs_v3(0.1, 0.1, 0.1));
	w->state.bodies[0].pos.z = 1.0;
	hs_body before = w->state.bodies[0];
	assert_false(hs_push_on_floor(motion_of(w), &w->state.bodies[0], hs_v3(0.04, 0, 1.05), hs_v3(0.04, 0, 1.049)));
	assert_memory_equal(&before, &w->state.bodies[0], sizeof before);
	hs_world_destroy(w);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_press_down_leaves_box),
	    cmocka_unit_test(test_push_low_slides),
	    cmocka_unit_test(test_push_high_tips),
	    cmocka_unit_test(test_press_within_floor_cone_holds),
	    cmocka_unit_test(test_push_remembers_finger_speed),
	    cmocka_unit_test(test_push_on_a_corner_keeps_floor),
	    cmocka_unit_test(test_skewed_push_tips_about_floor_edge),
	    cmocka_unit_test(test_push_end_stops_on_floor),
	    cmocka_unit_test(test_push_many_end_stays_on_floor),
	    cmocka_unit_test(test_leaving_part_keeps_motion),
	    cmocka_unit_test(test_free_object_untouched),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
