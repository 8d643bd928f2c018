// test_spring_technique.c — the workbench paper's techniques beyond the spring (§2.2, §3;
// docs/techniques.md): slave, stick, cross-plane, cross-surface, the magnet gesture, the release
// back home, massless objects, and their state saved, loaded and hashed.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "test_util.h"

static const double DT = 1.0 / 60.0;
static const hs_vec3 EARTH = {0.0, 0.0, -9.81};

static hs_world *tech_world(bool techniques) {
	hs_world_def def = hs_default_world_def();
	def.dt = DT;
	def.gravity = EARTH;
	def.kind = HS_WORLD_SPRING;
	def.spring = hs_default_spring_def();
	def.spring.techniques = techniques;
	hs_status st;
	hs_world *w = hs_world_create(&def, &st);
	assert_non_null(w);
	return w;
}

static hs_object_id add_cube(hs_world *w, double size, double mass, hs_vec3 pos) {
	hs_status st;
	return hs_test_add_mass(w, hs_shape_box(hs_v3(size, size, size), &st), mass, pos, hs_v3(0.0, 0.0, 0.0));
}

static hs_object_state state_of(hs_world *w, hs_object_id id) {
	hs_object_state s;
	assert_int_equal(hs_world_object_state(w, id, &s), HS_OK);
	return s;
}

static void set_technique(hs_world *w, hs_technique t, hs_release_mode r) {
	hs_technique_def d = hs_default_technique_def();
	d.technique = t;
	d.release = r;
	assert_int_equal(hs_world_spring_set_technique(w, &d), HS_OK);
}

static void frame(hs_world *w, hs_vec3 s, hs_quat q, bool button) {
	assert_int_equal(hs_world_set_stylus(w, s, q, button), HS_OK);
	assert_int_equal(hs_world_step(w), HS_OK);
}

static hs_quat yaw(double deg) { return hs_quat_from_axis_angle(hs_v3(0.0, 0.0, 1.0), deg * HS_PI / 180.0); }
static hs_quat pitch(double deg) { return hs_quat_from_axis_angle(hs_v3(0.0, 1.0, 0.0), deg * HS_PI / 180.0); }

// Off by default: no settings, no massless objects; on: both.
static void test_off_by_default(void **state) {
	(void)state;
	hs_world *w = tech_world(false);
	hs_technique_def d = hs_default_technique_def();
	assert_int_equal(hs_world_spring_set_technique(w, &d), HS_ERR_INVALID_ARGUMENT);
	hs_status st;
	hs_object_def od = hs_default_object_def();
	hs_shape *box = hs_shape_box(hs_v3(0.1, 0.1, 0.1), &st); // the world copies it
	od.shape = hs_world_add_shape(w, box, &st);
	od.density = 0.0;
	hs_world_add_object(w, &od, &st);
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	hs_world_destroy(w);
	w = tech_world(true);
	assert_int_equal(hs_world_spring_set_technique(w, &d), HS_OK);
	d.magnet_near = d.magnet_far; // the working sphere must lie inside the extended arm's
	assert_int_equal(hs_world_spring_set_technique(w, &d), HS_ERR_INVALID_ARGUMENT);
	d = hs_default_technique_def();
	d.technique = (hs_technique)7;
	assert_int_equal(hs_world_spring_set_technique(w, &d), HS_ERR_INVALID_ARGUMENT);
	od.shape = hs_world_add_shape(w, box, &st);
	hs_world_add_object(w, &od, &st);
	assert_int_equal(st, HS_OK);
	hs_world_destroy(w);
	hs_shape_destroy(box);
}

// Slave: the pen's translation since the grab, and its turn about the object's own G.
static void test_slave_follows_pen(void **state) {
	(void)state;
	hs_world *w = tech_world(true);
	set_technique(w, HS_TECHNIQUE_SLAVE, HS_RELEASE_MODE_HAND);
	hs_object_id c = add_cube(w, 0.1, 1.0, hs_v3(0.3, 0.0, 0.05));
	hs_vec3 s0 = hs_v3(0.32, 0.01, 0.06); // inside, off centre
	frame(w, s0, hs_quat_identity(), false);
	frame(w, s0, hs_quat_identity(), true); // the press: a direct pick
	hs_spring_state ss;
	assert_int_equal(hs_world_spring_state(w, &ss), HS_OK);
	assert_int_equal(ss.technique, HS_TECHNIQUE_SLAVE);
	assert_int_equal(ss.attach_kind, HS_ATTACH_PICK);
	for (int k = 1; k <= 30; ++k) {
		double u = k / 30.0;
		hs_vec3 s = hs_add(s0, hs_v3(0.0, 0.2 * u, 0.3 * u));
		frame(w, s, yaw(90.0 * u), true);
		hs_object_state o = state_of(w, c);
		assert_vec3_near(o.position, hs_add(hs_v3(0.3, 0.0, 0.05), hs_v3(0.0, 0.2 * u, 0.3 * u)), 1e-12);
		assert_near(hs_quat_angle(o.orientation), 90.0 * u * HS_PI / 180.0, 1e-9);
	}
	assert_int_equal(hs_world_spring_state(w, &ss), HS_OK);
	assert_near(ss.extension, 0.0, 0.0); // no spring
	assert_vec3_near(ss.force, hs_v3(0.0, 0.0, 0.0), 0.0);
	hs_world_destroy(w);
}

