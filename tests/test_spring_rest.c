// test_spring_rest.c — resting contact between the spring model's objects (spring_rest.c,
// docs/model.md §8): stacks stand still to the bit at the paper's frame rates, the weight above
// reaches the floor, static friction holds through contacts, restitution is the pair's, and a
// closed box of objects never gains energy.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>
#include <gsl/gsl_rng.h>

#include "spring_rest.h"
#include "spring_system.h"
#include "test_util.h"

static const double rates[] = {12.0, 60.0, 120.0};

typedef struct scene {
	hs_world *world;
	hs_shape_id sphere, cube;
} scene;

// A spring world at `hz` frames/s, optionally walled, with a 5 cm sphere and a 10 cm cube shape.
static scene make_scene(double hz, double wall, double friction) {
	hs_world_def def = hs_default_world_def();
	def.dt = 1.0 / hz;
	def.max_objects = 256;
	hs_status st;
	scene s;
	hs_spring_def sd = hs_default_spring_def();
	sd.friction_static = sd.friction_sliding = friction;
	if (wall > 0.0) {
		sd.walls.enabled = true;
		sd.walls.x_min = sd.walls.y_min = -wall;
		sd.walls.x_max = sd.walls.y_max = wall;
	}
	def.kind = HS_WORLD_SPRING;
	def.spring = sd;
	s.world = hs_world_create(&def, &st);
	assert_non_null(s.world);
	hs_shape *ball = hs_shape_sphere(0.05, &st), *box = hs_shape_box(hs_v3(0.1, 0.1, 0.1), &st);
	s.sphere = hs_world_add_shape(s.world, ball, &st);
	s.cube = hs_world_add_shape(s.world, box, &st);
	hs_shape_destroy(ball);
	hs_shape_destroy(box);
	hs_world_set_stylus(s.world, hs_v3(5.0, 5.0, 5.0), hs_quat_identity(), false);
	return s;
}

static hs_object_id put(scene *s, hs_shape_id shape, hs_vec3 p, double density) {
	hs_object_def od = hs_default_object_def();
	od.shape = shape;
	od.position = p;
	od.density = density;
	hs_status st;
	hs_object_id id = hs_world_add_object(s->world, &od, &st);
	assert_int_equal(st, HS_OK);
	return id;
}

// Steps `frames` and fails unless every object keeps the bits of its position and its velocity
// stays zero after the first frame (which may round a position onto a wall: x_min − lo.x).
static void assert_still(hs_world *w, long frames) {
	int n = hs_world_object_count(w);
	hs_vec3 start[64];
	assert_true(n <= 64);
	hs_world_step(w);
	for (int i = 0; i < n; ++i)
		start[i] = w->state.bodies[i].pos;
	for (long f = 0; f < frames; ++f) {
		hs_world_step(w);
		for (int i = 0; i < n; ++i) {
			hs_vec3 p = w->state.bodies[i].pos, v = w->state.bodies[i].vel;
			if (memcmp(&p, &start[i], sizeof p) != 0 || v.x != 0.0 || v.y != 0.0 || v.z != 0.0)
				fail_msg("object %d moved at frame %ld: (%.17g, %.17g, %.17g) from (%.17g, %.17g, %.17g), v.z %g", i,
				         f, p.x, p.y, p.z, start[i].x, start[i].y, start[i].z, v.z);
		}
	}
}

// A ball on a ball: it used to sink g dt²/2 a frame (z = 0.1159 instead of 0.15 at 1/12 s) while
// the lower one kept a stored speed of 0.82 m/s. Now both keep their bits for 10 s at every rate.
static void test_ball_on_ball(void **state) {
	(void)state;
	for (int r = 0; r < 3; ++r) {
		scene s = make_scene(rates[r], 0.0, 0.5);
		put(&s, s.sphere, hs_v3(0, 0, 0.05), 500);
		put(&s, s.sphere, hs_v3(0, 0, 0.15), 500);
		assert_still(s.world, (long)(10 * rates[r]));
		hs_world_destroy(s.world);
	}
}

