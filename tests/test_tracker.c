// test_tracker.c — the tracker daemon (§3, §5.1): 50 Hz sampling from any frame rate, velocity and
// acceleration estimates with and without the Fastrak's noise (drawn here: noise is input, the
// model adds none), rest / motion events, drop versus throw (§4.4), catch, and 'I want this one'
// selection.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "tracker.h"
#include "test_util.h"

static const hs_vec3 EARTH = {0.0, 0.0, -9.81};

#define FASTRAK_POSITION (0.03 * 0.0254)        // m RMS per axis: 0.03 inch (static accuracy, §5.1, [13])
#define FASTRAK_ORIENTATION (0.15 * HS_PI / 180.0) // rad RMS per axis: 0.15°

// A Fastrak reading of the pose: Gaussian noise on each position axis, then a rotation whose
// rotation vector has Gaussian components, drawn in this order (the order the model used when it
// drew the noise itself, so the seeds of these tests give the same readings as before).
static void fastrak_noise(gsl_rng *rng, hs_vec3 *position, hs_quat *orientation) {
	double nx = gsl_ran_gaussian(rng, FASTRAK_POSITION);
	double ny = gsl_ran_gaussian(rng, FASTRAK_POSITION);
	double nz = gsl_ran_gaussian(rng, FASTRAK_POSITION);
	*position = hs_add(*position, hs_v3(nx, ny, nz));
	double rx = gsl_ran_gaussian(rng, FASTRAK_ORIENTATION);
	double ry = gsl_ran_gaussian(rng, FASTRAK_ORIENTATION);
	double rz = gsl_ran_gaussian(rng, FASTRAK_ORIENTATION);
	hs_vec3 rv = hs_v3(rx, ry, rz);
	double angle = hs_length(rv);
	if (angle > 0.0)
		*orientation =
		    hs_quat_normalize(hs_quat_mul(hs_quat_from_axis_angle(hs_scale(rv, 1.0 / angle), angle), *orientation));
}

static hs_world *spring_world(double dt, const hs_spring_def *sd) {
	hs_world_def def = hs_default_world_def();
	def.dt = dt;
	def.gravity = EARTH;
	def.kind = HS_WORLD_SPRING;
	def.spring = sd ? *sd : hs_default_spring_def();
	hs_status st;
	hs_world *w = hs_world_create(&def, &st);
	assert_non_null(w);
	return w;
}

static hs_object_id add_sphere(hs_world *w, double r, double mass, hs_vec3 pos, hs_vec3 vel) {
	return hs_test_add_mass(w, hs_shape_sphere(r, NULL), mass, pos, vel);
}

static void stylus_at(hs_world *w, hs_vec3 p, bool button) {
	assert_int_equal(hs_world_set_stylus(w, p, hs_quat_identity(), button), HS_OK);
}

static void step(hs_world *w) { assert_int_equal(hs_world_step(w), HS_OK); }

static hs_tracker_state tracker_of(hs_world *w) {
	hs_tracker_state t;
	assert_int_equal(hs_world_tracker_state(w, &t), HS_OK);
	return t;
}

static hs_spring_state spring_of(hs_world *w) {
	hs_spring_state s;
	assert_int_equal(hs_world_spring_state(w, &s), HS_OK);
	return s;
}

static hs_vec3 pos_of(hs_world *w, hs_object_id id) {
	hs_object_state s;
	assert_int_equal(hs_world_object_state(w, id, &s), HS_OK);
	return s.position;
}

