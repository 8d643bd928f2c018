// test_state.c — the state block (docs/model.md "The state block"): save at frame N, step, load,
// step again: every hash equal, in the same world and in a second world built from the same
// definitions; hand worlds with a grasp in progress and an object in flight, spring worlds with an
// object on the spring and tracker noise. Refusals of foreign or corrupt buffers leave the world
// untouched. The hash sees every single state field.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <gsl/gsl_rng.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "hs_bench.h"
#include "handspring.h"
#include "broadphase.h"
#include "test_util.h"
#include "spring_system.h"
#include "world_internal.h"

#define WORD 8
#define HEADER_WORDS 9

static hs_shape_id add_shape(hs_world *w, hs_shape *shape) {
	assert_non_null(shape);
	hs_shape_id id = hs_world_add_shape(w, shape, NULL);
	hs_shape_destroy(shape);
	assert_int_not_equal(id.index1, 0);
	return id;
}

static hs_object_id add_object(hs_world *w, hs_shape_id shape, hs_vec3 pos, hs_vec3 vel) {
	hs_object_def od = hs_default_object_def();
	od.shape = shape;
	od.position = pos;
	od.velocity = vel;
	hs_object_id id = hs_world_add_object(w, &od, NULL);
	assert_int_not_equal(id.index1, 0);
	return id;
}

// ---------------------------------------------------------------------------------------------
// A hand world: a hand closes on a cube, lifts it and swings it sideways; a block thrown high is
// in flight meanwhile; two cubes rest side by side. `cube_size` lets a test build another world.

typedef struct hand_rig {
	hs_world *world;
	hs_hand_id hand;
	hs_object_id target, flyer;
	uint8_t wide[HS_GLOVE_SENSORS], grasp[HS_GLOVE_SENSORS];
	hs_vec3 grip;
} hand_rig;

static bool rig_any_contacts; // the grasp rule of the hand worlds built next (default: false)
static double rig_fps = 60.0;  // their frame rate (drive_hand's time follows it)
static double rig_release_window = 0.05;
static hs_release_fit rig_release_fit = HS_RELEASE_FIT_MEAN;
static int rig_max_objects = 0; // their capacity, when more than they start with

static hand_rig hand_world(double cube_size, int extra_objects, bool skip_work) {
	hand_rig r;
	hs_world_def def = hs_default_world_def();
	def.max_objects = 4 + extra_objects > 8 ? 4 + extra_objects : 8;
	def.max_objects = rig_max_objects > def.max_objects ? rig_max_objects : def.max_objects;
	def.grasp_any_contacts = rig_any_contacts;
	def.dt = 1.0 / rig_fps;
	def.release_window_s = rig_release_window;
	def.release_fit = rig_release_fit;
	r.world = hs_world_create(&def, NULL);
	assert_non_null(r.world);
	hs_world_set_skip_work(r.world, skip_work);
	hs_shape_id cube = add_shape(r.world, hs_shape_box(hs_v3(cube_size, cube_size, cube_size), NULL));
	hs_shape_id block = add_shape(r.world, hs_shape_box(hs_v3(0.1, 0.06, 0.04), NULL));
	r.target = add_object(r.world, cube, hs_v3(0, 0, 0.025), hs_v3(0, 0, 0));
	r.flyer = add_object(r.world, block, hs_v3(1, 0, 0.5), hs_v3(0.4, 0.1, 9.0));
	add_object(r.world, cube, hs_v3(0.5, 0.3, 0.025), hs_v3(0, 0, 0));
	add_object(r.world, cube, hs_v3(0.56, 0.3, 0.025), hs_v3(0, 0, 0));
	for (int i = 0; i < extra_objects; ++i)
		add_object(r.world, cube, hs_v3(-1.0 - 0.1 * i, 0, 0.025), hs_v3(0, 0, 0));
	hs_hand_def hd = hs_default_hand_def();
	r.hand = hs_world_add_hand(r.world, &hd, NULL);
	assert_int_not_equal(r.hand.index1, 0);
	assert_int_equal(hs_hand_posture(&hd, HS_POSTURE_GRASP, 0.12, r.wide), HS_OK);
	assert_int_equal(hs_hand_posture(&hd, HS_POSTURE_GRASP, 0.05, r.grasp), HS_OK);
	hs_vec3 axis;
	hs_hand_grip(&hd, r.grasp, &r.grip, &axis);
	return r;
}

// The input of frame f: down over the cube, close, lift, swing sideways, open (a throw).
static void drive_hand(const hand_rig *r, hs_world *w, int f) {
	double t = (f + 1) / rig_fps;
	double down = t < 1.0 ? 0.2 * (1.0 - t) : 0.0, close = t < 1.0 ? 0.0 : (t < 1.5 ? (t - 1.0) * 2.0 : 1.0);
	double lift = t < 1.5 ? 0.0 : (t < 3.0 ? (t - 1.5) * 0.3 : 0.45);
	double side = t < 2.0 ? 0.0 : (t - 2.0) * 2.0;
	if (t > 3.0)
		close = 0.0;
	uint8_t s[HS_GLOVE_SENSORS];
	for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
		s[i] = (uint8_t)(r->wide[i] + close * (r->grasp[i] - r->wide[i]) + 0.5);
	hs_vec3 grip = hs_v3(side, 0, 0.025 + down + lift);
	hs_quat turn = hs_quat_from_rpy(0.0, 0.0, 0.2 * (t > 2.0 ? t - 2.0 : 0.0));
	assert_int_equal(hs_world_set_hand(w, hs_world_hand_at(w, 0), hs_sub(grip, r->grip), turn, s), HS_OK);
}