// Four balls in a row on the floor between two walls, the second 0.3 mm in the first and the third
// 0.3 mm short of the fourth: the end passes part a pair at a time, moving the ball that moved (the
// other's static friction holds it), so the overlap went to and fro along the row for good (a
// floor layer near jamming in the dense drop). The floor layer's projection parts the row at once:
// every pair apart to within the drift, every ball still to the bit, at 12, 60 and 120 frames/s.
static void test_floor_row_comes_apart(void **state) {
	(void)state;
	const double xs[4] = {-0.15, -0.0503, 0.0497, 0.15};
	for (int r = 0; r < 3; ++r) {
		scene s = make_scene(rates[r], 0.2, 0.5);
		for (int k = 0; k < 4; ++k)
			put(&s, s.sphere, hs_v3(xs[k], 0.0, 0.05), 500);
		hs_world_step(s.world);
		assert_still(s.world, (long)(2 * rates[r]));
		for (int k = 0; k < 3; ++k) {
			double gap = hs_length(hs_sub(s.world->state.bodies[k + 1].pos, s.world->state.bodies[k].pos)) - 0.1;
			assert_true(gap > -(HS_REST_DRIFT + s.world->model.def.floor_tolerance));
		}
		hs_world_destroy(s.world);
	}
}

// A ball lying in another by more than the drift but less than the drift and the touch gap: the
// separation leaves such a pair where it is (it parts only what lies beyond the gap, and that is
// within the drift: paid from kinetic energy, of which there is none), so it must be held. It was
// not (the hold counted the whole depth): it was stepped every frame and moved by rounding.
static void test_drift_within_the_gap_is_held(void **state) {
	(void)state;
	for (int r = 0; r < 3; ++r)
		for (int k = 0; k < 3; ++k) {
			scene s = make_scene(rates[r], 0.0, 0.5);
			double depth = HS_REST_DRIFT + (0.2 + 0.3 * k) * s.world->model.def.floor_tolerance;
			put(&s, s.sphere, hs_v3(0, 0, 0.05), 500);
			put(&s, s.sphere, hs_v3(0.03, 0.0, 0.05 + sqrt((0.1 - depth) * (0.1 - depth) - 0.03 * 0.03)), 500);
			assert_still(s.world, (long)(2 * rates[r]));
			hs_world_destroy(s.world);
		}
}

// Three boxes, each 1 cm off the one below: they stand; the bottom one carries both above it
// (its contact load is twice a box's weight, to 1e-9), and the floor all three.
static void test_stack_of_boxes(void **state) {
	(void)state;
	for (int r = 0; r < 3; ++r) {
		scene s = make_scene(rates[r], 0.0, 0.5);
		for (int k = 0; k < 3; ++k)
			put(&s, s.cube, hs_v3(0.01 * k, 0, 0.05 + 0.1 * k), 500);
		assert_still(s.world, (long)(10 * rates[r]));
		double weight = 0.5 * 9.81; // 10 cm at 500 kg/m³
		const hs_spring_system *sys = s.world->state.spring;
		assert_near(sys->load[0].z, -2.0 * weight, 1e-9 * weight);
		assert_near(sys->load[1].z, weight, 1e-9 * weight); // 2 w from below, w from above
		assert_near(sys->load[2].z, weight, 1e-9 * weight);
		assert_true(sys->held[0] && sys->held[1] && sys->held[2]);
		hs_object_state os;
		assert_int_equal(hs_world_object_state(s.world, hs_world_object_at(s.world, 2), &os), HS_OK);
		assert_true(os.resting);
		hs_world_destroy(s.world);
	}
}