// The least-squares quadratic is exact on linear and quadratic paths (to rounding).
static void test_estimates_exact_on_polynomial_paths(void **state) {
	(void)state;
	hs_spring_def sd = hs_default_spring_def();
	for (int window = 3; window <= 16; window += 13) {
		sd.tracker_window = window;
		hs_tracker tr;
		hs_tracker_init(&tr, &sd, 0.0);
		hs_vec3 p0 = hs_v3(0.3, -0.2, 1.1), v = hs_v3(0.7, -1.3, 0.25);
		for (int k = 0; k < 40; ++k) { // linear: p = p0 + v t
			double t = 0.02 * k;
			hs_tracker_record(&tr, t, hs_mul_add(p0, t, v), hs_quat_identity(), false);
			if (k >= 1) {
				assert_vec3_near(tr.velocity, v, 1e-12);
				assert_vec3_near(tr.acceleration, hs_v3(0, 0, 0), 1e-9);
			}
		}
		hs_tracker_init(&tr, &sd, 0.0);
		hs_vec3 a = hs_v3(-2.0, 0.5, -9.81);
		for (int k = 0; k < 40; ++k) { // quadratic: p = p0 + v t + a t²/2
			double t = 0.02 * k;
			hs_tracker_record(&tr, t, hs_add(hs_mul_add(p0, t, v), hs_scale(a, 0.5 * t * t)), hs_quat_identity(),
			                  false);
			if (k >= 2) {
				assert_vec3_near(tr.velocity, hs_mul_add(v, t, a), 1e-11);
				assert_vec3_near(tr.acceleration, a, 1e-8);
			}
		}
		assert_int_equal(tr.count, 40);
	}
}

// With the Fastrak's 0.762 mm RMS noise, the window-9 fit's velocity error is 0.0181 m/s RMS per axis
// (σ √(Σ w²) of the fit's weights, tracker.c). Over 3000 samples the measured RMS must lie within 10 %
// of that and no error may exceed 5.5 σ (a 4e-8 chance per draw); without noise the error is zero.
// The noise is drawn here and the noisy samples recorded: the tracker records what it is given.
static void test_velocity_estimate_with_noise(void **state) {
	(void)state;
	hs_spring_def sd = hs_default_spring_def();
	gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
	assert_non_null(rng);
	gsl_rng_set(rng, 2024);
	hs_tracker tr;
	hs_tracker_init(&tr, &sd, 0.0);
	hs_vec3 p0 = hs_v3(0.0, 0.2, 1.0), v = hs_v3(0.8, 0.1, -0.4);
	const double sigma_v = 0.01805;
	double sum2 = 0.0, worst = 0.0;
	int n = 0;
	for (int k = 0; k < 3000; ++k) {
		double t = 0.02 * k;
		hs_vec3 p = hs_mul_add(p0, t, v);
		hs_quat q = hs_quat_identity();
		fastrak_noise(rng, &p, &q);
		hs_tracker_record(&tr, t, p, q, false);
		if (k < sd.tracker_window)
			continue;
		hs_vec3 err = hs_sub(tr.velocity, v);
		double e[3] = {err.x, err.y, err.z};
		for (int i = 0; i < 3; ++i) {
			sum2 += e[i] * e[i];
			worst = fabs(e[i]) > worst ? fabs(e[i]) : worst;
			n++;
		}
	}
	double rms = sqrt(sum2 / n);
	printf("tracker velocity noise: RMS %.4f m/s per axis (predicted %.4f), worst %.4f m/s\n", rms, sigma_v, worst);
	assert_near(rms, sigma_v, 0.1 * sigma_v);
	assert_true(worst < 5.5 * sigma_v);
	// the noisy samples scatter about the path by the Fastrak's 0.762 mm
	hs_tracker_sample s;
	assert_true(hs_tracker_sample_at(&tr, 0, &s));
	assert_true(fabs(s.position.x - (p0.x + v.x * s.time)) < 5.0 * 0.762e-3);
	assert_true(hs_length(hs_sub(s.position, hs_mul_add(p0, s.time, v))) > 0.0);
	gsl_rng_free(rng);
}

