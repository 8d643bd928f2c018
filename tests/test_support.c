// test_support.c — objects on objects: the paper's §4.3 mode and the 'support' mode
// (docs/model.md §6).
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "hs_bench.h"
#include "broadphase.h"
#include "interfere.h"
#include "manipulate.h"
#include "stacking.h"
#include "support.h"
#include "world_internal.h"
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

// Support mode: G beyond the support's edge: it tips over the edge (rule (2)), its turn bounded by
// the support's top face (eq. 7's first touch), slides off the edge and ends standing on its
// 0.02 x 0.04 end beside the cube, flush with its side: G at half its length, 0.06 m, turned 90 deg,
// four floor contacts, never inside the cube.
static void test_support_overhang_past_edge_tips(void **state) {
	(void)state;
	hs_world *w = world_with(HS_STACKING_SUPPORT);
	add_box(w, hs_v3(0.1, 0.1, 0.1), hs_v3(0.6, 0, 0.05));
	hs_object_id plank = add_box(w, hs_v3(0.12, 0.04, 0.02), hs_v3(0.68, 0, 0.15));
	hs_object_state s = run(w, plank, 180);
	assert_true(s.resting);
	assert_near(s.position.z, 0.06, 1e-12);
	assert_int_equal(s.floor_contacts, 4);
	assert_near(hs_quat_angle(s.orientation), 0.5 * HS_PI, 1e-9);
	assert_true(s.position.x - 0.01 >= 0.65 - 1e-9); // its face against the cube's side, not in it
	hs_world_destroy(w);
}

// Paper mode (§4.3): a falling object stops at its first interference with another and, being
// untouched by the hand, ignores gravity from then on; the interpenetration is rectified as
// against the floor (Fig. 11): it rests on the top face, 0.1 + 0.01 = 0.11 m.
static void test_paper_mode_stops_at_interference(void **state) {
	(void)state;
	hs_world *w = world_with(HS_STACKING_PAPER);
	add_box(w, hs_v3(0.1, 0.1, 0.1), hs_v3(0.3, 0, 0.05));
	hs_object_id small = add_box(w, hs_v3(0.02, 0.02, 0.02), hs_v3(0.3, 0, 0.3));
	hs_object_state s = run(w, small, 120);
	assert_near(s.position.z, 0.11, 1e-6);
	assert_true(s.resting);
	hs_world_destroy(w);
}

// Paper mode (docs/model.md §6): a stack of three cubes placed in mid-air, each resting on the one
// below (interfering), is held up by nothing: it falls as one and lands as one, the bottom on the
// floor and the others on it where they sat, in the frame the closed form says (the bottom's base,
// 0.2 m up, below the floor first at frame ceil(sqrt(2 * 0.2 / g) * 60) = 13). On the floor, the
// same stack stays where it is (the floor holds it up).
static void test_paper_stack_falls_as_one(void **state) {
	(void)state;
	for (int on_floor = 0; on_floor <= 1; ++on_floor) {
		hs_world *w = world_with(HS_STACKING_PAPER);
		double base = on_floor ? 0.0 : 0.2;
		hs_object_id c[3];
		for (int k = 0; k < 3; ++k)
			c[k] = add_box(w, hs_v3(0.05, 0.05, 0.05), hs_v3(0.01 * k, 0, base + 0.025 + 0.05 * k));
		int landed = -1;
		for (int f = 1; f <= 60; ++f) {
			assert_int_equal(hs_world_step(w), HS_OK);
			hs_object_state s;
			assert_int_equal(hs_world_object_state(w, c[0], &s), HS_OK);
			if (landed < 0 && s.floor_contacts > 0)
				landed = f;
		}
		assert_int_equal(landed, on_floor ? 1 : 13);
		for (int k = 0; k < 3; ++k) {
			hs_object_state s;
			assert_int_equal(hs_world_object_state(w, c[k], &s), HS_OK);
			assert_near(s.position.x, 0.01 * k, 1e-15);
			assert_near(s.position.z, 0.025 + 0.05 * k, 1e-12);
			assert_true(s.resting);
		}
		hs_world_destroy(w);
	}
}

