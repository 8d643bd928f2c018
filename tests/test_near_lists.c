// test_near_lists.c — the broad phase's neighbour lists (broadphase.c, hs_grid_near). In a world
// larger than is scanned whole, every answer holds each object whose centre lies within the
// query's radius plus its own in (x, y) — what its callers' tests rely on — in index order, while
// a hand grasps, drags, pushes and lets go among resting cubes and they come to rest again; the
// bits are those of skip_work off (no lists, no grid); and an object that comes to rest where a
// list was made is found there.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "broadphase.h"
#include "hs_bench.h"
#include "handspring.h"
#include "test_util.h"
#include "world_internal.h"

static hs_shape_id add_cube(hs_world *w) {
	hs_shape *shape = hs_shape_box(hs_v3(0.05, 0.05, 0.05), NULL);
	assert_non_null(shape);
	hs_shape_id id = hs_world_add_shape(w, shape, NULL);
	hs_shape_destroy(shape);
	assert_int_not_equal(id.index1, 0);
	return id;
}

static int add_object(hs_world *w, hs_shape_id shape, hs_vec3 pos) {
	hs_object_def od = hs_default_object_def();
	od.shape = shape;
	od.position = pos;
	hs_object_id id = hs_world_add_object(w, &od, NULL);
	assert_int_not_equal(id.index1, 0);
	return (int)id.index1 - 1;
}

// hs_grid_near's answer at (c, r) holds, ascending, every object whose centre lies within r plus
// its bounding radius of c in (x, y).
static void check_answer(hs_world *w, hs_vec3 c, double r, const char *what, int frame) {
	hs_broadphase bp = hs_broadphase_of(w);
	int n = hs_grid_near(&bp, c, r);
	for (int k = 1; k < n; ++k)
		if (w->scratch.near[k - 1] >= w->scratch.near[k])
			fail_msg("frame %d, %s: answer not ascending at %d", frame, what, k);
	for (int j = 0, k = 0; j < w->model.object_count; ++j) {
		while (k < n && w->scratch.near[k] < j)
			++k;
		hs_vec3 p = w->state.bodies[j].pos;
		if (hypot(p.x - c.x, p.y - c.y) <= r + w->model.shapes[w->state.bodies[j].shape].radius && (k == n || w->scratch.near[k] != j))
			fail_msg("frame %d, %s at (%g, %g) r %g: object %d at (%g, %g) missing", frame, what, c.x, c.y, r, j, p.x,
			         p.y);
	}
}

// ---------------------------------------------------------------------------------------------
// A hand closes on a cube, lifts it 3 cm and drags it through three rows of resting cubes, lets
// go, and rises away; the cubes it met are pushed and carried, and come to rest again.

#define ROW 12 // cubes per row

typedef struct rig {
	hs_world *world;
	uint8_t wide[HS_GLOVE_SENSORS], grasp[HS_GLOVE_SENSORS];
	hs_vec3 grip;
} rig;

static rig make(bool skip_work, hs_stacking stacking, double fps) {
	rig r;
	hs_world_def def = hs_default_world_def();
	def.dt = 1.0 / fps;
	def.max_objects = 1 + 3 * ROW;
	def.stacking = stacking;
	// the lists are what is tested, the hand only has to move objects: grasps start on the
	// normals alone (the paper's letter), as the driven hand closes on them only once
	def.grasp_opposed = false;
	def.grasp_close_mm = 0.0;
	r.world = hs_world_create(&def, NULL);
	assert_non_null(r.world);
	hs_world_set_skip_work(r.world, skip_work);
	hs_shape_id cube = add_cube(r.world);
	add_object(r.world, cube, hs_v3(0, 0, 0.025));
	for (int row = 0; row < 3; ++row)
		for (int i = 0; i < ROW; ++i)
			add_object(r.world, cube, hs_v3(0.12 + 0.07 * i, 0.065 * (row - 1), 0.025));
	hs_hand_def hd = hs_default_hand_def();
	assert_int_not_equal(hs_world_add_hand(r.world, &hd, NULL).index1, 0);
	assert_int_equal(hs_hand_posture(&hd, HS_POSTURE_GRASP, 0.12, r.wide), HS_OK);
	assert_int_equal(hs_hand_posture(&hd, HS_POSTURE_GRASP, 0.05, r.grasp), HS_OK);
	hs_vec3 axis;
	hs_hand_grip(&hd, r.grasp, &r.grip, &axis);
	return r;
}