// 50 Hz from any frame rate: one sample per 20 ms tick, the stylus interpolated within the frame.
static void test_resampling_at_50_hz(void **state) {
	(void)state;
	const double dts[] = {1.0 / 12, 1.0 / 60, 1.0 / 1000, 1.0 / 50};
	const long frames[] = {12, 60, 1000, 50};
	for (int k = 0; k < 4; ++k) {
		hs_world *w = spring_world(dts[k], NULL);
		hs_vec3 p0 = hs_v3(0.1, 0.2, 0.3), v = hs_v3(0.5, -0.25, 0.125);
		stylus_at(w, p0, false);
		for (long f = 1; f <= frames[k]; ++f) {
			stylus_at(w, hs_mul_add(p0, (double)f * dts[k], v), false);
			step(w);
		}
		hs_tracker_state ts = tracker_of(w);
		assert_int_equal(ts.sample_count, 51); // t = 0, 0.02, ..., 1.00
		for (int age = 0; age < 51 && age < HS_TRACKER_CAPACITY; ++age) {
			hs_tracker_sample s;
			assert_int_equal(hs_world_tracker_sample(w, age, &s), HS_OK);
			assert_near(s.time, 0.02 * (50 - age), 1e-12);
			assert_vec3_near(s.position, hs_mul_add(p0, s.time, v), 1e-12);
		}
		assert_vec3_near(ts.velocity, v, 1e-9);
		hs_tracker_sample s;
		assert_int_equal(hs_world_tracker_sample(w, 51, &s), HS_ERR_INVALID_ARGUMENT);
		hs_world_destroy(w);
	}
}

// Rest → motion start above 0.20 m/s → motion end below 0.10 m/s; between the two nothing changes.
// The hand changes speed smoothly (smoothstep over 0.5 s), as a hand does: a quadratic fit overshoots
// at a kink of the path, by 40 % for a sudden start.
static void test_rest_and_motion_events(void **state) {
	(void)state;
	const double dt = 1.0 / 100;
	hs_world *w = spring_world(dt, NULL);
	hs_vec3 p = hs_v3(0, 0, 0.5);
	const double levels[] = {0.0, 0.15, 0.5, 0.15, 0.05, 0.0};
	// after each phase: 0 at rest; 0.15 m/s, between the thresholds: still at rest; 0.5 m/s: moving;
	// back to 0.15 m/s: still moving; 0.05 m/s: at rest; still
	const bool at_rest_after[] = {true, true, false, false, true, true};
	const long starts_after[] = {0, 0, 1, 1, 1, 1}, ends_after[] = {0, 0, 0, 0, 1, 1};
	stylus_at(w, p, false);
	double speed = 0.0;
	for (int phase = 0; phase < 6; ++phase) {
		double from = speed, to = levels[phase];
		double lo = INFINITY, hi = 0.0; // estimated speed during the hold
		for (int f = 0; f < 150; ++f) { // 0.5 s of transition, 1 s of hold
			double u = f < 50 ? (f + 1) / 50.0 : 1.0;
			speed = from + (to - from) * u * u * (3.0 - 2.0 * u);
			p.x += speed * dt;
			stylus_at(w, p, false);
			step(w);
			if (f >= 75) {
				double s = tracker_of(w).speed;
				lo = s < lo ? s : lo;
				hi = s > hi ? s : hi;
			}
		}
		hs_tracker_state ts = tracker_of(w);
		assert_near(lo, to, 1e-9); // steady speed: estimated exactly
		assert_near(hi, to, 1e-9);
		assert_true(ts.at_rest == at_rest_after[phase]);
		assert_int_equal(ts.motion_starts, starts_after[phase]);
		assert_int_equal(ts.motion_ends, ends_after[phase]);
		if (phase == 2) {
			assert_int_equal(ts.last_event, HS_TRACKER_EVENT_MOTION_START);
			assert_true(ts.last_event_time > 3.0 && ts.last_event_time < 3.5); // in the 0.15 → 0.5 ramp
		}
		if (phase == 4) {
			assert_int_equal(ts.last_event, HS_TRACKER_EVENT_MOTION_END);
			assert_true(ts.last_event_time > 6.0 && ts.last_event_time < 6.5); // in the 0.15 → 0.05 ramp
		}
	}
	hs_world_destroy(w);
}