// Paper mode, Fig. 11 (docs/model.md §6): a 10 cm cube that an L-block's 2.5 cm foot has met 3 mm
// deep from the side is piled onto the foot: lifted exactly 2.5 cm less half the 1e-9 m
// interference depth (interfering, so carried from then on); left there, the L-block on the floor
// holds it up and it stays. A flat box 4 cm tall met the same way is not lifted (2.5 cm is more
// than its G's 2 cm above its base: the foot is not below its G).
static void test_paper_push_piles_onto_foot(void **state) {
	(void)state;
	hs_world *w = world_with(HS_STACKING_PAPER);
	hs_shape *l = hs_shape_l_block(hs_v3(0.08, 0.04, 0.08), 0.025, NULL);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(w, l, NULL);
	hs_shape_destroy(l);
	double g = 0.0287962962962963; // G of the L-block, x and z from its back lower edge
	od.position = hs_v3(0.0, 0.0, g);
	hs_object_id lb = hs_world_add_object(w, &od, NULL);
	double front = 0.08 - g;                                              // the foot's front face
	hs_object_id cube = add_box(w, hs_v3(0.1, 0.1, 0.1), hs_v3(front - 0.003 + 0.05, 0, 0.05));
	hs_object_id flat = add_box(w, hs_v3(0.1, 0.1, 0.04), hs_v3(front - 0.003 + 0.05, 0.2, 0.02));
	hs_body *c = &w->state.bodies[cube.index1 - 1], *f = &w->state.bodies[flat.index1 - 1];
	double fall = c->pos.z - c->prev.z;
	assert_true(hs_stack_pile_onto(&w->model, w->state.bodies, (int)cube.index1 - 1, (int)lb.index1 - 1));
	assert_near(c->pos.z, 0.075 - 0.5e-9, 1e-12);
	assert_near(c->pos.z - c->prev.z, fall, 1e-15); // lifted, not thrown: its motion is as it was
	assert_true(hs_objects_interfere(&w->model, w->state.bodies, w->cache.box_memo, (int)cube.index1 - 1, (int)lb.index1 - 1));
	f->pos.y = 0.0; // the same place, in the cube's stead
	c->pos.y = c->prev.y = 0.3;
	assert_false(hs_stack_pile_onto(&w->model, w->state.bodies, (int)flat.index1 - 1, (int)lb.index1 - 1));
	assert_near(f->pos.z, 0.02, 1e-15);
	f->pos.y = f->prev.y = 0.3;
	c->pos.y = c->prev.y = 0.0;
	hs_grid_update(&w->model, w->state.bodies, &w->cache, (int)cube.index1 - 1);
	hs_grid_update(&w->model, w->state.bodies, &w->cache, (int)flat.index1 - 1);
	hs_object_state s = run(w, cube, 30);
	assert_near(s.position.z, 0.075 - 0.5e-9, 1e-12); // held up by the foot, the foot by the floor
	hs_world_destroy(w);
}

// Both modes (docs/model.md §5): a post tilted 20 deg toward a cube beside it tips over about its
// floor edge until its face meets the cube's top edge, and rests there leaning on it, at the closed
// form (scenarios/tip_onto_cube_*.yaml) at 12 and 144 frames/s; before, it turned into the cube,
// was lifted out of it off the floor and rocked for seconds.
static void test_tip_stops_on_neighbour(void **state) {
	(void)state;
	const double d20 = 20.0 * HS_PI / 180.0, xp = 0.04 + 0.02 * cos(d20) - 0.1 * sin(d20);
	const double lean = atan((0.13 - xp) / 0.06);
	for (int mode = 0; mode < 2; ++mode)
		for (int fps = 12; fps <= 144; fps += 132) {
			hs_world_def def = hs_default_world_def();
			def.stacking = mode ? HS_STACKING_SUPPORT : HS_STACKING_PAPER;
			def.dt = 1.0 / fps;
			hs_world *w = hs_world_create(&def, NULL);
			hs_shape *box = hs_shape_box(hs_v3(0.04, 0.04, 0.2), NULL);
			hs_object_def od = hs_default_object_def();
			od.shape = hs_world_add_shape(w, box, NULL);
			hs_shape_destroy(box);
			od.position = hs_v3(0.04, 0, 0.105);
			od.orientation = hs_quat_from_axis_angle(hs_v3(0, 1, 0), d20);
			hs_object_id post = hs_world_add_object(w, &od, NULL);
			add_box(w, hs_v3(0.06, 0.06, 0.06), hs_v3(0.16, 0, 0.03));
			hs_object_state s = run(w, post, 2 * fps);
			assert_near(s.position.x, xp - 0.02 * cos(lean) + 0.1 * sin(lean), 1e-6);
			assert_near(s.position.z, 0.02 * sin(lean) + 0.1 * cos(lean), 1e-6);
			assert_int_equal(s.floor_contacts, 2);
			assert_true(s.resting);
			hs_world_destroy(w);
		}
}