// A reading's noise, the same for both worlds: ±amp from (frame, channel), a fixed integer mix.
static double noise(int f, int channel, double amp) {
	uint64_t h = (uint64_t)f * UINT64_C(0x9E3779B97F4A7C15) ^ (uint64_t)channel * UINT64_C(0xC2B2AE3D27D4EB4F);
	h ^= h >> 29;
	h *= UINT64_C(0xBF58476D1CE4E5B9);
	h ^= h >> 32;
	return amp * (2.0 * (double)(h >> 11) / (double)(UINT64_C(1) << 53) - 1.0);
}

// The script at `fps`; `noisy`: ±4 units on every glove sensor and ±1 mm on the wrist, as a real
// glove and tracker read.
static void drive(const rig *r, int f, double fps, bool noisy) {
	double t = (f + 1) / fps;
	double down = t < 1.0 ? 0.2 * (1.0 - t) : 0.0, close = t < 1.0 ? 0.0 : (t < 1.5 ? (t - 1.0) * 2.0 : 1.0);
	double lift = t < 1.5 ? 0.0 : (t < 2.0 ? (t - 1.5) * 0.06 : 0.03);
	double side = t < 2.0 ? 0.0 : (t < 5.0 ? (t - 2.0) * 0.3 : 0.9);
	if (t > 5.0) { // let go and rise away
		close = 0.0;
		lift += (t - 5.0) * 0.5;
	}
	uint8_t s[HS_GLOVE_SENSORS];
	for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
		s[i] = (uint8_t)fmin(255.0, fmax(0.0, r->wide[i] + close * (r->grasp[i] - r->wide[i]) + 0.5 +
		                                              (noisy ? noise(f, i, 4.0) : 0.0)));
	hs_vec3 grip = hs_v3(side, 0, 0.025 + down + lift);
	if (noisy)
		grip = hs_add(grip, hs_v3(noise(f, 20, 1e-3), noise(f, 21, 1e-3), noise(f, 22, 1e-3)));
	hs_quat turn = hs_quat_from_rpy(0.0, 0.0, 0.3 * (t > 2.0 && t < 5.0 ? t - 2.0 : 0.0));
	assert_int_equal(hs_world_set_hand(r->world, hs_world_hand_at(r->world, 0), hs_sub(grip, r->grip), turn, s), HS_OK);
}

// Every frame also against a world with skip_work off (no lists, no grid, no culls).
static void lists_in_a_busy_world(hs_stacking stacking, double fps, bool noisy) {
	rig on = make(true, stacking, fps), off = make(false, stacking, fps);
	int moved = 0, frames = (int)(8.0 * fps);
	for (int f = 0; f < frames; ++f) {
		drive(&on, f, fps, noisy);
		drive(&off, f, fps, noisy);
		assert_int_equal(hs_world_step(on.world), HS_OK);
		assert_int_equal(hs_world_step(off.world), HS_OK);
		if (hs_world_hash(on.world) != hs_world_hash(off.world)) {
			for (int i = 0; i < on.world->model.object_count; ++i) {
				const hs_body *a = &on.world->state.bodies[i], *b = &off.world->state.bodies[i];
				if (memcmp(a, b, sizeof *a))
					print_message("object %d: on (%.17g %.17g %.17g) asleep %d held %d carried %d | off (%.17g %.17g %.17g) asleep %d held %d carried %d\n", i, a->pos.x, a->pos.y, a->pos.z, a->asleep, a->held, a->carried, b->pos.x, b->pos.y, b->pos.z, b->asleep, b->held, b->carried);
			}
			fail_msg("stacking %d, %g frames/s, frame %d: skip_work on and off differ", (int)stacking, fps, f + 1);
		}
		hs_world *w = on.world;
		const hs_hand *hand = &w->state.hands[0];
		check_answer(w, hand->cache.sweep_center, hand->cache.sweep_radius, "the hand", f + 1);
		for (int k = 0; k < w->cache.awake_count; ++k) { // the queries the step makes for moved objects
			const hs_body *b = &w->state.bodies[w->cache.awake[k]];
			check_answer(w, b->pos, w->model.shapes[b->shape].radius, "an awake object", f + 1);
		}
		for (int k = 0; k < 4; ++k) // along the rows, where cubes are pushed and come to rest
			check_answer(w, hs_v3(0.2 + 0.2 * k, 0.0, 0.0), 0.08, "the rows", f + 1);
	}
	for (int i = 1; i < on.world->model.object_count; ++i) {
		hs_vec3 p = on.world->state.bodies[i].pos;
		int row = (i - 1) / ROW, col = (i - 1) % ROW;
		moved += fabs(p.x - (0.12 + 0.07 * col)) + fabs(p.y - 0.065 * (row - 1)) > 1e-3;
	}
	assert_true(moved >= 1);                          // the hand did work among them
	assert_true(on.world->cache.near_lists.hits > frames);        // most answers came from the lists
	assert_true(on.world->cache.awake_count < 3 * ROW / 2); // and most came to rest again
	hs_world_destroy(on.world);
	hs_world_destroy(off.world);
}