// Stick: rigid on the pen, turning about the hand (API attach takes the technique too).
static void test_stick_turns_about_hand(void **state) {
	(void)state;
	hs_world *w = tech_world(true);
	set_technique(w, HS_TECHNIQUE_STICK, HS_RELEASE_MODE_HAND);
	hs_object_id c = add_cube(w, 0.1, 1.0, hs_v3(1.0, 0.0, 0.05));
	hs_vec3 s = hs_v3(0.0, 0.0, 0.3);
	frame(w, s, hs_quat_identity(), false);
	assert_int_equal(hs_world_spring_attach(w, c), HS_OK);
	for (int k = 1; k <= 20; ++k)
		frame(w, s, yaw(4.5 * k), false);
	hs_object_state o = state_of(w, c);
	assert_vec3_near(o.position, hs_v3(0.0, 1.0, 0.3 - 0.25), 1e-12); // (1, 0, -0.25) turned 90 deg
	assert_near(hs_quat_angle(o.orientation), HS_PI / 2.0, 1e-9);
	// the spring would have let it sag: with it, the same turn leaves it far from there
	hs_world_destroy(w);
}

// Cross-plane: G on z = G0.z where the pointing ray meets it; a ray that misses leaves it.
static void test_cross_plane(void **state) {
	(void)state;
	hs_world *w = tech_world(true);
	set_technique(w, HS_TECHNIQUE_CROSS_PLANE, HS_RELEASE_MODE_HAND);
	hs_object_id c = add_cube(w, 0.1, 1.0, hs_v3(0.25, 0.0, 0.05));
	hs_quat down45 = pitch(45.0);
	hs_vec3 s = hs_v3(0.0, 0.0, 0.3); // the ray meets z = 0.05 at x = 0.25: G0
	frame(w, s, down45, false);
	assert_int_equal(hs_world_spring_attach(w, c), HS_OK);
	frame(w, hs_v3(0.1, 0.2, 0.4), down45, false); // reach 0.35 from x = 0.1
	assert_vec3_near(state_of(w, c).position, hs_v3(0.45, 0.2, 0.05), 1e-12);
	frame(w, hs_v3(0.1, 0.2, 0.4), pitch(-10.0), false); // pointing up: misses, stays
	assert_vec3_near(state_of(w, c).position, hs_v3(0.45, 0.2, 0.05), 1e-12);
	hs_world_destroy(w);
}

// Cross-surface: the first surface along the ray (another object's top, else the floor).
static void test_cross_surface(void **state) {
	(void)state;
	hs_world *w = tech_world(true);
	set_technique(w, HS_TECHNIQUE_CROSS_SURFACE, HS_RELEASE_MODE_HAND);
	hs_object_id c = add_cube(w, 0.1, 1.0, hs_v3(-0.5, 0.0, 0.05));
	hs_status st;
	hs_test_add_mass(w, hs_shape_box(hs_v3(0.4, 0.4, 0.2), &st), 10.0, hs_v3(1.0, 0.0, 0.1), hs_v3(0.0, 0.0, 0.0));
	hs_quat down45 = pitch(45.0);
	frame(w, hs_v3(0.0, 0.0, 0.5), down45, false);
	assert_int_equal(hs_world_spring_attach(w, c), HS_OK);
	frame(w, hs_v3(0.0, 0.0, 0.5), down45, false); // the floor at x = 0.5
	assert_vec3_near(state_of(w, c).position, hs_v3(0.5, 0.0, 0.05), 1e-12);
	frame(w, hs_v3(0.6, 0.1, 0.5), down45, false); // the block's top (z = 0.2) at x = 0.9
	assert_vec3_near(state_of(w, c).position, hs_v3(0.9, 0.1, 0.25), 1e-12);
	hs_world_destroy(w);
}