// Both modes: a cube placed 2 cm deep in another (faces flush: no vertex strictly inside) is
// lifted along +z onto its top face in the first step (Fig. 11: rectified as against the floor),
// G at 0.1 + 0.05 within the floor tolerance; in paper mode it then interferes (touches) and stays.
static void test_placed_inside_is_rectified(void **state) {
	(void)state;
	for (int m = 0; m < 2; ++m) {
		hs_world *w = world_with(m ? HS_STACKING_SUPPORT : HS_STACKING_PAPER);
		add_box(w, hs_v3(0.1, 0.1, 0.1), hs_v3(0, 0, 0.05));
		hs_object_id upper = add_box(w, hs_v3(0.1, 0.1, 0.1), hs_v3(0, 0, 0.13));
		hs_object_state s = run(w, upper, 1);
		assert_near(s.position.z, 0.15, 1e-6);
		assert_true(s.position.z >= 0.15);
		s = run(w, upper, 60);
		assert_near(s.position.z, 0.15, 1e-6);
		assert_true(s.resting);
		hs_world_destroy(w);
	}
}

// Depth of b's penetration into a (0 when they only touch or are apart).
static double penetration(const hs_shape *sa, hs_object_state a, const hs_shape *sb, hs_object_state b) {
	double depth = 0.0;
	hs_vec3 dir;
	if (!hs_shapes_penetration(sa, a.position, a.orientation, sb, b.position, b.orientation, &depth, &dir))
		return 0.0;
	return depth;
}

// A cube of edge `size` dropped from rest with its base at `height` onto a 10 cm cube (top at
// z = 0.1), at `dt`: it never sinks into it at any frame end (libccd depth within 1e-9) and ends
// resting on the top face, G at 0.1 + size / 2 within the floor tolerance, not turned.
static void drop_onto_cube(hs_stacking stacking, double size, double height, double dt) {
	hs_world_def def = hs_default_world_def();
	def.stacking = stacking;
	def.dt = dt;
	hs_world *w = hs_world_create(&def, NULL);
	assert_non_null(w);
	hs_shape *big = hs_shape_box(hs_v3(0.1, 0.1, 0.1), NULL), *cube = hs_shape_box(hs_v3(size, size, size), NULL);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(w, big, NULL);
	od.position = hs_v3(0.3, 0, 0.05);
	hs_object_id lower = hs_world_add_object(w, &od, NULL);
	od.shape = hs_world_add_shape(w, cube, NULL);
	od.position = hs_v3(0.3, 0, height + 0.5 * size);
	hs_object_id upper = hs_world_add_object(w, &od, NULL);
	int frames = (int)(2.5 / dt);
	hs_object_state a, b;
	for (int i = 0; i < frames; ++i) {
		hs_world_step(w);
		hs_world_object_state(w, lower, &a);
		hs_world_object_state(w, upper, &b);
		if (penetration(big, a, cube, b) > 1e-9)
			fail_msg("size %g from %g m at dt %g: %.3g m deep at frame %d", size, height, dt,
			         penetration(big, a, cube, b), i);
	}
	assert_true(b.resting);
	assert_near(b.position.z, 0.1 + 0.5 * size, def.floor_tolerance);
	assert_near(b.position.x, 0.3, 1e-12);
	assert_near(b.position.y, 0.0, 1e-12);
	assert_near(hs_quat_angle(b.orientation), 0.0, 1e-12);
	assert_vec3_near(a.position, hs_v3(0.3, 0, 0.05), 0.0); // the lower cube never moves
	hs_shape_destroy(big);
	hs_shape_destroy(cube);
	hs_world_destroy(w);
}