static void test_lists_in_a_busy_world_paper(void **state) {
	(void)state;
	lists_in_a_busy_world(HS_STACKING_PAPER, 60.0, false);
	lists_in_a_busy_world(HS_STACKING_PAPER, 12.0, true); // the paper's rate, a real glove's noise
}

static void test_lists_in_a_busy_world_support(void **state) {
	(void)state;
	lists_in_a_busy_world(HS_STACKING_SUPPORT, 60.0, false);
	lists_in_a_busy_world(HS_STACKING_SUPPORT, 12.0, true);
}

// 24 cubes resting on a 5 × 5 grid with its centre slot empty, and a cube dropped into it.
static hs_world *drop_world(int *dropped) {
	hs_world_def def = hs_default_world_def();
	def.max_objects = 32;
	hs_world *w = hs_world_create(&def, NULL); // skipping work: on in every new world
	assert_non_null(w);
	hs_shape_id cube = add_cube(w);
	for (int i = 0; i < 25; ++i)
		if (i != 12)
			add_object(w, cube, hs_v3(0.1 * (i % 5), 0.1 * (i / 5), 0.025));
	*dropped = add_object(w, cube, hs_v3(0.2, 0.2, 0.3));
	return w;
}

#define SLOT hs_v3(0.2, 0.2, 0.0)

// Steps until the dropped cube has come to rest (left the awake list), asking for the slot's
// objects after every step; returns the frames stepped.
static int until_at_rest(hs_world *w, int dropped) {
	int f = 0;
	for (; f < 600 && (f < 2 || w->cache.awake_flag[dropped]); ++f) {
		assert_int_equal(hs_world_step(w), HS_OK);
		check_answer(w, SLOT, 0.06, "the slot", f + 1);
	}
	assert_true(f < 600);                         // it came to rest
	assert_true(w->state.bodies[dropped].pos.z < 0.03); // on the floor, in the slot
	return f;
}

// A list made at the slot while the cube falls (awake, so not listed) must not answer once it
// has come to rest there.
static void test_object_coming_to_rest_is_found(void **state) {
	(void)state;
	int dropped;
	hs_world *w = drop_world(&dropped);
	int f = until_at_rest(w, dropped);
	assert_true(w->cache.near_lists.hits > f / 2); // a list made while it fell answered most queries
	check_answer(w, SLOT, 0.06, "the slot at rest", f);
	hs_world_destroy(w);
}

// A state saved with the cube at rest, loaded into a world where it is still falling and a list
// was made at the slot: after the next step the slot's answer holds it.
static void test_object_loaded_at_rest_is_found(void **state) {
	(void)state;
	int dropped;
	hs_world *rested = drop_world(&dropped), *falling = drop_world(&dropped);
	until_at_rest(rested, dropped);
	size_t size = hs_world_state_size(rested);
	unsigned char *buffer = malloc(size);
	assert_non_null(buffer);
	assert_int_equal(hs_world_save_state(rested, buffer, size), HS_OK);
	for (int f = 0; f < 5; ++f) {
		assert_int_equal(hs_world_step(falling), HS_OK);
		check_answer(falling, SLOT, 0.06, "the slot, falling", f + 1);
	}
	assert_true(falling->cache.awake_flag[dropped]);
	assert_int_equal(hs_world_load_state(falling, buffer, size), HS_OK);
	assert_int_equal(hs_world_step(falling), HS_OK);
	assert_int_equal(falling->cache.awake_flag[dropped], 0);
	check_answer(falling, SLOT, 0.06, "the slot, loaded", 0);
	free(buffer);
	hs_world_destroy(rested);
	hs_world_destroy(falling);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_object_coming_to_rest_is_found),
	    cmocka_unit_test(test_object_loaded_at_rest_is_found),
	    cmocka_unit_test(test_lists_in_a_busy_world_paper),
	    cmocka_unit_test(test_lists_in_a_busy_world_support),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