static void step_hand(const hand_rig *r, hs_world *w, int first, int count, uint64_t *hashes) {
	for (int k = 0; k < count; ++k) {
		drive_hand(r, w, first + k);
		assert_int_equal(hs_world_step(w), HS_OK);
		if (hashes)
			hashes[k] = hs_world_hash(w);
	}
}

static unsigned char *save(const hs_world *w, size_t *size) {
	*size = hs_world_state_size(w);
	assert_true(*size > HEADER_WORDS * WORD);
	assert_int_equal(*size % WORD, 0);
	unsigned char *buffer = malloc(*size);
	assert_non_null(buffer);
	assert_int_equal(hs_world_save_state(w, buffer, *size), HS_OK);
	return buffer;
}

#define N_FRAMES 100 // t = 1.67 s: the cube is held and lifting, the block still in flight
#define M_FRAMES 160 // through the swing and the release

static void test_hand_world_continues_identically(void **state) {
	(void)state;
	hand_rig r = hand_world(0.05, 0, true);
	step_hand(&r, r.world, 0, N_FRAMES, NULL);
	hs_object_state target, flyer;
	assert_int_equal(hs_world_object_state(r.world, r.target, &target), HS_OK);
	assert_int_equal(hs_world_object_state(r.world, r.flyer, &flyer), HS_OK);
	assert_int_equal(target.contact, HS_CONTACT_GRASP); // a grasp in progress
	assert_true(flyer.position.z > 0.2);                // an object in flight
	hs_contact contacts[8];
	int n = hs_world_contacts(r.world, contacts, 8);
	assert_true(n >= 2);
	for (int k = 0; k < n && k < 8; ++k) { // the contacts' handles are the world's own
		hs_object_state cs;
		hs_vec3 points[HS_HAND_POINTS];
		assert_int_equal(hs_world_object_state(r.world, contacts[k].object, &cs), HS_OK);
		assert_int_equal(hs_world_hand_points(r.world, contacts[k].hand, points), HS_OK);
	}
	size_t size;
	unsigned char *buffer = save(r.world, &size);
	uint64_t at_n = hs_world_hash(r.world);
	hs_vec3 points[HS_HAND_POINTS], reloaded[HS_HAND_POINTS];
	drive_hand(&r, r.world, N_FRAMES); // the reading of the next frame is set: points and previous differ
	assert_int_equal(hs_world_hand_points(r.world, r.hand, points), HS_OK);
	hs_hand_ready_all(&r.world->state.hands[0]); // the lines are placed when read: all of them, to compare
	hs_hand cached = r.world->state.hands[0]; // its points and lines copied too: the hand's own pointers
	hs_vec3 cached_prev_points[HS_HAND_POINTS], cached_lines[HS_HAND_LINES][2], cached_prev_lines[HS_HAND_LINES][2];
	memcpy(cached_prev_points, cached.cache.prev_points, sizeof cached_prev_points);
	memcpy(cached_lines, cached.cache.lines, sizeof cached_lines);
	memcpy(cached_prev_lines, cached.cache.prev_lines, sizeof cached_prev_lines);
	unsigned char *set = save(r.world, &size);
	assert_int_equal(hs_world_load_state(r.world, set, size), HS_OK);
	assert_int_equal(hs_world_hand_points(r.world, r.hand, reloaded), HS_OK);
	assert_memory_equal(points, reloaded, sizeof points); // the caches are rebuilt bit for bit
	assert_memory_equal(cached_prev_points, r.world->state.hands[0].cache.prev_points, sizeof cached_prev_points);
	hs_hand_ready_all(&r.world->state.hands[0]);
	assert_memory_equal(cached_lines, r.world->state.hands[0].cache.lines, sizeof cached_lines);
	assert_memory_equal(cached_prev_lines, r.world->state.hands[0].cache.prev_lines, sizeof cached_prev_lines);
	assert_true(cached.cache.center.x == r.world->state.hands[0].cache.center.x && cached.cache.radius == r.world->state.hands[0].cache.radius);
	free(set);
	assert_int_equal(hs_world_load_state(r.world, buffer, size), HS_OK);
	uint64_t first[M_FRAMES], again[M_FRAMES], other[M_FRAMES];
	step_hand(&r, r.world, N_FRAMES, M_FRAMES, first);
	assert_int_equal(hs_world_load_state(r.world, buffer, size), HS_OK);
	assert_string_equal(hs_world_state_error(r.world), "");
	assert_true(hs_world_hash(r.world) == at_n);
	assert_int_equal(hs_world_frame(r.world), N_FRAMES);
	size_t size2;
	unsigned char *resaved = save(r.world, &size2); // the round trip is exact, byte for byte
	assert_int_equal(size2, size);
	assert_memory_equal(resaved, buffer, size);
	step_hand(&r, r.world, N_FRAMES, M_FRAMES, again);
	// a second world built by the same calls but without the skipping (bounding volumes, sleep,
	// grid: they change no result), never stepped, takes the state over
	hand_rig r2 = hand_world(0.05, 0, false);
	assert_int_equal(hs_world_load_state(r2.world, buffer, size), HS_OK);
	assert_true(hs_world_hash(r2.world) == at_n);
	step_hand(&r2, r2.world, N_FRAMES, M_FRAMES, other);
	for (int k = 0; k < M_FRAMES; ++k) {
		if (first[k] != again[k] || first[k] != other[k])
			fail_msg("frame %d after the save: hashes %016llx %016llx %016llx", N_FRAMES + k + 1,
			         (unsigned long long)first[k], (unsigned long long)again[k], (unsigned long long)other[k]);
	}
	assert_true(first[0] != first[M_FRAMES - 1]); // the world did move
	free(resaved);
	free(buffer);
	hs_world_destroy(r.world);
	hs_world_destroy(r2.world);
}