// The magnet: extended toward a candidate, then into the working sphere in time; not when slow.
static bool magnet_run(double pull_s) {
	hs_world *w = tech_world(true);
	hs_technique_def d = hs_default_technique_def();
	d.magnet = true;
	d.body = hs_v3(0.0, 0.0, 0.3);
	assert_int_equal(hs_world_spring_set_technique(w, &d), HS_OK);
	hs_object_id c = add_cube(w, 0.1, 1.0, hs_v3(1.5, 0.0, 0.05));
	hs_quat aim = pitch(atan(0.25 / 0.8) * 180.0 / HS_PI);
	for (int k = 0; k < 40; ++k) // extended and still: ray casting picks the cube
		frame(w, hs_v3(0.7, 0.0, 0.3), aim, false);
	int n = (int)llround(pull_s / DT);
	for (int k = 1; k <= n; ++k)
		frame(w, hs_v3(0.7 - 0.5 * k / n, 0.0, 0.3), aim, false);
	hs_spring_state ss;
	assert_int_equal(hs_world_spring_state(w, &ss), HS_OK);
	bool grabbed = ss.attach_kind == HS_ATTACH_MAGNET;
	if (grabbed)
		assert_vec3_near(state_of(w, c).position, hs_v3(0.2, 0.0, 0.3), 1e-12);
	else
		assert_vec3_near(state_of(w, c).position, hs_v3(1.5, 0.0, 0.05), 1e-12);
	hs_world_destroy(w);
	return grabbed;
}

static void test_magnet_gesture(void **state) {
	(void)state;
	assert_true(magnet_run(0.4));  // 0.5 m in 0.4 s: far to near in 0.2 s
	assert_false(magnet_run(2.0)); // 0.5 m in 2 s: far to near in 1 s > 0.6 s
}

// Release back home: even from the spring, a button release puts the object back, at rest.
static void test_release_return(void **state) {
	(void)state;
	hs_world *w = tech_world(true);
	set_technique(w, HS_TECHNIQUE_SPRING, HS_RELEASE_MODE_RETURN);
	hs_object_id c = add_cube(w, 0.1, 1.0, hs_v3(0.0, 0.0, 0.05));
	hs_vec3 s = hs_v3(0.0, 0.0, 0.05);
	frame(w, s, hs_quat_identity(), false);
	frame(w, s, hs_quat_identity(), true);
	for (int k = 1; k <= 60; ++k)
		frame(w, hs_v3(0.01 * k, 0.0, 0.05 + 0.005 * k), hs_quat_identity(), true);
	assert_true(state_of(w, c).position.z > 0.2);
	frame(w, hs_v3(0.6, 0.0, 0.35), hs_quat_identity(), false); // released moving
	hs_release r;
	assert_int_equal(hs_world_spring_last_release(w, &r), HS_OK);
	assert_int_equal(r.kind, HS_RELEASE_RETURN);
	assert_vec3_near(r.velocity, hs_v3(0.0, 0.0, 0.0), 0.0);
	assert_vec3_near(state_of(w, c).position, hs_v3(0.0, 0.0, 0.05), 0.0);
	frame(w, hs_v3(0.6, 0.0, 0.35), hs_quat_identity(), false);
	assert_vec3_near(state_of(w, c).position, hs_v3(0.0, 0.0, 0.05), 0.0);
	hs_world_destroy(w);
}

// Massless: no weight (it floats), nothing to meet (a ball falls through), held as the slave,
// no velocity kept at a release, and finite spring numbers.
static void test_massless(void **state) {
	(void)state;
	hs_world *w = tech_world(true);
	hs_object_id f = add_cube(w, 0.1, 0.0, hs_v3(0.0, 0.0, 0.5));
	hs_status st;
	hs_object_id b = hs_test_add_mass(w, hs_shape_sphere(0.05, &st), 1.0, hs_v3(0.0, 0.0, 0.9), hs_v3(0.0, 0.0, 0.0));
	hs_vec3 s = hs_v3(0.5, 0.0, 0.5);
	for (int k = 0; k < 60; ++k)
		frame(w, s, hs_quat_identity(), false);
	hs_object_state o = state_of(w, f);
	assert_vec3_near(o.position, hs_v3(0.0, 0.0, 0.5), 0.0);
	assert_vec3_near(state_of(w, b).position, hs_v3(0.0, 0.0, 0.05), 1e-9); // fell through it
	hs_spring_object so;
	assert_int_equal(hs_world_spring_object(w, f, &so), HS_OK);
	assert_near(so.mass, 0.0, 0.0);
	assert_true(isfinite(so.omega) && isfinite(so.stiffness) && isfinite(so.damping));
	frame(w, hs_v3(0.0, 0.0, 0.5), hs_quat_identity(), false);
	frame(w, hs_v3(0.0, 0.0, 0.5), hs_quat_identity(), true); // inside: a pick, held as the slave
	hs_spring_state ss;
	assert_int_equal(hs_world_spring_state(w, &ss), HS_OK);
	assert_int_equal(ss.attach_kind, HS_ATTACH_PICK);
	assert_int_equal(ss.technique, HS_TECHNIQUE_SLAVE);
	for (int k = 1; k <= 30; ++k)
		frame(w, hs_v3(0.01 * k, 0.0, 0.5), hs_quat_identity(), true);
	assert_vec3_near(state_of(w, f).position, hs_v3(0.3, 0.0, 0.5), 1e-12);
	frame(w, hs_v3(0.31, 0.0, 0.5), hs_quat_identity(), false); // released moving
	for (int k = 0; k < 30; ++k)
		frame(w, hs_v3(0.31, 0.0, 0.5), hs_quat_identity(), false);
	assert_vec3_near(state_of(w, f).position, hs_v3(0.31, 0.0, 0.5), 1e-12);
	hs_world_destroy(w);
}