// In both modes, 10 cm and 5 cm cubes from 0.2 m and 2 m (at 1/12 s a 2 m fall moves
// 0.52 m in its last frame, more than the cube it lands on is tall) at 12, 30 and 60 frames/s.
static void test_drops_land_on_top_face(void **state) {
	(void)state;
	const hs_stacking modes[2] = {HS_STACKING_PAPER, HS_STACKING_SUPPORT};
	const double sizes[2] = {0.1, 0.05}, heights[2] = {0.2, 2.0}, dts[3] = {1.0 / 12, 1.0 / 30, 1.0 / 60};
	for (int m = 0; m < 2; ++m)
		for (int s = 0; s < 2; ++s)
			for (int h = 0; h < 2; ++h)
				for (int d = 0; d < 3; ++d)
					drop_onto_cube(modes[m], sizes[s], heights[h], dts[d]);
}

// Support mode: a 4 cm cube let go turned `tilt` about y (a noisy release) from
// `height` above a 10 cm cube's top lands on an edge and settles by §4.2's rules against the top
// face: rule (2) turns it about that edge until the next face reaches the top (eq. 7's first touch
// against the support, not only the floor), where it rests (Gm gone, G' inside). Invariants at
// every frame end: never inside the lower cube; at the end: on a face (turned a multiple of 90 deg
// about y), G at 0.1 + 0.02, over the top face, at rest, and the lower cube never moved.
static void tilted_landing(double tilt, double height, double dt) {
	hs_world_def def = hs_default_world_def();
	def.stacking = HS_STACKING_SUPPORT;
	def.dt = dt;
	hs_world *w = hs_world_create(&def, NULL);
	hs_shape *big = hs_shape_box(hs_v3(0.1, 0.1, 0.1), NULL), *cube = hs_shape_box(hs_v3(0.04, 0.04, 0.04), NULL);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(w, big, NULL);
	od.position = hs_v3(0.3, 0, 0.05);
	hs_object_id lower = hs_world_add_object(w, &od, NULL);
	od.shape = hs_world_add_shape(w, cube, NULL);
	od.position = hs_v3(0.31, 0.005, 0.1 + height + 0.03);
	od.orientation = hs_quat_from_axis_angle(hs_v3(0, 1, 0), tilt);
	hs_object_id upper = hs_world_add_object(w, &od, NULL);
	hs_object_state a, b;
	for (int i = 0; i < (int)(2.0 / dt); ++i) {
		hs_world_step(w);
		hs_world_object_state(w, lower, &a);
		hs_world_object_state(w, upper, &b);
		if (penetration(big, a, cube, b) > 1e-9)
			fail_msg("tilt %g at dt %g: %.3g m deep at frame %d", tilt, dt, penetration(big, a, cube, b), i);
	}
	assert_true(b.resting);
	assert_near(b.position.z, 0.12, def.floor_tolerance);
	// on a face: off a multiple of 90 deg by at most the contact tolerance across the 4 cm face
	double quarter = hs_quat_angle(b.orientation) / (0.5 * HS_PI);
	double off = fabs(quarter - (double)(long)(quarter + 0.5)) * 0.5 * HS_PI;
	if (off > 2.0 * def.floor_tolerance / 0.04)
		fail_msg("tilt %g from %g at dt %g: rests %.3g rad off a face", tilt, height, dt, off);
	assert_true(fabs(b.position.x - 0.3) < 0.05 && fabs(b.position.y) < 0.05);
	assert_vec3_near(a.position, hs_v3(0.3, 0, 0.05), 0.0);
	hs_shape_destroy(big);
	hs_shape_destroy(cube);
	hs_world_destroy(w);
}

static void test_support_tilted_landing_settles(void **state) {
	(void)state;
	const double tilts[3] = {0.02, 0.2, -0.5}, dts[3] = {1.0 / 12, 1.0 / 60, 1.0 / 120};
	for (int t = 0; t < 3; ++t)
		for (int d = 0; d < 3; ++d) {
			tilted_landing(tilts[t], 0.002, dts[d]);
			tilted_landing(tilts[t], 0.2, dts[d]);
		}
}

// A deterministic jitter in [-1, 1] (xorshift), standing in for a noisy tracker.
static double jitter(uint32_t *x) {
	*x ^= *x << 13;
	*x ^= *x >> 17;
	*x ^= *x << 5;
	return (double)(*x % 20001u) / 10000.0 - 1.0;
}