// A resting hand read through the Fastrak's noise (each frame's pose drawn afresh and passed to
// hs_world_set_stylus, as the harness does) stays 'at rest' (5.5 σ below the rest threshold).
static void test_noisy_rest_stays_at_rest(void **state) {
	(void)state;
	gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
	assert_non_null(rng);
	gsl_rng_set(rng, 99);
	hs_world *w = spring_world(1.0 / 60, NULL);
	double top = 0.0;
	for (int f = 0; f < 600; ++f) {
		hs_vec3 p = hs_v3(0.1, 0.1, 0.4);
		hs_quat q = hs_quat_identity();
		fastrak_noise(rng, &p, &q);
		assert_int_equal(hs_world_set_stylus(w, p, q, false), HS_OK);
		step(w);
		double speed = tracker_of(w).speed;
		if (f >= 12) // once the fit window is full (9 samples = 0.16 s)
			top = speed > top ? speed : top;
	}
	printf("noisy resting hand: highest speed estimate %.4f m/s over 10 s\n", top);
	hs_tracker_state ts = tracker_of(w);
	assert_true(ts.at_rest);
	assert_int_equal(ts.motion_starts, 0);
	assert_true(top > 0.0 && top < 0.2);
	hs_tracker_sample s;
	assert_int_equal(hs_world_tracker_sample(w, 0, &s), HS_OK);
	assert_true(hs_quat_angle(s.orientation) > 0.0 && hs_quat_angle(s.orientation) < 5.0 * 0.15 * HS_PI / 180.0 * 2.0);
	assert_true(hs_distance(s.position, hs_v3(0.1, 0.1, 0.4)) < 5.0 * FASTRAK_POSITION * 2.0);
	hs_world_destroy(w);
	gsl_rng_free(rng);
}

// Carry an object at constant speed `speed` from the first frame, release the button after 0.5 s.
static hs_release release_at_speed(double speed, hs_vec3 *object_velocity) {
	hs_world *w = spring_world(1.0 / 60, NULL);
	hs_object_id ball = add_sphere(w, 0.03, 0.1, hs_v3(0, 0, 0.9), hs_v3(0, 0, 0));
	hs_vec3 s = hs_v3(0, 0, 1.0);
	stylus_at(w, s, true);
	assert_int_equal(hs_world_spring_attach(w, ball), HS_OK);
	for (int f = 0; f < 30; ++f) {
		s.x += speed / 60;
		stylus_at(w, s, true);
		step(w);
	}
	assert_int_equal(spring_of(w).attached.index1, ball.index1);
	s.x += speed / 60;
	stylus_at(w, s, false);
	step(w);
	assert_int_equal(spring_of(w).attached.index1, 0);
	hs_release r;
	assert_int_equal(hs_world_spring_last_release(w, &r), HS_OK);
	assert_int_equal(r.object.index1, ball.index1);
	hs_spring_object o;
	assert_int_equal(hs_world_spring_object(w, ball, &o), HS_OK);
	*object_velocity = o.velocity;
	hs_world_destroy(w);
	return r;
}

// §4.4: released at rest → drop; released while moving → throw with the hand's velocity.
// The line is motion_speed (0.20 m/s): 1 % below stays a drop, 1 % above is a throw.
static void test_drop_versus_throw_threshold(void **state) {
	(void)state;
	hs_vec3 v;
	hs_release below = release_at_speed(0.99 * 0.20, &v);
	assert_int_equal(below.kind, HS_RELEASE_DROP);
	assert_near(below.hand_speed, 0.99 * 0.20, 1e-9);
	assert_vec3_near(below.velocity, v, 0.0); // the object kept its own velocity
	hs_release above = release_at_speed(1.01 * 0.20, &v);
	assert_int_equal(above.kind, HS_RELEASE_THROW);
	assert_vec3_near(above.velocity, hs_v3(1.01 * 0.20, 0, 0), 1e-9); // the hand's velocity
	assert_vec3_near(v, above.velocity, 0.0);
	assert_near(above.time, 31.0 / 60.0, 1e-12);
}