// A square pyramid of 14 spheres (3 × 3, 2 × 2, 1), each upper one in the hollow of four below,
// and the same in a walled box just wide enough, so that the base presses on the walls.
static void pyramid(scene *s) {
	double r = 0.05, h = 0.07071067811865475; // √2 r: a layer's rise
	for (int layer = 0, m = 3; layer < 3; ++layer, --m)
		for (int i = 0; i < m; ++i)
			for (int j = 0; j < m; ++j)
				put(s, s->sphere, hs_v3((2 * i - (m - 1)) * r, (2 * j - (m - 1)) * r, r + layer * h), 500);
}

static void test_pyramid_of_spheres(void **state) {
	(void)state;
	for (int r = 0; r < 3; ++r) {
		for (int walled = 0; walled < 2; ++walled) {
			scene s = make_scene(rates[r], walled ? 0.15 : 0.0, 0.5);
			pyramid(&s);
			assert_still(s.world, (long)(10 * rates[r]));
			hs_world_destroy(s.world);
		}
	}
}

// Without friction the base of the pyramid spreads (nothing holds the spheres pushed outward),
// so the test above can fail; in the walled box the walls hold them, and it stands.
static void test_frictionless_pyramid_spreads(void **state) {
	(void)state;
	scene s = make_scene(60.0, 0.0, 0.0);
	pyramid(&s);
	hs_vec3 top = s.world->state.bodies[13].pos;
	for (int f = 0; f < 120; ++f)
		hs_world_step(s.world);
	assert_true(s.world->state.bodies[13].pos.z < top.z - 0.01);
	hs_world_destroy(s.world);
	s = make_scene(60.0, 0.15, 0.0);
	pyramid(&s);
	assert_still(s.world, 600);
	hs_world_destroy(s.world);
}

// A 20 cm box on four balls on the floor (a box on a sphere-filled floor), in a walled box too.
static void test_box_on_balls(void **state) {
	(void)state;
	for (int r = 0; r < 3; ++r) {
		for (int walled = 0; walled < 2; ++walled) {
			scene s = make_scene(rates[r], walled ? 0.1 : 0.0, 0.5);
			for (int k = 0; k < 4; ++k)
				put(&s, s.sphere, hs_v3(k & 1 ? 0.05 : -0.05, k & 2 ? 0.05 : -0.05, 0.05), 500);
			hs_status st;
			hs_shape *big = hs_shape_box(hs_v3(0.2, 0.2, 0.05), &st);
			hs_shape_id id = hs_world_add_shape(s.world, big, &st);
			hs_shape_destroy(big);
			put(&s, id, hs_v3(0.0, 0.0, 0.125), 500);
			assert_still(s.world, (long)(10 * rates[r]));
			hs_world_destroy(s.world);
		}
	}
}

// A 10 cm cube on the spring pressed with 49 N into a 125 kg block (50 cm, 1000 kg/m³) whose
// static friction is μ m g = 613 N: the block never moves (it used to creep 3.6 mm). A 5 kg block
// (static friction 24.5 N) goes, so the test can fail.
static double push_block(double rate, double block_density, hs_vec3 *block_start, hs_vec3 *block_end) {
	scene s = make_scene(rate, 0.0, 0.5);
	hs_status st;
	hs_shape *big = hs_shape_box(hs_v3(0.5, 0.5, 0.5), &st);
	hs_shape_id id = hs_world_add_shape(s.world, big, &st);
	hs_shape_destroy(big);
	hs_object_id block = put(&s, id, hs_v3(0.0, 0.0, 0.25), block_density);
	hs_vec3 g = hs_v3(-0.30, 0.0, 0.05);
	hs_object_id cube = put(&s, s.cube, g, 500);
	hs_spring_object so;
	hs_world_spring_object(s.world, cube, &so);
	// the API's attach anchors the spring at the stylus: from x0 beside G along +x (neutral) to
	// x0 + 49 N / k, the spring stretched horizontally by 49 N / k
	hs_vec3 from = hs_v3(so.rest_length, 0.0, 0.0), to = hs_v3(so.rest_length + 49.0 / so.stiffness, 0.0, 0.0);
	hs_world_set_stylus(s.world, hs_add(g, from), hs_quat_identity(), false);
	hs_world_step(s.world); // the stylus there for a frame: no jump at the attach
	assert_int_equal(hs_world_spring_attach(s.world, cube), HS_OK);
	hs_object_state os;
	hs_world_object_state(s.world, block, &os);
	*block_start = os.position;
	long frames = (long)(6 * rate);
	for (long f = 0; f < frames; ++f) {
		double u = fmin(1.0, (double)f / (double)(frames / 2));
		hs_world_set_stylus(s.world, hs_add(g, hs_add(hs_scale(from, 1.0 - u), hs_scale(to, u))), hs_quat_identity(), false);
		hs_world_step(s.world);
	}
	hs_spring_state ss;
	hs_world_spring_state(s.world, &ss);
	hs_world_object_state(s.world, block, &os);
	*block_end = os.position;
	hs_world_destroy(s.world);
	return ss.force.x;
}