// A world of more objects than broadphase.c scans whole (HS_GRID_SCAN_MAX, 16): its grid's
// queries find fewer objects than all, and the hand's grasp and throw give the same hash every
// frame with skip_work on (the grid, sleep, bounding volumes) and off.
static void test_grid_world_same_bits(void **state) {
	(void)state;
	hand_rig on = hand_world(0.05, 20, true), off = hand_world(0.05, 20, false);
	uint64_t a[N_FRAMES + M_FRAMES], b[N_FRAMES + M_FRAMES];
	step_hand(&on, on.world, 0, N_FRAMES + M_FRAMES, a);
	step_hand(&off, off.world, 0, N_FRAMES + M_FRAMES, b);
	for (int k = 0; k < N_FRAMES + M_FRAMES; ++k)
		if (a[k] != b[k])
			fail_msg("frame %d: skip_work on %016llx, off %016llx", k + 1, (unsigned long long)a[k], (unsigned long long)b[k]);
	int n = on.world->model.object_count, *found = malloc((size_t)n * sizeof *found);
	assert_non_null(found);
	assert_int_equal(n, 24);
	int near = hs_grid_query(&on.world->model, &on.world->cache, hs_v3(-1.0, 0.0, 0.025), 0.05, found); // the first of the row
	assert_true(near >= 1 && near < n);
	assert_int_equal(hs_grid_query(&off.world->model, &off.world->cache, hs_v3(-1.0, 0.0, 0.025), 0.05, found), n); // off: all
	free(found);
	hs_world_destroy(on.world);
	hs_world_destroy(off.world);
}

// A world small enough to be scanned whole files no moved object in its grid (broadphase.c): one
// that grows past HS_GRID_SCAN_MAX while its cube is held and its block in flight files them all
// at its next step. Every object is then found where it is, and the bits are those of skip_work
// off; at 60 and at 12 frames/s (the script's times follow the rate).
static void grown_past_the_scan(double fps) {
	rig_max_objects = 24;
	rig_fps = fps;
	hand_rig on = hand_world(0.05, 0, true), off = hand_world(0.05, 0, false);
	rig_max_objects = 0;
	int before = (int)(N_FRAMES * fps / 60.0), after = (int)(M_FRAMES * fps / 60.0); // 1.67 s, then 2.67 s
	step_hand(&on, on.world, 0, before, NULL);
	step_hand(&off, off.world, 0, before, NULL);
	assert_true(on.world->state.bodies[on.target.index1 - 1].grasped_by > 0); // held as the world grows
	hs_world *w[2] = {on.world, off.world};
	for (int k = 0; k < 2; ++k) {
		hs_shape_id cube = add_shape(w[k], hs_shape_box(hs_v3(0.05, 0.05, 0.05), NULL));
		for (int i = 0; i < 20; ++i) // a row along the swing, past its end
			add_object(w[k], cube, hs_v3(0.2 + 0.1 * i, 0.12, 0.025), hs_v3(0, 0, 0));
	}
	uint64_t a[M_FRAMES], b[M_FRAMES];
	step_hand(&on, on.world, before, 1, a);
	step_hand(&off, off.world, before, 1, b);
	int n = on.world->model.object_count, *found = malloc((size_t)n * sizeof *found);
	assert_non_null(found);
	assert_int_equal(n, 24);
	for (int i = 0; i < n; ++i) { // the held cube and the block included, where they are now
		const hs_body *body = &on.world->state.bodies[i];
		int near = hs_grid_query(&on.world->model, &on.world->cache, body->pos, on.world->model.shapes[body->shape].radius, found), k = 0;
		while (k < near && found[k] != i)
			++k;
		if (k == near)
			fail_msg("%g frames/s: object %d not found where it is", fps, i);
		assert_true(near < n);
	}
	free(found);
	step_hand(&on, on.world, before + 1, after - 1, a + 1);
	step_hand(&off, off.world, before + 1, after - 1, b + 1);
	for (int k = 0; k < after; ++k)
		if (a[k] != b[k])
			fail_msg("%g frames/s, frame %d: skip_work on %016llx, off %016llx", fps, before + k + 1,
			         (unsigned long long)a[k], (unsigned long long)b[k]);
	hs_world_destroy(on.world);
	hs_world_destroy(off.world);
	rig_fps = 60.0;
}