// The same path released in motion and after coming to rest: throw, then drop; the thrown object
// flies off with the hand's velocity, the dropped one falls straight down.
static void test_drop_and_throw_on_one_path(void **state) {
	(void)state;
	for (int rest = 0; rest < 2; ++rest) {
		hs_world *w = spring_world(1.0 / 60, NULL);
		hs_object_id ball = add_sphere(w, 0.03, 0.1, hs_v3(0, 0, 0.03), hs_v3(0, 0, 0));
		hs_vec3 s = hs_v3(0, 0, 0.03);
		stylus_at(w, s, true); // inside the ball: direct picking
		step(w);
		hs_spring_state ss = spring_of(w);
		assert_int_equal(ss.attached.index1, ball.index1);
		assert_int_equal(ss.attach_kind, HS_ATTACH_PICK);
		for (int f = 0; f < 60; ++f) { // lift to 0.5 m
			s.z += 0.45 / 60;
			stylus_at(w, s, true);
			step(w);
		}
		for (int f = 0; f < 60; ++f) { // swing out along x at up to 1.5 m/s
			double t = (f + 1) / 60.0;
			s.x = 0.75 * t * t;
			stylus_at(w, s, true);
			step(w);
		}
		if (rest)
			for (int f = 0; f < 60; ++f)
				step(w); // the hand stops and rests for 1 s
		hs_vec3 before = pos_of(w, ball);
		if (!rest) // the hand goes on moving while the button comes up
			s.x = 0.75 * (61.0 / 60.0) * (61.0 / 60.0);
		stylus_at(w, s, false);
		step(w);
		hs_release r;
		assert_int_equal(hs_world_spring_last_release(w, &r), HS_OK);
		assert_int_equal(r.kind, rest ? HS_RELEASE_DROP : HS_RELEASE_THROW);
		if (!rest)
			assert_near(r.velocity.x, 1.5, 0.02);
		for (int f = 0; f < 120; ++f)
			step(w);
		hs_vec3 after = pos_of(w, ball);
		assert_true(after.z == 0.03); // on the floor
		if (rest)
			assert_near(after.x, before.x, 0.01); // straight down
		else
			assert_true(after.x > before.x + 0.3); // flew on
		hs_world_destroy(w);
	}
}

// §4.4 catch: pressing the button next to a flying object attaches the spring; it stops and hangs.
static void test_catch(void **state) {
	(void)state;
	hs_world *w = spring_world(1.0 / 60, NULL);
	hs_vec3 p0 = hs_v3(-0.6, 0, 0.6), v0 = hs_v3(2.0, 0, 1.0);
	hs_object_id ball = add_sphere(w, 0.04, 0.2, p0, v0);
	double tc = 0.3; // where the ball will be at 0.3 s
	hs_vec3 s = hs_v3(p0.x + v0.x * tc, 0.02, p0.z + v0.z * tc - 0.5 * 9.81 * tc * tc);
	stylus_at(w, s, false);
	bool pressed = false;
	for (int f = 0; f < 40 && !pressed; ++f) {
		step(w);
		double d = hs_distance(pos_of(w, ball), s) - 0.04;
		if (d < 0.04) { // within reach: press for the next frame
			stylus_at(w, s, true);
			step(w);
			pressed = true;
		}
	}
	assert_true(pressed);
	hs_spring_state ss = spring_of(w);
	assert_int_equal(ss.attached.index1, ball.index1);
	assert_int_equal(ss.attach_kind, HS_ATTACH_CATCH);
	for (int f = 0; f < 240; ++f) {
		stylus_at(w, s, true);
		step(w);
	}
	hs_spring_object o;
	assert_int_equal(hs_world_spring_object(w, ball, &o), HS_OK);
	assert_near(hs_length(o.velocity), 0.0, 1e-6); // decelerated and stopped
	ss = spring_of(w);
	assert_near(ss.extension, 0.2 * o.rest_length, 1e-6); // hanging at rest
	hs_vec3 p = pos_of(w, ball); // hanging 1.2 x0 below the anchor fixed at the catch (neutral)
	assert_near(p.x, ss.anchor.x, 1e-6);
	assert_near(p.y, ss.anchor.y, 1e-6);
	assert_near(p.z, ss.anchor.z - 1.2 * o.rest_length, 1e-6);
	hs_world_destroy(w);
}