static void test_push_into_heavy_block(void **state) {
	(void)state;
	for (int r = 0; r < 3; ++r) {
		hs_vec3 a, b;
		double force = push_block(rates[r], 1000.0, &a, &b);
		assert_near(force, 49.0, 1e-6);
		assert_memory_equal(&a, &b, sizeof a);
		push_block(rates[r], 40.0, &a, &b); // 5 kg: static friction 24.5 N
		if (!(b.x > a.x + 0.01))
			fail_msg("at %g frames/s the 5 kg block moved %g m", rates[r], b.x - a.x);
	}
}

// A light box (10 cm, 0.2 kg) on the spring dragged along the floor at 0.5 m/s into a 128 kg
// block (40 cm, 2000 kg/m³), the pull kept on after it arrives: it bounces off, the spring pulls
// it back, and a slow bounce that the spring would close within the frame has its separating speed
// removed — against the block the floor's friction holds, the box's speed became exactly 0 while
// it still counted as sliding, and the floor's sliding friction divided by that speed: every value
// non-finite, both objects frozen for good, at every frame rate. Now no fault, the box never in
// the block by more than the touch gap, and it ends at rest against the block's face; the block
// moves at most what one impact's momentum allows (2 m v / (m + M) = 1.56 mm/s, which friction
// stops within 0.25 µm; the later bounces are slower): under 1 µm.
static void test_drag_into_heavy_block(void **state) {
	(void)state;
	const double hz[5] = {12.0, 30.0, 60.0, 120.0, 144.0};
	for (int r = 0; r < 5; ++r) {
		scene s = make_scene(hz[r], 0.0, 0.5);
		hs_status st;
		hs_shape *big = hs_shape_box(hs_v3(0.4, 0.4, 0.4), &st);
		hs_shape_id id = hs_world_add_shape(s.world, big, &st);
		hs_shape_destroy(big);
		hs_object_id block = put(&s, id, hs_v3(0.5, 0.0, 0.2), 2000);
		hs_vec3 g = hs_v3(-0.2, 0.0, 0.05);
		hs_object_id box = put(&s, s.cube, g, 200);
		hs_spring_object so;
		hs_world_spring_object(s.world, box, &so);
		hs_vec3 pen = hs_add(g, hs_v3(so.rest_length, 0.0, 0.0)); // beside G at x0: neutral
		hs_world_set_stylus(s.world, pen, hs_quat_identity(), false);
		hs_world_step(s.world);
		assert_int_equal(hs_world_spring_attach(s.world, box), HS_OK);
		long frames = lround(4.0 * hz[r]);
		for (long f = 1; f <= frames; ++f) { // 0.5 m/s for 2 s, then held there
			double t = fmin((double)f / hz[r], 2.0);
			hs_world_set_stylus(s.world, hs_add(pen, hs_v3(0.5 * t, 0.0, 0.0)), hs_quat_identity(), false);
			assert_int_equal(hs_world_step(s.world), HS_OK);
			const hs_body *a = &s.world->state.bodies[0], *b = &s.world->state.bodies[1];
			if (hs_world_get_counters(s.world).numeric_faults != 0 || !hs_vec3_is_finite(b->pos) ||
			    !hs_vec3_is_finite(b->vel))
				fail_msg("at %g frames/s, frame %ld: a numeric fault (box at %g m, %g m/s)", hz[r], f, b->pos.x, b->vel.x);
			if (b->pos.x + 0.05 > a->pos.x - 0.2 + 1e-6)
				fail_msg("at %g frames/s, frame %ld: the box %g m in the block", hz[r], f,
				         b->pos.x + 0.05 - (a->pos.x - 0.2));
		}
		hs_object_state bs, os;
		hs_world_object_state(s.world, block, &bs);
		hs_world_object_state(s.world, box, &os);
		assert_true(hs_distance(bs.position, hs_v3(0.5, 0.0, 0.2)) < 1e-6);
		assert_near(os.position.x, bs.position.x - 0.25, 2e-6);
		assert_true(hs_length(os.velocity) == 0.0);
		hs_world_destroy(s.world);
	}
}