static void test_grid_world_grown_past_the_scan(void **state) {
	(void)state;
	grown_past_the_scan(60.0);
	grown_past_the_scan(12.0);
}

// A state saved before the hand was first set, loaded into a world whose hand has been set since:
// the hand's cache of finger chains (not state) must not stand for the shape the load cleared.
// The next reading, the one last used before the load (every finger's chain in the cache), gives
// the points, lines and bounds a fresh world gives.
static void test_load_unset_hand_then_set(void **state) {
	(void)state;
	hand_rig r = hand_world(0.05, 0, true), fresh = hand_world(0.05, 0, true);
	size_t size;
	unsigned char *unset = save(r.world, &size);
	step_hand(&r, r.world, 0, 5, NULL);
	assert_int_equal(hs_world_load_state(r.world, unset, size), HS_OK);
	assert_int_equal(hs_world_load_state(fresh.world, unset, size), HS_OK);
	drive_hand(&r, r.world, 4);
	drive_hand(&fresh, fresh.world, 4);
	const hs_hand *a = &r.world->state.hands[0], *b = &fresh.world->state.hands[0];
	hs_hand_ready_all(&r.world->state.hands[0]);
	hs_hand_ready_all(&fresh.world->state.hands[0]);
	assert_memory_equal(a->cache.points, b->cache.points, sizeof a->cache.point_buf[0]);
	assert_memory_equal(a->cache.lines, b->cache.lines, sizeof a->cache.line_buf[0]);
	assert_memory_equal(a->cache.local->points, b->cache.local->points, sizeof a->cache.local->points);
	assert_true(a->cache.center.x == b->cache.center.x && a->cache.radius == b->cache.radius);
	assert_true(hs_world_hash(r.world) == hs_world_hash(fresh.world));
	free(unset);
	hs_world_destroy(r.world);
	hs_world_destroy(fresh.world);
}

// ---------------------------------------------------------------------------------------------
// A spring world: a ball on the spring swung by a moving stylus, a box sliding, tracker noise.

// Tracker noise is input (docs/model.md "Noise is input"): drawn here per frame from a generator
// seeded by the frame, so the frames after a load see the same readings as the frames after the
// save.
static bool stylus_noise;

static hs_vec3 noisy(hs_vec3 p, int f) {
	if (!stylus_noise)
		return p;
	gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
	assert_non_null(r);
	gsl_rng_set(r, 1000u + (unsigned long)f);
	for (int k = 0; k < 3; ++k) // ±0.76 mm per axis, the Fastrak's RMS
		(&p.x)[k] += 0.762e-3 * (2.0 * gsl_rng_uniform(r) - 1.0);
	gsl_rng_free(r);
	return p;
}

// A spring world of the spring definition sd, with two spheres and a box.
static hs_world *spring_world_with(bool noise, hs_object_id *ball, const hs_spring_def *sd) {
	hs_world_def def = hs_default_world_def();
	def.max_objects = 4;
	def.kind = HS_WORLD_SPRING;
	def.spring = *sd;
	hs_world *w = hs_world_create(&def, NULL);
	assert_non_null(w);
	stylus_noise = noise;
	hs_shape_id sphere = add_shape(w, hs_shape_sphere(0.05, NULL));
	hs_shape_id box = add_shape(w, hs_shape_box(hs_v3(0.1, 0.1, 0.1), NULL));
	*ball = add_object(w, sphere, hs_v3(0, 0, 0.05), hs_v3(0, 0, 0));
	add_object(w, box, hs_v3(1, 0, 0.05), hs_v3(-1, 0, 0));
	add_object(w, sphere, hs_v3(0.5, 0.3, 0.6), hs_v3(0, 0, 0));
	return w;
}

static hs_world *spring_world(bool noise, hs_object_id *ball) {
	hs_spring_def sd = hs_default_spring_def();
	return spring_world_with(noise, ball, &sd);
}

static void drive_stylus(hs_world *w, int f) {
	double t = (f + 1) / 60.0;
	hs_vec3 p = t < 1.0 ? hs_v3(0, 0, 0.2) : hs_v3(0.4 * hs_sin(2.0 * (t - 1.0)), 0.1 * (t - 1.0), 0.2 + 0.1 * (t - 1.0));
	p = noisy(p, f);
	assert_int_equal(hs_world_set_stylus(w, p, hs_quat_from_rpy(0.0, 0.0, 0.1 * t), t > 3.0 && t < 3.5), HS_OK);
}