// A button press far from everything attaches nothing; a press at rest next to a resting object
// that was never a candidate attaches nothing either.
static void test_press_in_empty_space(void **state) {
	(void)state;
	hs_world *w = spring_world(1.0 / 60, NULL);
	add_sphere(w, 0.05, 0.5, hs_v3(0.5, 0, 0.05), hs_v3(0, 0, 0));
	stylus_at(w, hs_v3(0.3, 0, 0.05), true);
	step(w);
	hs_spring_state ss = spring_of(w);
	assert_int_equal(ss.attached.index1, 0);
	assert_int_equal(ss.candidate.index1, 0);
	hs_world_destroy(w);
}

// §3 'I want this one': the hand moves toward one of three objects; the ray along its velocity
// picks that one; a press then attaches it. Inside an object, direct picking wins.
static void test_selection_among_three(void **state) {
	(void)state;
	for (int target = 0; target < 3; ++target) {
		hs_world *w = spring_world(1.0 / 60, NULL);
		hs_object_id ids[3];
		hs_vec3 centres[3];
		for (int i = 0; i < 3; ++i) {
			centres[i] = hs_v3(0.6, -0.3 + 0.3 * i, 0.05);
			ids[i] = add_sphere(w, 0.05, 0.5, centres[i], hs_v3(0, 0, 0));
		}
		hs_vec3 s = hs_v3(0, 0, 0.15);
		hs_vec3 dir = hs_normalize(hs_sub(centres[target], s));
		stylus_at(w, s, false);
		for (int f = 0; f < 10; ++f) // at rest: no candidate yet
			step(w);
		assert_int_equal(spring_of(w).candidate.index1, 0);
		for (int f = 0; f < 45; ++f) { // 0.75 s at 0.5 m/s toward the target (0.375 m of 0.61 m)
			s = hs_mul_add(s, 0.5 / 60, dir);
			stylus_at(w, s, false);
			step(w);
		}
		assert_int_equal(spring_of(w).candidate.index1, ids[target].index1);
		for (int f = 0; f < 30; ++f) // stop: the candidate stays
			step(w);
		assert_true(tracker_of(w).at_rest);
		assert_int_equal(spring_of(w).candidate.index1, ids[target].index1);
		stylus_at(w, s, true);
		step(w);
		hs_spring_state ss = spring_of(w);
		assert_int_equal(ss.attached.index1, ids[target].index1);
		assert_int_equal(ss.attach_kind, HS_ATTACH_SELECT);
		hs_world_destroy(w);
	}
	// direct picking: the stylus inside the middle object, at rest
	hs_world *w = spring_world(1.0 / 60, NULL);
	hs_object_id ids[3];
	for (int i = 0; i < 3; ++i)
		ids[i] = add_sphere(w, 0.05, 0.5, hs_v3(0.6, -0.3 + 0.3 * i, 0.05), hs_v3(0, 0, 0));
	stylus_at(w, hs_v3(0.61, 0.01, 0.06), false);
	step(w);
	assert_int_equal(spring_of(w).candidate.index1, ids[1].index1);
	stylus_at(w, hs_v3(0.61, 0.01, 0.06), true);
	step(w);
	assert_int_equal(spring_of(w).attached.index1, ids[1].index1);
	assert_int_equal(spring_of(w).attach_kind, HS_ATTACH_PICK);
	hs_world_destroy(w);
}

// The fit's end-point velocity weights for window 9, newest first (tracker.c): the closed form of
// the least-squares quadratic's derivative at τ = 0 over τ = 0, −1, ..., −8 periods.
static const double W9[9] = {17.0 / 55,    73.0 / 660,  -83.0 / 2310, -201.0 / 1540, -40.0 / 231,
                             -757.0 / 4620, -79.0 / 770, 7.0 / 660,    29.0 / 165};

// The unclipped response Σ w_j y_j / h to positions y(age j) = f(k − j) (k: periods since the event).
static double fit_response(double (*f)(double), int k, double h) {
	double v = 0.0;
	for (int j = 0; j < 9; ++j)
		v += W9[j] * f((double)(k - j));
	return v / h;
}