// Restitution per pair: a ball of e = 0.5 slides into a resting ball of e = 1 on a frictionless
// floor: the pair takes e = 0.5, v_a' = (m_a − e m_b) v / (m_a + m_b), v_b' = (1 + e) m_a v / (m_a + m_b).
static void test_restitution_per_pair(void **state) {
	(void)state;
	for (int swap = 0; swap < 2; ++swap) {
		scene s = make_scene(120.0, 0.0, 0.0);
		hs_object_def od = hs_default_object_def();
		hs_status st;
		od.shape = s.sphere;
		od.position = hs_v3(-0.3, 0, 0.05);
		od.velocity = hs_v3(1.0, 0, 0);
		od.density = 1000.0;
		od.restitution = swap ? 1.0 : 0.5;
		hs_object_id a = hs_world_add_object(s.world, &od, &st);
		od.position = hs_v3(0, 0, 0.05);
		od.velocity = hs_v3(0, 0, 0);
		od.density = 500.0;
		od.restitution = swap ? 0.5 : 1.0;
		hs_object_id b = hs_world_add_object(s.world, &od, &st);
		for (int f = 0; f < 60; ++f)
			hs_world_step(s.world);
		hs_spring_object oa, ob;
		hs_world_spring_object(s.world, a, &oa);
		hs_world_spring_object(s.world, b, &ob);
		double ma = oa.mass, mb = ob.mass, e = 0.5;
		assert_near(oa.velocity.x, (ma - e * mb) / (ma + mb), 1e-12);
		assert_near(ob.velocity.x, (1.0 + e) * ma / (ma + mb), 1e-12);
		hs_world_destroy(s.world);
	}
	hs_world_def def = hs_default_world_def();
	hs_status st;
	hs_world *w = hs_world_create(&def, &st);
	hs_shape *ball = hs_shape_sphere(0.05, &st);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(w, ball, &st);
	hs_shape_destroy(ball);
	od.restitution = 1.5; // beyond 1: refused
	assert_int_equal(hs_world_add_object(w, &od, &st).index1, 0u);
	assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	hs_world_destroy(w);
}

// Σ ½ m |v|² + m g z of every object (J).
static double energy(const hs_world *w) {
	double e = 0.0;
	for (int i = 0; i < w->model.object_count; ++i) {
		const hs_body *b = &w->state.bodies[i];
		e += 0.5 * b->mass * hs_length_sq(b->vel) - b->mass * hs_dot(w->model.def.gravity, b->pos);
	}
	return e;
}