static void step_spring(hs_world *w, int first, int count, uint64_t *hashes) {
	for (int k = 0; k < count; ++k) {
		drive_stylus(w, first + k);
		assert_int_equal(hs_world_step(w), HS_OK);
		hashes[k] = hs_world_hash(w);
	}
}

static void spring_round_trip(bool noise) {
	hs_object_id ball;
	hs_world *w = spring_world(noise, &ball);
	uint64_t warm[N_FRAMES];
	drive_stylus(w, 0);
	assert_int_equal(hs_world_spring_attach(w, ball), HS_OK);
	step_spring(w, 0, N_FRAMES, warm);
	hs_spring_state ss;
	assert_int_equal(hs_world_spring_state(w, &ss), HS_OK);
	assert_int_equal(ss.attached.index1, ball.index1); // an object on the spring
	size_t size;
	unsigned char *buffer = save(w, &size);
	uint64_t first[M_FRAMES], again[M_FRAMES], other[M_FRAMES];
	step_spring(w, N_FRAMES, M_FRAMES, first);
	hs_release rel;
	assert_int_equal(hs_world_spring_last_release(w, &rel), HS_OK);
	assert_int_not_equal(rel.kind, HS_RELEASE_NONE); // the button's release let it go
	assert_int_equal(hs_world_load_state(w, buffer, size), HS_OK);
	step_spring(w, N_FRAMES, M_FRAMES, again);
	hs_object_id ball2;
	hs_world *w2 = spring_world(noise, &ball2);
	assert_int_equal(hs_world_load_state(w2, buffer, size), HS_OK);
	step_spring(w2, N_FRAMES, M_FRAMES, other);
	for (int k = 0; k < M_FRAMES; ++k)
		if (first[k] != again[k] || first[k] != other[k])
			fail_msg("spring frame %d after the save: hashes differ", N_FRAMES + k + 1);
	free(buffer);
	hs_world_destroy(w);
	hs_world_destroy(w2);
}

static void test_spring_world_continues_identically(void **state) {
	(void)state;
	spring_round_trip(false);
}

static void test_spring_world_with_noise_continues_identically(void **state) {
	(void)state;
	spring_round_trip(true); // noisy readings reach the tracker and the spring
}

// ---------------------------------------------------------------------------------------------
// Refusals: the world is untouched and the reason names the problem.

static void put_word(unsigned char *buffer, size_t word, uint64_t v) {
	for (int i = 0; i < WORD; ++i)
		buffer[WORD * word + (size_t)i] = (unsigned char)(v >> (8 * i));
}

static uint64_t get_word(const unsigned char *buffer, size_t word) {
	uint64_t v = 0;
	for (int i = 0; i < WORD; ++i)
		v |= (uint64_t)buffer[WORD * word + (size_t)i] << (8 * i);
	return v;
}

static void expect_refused(hs_world *w, const void *buffer, size_t size, const char *reason) {
	uint64_t before = hs_world_hash(w);
	long frame = hs_world_frame(w);
	assert_int_equal(hs_world_load_state(w, buffer, size), HS_ERR_STATE_MISMATCH);
	const char *why = hs_world_state_error(w);
	if (!strstr(why, reason))
		fail_msg("refused with '%s', expected '%s'", why, reason);
	assert_true(hs_world_hash(w) == before);
	assert_int_equal(hs_world_frame(w), frame);
}

static void test_refusals(void **state) {
	(void)state;
	hand_rig r = hand_world(0.05, 0, true);
	step_hand(&r, r.world, 0, 30, NULL);
	size_t size;
	unsigned char *good = save(r.world, &size);
	unsigned char *bad = malloc(size + WORD);
	assert_non_null(bad);
	step_hand(&r, r.world, 30, 5, NULL); // the world has moved on: a refusal must not rewind it
	assert_int_equal(hs_world_load_state(NULL, good, size), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_load_state(r.world, NULL, size), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_save_state(r.world, bad, size - 1), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_save_state(NULL, bad, size), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_state_size(NULL), 0);
	expect_refused(r.world, good, 3 * WORD, "too short");
	expect_refused(r.world, good, size - WORD, "bytes where");
	memcpy(bad, good, size);
	bad[size] = 0;
	expect_refused(r.world, bad, size + WORD, "bytes where");
	const struct {
		size_t word;
		const char *reason;
	} header[] = {{0, "magic"}, {1, "format version"}, {2, "library version"}, {3, "kind of world"},
	              {4, "object count"}, {5, "hand count"}, {6, "shape count"}, {7, "contact capacity"},
	              {8, "world definition"}};
	for (size_t k = 0; k < sizeof header / sizeof header[0]; ++k) {
		memcpy(bad, good, size);
		put_word(bad, header[k].word, get_word(bad, header[k].word) + 1);
		expect_refused(r.world, bad, size, header[k].reason);
	}
	// a NaN in the first object's position, an enum and an index out of range
	double nan = NAN;
	uint64_t nan_bits;
	memcpy(&nan_bits, &nan, sizeof nan_bits);
	size_t body0 = HEADER_WORDS + 4; // after frame, faults, first fault frame and object
	memcpy(bad, good, size);
	put_word(bad, body0 + 2, nan_bits);
	expect_refused(r.world, bad, size, "non-finite");
	memcpy(bad, good, size);
	put_word(bad, body0 + 21, 7); // contact state
	expect_refused(r.world, bad, size, "out of range");
	memcpy(bad, good, size);
	put_word(bad, body0 + 27, 2); // grasped_by: the world has one hand
	expect_refused(r.world, bad, size, "out of range");
	memcpy(bad, good, size);
	put_word(bad, body0 + 6, 0); // rot.w: no longer a unit quaternion
	expect_refused(r.world, bad, size, "unit quaternion");
	free(bad);
	free(good);
	hs_world_destroy(r.world);
}