// Support mode: a hand lifts a bar (as manipulate.c does: pose set, prev / rot_prev the
// frame's start, held, then hs_support_wake_neighbours) 0.1 m in 60 frames with +-0.762 mm and
// +-0.15 deg of tracker jitter a frame. The cube on it is carried by the bar's rigid motion: its
// pose in the bar's frame never changes (1e-12), it never sinks into the bar, and it rests every
// frame (no flicker). Let go, both fall; the cube ends resting on the bar's top face.
static void test_support_carried_by_lifted_support(void **state) {
	(void)state;
	hs_world *w = world_with(HS_STACKING_SUPPORT);
	hs_object_id bar = add_box(w, hs_v3(0.05, 0.2, 0.05), hs_v3(0, 0, 0.025));
	hs_object_id cube = add_box(w, hs_v3(0.04, 0.04, 0.04), hs_v3(0, -0.06, 0.07));
	hs_object_state a, b;
	run(w, cube, 2);
	int li = (int)bar.index1 - 1;
	hs_body *lower = &w->state.bodies[li], *upper = &w->state.bodies[(int)cube.index1 - 1];
	hs_vec3 rel = hs_quat_inv_rotate(lower->rot, hs_sub(upper->pos, lower->pos));
	hs_quat rel_rot = hs_quat_mul(hs_quat_conj(lower->rot), upper->rot);
	uint32_t seed = 12345u;
	for (int i = 1; i <= 60; ++i) {
		lower->prev = lower->pos;
		lower->rot_prev = lower->rot;
		lower->pos = hs_v3(0.000762 * jitter(&seed), 0.000762 * jitter(&seed), 0.025 + 0.1 * i / 60.0 + 0.000762 * jitter(&seed));
		lower->rot = hs_quat_from_rpy(0.15 * HS_PI / 180 * jitter(&seed), 0.15 * HS_PI / 180 * jitter(&seed), 0.0);
		lower->held = 1;
		hs_wake(w->state.bodies, &w->cache, li);
		hs_grid_update(&w->model, w->state.bodies, &w->cache, li);
		hs_broadphase bp = hs_broadphase_of(w);
		hs_support_wake_neighbours(&bp, li, lower->prev);
		hs_world_step(w);
		hs_world_object_state(w, bar, &a);
		hs_world_object_state(w, cube, &b);
		assert_vec3_near(hs_quat_inv_rotate(lower->rot, hs_sub(upper->pos, lower->pos)), rel, 1e-12);
		assert_near(hs_quat_angle(hs_quat_mul(hs_quat_conj(rel_rot), hs_quat_mul(hs_quat_conj(lower->rot), upper->rot))), 0.0, 1e-9);
		assert_true(penetration(&w->model.shapes[lower->shape], a, &w->model.shapes[upper->shape], b) <= 1e-9);
		assert_true(b.resting);
	}
	lower->held = 0; // let go: it falls from rest (eq. 3), the cube with it
	lower->prev = lower->pos;
	b = run(w, cube, 120);
	hs_world_object_state(w, bar, &a);
	assert_true(a.resting && b.resting);
	assert_near(a.position.z, 0.025, 1e-9);
	assert_near(b.position.z, 0.07, 1e-6);
	assert_true(penetration(&w->model.shapes[lower->shape], a, &w->model.shapes[upper->shape], b) <= 1e-9);
	hs_world_destroy(w);
}

// Support mode: a world with skip_work off gives the same bits (broadphase.c): an object asleep on
// a support is left as the awake list's skip leaves it (before: it fell g dt^2 into its support
// and was swept back each frame, with the landing's Gm left in its motion).
static uint64_t settle_hash(bool skip) {
	hs_world_def def = hs_default_world_def();
	def.stacking = HS_STACKING_SUPPORT;
	def.dt = 1.0 / 12;
	hs_world *w = hs_world_create(&def, NULL);
	hs_world_set_skip_work(w, skip);
	add_box(w, hs_v3(0.1, 0.1, 0.1), hs_v3(0.3, 0, 0.05));
	add_box(w, hs_v3(0.04, 0.04, 0.04), hs_v3(0.31, 0.005, 0.15));
	run(w, add_box(w, hs_v3(0.04, 0.04, 0.04), hs_v3(0.6, 0, 0.5)), 60);
	uint64_t h = hs_world_hash(w);
	hs_world_destroy(w);
	return h;
}

static void test_support_skip_work_same_bits(void **state) {
	(void)state;
	assert_int_equal(settle_hash(true), settle_hash(false));
}