// A closed box (walls and floor; nothing leaves it) of 100 objects of random sizes, shapes,
// restitutions and velocities, seeded: over 60 s at 60 frames/s the total energy never rises.
static void test_closed_box_energy(void **state) {
	(void)state;
	scene s = make_scene(60.0, 0.5, 0.5);
	gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
	gsl_rng_set(rng, 11);
	hs_status st;
	hs_shape_id shapes[4] = {s.sphere, s.cube};
	hs_shape *b1 = hs_shape_box(hs_v3(0.12, 0.06, 0.08), &st), *s1 = hs_shape_sphere(0.035, &st);
	shapes[2] = hs_world_add_shape(s.world, b1, &st);
	shapes[3] = hs_world_add_shape(s.world, s1, &st);
	hs_shape_destroy(b1);
	hs_shape_destroy(s1);
	for (int k = 0; k < 100; ++k) { // a 5 × 5 × 4 lattice 0.18 m apart, jittered, moving
		hs_object_def od = hs_default_object_def();
		od.shape = shapes[gsl_rng_uniform_int(rng, 4)];
		od.position = hs_v3(-0.36 + 0.18 * (k % 5) + 0.02 * (gsl_rng_uniform(rng) - 0.5),
		                    -0.36 + 0.18 * (k / 5 % 5) + 0.02 * (gsl_rng_uniform(rng) - 0.5), 0.1 + 0.2 * (k / 25));
		od.velocity = hs_v3(2.0 * (gsl_rng_uniform(rng) - 0.5), 2.0 * (gsl_rng_uniform(rng) - 0.5),
		                    2.0 * (gsl_rng_uniform(rng) - 0.5));
		od.density = 200.0 + 800.0 * gsl_rng_uniform(rng);
		od.restitution = gsl_rng_uniform(rng);
		hs_world_add_object(s.world, &od, &st);
		assert_int_equal(st, HS_OK);
	}
	gsl_rng_free(rng);
	double e0 = energy(s.world), prev = e0, worst = 0.0;
	long worst_frame = -1;
	for (long f = 0; f < 3600; ++f) {
		hs_world_step(s.world);
		double e = energy(s.world);
		if ((e - prev) / e0 > worst) {
			worst = (e - prev) / e0;
			worst_frame = f;
		}
		prev = e;
	}
	print_message("closed box: E %.6g J -> %.6g J, largest rise in a frame %.3g of E0 (frame %ld)\n", e0, prev, worst,
	              worst_frame);
	assert_true(worst <= 1e-12); // rounding only (3.8e-16 measured)
	hs_world_destroy(s.world);
}

// 27 balls of 5 cm dropped from a jittered 3 × 3 × 3 lattice with random velocities (seeded) into
// a 40 cm walled box at `hz` frames/s.
static scene dense_drop(double hz, unsigned long seed) {
	scene s = make_scene(hz, 0.2, 0.5);
	gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
	gsl_rng_set(rng, seed);
	for (int k = 0; k < 27; ++k) {
		hs_object_def od = hs_default_object_def();
		od.shape = s.sphere;
		od.position = hs_v3(-0.12 + 0.12 * (k % 3) + 0.02 * (gsl_rng_uniform(rng) - 0.5),
		                    -0.12 + 0.12 * (k / 3 % 3) + 0.02 * (gsl_rng_uniform(rng) - 0.5), 0.3 + 0.15 * (k / 9));
		od.velocity = hs_v3(0.5 * (gsl_rng_uniform(rng) - 0.5), 0.5 * (gsl_rng_uniform(rng) - 0.5), 0.0);
		hs_status st;
		hs_world_add_object(s.world, &od, &st);
		assert_int_equal(st, HS_OK);
	}
	gsl_rng_free(rng);
	return s;
}

