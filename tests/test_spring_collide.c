// test_spring_collide.c — object–object contact of the spring model on the true shapes (§4.5:
// "physical contact of objects is intuitively equivalent with geometric intersection"): turned
// boxes by closest point and separating axes, other shapes through libccd, against closed forms.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "spring_collide.h"
#include "spring_touch.h"
#include "test_util.h"

#define SQRT1_2 0.70710678118654752440

typedef struct pair {
	hs_world *world;
	hs_spring_geom ga, gb;
} pair;

// A spring world with shapes a and b (taken over) at the origin in the given orientations.
static pair make_pair(hs_shape *a, hs_quat ra, hs_shape *b, hs_quat rb) {
	hs_world_def def = hs_default_world_def();
	def.kind = HS_WORLD_SPRING;
	hs_status st;
	pair p;
	p.world = hs_world_create(&def, &st);
	assert_non_null(p.world);
	hs_shape *shapes[2] = {a, b};
	hs_quat rots[2] = {ra, rb};
	for (int k = 0; k < 2; ++k) {
		assert_non_null(shapes[k]);
		hs_object_def od = hs_default_object_def();
		od.shape = hs_world_add_shape(p.world, shapes[k], &st);
		od.orientation = rots[k];
		hs_shape_destroy(shapes[k]);
		hs_world_add_object(p.world, &od, &st);
		assert_int_equal(st, HS_OK);
	}
	p.ga = hs_spring_geom_of(&p.world->model.shapes[p.world->state.bodies[0].shape], &p.world->state.bodies[0]);
	p.gb = hs_spring_geom_of(&p.world->model.shapes[p.world->state.bodies[1].shape], &p.world->state.bodies[1]);
	return p;
}

static bool touch(const pair *p, hs_vec3 pa, hs_vec3 pb, hs_vec3 *n, double *depth) {
	return hs_spring_contact(p->world, &p->ga, pa, &p->gb, pb, n, depth);
}

static hs_quat about_z(double angle) { return hs_quat_from_axis_angle(hs_v3(0, 0, 1), angle); }

// A ball beside a 1 m rod turned 45° about z: contact exactly when its centre is nearer than r to
// the rod's side face; none in the empty corner of the rod's bounding box.
static void test_sphere_rotated_rod(void **state) {
	(void)state;
	hs_status st;
	double r = 0.05, w = 0.025; // ball radius, rod half-width
	pair p = make_pair(hs_shape_sphere(r, &st), hs_quat_identity(), hs_shape_box(hs_v3(1.0, 2 * w, 2 * w), &st),
	                   about_z(0.25 * HS_PI));
	assert_int_equal(p.ga.form, HS_FORM_SPHERE);
	assert_int_equal(p.gb.form, HS_FORM_BOX);
	hs_vec3 side = hs_v3(-SQRT1_2, SQRT1_2, 0.0), rod = hs_v3(0, 0, 0), n;
	double depth;
	assert_false(touch(&p, hs_scale(side, w + r + 1e-9), rod, &n, &depth));
	assert_true(touch(&p, hs_scale(side, w + r - 1e-6), rod, &n, &depth));
	assert_near(depth, 1e-6, 1e-15);
	assert_vec3_near(n, hs_neg(side), 1e-12);
	// 0.3 m along x and −y from the centre: inside the bounding box, 0.42 m from the rod
	assert_true(0.3 + r < p.gb.hi.x && -0.3 - r > p.gb.lo.y);
	assert_false(touch(&p, hs_v3(0.3, -0.3, 0.0), rod, &n, &depth));
	// centre inside the rod: out through the nearest face
	assert_true(touch(&p, hs_scale(side, 0.01), rod, &n, &depth));
	assert_near(depth, w - 0.01 + r, 1e-15);
	assert_vec3_near(n, hs_neg(side), 1e-15);
	hs_world_destroy(p.world);
}