// The techniques' state round-trips: a save mid-hold, loaded after the settings and the hold
// changed, replays the same frames bit for bit; and the fields are in the hash.
static void run_frames(hs_world *w, int from, int n, uint64_t *hashes) {
	for (int k = 0; k < n; ++k) {
		int f = from + k;
		frame(w, hs_v3(0.01 * f, 0.002 * f, 0.3), hs_quat_mul(yaw(1.0 * f), pitch(9.46)), f < 70);
		hashes[k] = hs_world_hash(w);
	}
}

static void test_state_round_trip(void **state) {
	(void)state;
	hs_world *w = tech_world(true);
	hs_technique_def d = hs_default_technique_def();
	d.technique = HS_TECHNIQUE_STICK;
	d.release = HS_RELEASE_MODE_RETURN;
	d.magnet = true;
	d.body = hs_v3(-0.1, 0.0, 0.3);
	assert_int_equal(hs_world_spring_set_technique(w, &d), HS_OK);
	add_cube(w, 0.1, 1.0, hs_v3(1.5, 0.0, 0.05));
	add_cube(w, 0.1, 0.0, hs_v3(0.5, 0.5, 0.4));
	uint64_t first[40], again[40];
	run_frames(w, 0, 40, first); // pressed at frame 0: the cube is on the stick
	hs_spring_state ss;
	assert_int_equal(hs_world_spring_state(w, &ss), HS_OK);
	assert_int_equal(ss.technique, HS_TECHNIQUE_STICK);
	size_t size = hs_world_state_size(w);
	void *buf = malloc(size);
	assert_non_null(buf);
	assert_int_equal(hs_world_save_state(w, buf, size), HS_OK);
	run_frames(w, 40, 40, first); // on past the release (frame 70): sent home
	hs_technique_def other = hs_default_technique_def();
	assert_int_equal(hs_world_spring_set_technique(w, &other), HS_OK);
	assert_int_equal(hs_world_load_state(w, buf, size), HS_OK);
	hs_technique_def back;
	assert_int_equal(hs_world_spring_technique(w, &back), HS_OK);
	assert_int_equal(back.technique, HS_TECHNIQUE_STICK);
	assert_int_equal(back.release, HS_RELEASE_MODE_RETURN);
	assert_true(back.magnet);
	assert_vec3_near(back.body, d.body, 0.0);
	run_frames(w, 40, 40, again);
	for (int k = 0; k < 40; ++k)
		assert_true(first[k] == again[k]);
	hs_release r;
	assert_int_equal(hs_world_spring_last_release(w, &r), HS_OK);
	assert_int_equal(r.kind, HS_RELEASE_RETURN);
	// the settings are hashed: changing one changes the hash
	uint64_t h = hs_world_hash(w);
	assert_int_equal(hs_world_spring_set_technique(w, &other), HS_OK);
	assert_true(hs_world_hash(w) != h);
	// and off, the state is smaller: the techniques' fields are walked only when on
	hs_world *off = tech_world(false);
	add_cube(off, 0.1, 1.0, hs_v3(1.5, 0.0, 0.05));
	add_cube(off, 0.1, 1.0, hs_v3(0.5, 0.5, 0.4));
	assert_true(hs_world_state_size(off) < size);
	hs_world_destroy(off);
	free(buf);
	hs_world_destroy(w);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_off_by_default),   cmocka_unit_test(test_slave_follows_pen),
	    cmocka_unit_test(test_stick_turns_about_hand), cmocka_unit_test(test_cross_plane),
	    cmocka_unit_test(test_cross_surface),    cmocka_unit_test(test_magnet_gesture),
	    cmocka_unit_test(test_release_return),   cmocka_unit_test(test_massless),
	    cmocka_unit_test(test_state_round_trip),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