// The dense drop at the paper's 12 and 17 frames/s: a separation used to throw a ball wedged in a
// corner 0.3 m across the box in one frame (its one free direction ran almost across the contact
// normal), and a row of balls along a wall, more than fit, was parted along the row pair by pair
// and back until two balls lay centre on centre (overlap 0.1 m, 5 of 13 seeds). Then none lay
// more than 60 % of a diameter inside another (0.047 m measured); since a pair pushed into each
// other mid-frame is answered where that begins, none more than 35 % (0.029 m measured).
static void test_dense_drop_keeps_balls_apart(void **state) {
	(void)state;
	const double hz[2] = {12.0, 17.0};
	double worst = 0.0;
	for (int r = 0; r < 2; ++r)
		for (unsigned long seed = 1; seed <= 8; ++seed) {
			scene s = dense_drop(hz[r], seed);
			for (long f = 0; f < (long)(4.0 * hz[r]); ++f) {
				hs_world_step(s.world);
				for (int i = 0; i < 27; ++i) {
					const hs_body *a = &s.world->state.bodies[i];
					for (int j = i + 1; j < 27; ++j)
						worst = fmax(worst, 0.1 - hs_length(hs_sub(a->pos, s.world->state.bodies[j].pos)));
				}
			}
			hs_world_destroy(s.world);
		}
	print_message("dense drop: largest overlap %.4f m\n", worst);
	assert_true(worst < 0.035);
}

// The dense drop comes to rest: over the last second of 10 s no ball moves 1 µm in a frame nor
// keeps 1 mm/s, and in most seeds every ball keeps its bits. It did not at these rates (seeds
// 1-8 at rest: 4 at 12 frames/s, 1 at 17, 5 at 30; none to the bit; balls jittering 1-2 cm a
// frame): a ball that met a second support mid-frame fell on into it and was separated off the
// first by mm, so next frame it fell again; and a ball lying 1 µm-0.1 mm in another was never
// held (the separation of such a drift is paid from kinetic energy: it stayed), so it stepped and
// fell back into place every frame. Then 4 of 8 seeds still jittered at 12 frames/s (1.2 cm a
// frame) and 2 at 17: a ball on one support, its second one a few µm beyond the touch gap, slid
// and fell into it every frame; such a pair now joins the resting solve ahead of its meeting
// (spring_rest.c). Seeds 15 and 21 jammed: a ball pushed into a third one mid-fall reached the
// floor inside it, 16 balls on a floor for a 4 × 4 grid, pushed to and fro by 1 cm a frame; that
// overlap is now answered where it begins (spring_collide.c first_meeting). Every seed at rest at
// 12, 17 and 30 frames/s, to the bit 7, 8 and 7 (the rest crept by under 1 µm a frame: a ball on
// friction at its limit, where the resting solve did not converge). With sticking contacts solved
// in Coulomb's cone (spring_solve.c) to the bit 8, 10 and 8; at 12 frames/s seed 5 is no longer at
// rest: a ball on a ball in a corner slides 3 mm and is put back every other frame (its slow
// sliding reversed within the frame, where sliding friction does not act). With each frame's
// solve starting from the last frame's forces (warm start) seed 5 settles, to the bit 9, 9 and
// 10; at 12 frames/s seed 21 is not at rest: a row of four balls along a wall, overfull by
// 0.7 mm, is parted by 5 µm a frame. With a drift within the touch gap held, to the bit 9, 10
// and 10. With the floor layer's overlaps projected out all at once (spring_collide.c), every
// seed at rest and to the bit at all three rates.
static void test_dense_drop_comes_to_rest(void **state) {
	(void)state;
	const double hz[3] = {12.0, 17.0, 30.0};
	// seeds 1-8, and 15 and 21, whose floor layer jammed (16 balls; 1 cm a frame)
	const unsigned long seeds[10] = {1, 2, 3, 4, 5, 6, 7, 8, 15, 21};
	const int need_rest[3] = {10, 10, 10}, need_bits[3] = {10, 10, 10}; // of 10 seeds
	for (int r = 0; r < 3; ++r) {
		int settled = 0, bits = 0;
		long latest = 0; // the last frame a ball moved, over the seeds at rest to the bit
		double worst_v = 0.0, worst_step = 0.0;
		for (int k = 0; k < 10; ++k) {
			scene s = dense_drop(hz[r], seeds[k]);
			long frames = (long)(10.0 * hz[r]), moved = 0;
			double v = 0.0, step = 0.0;
			for (long f = 0; f < frames; ++f) {
				hs_vec3 before[27];
				for (int i = 0; i < 27; ++i)
					before[i] = s.world->state.bodies[i].pos;
				hs_world_step(s.world);
				for (int i = 0; i < 27; ++i) {
					moved = memcmp(&before[i], &s.world->state.bodies[i].pos, sizeof before[i]) != 0 ? f + 1 : moved;
					if (f < frames - (long)hz[r])
						continue;
					v = fmax(v, hs_length(s.world->state.bodies[i].vel));
					step = fmax(step, hs_length(hs_sub(s.world->state.bodies[i].pos, before[i])));
				}
			}
			settled += step < 1e-6 && v < 1e-3;
			bits += step == 0.0 && v == 0.0;
			latest = step == 0.0 && v == 0.0 && moved > latest ? moved : latest;
			worst_v = fmax(worst_v, v);
			worst_step = fmax(worst_step, step);
			hs_world_destroy(s.world);
		}
		print_message("dense drop at %.0f/s: %d of 10 seeds at rest in the last second, %d to the bit (by %.2f s); "
		              "worst %.3g m/s, %.3g m a frame\n",
		              hz[r], settled, bits, (double)latest / hz[r], worst_v, worst_step);
		assert_true(settled >= need_rest[r]);
		assert_true(bits >= need_bits[r]);
	}
}