static double path_start(double n) { return n > 0.0 ? n : 0.0; }        // V = 1 period⁻¹ from n = 0
static double path_ramp(double n) { return n > 0.0 ? 0.5 * n * n : 0.0; } // a = 1 period⁻² from n = 0
static double path_stop(double n) { return n < 0.0 ? n : 0.0; }         // V = 1 period⁻¹ until n = 0

typedef struct response {
	double v[16];   // velocity estimate (m/s along x) at 0..15 samples after the event
	int event_at;   // samples after the event of the first rest/motion event, -1 when none
	bool at_rest;   // after the last sample
	long starts, ends;
} response;

// Feeds the tracker 1 s of a hand at rest (or moving at 'speed' along x), then the path
// p(t) = scale · f(t / h) along x for 16 samples after the event at t = 1 s.
static response run_response(double (*f)(double), double scale, double speed_before) {
	hs_spring_def sd = hs_default_spring_def();
	hs_tracker tr;
	hs_tracker_init(&tr, &sd, 0.0);
	double h = 1.0 / sd.tracker_rate;
	response r = {.event_at = -1};
	for (int k = -50; k < 16; ++k) {
		double x = k <= 0 ? speed_before * k * h : scale * f((double)k);
		long events = tr.motion_starts + tr.motion_ends;
		hs_tracker_record(&tr, 1.0 + k * h, hs_v3(x, 0.2, 0.5), hs_quat_identity(), false);
		if (k == 0) {
			assert_true(tr.at_rest == (speed_before == 0.0)); // settled before the event
			r.starts = tr.motion_starts;
			r.ends = tr.motion_ends;
		}
		if (k >= 0) {
			r.v[k] = tr.velocity.x;
			assert_near(tr.velocity.y, 0.0, 1e-12);
			if (k > 0 && r.event_at < 0 && tr.motion_starts + tr.motion_ends != events)
				r.event_at = k;
		}
	}
	r.at_rest = tr.at_rest;
	r.starts = tr.motion_starts - r.starts;
	r.ends = tr.motion_ends - r.ends;
	return r;
}

// Step (a start from rest at V), ramp (constant acceleration from rest) and stop (V to rest at
// once) responses of the estimator against their closed forms Σ w_j y_j / h, and the latency of
// the events in tracker samples (20 ms at 50 Hz). The stop response is the fit's with the part
// against the hand's path removed: V, 0.691 V, 0.271 V, then 0 — never backwards (the bare fit
// reads −0.446 V 5 samples after the stop).
static void test_step_ramp_stop_responses(void **state) {
	(void)state;
	const double h = 0.02, V = 1.0, A = 10.0;
	response r = run_response(path_start, V * h, 0.0); // step: 0, 0.309, 0.729, 1.113 ... 1.446 ... V
	for (int k = 0; k < 16; ++k)
		assert_near(r.v[k], V * h * fit_response(path_start, k, h), 1e-12);
	assert_near(r.v[5], 1.4458874458874459 * V, 1e-12); // the overshoot: +44.6 % (left as it is)
	assert_near(r.v[8], V, 1e-12);                       // exact from 8 samples on
	assert_int_equal(r.event_at, 1);                     // motion start: 1 sample (0.309 V > 0.20)
	assert_int_equal(r.starts, 1);
	assert_int_equal(r.ends, 0);

	r = run_response(path_ramp, A * h * h, 0.0); // ramp: exact (A k h) from 8 samples on
	for (int k = 0; k < 16; ++k)
		assert_near(r.v[k], A * h * h * fit_response(path_ramp, k, h), 1e-11);
	for (int k = 8; k < 16; ++k)
		assert_near(r.v[k], A * k * h, 1e-11);
	// 10 m/s²: the hand passes 0.20 m/s at sample 1; the fit reads 0.031, 0.135, 0.319 m/s at
	// samples 1-3 (true 0.2, 0.4, 0.6): motion start at sample 3, 2 samples (40 ms) late
	assert_int_equal(r.event_at, 3);
	assert_int_equal(r.starts, 1);

	r = run_response(path_stop, V * h, V); // stop from 1 m/s: V, 0.691 V, 0.271 V, 0, 0, ...
	assert_near(r.v[0], V, 1e-12);
	assert_near(r.v[1], 38.0 / 55 * V, 1e-12);
	assert_near(r.v[2], 179.0 / 660 * V, 1e-12);
	for (int k = 3; k < 16; ++k) {
		assert_true(V * h * fit_response(path_stop, k, h) <= 1e-12); // the bare fit: ≤ 0 (−0.446 V at 5)
		assert_near(r.v[k], 0.0, 1e-12);                              // clipped: no motion invented
	}
	assert_int_equal(r.event_at, 3); // motion end: 3 samples (60 ms) after the stop
	assert_true(r.at_rest);
	assert_int_equal(r.starts, 0);
	assert_int_equal(r.ends, 1);

	r = run_response(path_stop, 0.3 * h, 0.3); // from 0.3 m/s: 0.271 V = 0.081 < 0.10 at sample 2
	assert_int_equal(r.event_at, 2);
	assert_int_equal(r.starts, 0);
}