// Support mode (docs/model.md §6): a box a hand pushes 1 cm into a cube beside it on the floor
// pushes the cube along by the push's horizontal motion, and that one the cube behind it: neither
// overlaps what pushed it; a cube behind the push is left where it is.
static void test_support_push_moves_what_is_beside(void **state) {
	(void)state;
	hs_world *w = world_with(HS_STACKING_SUPPORT);
	hs_object_id box = add_box(w, hs_v3(0.1, 0.2, 0.06), hs_v3(0, 0, 0.03));
	hs_object_id first = add_box(w, hs_v3(0.05, 0.05, 0.05), hs_v3(0.0755, 0, 0.025));
	hs_object_id second = add_box(w, hs_v3(0.05, 0.05, 0.05), hs_v3(0.1305, 0, 0.025));
	hs_object_id behind = add_box(w, hs_v3(0.05, 0.05, 0.05), hs_v3(-0.08, 0, 0.025));
	run(w, box, 2);
	int i = (int)box.index1 - 1;
	hs_body *b = &w->state.bodies[i];
	b->prev = b->pos;
	b->rot_prev = b->rot;
	b->pos = hs_add(b->pos, hs_v3(0.01, 0, 0));
	b->held = 1;
	b->contact = HS_CONTACT_PUSH_MANY;
	hs_wake(w->state.bodies, &w->cache, i);
	hs_grid_update(&w->model, w->state.bodies, &w->cache, i);
	hs_broadphase bp = hs_broadphase_of(w);
	hs_support_wake_neighbours(&bp, i, b->prev);
	assert_near(w->state.bodies[(int)first.index1 - 1].pos.x, 0.0855, 1e-15);  // 9.5 mm into it: moved 1 cm, the gap kept
	assert_near(w->state.bodies[(int)second.index1 - 1].pos.x, 0.1405, 1e-15); // moved into by the first
	assert_near(w->state.bodies[(int)behind.index1 - 1].pos.x, -0.08, 0);
	assert_near(b->pos.x, 0.01, 1e-15);
	hs_world_destroy(w);
}

// Support mode: an object a hand pushes (not grasps) into a support is rectified onto its top face
// in the hand pass, as a push on the floor (§4.2), and the lift is not motion: pushed 3 mm down
// and 2 mm across a cube's top, it ends on the top face (G at 0.12) with the push's own motion.
static void test_support_push_does_not_sink(void **state) {
	(void)state;
	hs_world *w = world_with(HS_STACKING_SUPPORT);
	add_box(w, hs_v3(0.1, 0.1, 0.1), hs_v3(0.3, 0, 0.05));
	hs_object_id id = add_box(w, hs_v3(0.04, 0.04, 0.04), hs_v3(0.3, 0, 0.12));
	run(w, id, 2);
	int i = (int)id.index1 - 1;
	hs_body *b = &w->state.bodies[i];
	b->prev = b->pos;
	b->rot_prev = b->rot;
	b->pos = hs_add(b->pos, hs_v3(0.002, 0, -0.003));
	b->held = 1;
	b->contact = HS_CONTACT_PUSH_ONE;
	hs_wake(w->state.bodies, &w->cache, i);
	hs_grid_update(&w->model, w->state.bodies, &w->cache, i);
	hs_broadphase bp = hs_broadphase_of(w);
	hs_support_wake_neighbours(&bp, i, b->prev);
	assert_near(b->pos.z, 0.12, 1e-12);
	assert_vec3_near(hs_sub(b->pos, b->prev), hs_v3(0.002, 0, -0.003), 1e-15);
	hs_world_destroy(w);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_support_rests_on_top),
	    cmocka_unit_test(test_support_overhang_short_of_edge),
	    cmocka_unit_test(test_support_overhang_past_edge_tips),
	    cmocka_unit_test(test_paper_mode_stops_at_interference),
	    cmocka_unit_test(test_paper_stack_falls_as_one),
	    cmocka_unit_test(test_paper_push_piles_onto_foot),
	    cmocka_unit_test(test_tip_stops_on_neighbour),
	    cmocka_unit_test(test_placed_inside_is_rectified),
	    cmocka_unit_test(test_drops_land_on_top_face),
	    cmocka_unit_test(test_support_tilted_landing_settles),
	    cmocka_unit_test(test_support_carried_by_lifted_support),
	    cmocka_unit_test(test_support_skip_work_same_bits),
	    cmocka_unit_test(test_support_push_does_not_sink),
	    cmocka_unit_test(test_support_push_moves_what_is_beside),
	};
	return cmocka_run_group_tests_name("support", tests, NULL, NULL);
}