// A ball on the side of one ball (37° from the top: it slides, μ = 0.5) with a second ball 3 or
// 30 µm away, beyond the 1 µm touch gap. The second support is met at its surface: the pair joins
// the frame's resting solve ahead of the meeting (a push, slower than 5 cm/s), whose force closes
// the gap by the frame's end and no more. It used to fall into the second ball through the rest
// of the frame, be stopped inside it and stay there as drift: 12-54 µm deep at 12 and 17
// frames/s (3.4 and 11 µm at 60). Now within 4 µm of both, at rest to the bit within 2 frames.
static void test_second_support_met_at_its_surface(void **state) {
	(void)state;
	const double hz[3] = {12.0, 17.0, 60.0}, gaps[2] = {3e-6, 3e-5};
	double worst = 0.0;
	for (int r = 0; r < 3; ++r)
		for (int g = 0; g < 2; ++g) {
			scene s = make_scene(hz[r], 0.0, 0.5);
			double x0 = 0.06, top = 0.05 + sqrt(0.01 - x0 * x0); // touching the first, at 37°
			put(&s, s.sphere, hs_v3(-x0, 0, 0.05), 500);
			put(&s, s.sphere, hs_v3(x0 + gaps[g], 0, 0.05), 500);
			put(&s, s.sphere, hs_v3(0, 0, top), 500);
			hs_world_step(s.world);
			hs_world_step(s.world);
			assert_still(s.world, (long)(2 * hz[r]));
			const hs_body *b = s.world->state.bodies;
			for (int k = 0; k < 2; ++k)
				worst = fmax(worst, fabs(hs_length(hs_sub(b[2].pos, b[k].pos)) - 0.1));
			hs_world_destroy(s.world);
		}
	print_message("second support: the top ball within %.3g m of both\n", worst);
	assert_true(worst <= 4e-6);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_ball_on_ball),
	    cmocka_unit_test(test_drift_within_the_gap_is_held),
	    cmocka_unit_test(test_floor_row_comes_apart),
	    cmocka_unit_test(test_stack_of_boxes),
	    cmocka_unit_test(test_pyramid_of_spheres),
	    cmocka_unit_test(test_frictionless_pyramid_spreads),
	    cmocka_unit_test(test_box_on_balls),
	    cmocka_unit_test(test_push_into_heavy_block),
	    cmocka_unit_test(test_drag_into_heavy_block),
	    cmocka_unit_test(test_restitution_per_pair),
	    cmocka_unit_test(test_closed_box_energy),
	    cmocka_unit_test(test_dense_drop_keeps_balls_apart),
	    cmocka_unit_test(test_dense_drop_comes_to_rest),
	    cmocka_unit_test(test_second_support_met_at_its_surface),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