// docs/model.md §9 "No motion against the path" in a spring world: carry a ball at 1 m/s, stop
// abruptly, release 0.1 s later — a drop (the bare fit read −0.45 m/s and threw it backwards); and
// after a 0.1 s linear deceleration to rest, released 0.1 s later, a drop too (the bare fit read
// −0.15 m/s).
static void test_release_after_stop_is_drop(void **state) {
	(void)state;
	for (int decel = 0; decel < 2; ++decel) {
		hs_world *w = spring_world(1.0 / 60, NULL);
		add_sphere(w, 0.04, 0.2, hs_v3(-0.6, 0, 0.04), hs_v3(0, 0, 0));
		hs_vec3 p = hs_v3(-0.6, 0, 0.04);
		for (int f = 0; f < 30; ++f) { // into the ball, press, lift to 0.4 m
			stylus_at(w, p, f >= 10);
			step(w);
		}
		for (int f = 0; f < 60; ++f) {
			p.z = 0.04 + 0.36 * (f + 1) / 60.0;
			stylus_at(w, p, true);
			step(w);
		}
		double speed = 1.0;
		for (int f = 0; f < 90; ++f) { // carry along +x at 1 m/s for 0.5 s, then stop
			if (f >= 30)
				speed = decel ? (speed - 1.0 / 6.0 > 0.0 ? speed - 1.0 / 6.0 : 0.0) : 0.0;
			p.x += speed / 60.0;
			stylus_at(w, p, true);
			step(w);
			if (f == 29 + (decel ? 6 : 0) + 6) // 0.1 s after the stop: release
				break;
		}
		stylus_at(w, p, false);
		step(w);
		hs_release rel;
		assert_int_equal(hs_world_spring_last_release(w, &rel), HS_OK);
		assert_int_equal(rel.kind, HS_RELEASE_DROP);
		assert_true(tracker_of(w).motion_starts == 1); // the carry's start only: no motion invented
		hs_world_destroy(w);
	}
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_estimates_exact_on_polynomial_paths),
	    cmocka_unit_test(test_velocity_estimate_with_noise),
	    cmocka_unit_test(test_resampling_at_50_hz),
	    cmocka_unit_test(test_rest_and_motion_events),
	    cmocka_unit_test(test_noisy_rest_stays_at_rest),
	    cmocka_unit_test(test_drop_versus_throw_threshold),
	    cmocka_unit_test(test_drop_and_throw_on_one_path),
	    cmocka_unit_test(test_catch),
	    cmocka_unit_test(test_press_in_empty_space),
	    cmocka_unit_test(test_selection_among_three),
	    cmocka_unit_test(test_step_ramp_stop_responses),
	    cmocka_unit_test(test_release_after_stop_is_drop),
	};
	return cmocka_run_group_tests_name("tracker", tests, NULL, NULL);
}