static void test_refuses_other_worlds(void **state) {
	(void)state;
	hand_rig r = hand_world(0.05, 0, true);
	size_t size;
	unsigned char *hand_state = save(r.world, &size);
	hand_rig bigger = hand_world(0.05, 1, true); // another object count
	expect_refused(bigger.world, hand_state, size, "object count");
	hand_rig other_shape = hand_world(0.06, 0, true); // the same counts, another cube
	expect_refused(other_shape.world, hand_state, size, "world definition");
	rig_any_contacts = true; // the same world with the paper's grasp rule
	hand_rig other_rule = hand_world(0.05, 0, true);
	rig_any_contacts = false;
	expect_refused(other_rule.world, hand_state, size, "world definition");
	hs_world_destroy(other_rule.world);
	hs_object_id ball;
	hs_world *springs = spring_world(false, &ball);
	size_t spring_size;
	unsigned char *spring_state = save(springs, &spring_size);
	expect_refused(r.world, spring_state, spring_size, "kind of world");
	expect_refused(springs, hand_state, size, "kind of world");
	hs_spring_def sd = hs_default_spring_def();
	sd.friction_static = 0.7; // another spring definition
	hs_world *noisy = spring_world_with(false, &ball, &sd);
	expect_refused(noisy, spring_state, spring_size, "spring definition");
	free(hand_state);
	free(spring_state);
	hs_world_destroy(r.world);
	hs_world_destroy(bigger.world);
	hs_world_destroy(other_shape.world);
	hs_world_destroy(springs);
	hs_world_destroy(noisy);
}

// ---------------------------------------------------------------------------------------------
// The hash sees every state field: change any one saved word (its lowest bit) and load it; every
// buffer that loads hashes differently from the original.

// zero_tail: words of the slots beyond a count that must stay zero (the spring's warm-start
// forces, which the hash leaves out): a change there must be refused.
static void every_word_changes_the_hash(hs_world *w, size_t zero_tail) {
	size_t size;
	unsigned char *good = save(w, &size);
	unsigned char *bad = malloc(size);
	assert_non_null(bad);
	uint64_t original = hs_world_hash(w);
	size_t words = size / WORD, loaded = 0, refused = 0;
	for (size_t k = HEADER_WORDS; k < words; ++k) {
		memcpy(bad, good, size);
		put_word(bad, k, get_word(bad, k) ^ 1u);
		if (hs_world_load_state(w, bad, size) != HS_OK) {
			++refused; // out of range once changed (a count, a flag, a zero slot): refused, not hashed
			continue;
		}
		++loaded;
		if (hs_world_hash(w) == original)
			fail_msg("word %zu of %zu changed, hash unchanged", k, words);
	}
	assert_int_equal(hs_world_load_state(w, good, size), HS_OK);
	assert_true(hs_world_hash(w) == original);
	assert_true(refused >= zero_tail);
	assert_true(loaded > (words - HEADER_WORDS - zero_tail) * 9 / 10);
	free(bad);
	free(good);
}

static void test_hash_sees_every_field(void **state) {
	(void)state;
	hand_rig r = hand_world(0.05, 0, true);
	step_hand(&r, r.world, 0, N_FRAMES, NULL);
	every_word_changes_the_hash(r.world, 0);
	hs_object_id ball;
	hs_world *springs = spring_world(true, &ball);
	uint64_t hashes[40];
	step_spring(springs, 0, 40, hashes);
	const hs_spring_system *sys = springs->state.spring;
	every_word_changes_the_hash(springs, (size_t)(sys->touch_capacity - sys->warm_count) * 6);
	hs_world_destroy(r.world);
	hs_world_destroy(springs);
}

// A release window longer than the default keeps more wrist poses (docs/model.md §4 "Release"):
// 0.16 s at 120 frames/s is 19 frames, 18 older poses a hand where the default keeps 7. The state
// grows by 11 × 7 words and covers them: a run resumed across the quadratic fit's release is bit
// for bit the run saved, in the same world and in another built alike; every word is hashed; a
// world with the default window or the mean fit refuses the state.
static hand_rig long_window_world(hs_release_fit fit, double window, bool skip_work) {
	rig_release_fit = fit;
	rig_release_window = window;
	hand_rig r = hand_world(0.05, 0, skip_work);
	rig_release_fit = HS_RELEASE_FIT_MEAN;
	rig_release_window = 0.05;
	return r;
}