// Separating axes: a unit cube and one turned 45° about z, d apart along x, overlap by
// 1/2 + √2/2 − d along x (the turned cube's edge in the other's face); apart beyond that.
static void test_box_box_separating_axes(void **state) {
	(void)state;
	hs_status st;
	pair p = make_pair(hs_shape_box(hs_v3(1, 1, 1), &st), hs_quat_identity(), hs_shape_box(hs_v3(1, 1, 1), &st),
	                   about_z(0.25 * HS_PI));
	assert_int_equal(p.ga.form, HS_FORM_AXIS_BOX);
	hs_vec3 n, o = hs_v3(0, 0, 0);
	double depth;
	assert_true(touch(&p, o, hs_v3(1.1, 0, 0), &n, &depth));
	assert_near(depth, 0.5 + SQRT1_2 - 1.1, 1e-12);
	assert_vec3_near(n, hs_v3(1, 0, 0), 1e-12);
	assert_true(touch(&p, hs_v3(1.1, 0, 0), o, &n, &depth)); // the other way round
	assert_vec3_near(n, hs_v3(-1, 0, 0), 1e-12);
	assert_false(touch(&p, o, hs_v3(0.5 + SQRT1_2 + 1e-9, 0, 0), &n, &depth));
	// along the diagonal u = (1, 1)/√2 the cubes reach √2/2 (a corner) and 1/2 (the turned one's
	// face): apart beyond d = 1/2 + √2/2, where the bounding boxes still overlap (up to d = 1 + √2/2)
	hs_vec3 u = hs_v3(SQRT1_2, SQRT1_2, 0);
	assert_false(touch(&p, o, hs_scale(u, 0.5 + SQRT1_2 + 1e-9), &n, &depth));
	assert_true(touch(&p, o, hs_scale(u, 0.5 + SQRT1_2 - 0.01), &n, &depth));
	assert_near(depth, 0.01, 1e-12);
	assert_vec3_near(n, u, 1e-12);
	hs_world_destroy(p.world);
	// both turned 30°: the overlap along their common x axis is 1 − d
	hs_quat q = about_z(HS_PI / 6.0);
	p = make_pair(hs_shape_box(hs_v3(1, 1, 1), &st), q, hs_shape_box(hs_v3(1, 1, 1), &st), q);
	hs_vec3 ux = hs_quat_rotate(q, hs_v3(1, 0, 0));
	assert_true(touch(&p, o, hs_scale(ux, 0.9), &n, &depth));
	assert_near(depth, 0.1, 1e-12);
	assert_vec3_near(n, ux, 1e-12);
	hs_world_destroy(p.world);
}

// libccd for a square pyramid (base 0.2 m, height 0.2 m: base plane z = −0.05, apex z = 0.15) and
// a ball of r = 0.05: under the base, on the apex, on a slanted face 2x + z = 0.15.
static void test_pyramid_sphere_libccd(void **state) {
	(void)state;
	hs_status st;
	double r = 0.05, delta = 0.01;
	pair p = make_pair(hs_shape_sphere(r, &st), hs_quat_identity(), hs_shape_pyramid(0.2, 0.2, &st),
	                   hs_quat_identity());
	assert_int_equal(p.gb.form, HS_FORM_CONVEX);
	hs_vec3 n, o = hs_v3(0, 0, 0);
	double depth;
	assert_true(touch(&p, hs_v3(0, 0, -0.05 - r + delta), o, &n, &depth));
	assert_near(depth, delta, 1e-9);
	assert_vec3_near(n, hs_v3(0, 0, 1), 1e-9);
	assert_true(touch(&p, hs_v3(0, 0, 0.15 + r - delta), o, &n, &depth));
	assert_near(depth, delta, 1e-9);
	assert_vec3_near(n, hs_v3(0, 0, -1), 1e-9);
	hs_vec3 face = hs_scale(hs_v3(2, 0, 1), 1.0 / sqrt(5.0)), q = hs_v3(0.05, 0, 0.05); // q on the face
	assert_true(touch(&p, hs_mul_add(q, r - delta, face), o, &n, &depth));
	assert_near(depth, delta, 1e-9);
	assert_vec3_near(n, hs_neg(face), 1e-9);
	assert_false(touch(&p, hs_mul_add(q, r + delta, face), o, &n, &depth));
	// beside the apex: inside the bounding box, 0.067 m from the face
	assert_false(touch(&p, hs_v3(0.09, 0, 0.12), o, &n, &depth));
	hs_world_destroy(p.world);
}