static void test_long_release_window_continues_identically(void **state) {
	(void)state;
	rig_fps = 120.0; // the worlds below and their input
	hand_rig plain = long_window_world(HS_RELEASE_FIT_MEAN, 0.05, true);
	hand_rig mean = long_window_world(HS_RELEASE_FIT_MEAN, 0.16, true);
	hand_rig r = long_window_world(HS_RELEASE_FIT_QUADRATIC, 0.16, true);
	assert_int_equal(r.world->state.hands[0].model.older_capacity, 18);
	assert_int_equal(hs_world_state_size(r.world) - hs_world_state_size(plain.world), WORD * 11 * 7);
	step_hand(&r, r.world, 0, 2 * N_FRAMES, NULL); // t = 1.67 s: held and lifting, the history full
	hs_object_state target;
	assert_int_equal(hs_world_object_state(r.world, r.target, &target), HS_OK);
	assert_int_equal(target.contact, HS_CONTACT_GRASP);
	assert_int_equal(r.world->state.hands[0].state.older_count, 18);
	size_t size;
	unsigned char *buffer = save(r.world, &size);
	uint64_t first[2 * M_FRAMES], again[2 * M_FRAMES], other[2 * M_FRAMES];
	step_hand(&r, r.world, 2 * N_FRAMES, 2 * M_FRAMES, first);
	assert_int_equal(hs_world_object_state(r.world, r.target, &target), HS_OK);
	assert_int_equal(target.contact, HS_CONTACT_NONE); // thrown
	assert_int_equal(hs_world_load_state(r.world, buffer, size), HS_OK);
	step_hand(&r, r.world, 2 * N_FRAMES, 2 * M_FRAMES, again);
	hand_rig r2 = long_window_world(HS_RELEASE_FIT_QUADRATIC, 0.16, false);
	assert_int_equal(hs_world_load_state(r2.world, buffer, size), HS_OK);
	step_hand(&r2, r2.world, 2 * N_FRAMES, 2 * M_FRAMES, other);
	for (int k = 0; k < 2 * M_FRAMES; ++k)
		if (first[k] != again[k] || first[k] != other[k])
			fail_msg("frame %d after the save: hashes differ", 2 * N_FRAMES + k + 1);
	assert_int_equal(hs_world_load_state(r.world, buffer, size), HS_OK);
	every_word_changes_the_hash(r.world, 0); // the 18 older poses included
	expect_refused(plain.world, buffer, size, "world definition");
	expect_refused(mean.world, buffer, size, "world definition");
	free(buffer);
	hs_world_destroy(plain.world);
	hs_world_destroy(mean.world);
	hs_world_destroy(r.world);
	hs_world_destroy(r2.world);
	rig_fps = 60.0;
}

// The hash after fields were written by hand, not through the library's calls (which mark what
// they change): its kept object digests are dropped first.
static uint64_t rehash(hs_world *w) {
	hs_digest_all_stale(&w->cache);
	return hs_world_hash(w);
}

// Fields the old hash (poses and contact states only) missed: each changes the hash now.
static void test_hash_sees_what_the_old_one_missed(void **state) {
	(void)state;
	hand_rig r = hand_world(0.05, 0, true);
	step_hand(&r, r.world, 0, N_FRAMES, NULL);
	hs_world *w = r.world;
	uint64_t h = hs_world_hash(w);
	hs_body saved = w->state.bodies[1];
	w->state.bodies[1].prev.x += 1e-9; // the velocity of a flying object
	assert_true(rehash(w) != h);
	w->state.bodies[1] = saved;
	w->state.bodies[1].spin.x = -w->state.bodies[1].spin.x;
	assert_true(rehash(w) != h);
	w->state.bodies[1] = saved;
	w->state.bodies[1].asleep ^= 1;
	assert_true(rehash(w) != h);
	w->state.bodies[1] = saved;
	w->state.bodies[0].grip_pos.y += 1e-12;
	assert_true(rehash(w) != h);
	w->state.bodies[0].grip_pos.y -= 1e-12;
	w->state.hands[0].state.sensors[3] ^= 1;
	assert_true(rehash(w) != h);
	w->state.hands[0].state.sensors[3] ^= 1;
	w->state.hands[0].state.prev_wrist_pos.z += 1e-9; // where the previous check points were placed from
	assert_true(rehash(w) != h);
	w->state.hands[0].state.prev_wrist_pos.z -= 1e-9;
	w->state.hands[0].state.prev_sensors[7] ^= 1;
	assert_true(rehash(w) != h);
	w->state.hands[0].state.prev_sensors[7] ^= 1;
	assert_true(rehash(w) == h);
	hs_world_destroy(w);
}