// A ball rolling past a 1 m rod turned 45° in a world, along the rod 0.1 m from its axis (0.025 m
// clear of its side): it passes untouched, velocity unchanged, where the rod's bounding box (0.37 m
// around the centre in x and y) would have turned it back.
static void test_ball_passes_rotated_rod(void **state) {
	(void)state;
	hs_world_def def = hs_default_world_def();
	def.kind = HS_WORLD_SPRING;
	def.spring.friction_static = def.spring.friction_sliding = 0.0;
	hs_status st;
	hs_world *w = hs_world_create(&def, &st);
	assert_non_null(w);
	hs_object_def od = hs_default_object_def();
	hs_shape *rod = hs_shape_box(hs_v3(1.0, 0.05, 0.05), &st);
	od.shape = hs_world_add_shape(w, rod, &st);
	hs_shape_destroy(rod);
	od.orientation = about_z(0.25 * HS_PI);
	od.position = hs_v3(0, 0, 0.025);
	hs_object_id rod_id = hs_world_add_object(w, &od, &st);
	hs_shape *ball = hs_shape_sphere(0.05, &st);
	od.shape = hs_world_add_shape(w, ball, &st);
	hs_shape_destroy(ball);
	od.orientation = hs_quat_identity();
	hs_vec3 along = hs_v3(SQRT1_2, SQRT1_2, 0), across = hs_v3(SQRT1_2, -SQRT1_2, 0);
	od.position = hs_add(hs_add(hs_scale(along, -0.7), hs_scale(across, 0.1)), hs_v3(0, 0, 0.05));
	od.velocity = along;
	hs_object_id ball_id = hs_world_add_object(w, &od, &st);
	hs_object_state s;
	for (int f = 0; f < 84; ++f) { // 1.4 m along the rod
		assert_int_equal(hs_world_step(w), HS_OK);
		assert_int_equal(hs_world_object_state(w, ball_id, &s), HS_OK);
		assert_near(hs_dot(s.position, across), 0.1, 1e-12);
		assert_vec3_near(s.velocity, along, 1e-12);
	}
	assert_true(hs_dot(s.position, along) > 0.69);
	assert_int_equal(hs_world_object_state(w, rod_id, &s), HS_OK);
	assert_vec3_near(s.position, hs_v3(0, 0, 0.025), 0.0);
	hs_world_destroy(w);
}

// No tunnelling (docs/model.md §8): at 12 frames/s a ball at 20 m/s moves 1.67 m a frame, through a
// 10 cm ball, box or turned box at rest in its way (frictionless floor). It meets the target where
// their surfaces touch, 0.9 m on (t = 0.045 s): equal masses, elastic, it stops there (x = -0.1 for
// the ball and the box, the box's face at -0.05) and the target goes on at 20 m/s: at t = 0.25 s it
// is 20 (0.25 - 0.045) = 4.1 m on.
static void test_no_tunnelling(void **state) {
	(void)state;
	for (int kind = 0; kind < 3; ++kind) {
		hs_world_def def = hs_default_world_def();
		def.dt = 1.0 / 12.0;
		def.kind = HS_WORLD_SPRING;
		def.spring.friction_static = def.spring.friction_sliding = 0.0;
		hs_status st;
		hs_world *w = hs_world_create(&def, &st);
		assert_non_null(w);
		hs_shape *ball = hs_shape_sphere(0.05, &st);
		hs_shape *target = kind == 0 ? hs_shape_sphere(0.05, &st) : hs_shape_box(hs_v3(0.1, 0.1, 0.1), &st);
		hs_object_def od = hs_default_object_def();
		od.shape = hs_world_add_shape(w, ball, &st);
		od.density = 1.0 / ball->volume;
		od.position = hs_v3(-1.0, 0, 0.05);
		od.velocity = hs_v3(20.0, 0, 0);
		hs_object_id a = hs_world_add_object(w, &od, &st);
		od.shape = hs_world_add_shape(w, target, &st);
		od.density = 1.0 / target->volume;
		od.position = hs_v3(0, 0, 0.05);
		od.velocity = hs_v3(0, 0, 0);
		if (kind == 2) // turned about z by 90 deg: an oriented box whose faces are the same planes
			od.orientation = hs_quat_from_axis_angle(hs_v3(0, 0, 1), HS_PI / 2);
		hs_object_id b = hs_world_add_object(w, &od, &st);
		hs_shape_destroy(ball);
		hs_shape_destroy(target);
		for (int f = 0; f < 3; ++f)
			assert_int_equal(hs_world_step(w), HS_OK);
		hs_object_state sa, sb;
		assert_int_equal(hs_world_object_state(w, a, &sa), HS_OK);
		assert_int_equal(hs_world_object_state(w, b, &sb), HS_OK);
		assert_near(sa.position.x, -0.1, 1e-9);
		assert_near(sa.velocity.x, 0.0, 1e-9);
		assert_near(sb.velocity.x, 20.0, 1e-9);
		assert_near(sb.position.x, 4.1, 1e-9);
		hs_world_destroy(w);
	}
}

static double lcg_unit(uint64_t *s) { // bench/collide_scaling.c's generator, in [-1, 1]
	*s = *s * 6364136223846793005ull + 1442695040888963407ull;
	return (double)(*s >> 11) / (double)(1ull << 52) - 1.0;
}

// The broad phase changes no bit: 300 spheres sliding in a frictionless walled box (make bench's
// scene, 30 frames, then 60 frames' hashes folded) give the same checksum as the all-pairs double
// loop the grid replaced (sys->all_pairs), and that run has collisions in it (each one met within a
// frame steps its two balls on for the rest of it: more object steps than frames × balls).
static uint64_t box_of_balls(bool all_pairs, double spacing, long *steps) {
	enum { BALLS = 300, SIDE = 18 };
	hs_world_def def = hs_default_world_def();
	def.dt = 1.0 / 60.0;
	def.max_objects = BALLS;
	hs_spring_def sd = hs_default_spring_def();
	sd.friction_static = sd.friction_sliding = 0.0;
	sd.walls.enabled = true;
	sd.walls.x_min = sd.walls.y_min = 0.0;
	sd.walls.x_max = sd.walls.y_max = SIDE * spacing;
	def.kind = HS_WORLD_SPRING;
	def.spring = sd;
	hs_status st;
	hs_world *w = hs_world_create(&def, &st);
	assert_non_null(w);
	w->state.spring->all_pairs = all_pairs;
	hs_shape *ball = hs_shape_sphere(0.05, &st);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(w, ball, &st);
	hs_shape_destroy(ball);
	uint64_t seed = 12345;
	for (int k = 0; k < BALLS; ++k) {
		double vx = lcg_unit(&seed), vy = lcg_unit(&seed);
		od.position = hs_v3((k % SIDE + 0.5) * spacing, (k / SIDE + 0.5) * spacing, 0.05);
		od.velocity = hs_v3(vx, vy, 0.0);
		hs_world_add_object(w, &od, &st);
		assert_int_equal(st, HS_OK);
	}
	for (int f = 0; f < 30; ++f)
		assert_int_equal(hs_world_step(w), HS_OK);
	uint64_t h = 14695981039346656037ull;
	for (int f = 0; f < 60; ++f) {
		assert_int_equal(hs_world_step(w), HS_OK);
		h ^= hs_world_hash(w);
		h *= 1099511628211ull;
	}
	*steps = hs_world_get_counters(w).object_steps;
	hs_world_destroy(w);
	return h;
}

static void test_broad_phase_same_bits(void **state) {
	(void)state;
	long steps = 0, steps_all = 0;
	uint64_t grid = box_of_balls(false, 0.15, &steps);
	assert_true(grid == box_of_balls(true, 0.15, &steps_all));
	assert_int_equal(steps, steps_all);
	assert_true(steps > 90L * 300L); // balls met within frames
}

// hs_spring_contact_within's depth is the shapes' overlap, negative when they are apart, for every
// kind of pair (sphere-sphere, axis box-box, turned box-box, sphere-box): two shapes apart by 1 mm
// asked with a 3 mm gap give -1 mm; apart by 4 mm, none. (Its comment said "the overlap less the
// gap"; code written to that comment once held balls up to 3.4 cm apart as touching.)
static void test_within_depth_is_overlap(void **state) {
	(void)state;
	hs_status st;
	struct {
		hs_shape *a, *b;
		hs_quat rb;
	} kinds[4] = {
	    {hs_shape_sphere(0.05, &st), hs_shape_sphere(0.05, &st), {1, 0, 0, 0}},
	    {hs_shape_box(hs_v3(0.1, 0.1, 0.1), &st), hs_shape_box(hs_v3(0.1, 0.1, 0.1), &st), {1, 0, 0, 0}},
	    {hs_shape_box(hs_v3(0.1, 0.1, 0.1), &st), hs_shape_box(hs_v3(0.1, 0.1, 0.1), &st), {1, 0, 0, 0}},
	    {hs_shape_sphere(0.05, &st), hs_shape_box(hs_v3(0.1, 0.1, 0.1), &st), {1, 0, 0, 0}},
	};
	kinds[2].rb = about_z(HS_PI / 2.0); // a turned box (its own orientation), the same extent along x
	for (int k = 0; k < 4; ++k) {
		pair p = make_pair(kinds[k].a, hs_quat_identity(), kinds[k].b, kinds[k].rb);
		hs_vec3 n;
		double depth;
		assert_true(hs_spring_contact_within(p.world, &p.ga, hs_v3(0, 0, 0), &p.gb, hs_v3(0.101, 0, 0), 3e-3, &n, &depth));
		assert_near(depth, -1e-3, 1e-12);
		assert_vec3_near(n, hs_v3(1, 0, 0), 1e-12);
		assert_false(hs_spring_contact_within(p.world, &p.ga, hs_v3(0, 0, 0), &p.gb, hs_v3(0.104, 0, 0), 3e-3, &n, &depth));
		hs_world_destroy(p.world);
	}
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_sphere_rotated_rod),
	    cmocka_unit_test(test_box_box_separating_axes),
	    cmocka_unit_test(test_within_depth_is_overlap),
	    cmocka_unit_test(test_pyramid_sphere_libccd),
	    cmocka_unit_test(test_ball_passes_rotated_rod),
	    cmocka_unit_test(test_broad_phase_same_bits),
	    cmocka_unit_test(test_no_tunnelling),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