// A world rebuilt through the public API from the public object states at frame N is not the
// same world: its previous positions come from the reported velocity, not the Verlet history.
static void test_rebuilt_world_hashes_differently(void **state) {
	(void)state;
	hs_world_def def = hs_default_world_def();
	hs_world *a = hs_world_create(&def, NULL), *b = hs_world_create(&def, NULL);
	hs_shape_id sa = add_shape(a, hs_shape_box(hs_v3(0.1, 0.06, 0.04), NULL));
	hs_shape_id sb = add_shape(b, hs_shape_box(hs_v3(0.1, 0.06, 0.04), NULL));
	add_object(a, sa, hs_v3(0, 0, 2), hs_v3(1.0 / 3.0, 0.1, 3.0));
	for (int f = 0; f < 25; ++f)
		assert_int_equal(hs_world_step(a), HS_OK);
	hs_object_state st;
	assert_int_equal(hs_world_object_state(a, hs_world_object_at(a, 0), &st), HS_OK);
	hs_object_def od = hs_default_object_def();
	od.shape = sb;
	od.position = st.position;
	od.orientation = st.orientation;
	od.velocity = st.velocity;
	assert_int_not_equal(hs_world_add_object(b, &od, NULL).index1, 0);
	assert_true(hs_world_hash(a) != hs_world_hash(b)); // the old hash called them equal
	assert_int_equal(hs_world_step(a), HS_OK);
	assert_int_equal(hs_world_step(b), HS_OK);
	hs_object_state sa1, sb1;
	hs_world_object_state(a, hs_world_object_at(a, 0), &sa1);
	hs_world_object_state(b, hs_world_object_at(b, 0), &sb1);
	assert_true(sa1.position.z != sb1.position.z); // and indeed they do not continue identically
	hs_world_destroy(a);
	hs_world_destroy(b);
}

// The first numeric fault is remembered (frame and object) and travels with the state.
static void test_first_fault(void **state) {
	(void)state;
	hand_rig r = hand_world(0.05, 0, true);
	long frame = 0;
	hs_object_id object = r.target;
	assert_int_equal(hs_world_first_fault(NULL, &frame, &object), HS_ERR_INVALID_ARGUMENT);
	assert_int_equal(hs_world_first_fault(r.world, &frame, &object), HS_OK);
	assert_int_equal(frame, -1);
	assert_int_equal(object.index1, 0);
	step_hand(&r, r.world, 0, 10, NULL);
	size_t size;
	unsigned char *clean = save(r.world, &size);
	hs_world_note_fault(&r.world->counters, &r.world->state, 1); // as the step does when it freezes an object
	step_hand(&r, r.world, 10, 3, NULL);
	hs_world_note_fault(&r.world->counters, &r.world->state, 2);
	assert_int_equal(hs_world_get_counters(r.world).numeric_faults, 2);
	assert_int_equal(hs_world_first_fault(r.world, &frame, &object), HS_OK);
	assert_int_equal(frame, 10);
	assert_true(object.index1 == r.flyer.index1 && object.world == r.flyer.world);
	unsigned char *faulted = save(r.world, &size);
	assert_int_equal(hs_world_load_state(r.world, clean, size), HS_OK);
	assert_int_equal(hs_world_first_fault(r.world, &frame, NULL), HS_OK);
	assert_int_equal(frame, -1);
	assert_int_equal(hs_world_get_counters(r.world).numeric_faults, 0);
	assert_int_equal(hs_world_load_state(r.world, faulted, size), HS_OK);
	assert_int_equal(hs_world_first_fault(r.world, &frame, &object), HS_OK);
	assert_int_equal(frame, 10);
	free(clean);
	free(faulted);
	hs_world_destroy(r.world);
}

// The seed scene's world (scenarios/seed_scene.yaml: ten 5 cm cubes, no hand): its state size.
static void test_seed_scene_size(void **state) {
	(void)state;
	hs_error err;
	hs_scenario *s = hs_scenario_load("scenarios/seed_scene.yaml", &err);
	if (!s)
		fail_msg("%s", err.message);
	size_t size = hs_world_state_size(hs_scenario_world(s));
	printf("seed scene: %d objects, state %zu bytes (%zu words)\n", hs_world_object_count(hs_scenario_world(s)),
	       size, size / WORD);
	assert_int_equal(size, WORD * (HEADER_WORDS + 4 + 39 * (size_t)hs_world_object_count(hs_scenario_world(s))));
	hs_scenario_destroy(s);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_hand_world_continues_identically),
	    cmocka_unit_test(test_load_unset_hand_then_set),
	    cmocka_unit_test(test_grid_world_same_bits),
	    cmocka_unit_test(test_grid_world_grown_past_the_scan),
	    cmocka_unit_test(test_spring_world_continues_identically),
	    cmocka_unit_test(test_spring_world_with_noise_continues_identically),
	    cmocka_unit_test(test_refusals),
	    cmocka_unit_test(test_refuses_other_worlds),
	    cmocka_unit_test(test_hash_sees_every_field),
	    cmocka_unit_test(test_long_release_window_continues_identically),
	    cmocka_unit_test(test_hash_sees_what_the_old_one_missed),
	    cmocka_unit_test(test_rebuilt_world_hashes_differently),
	    cmocka_unit_test(test_first_fault),
	    cmocka_unit_test(test_seed_scene_size),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
