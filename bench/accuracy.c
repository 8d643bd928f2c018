// accuracy.c — item 3 of `make bench`: speed against error for every integrator the library has.
//
// Integrators: the 1999 paper's Verlet (eq. 3, the hand world's free motion) and the spring
// world's four (HS_INTEGRATOR_EXACT, IMPLICIT_EULER, SEMI_IMPLICIT_EULER, RK4), each stepped at
// dt = 1/12 … 1/2000 s on four problems with trusted answers:
//  - projectile: G from (0, 0, 1) m at (2, 0, 1) m/s; range = x where G crosses z = 0.5 m (closed
//    form; the crossing is read off the samples by the quadratic through the last three, which is
//    exact for a sampled parabola, so the error is the integrator's alone);
//  - hanging spring: a 5 cm cube (density 500, m = 62.5 g, ω = √(g / 0.2 x0) ≈ 35 rad/s) on the
//    critically damped spring, let go 1 cm below its equilibrium at rest: x_d(t) = (x0 + (v0 + ω x0)
//    t) e^{−ωt} (workbench paper §4.3); error = max |z − z_closed| over the first second;
//  - swing: the same cube at the hanging length, 30° out, let go at rest. The model damps the
//    pendulum critically too (§4.4) and its 3D spring is nonlinear (the tension turns with the
//    spring, k⊥ = k (1 − x0/L)), so there is no closed form: the reference is the continuous-time
//    equation m p̈ = m g − u (k (L − x0) + c v·u) − c⊥ (v − (v·u) u), c⊥ = 2 √(k⊥ m), integrated by
//    GSL's gsl_odeiv2 rk8pd at 1e-12; error = max |p − p_ref| over the first two seconds;
//  - friction stop: the cube sliding freely on the floor at 1 m/s, μ = 0.5: stops after
//    v² / (2 μ g) = 0.1019 m (closed form); error = |distance − closed form|.
// The Verlet runs only the projectile (the 1999 model has no springs and no sliding).
// ns per step: the steps of each problem timed on CLOCK_MONOTONIC (world creation excluded),
// repeated in batches, median. Explicit schemes go unstable for large ω Δt: the tables mark
// ω Δt ≥ 2 and report what each run actually did ("unstable": it diverged or was frozen by the
// library's numeric guard).
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

enum { I_VERLET = 0, I_EXACT, I_IMPLICIT, I_SEMI, I_RK4, N_INTEGRATORS };
static const char *const integrator_names[N_INTEGRATORS] = {"verlet-1999", "exact", "implicit-euler",
                                                            "semi-implicit", "rk4"};
static const hs_integrator spring_integrator[N_INTEGRATORS] = {HS_INTEGRATOR_EXACT, HS_INTEGRATOR_EXACT,
                                                               HS_INTEGRATOR_IMPLICIT_EULER,
                                                               HS_INTEGRATOR_SEMI_IMPLICIT_EULER, HS_INTEGRATOR_RK4};

enum { P_PROJECTILE = 0, P_HANGING, P_SWING, P_FRICTION, N_PROBLEMS };
static const char *const problem_names[N_PROBLEMS] = {"projectile", "hanging", "swing", "friction"};
static const char *const problem_titles[N_PROBLEMS] = {
    "projectile range (closed form), m", "critically damped hanging spring (closed form), max |dz| over 1 s, m",
    "swing on the spring (rk8pd reference at 1e-12), max |dp| over 2 s, m",
    "friction stop distance v^2/(2 mu g) (closed form), m"};

static const double rates[] = {12, 17, 24, 30, 60, 120, 240, 500, 1000, 2000};
#define N_RATES ((int)(sizeof rates / sizeof rates[0]))

#define HANG_DROP 0.01  // m below equilibrium at t = 0
#define HANG_TIME 1.0   // s compared
#define SWING_DEG 30.0  // initial angle from the vertical
#define SWING_TIME 2.0  // s compared
#define SLIDE_SPEED 1.0 // m/s
#define SLIDE_MU 0.5
#define SLIDE_TIME 0.6 // s run (the stop comes at 0.204 s)
static const hs_vec3 STYLUS = {0.0, 0.0, 1.0};

typedef struct acc_result {
	bool run;
	double error;      // m (or -1: unstable)
	bool unstable;
	long steps;        // steps of one run
	double ns_per_step;
	double omega_dt;   // ω Δt of the problem's stiffest mode (0 without a spring)
} acc_result;

// ---------------------------------------------------------------------------------------------
// One problem, one integrator, one dt: a world, its steps, its error

typedef struct problem_run {
	hs_world *world;
	hs_object_id id;
	long steps;      // steps the problem takes
	double omega;    // rad/s of the spring (0: none)
	double x0, k, c, mass; // the spring (hanging, swing)
	hs_vec3 eq;      // equilibrium (hanging)
} problem_run;

static void die(const char *what) {
	fprintf(stderr, "bench: accuracy: %s\n", what);
	exit(2);
}

static void make_world(problem_run *pr, int integ, double dt, int problem) {
	memset(pr, 0, sizeof *pr);
	hs_world_def wd = hs_default_world_def();
	wd.dt = dt;
	wd.max_objects = 1;
	wd.max_hands = 0;
	if (integ != I_VERLET) {
		wd.kind = HS_WORLD_SPRING;
		wd.spring.integrator = spring_integrator[integ];
		wd.spring.friction_static = wd.spring.friction_sliding = SLIDE_MU;
	}
	hs_status st;
	pr->world = hs_world_create(&wd, &st);
	if (!pr->world)
		die(hs_status_string(st));
	hs_shape *cube = hs_shape_box(hs_v3(BENCH_CUBE, BENCH_CUBE, BENCH_CUBE), &st);
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(pr->world, cube, &st);
	hs_shape_destroy(cube);
	// the spring constants of this cube (mass, x0, k, ω) as the library computes them
	double mass = od.density * BENCH_CUBE * BENCH_CUBE * BENCH_CUBE;
	double x0 = 0.10 * cbrt(mass / 1.0);
	x0 = x0 < 0.01 ? 0.01 : (x0 > 1.0 ? 1.0 : x0);
	double k = mass * BENCH_G / (0.2 * x0);
	pr->mass = mass;
	pr->x0 = x0;
	pr->k = k;
	pr->c = 2.0 * sqrt(k * mass);
	pr->omega = sqrt(k / mass);
	switch (problem) {
	case P_PROJECTILE:
		od.position = hs_v3(0.0, 0.0, BENCH_PROJ_Z0);
		od.velocity = hs_v3(BENCH_PROJ_VX, 0.0, BENCH_PROJ_VZ);
		pr->omega = 0.0;
		pr->steps = (long)ceil(0.6 / dt) + 2; // the crossing comes at 0.43 s
		break;
	case P_HANGING:
		pr->eq = hs_sub(STYLUS, hs_v3(0.0, 0.0, 1.2 * x0)); // stretched by 0.2 x0 under its weight
		od.position = hs_sub(pr->eq, hs_v3(0.0, 0.0, HANG_DROP));
		pr->steps = (long)floor(HANG_TIME / dt + 1e-9);
		break;
	case P_SWING: {
		double a = SWING_DEG * HS_PI / 180.0, len = 1.2 * x0;
		od.position = hs_add(STYLUS, hs_v3(len * sin(a), 0.0, -len * cos(a)));
		pr->steps = (long)floor(SWING_TIME / dt + 1e-9);
		break;
	}
	case P_FRICTION:
		od.position = hs_v3(0.0, 0.0, 0.5 * BENCH_CUBE);
		od.velocity = hs_v3(SLIDE_SPEED, 0.0, 0.0);
		pr->omega = 0.0;
		pr->steps = (long)ceil(SLIDE_TIME / dt);
		break;
	}
	pr->id = hs_world_add_object(pr->world, &od, &st);
	if (st != HS_OK)
		die("object");
	if (problem == P_HANGING || problem == P_SWING) {
		hs_world_set_stylus(pr->world, STYLUS, hs_quat_identity(), false);
		if (hs_world_spring_attach(pr->world, pr->id) != HS_OK)
			die("attach");
		hs_spring_object so;
		hs_world_spring_object(pr->world, pr->id, &so);
		if (fabs(so.omega - pr->omega) > 1e-9 * pr->omega) // the library's spring is the one modelled here
			die("spring constants differ from the library's (rest-length rule changed?)");
	}
}

static hs_vec3 position_of(const problem_run *pr) {
	hs_object_state os;
	hs_world_object_state(pr->world, pr->id, &os);
	return os.position;
}

// The swing's continuous-time equation for GSL: y = (p, v), stylus fixed at STYLUS.
static int swing_rhs(double t, const double y[], double dydt[], void *params) {
	(void)t;
	const problem_run *pr = params;
	hs_vec3 p = hs_v3(y[0], y[1], y[2]), v = hs_v3(y[3], y[4], y[5]);
	hs_vec3 d = hs_sub(p, STYLUS);
	double len = hs_length(d);
	hs_vec3 u = hs_scale(d, 1.0 / len);
	double ra = hs_dot(v, u);
	hs_vec3 rp = hs_mul_add(v, -ra, u);
	double kt = len > pr->x0 ? pr->k * (1.0 - pr->x0 / len) : 0.0;
	double ct = 2.0 * sqrt(kt * pr->mass);
	hs_vec3 f = hs_sub(hs_scale(u, -(pr->k * (len - pr->x0) + pr->c * ra)), hs_scale(rp, ct));
	hs_vec3 a = hs_add(hs_v3(0.0, 0.0, -BENCH_G), hs_scale(f, 1.0 / pr->mass));
	dydt[0] = v.x;
	dydt[1] = v.y;
	dydt[2] = v.z;
	dydt[3] = a.x;
	dydt[4] = a.y;
	dydt[5] = a.z;
	return GSL_SUCCESS;
}

// Runs the problem once, recording what the error needs.
static acc_result run_error(int integ, double dt, int problem, uint64_t *checksum) {
	acc_result r;
	memset(&r, 0, sizeof r);
	r.run = true;
	problem_run pr;
	make_world(&pr, integ, dt, problem);
	r.steps = pr.steps;
	r.omega_dt = pr.omega * dt;
	hs_vec3 start = position_of(&pr);
	double err = 0.0, excursion = 0.0;
	if (problem == P_PROJECTILE) {
		double *xs = malloc((size_t)(pr.steps + 1) * sizeof *xs), *zs = malloc((size_t)(pr.steps + 1) * sizeof *zs);
		if (!xs || !zs)
			die("memory");
		int n = 0;
		xs[n] = start.x;
		zs[n++] = start.z;
		for (long s = 0; s < pr.steps && zs[n - 1] >= BENCH_PROJ_PLANE; ++s) {
			hs_world_step(pr.world);
			hs_vec3 p = position_of(&pr);
			xs[n] = p.x;
			zs[n++] = p.z;
		}
		if (n >= 3 && zs[n - 1] < BENCH_PROJ_PLANE)
			err = fabs(bench_crossing_x(xs, zs, n, BENCH_PROJ_PLANE) - bench_projectile_range());
		else
			r.unstable = true;
		free(xs);
		free(zs);
	} else if (problem == P_HANGING) {
		for (long s = 1; s <= pr.steps; ++s) {
			hs_world_step(pr.world);
			double t = (double)s * dt, d0 = -HANG_DROP, w = pr.omega;
			double closed = (d0 + w * d0 * t) * exp(-w * t); // x_d(t), v0 = 0
			double dz = position_of(&pr).z - pr.eq.z;
			err = fmax(err, fabs(dz - closed));
			excursion = fmax(excursion, fabs(dz));
		}
		r.unstable = !(excursion <= 1.5 * HANG_DROP);
	} else if (problem == P_SWING) {
		gsl_odeiv2_system sys = {swing_rhs, NULL, 6, &pr};
		gsl_odeiv2_driver *drv = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-6 * dt, 1e-12, 1e-12);
		double y[6] = {start.x, start.y, start.z, 0.0, 0.0, 0.0}, t = 0.0;
		double amplitude = hs_distance(start, hs_sub(STYLUS, hs_v3(0.0, 0.0, 1.2 * pr.x0)));
		for (long s = 1; s <= pr.steps; ++s) {
			hs_world_step(pr.world);
			if (gsl_odeiv2_driver_apply(drv, &t, (double)s * dt, y) != GSL_SUCCESS)
				die("rk8pd reference failed");
			hs_vec3 p = position_of(&pr);
			err = fmax(err, hs_distance(p, hs_v3(y[0], y[1], y[2])));
			excursion = fmax(excursion, hs_distance(p, hs_sub(STYLUS, hs_v3(0.0, 0.0, 1.2 * pr.x0))));
		}
		gsl_odeiv2_driver_free(drv);
		r.unstable = !(excursion <= 1.5 * amplitude);
	} else { // friction
		for (long s = 0; s < pr.steps; ++s)
			hs_world_step(pr.world);
		double dist = position_of(&pr).x - start.x;
		err = fabs(dist - SLIDE_SPEED * SLIDE_SPEED / (2.0 * SLIDE_MU * BENCH_G));
		r.unstable = !isfinite(dist);
	}
	hs_world_counters wc = hs_world_get_counters(pr.world);
	if (wc.numeric_faults > 0 || !isfinite(err))
		r.unstable = true;
	r.error = err;
	*checksum = bench_mix(*checksum, position_of(&pr).x) ^ hs_world_hash(pr.world);
	hs_world_destroy(pr.world);
	return r;
}

// ns per step: batches of whole runs (the world built outside the clock), median of the batches.
static double run_timing(int integ, double dt, int problem, const bench_opts *opts, uint64_t *checksum) {
	double per[64];
	int reps = opts->reps;
	for (int rep = -1; rep < reps; ++rep) { // rep −1 is the warm-up
		double timed = 0.0;
		long steps = 0;
		while (timed < 0.25 * opts->batch_s || steps < 64) {
			problem_run pr;
			make_world(&pr, integ, dt, problem);
			double t0 = bench_now();
			for (long s = 0; s < pr.steps; ++s)
				hs_world_step(pr.world);
			timed += bench_now() - t0;
			steps += pr.steps;
			*checksum = bench_mix(*checksum, position_of(&pr).z);
			hs_world_destroy(pr.world);
		}
		if (rep >= 0)
			per[rep] = timed / (double)steps;
	}
	return 1e9 * bench_median(per, reps);
}

// ---------------------------------------------------------------------------------------------

void bench_accuracy(const bench_opts *opts, bench_shared *shared) {
	gsl_set_error_handler_off();
	static acc_result res[N_PROBLEMS][N_INTEGRATORS][N_RATES];
	memset(res, 0, sizeof res);
	uint64_t checksum = 14695981039346656037ull;
	for (int p = 0; p < N_PROBLEMS; ++p) {
		for (int i = 0; i < N_INTEGRATORS; ++i) {
			if (i == I_VERLET && p != P_PROJECTILE)
				continue; // the 1999 model has no springs and no sliding
			for (int k = 0; k < N_RATES; ++k) {
				double dt = 1.0 / rates[k];
				acc_result r = run_error(i, dt, p, &checksum);
				r.ns_per_step = run_timing(i, dt, p, opts, &checksum);
				res[p][i][k] = r;
			}
			bench_progress("[accuracy] %-10s %-14s done (error at 1/60 s: %.3g m, %.0f ns/step)\n", problem_names[p],
			               integrator_names[i], res[p][i][4].error, res[p][i][4].ns_per_step);
		}
	}
	shared->checksum ^= checksum;

	FILE *csv = bench_csv(opts, "accuracy.csv",
	                      "speed against error: error (m) and ns per step; unstable = diverged or frozen by the numeric guard");
	fprintf(csv, "problem,integrator,fps,dt,omega_dt,steps,error,ns_per_step,us_per_sim_s,unstable,explicit_limit\n");
	for (int p = 0; p < N_PROBLEMS; ++p)
		for (int i = 0; i < N_INTEGRATORS; ++i)
			for (int k = 0; k < N_RATES; ++k) {
				const acc_result *r = &res[p][i][k];
				if (!r->run)
					continue;
				fprintf(csv, "%s,%s,%g,%.10g,%.4f,%ld,%.6e,%.2f,%.4f,%d,%d\n", problem_names[p], integrator_names[i],
				        rates[k], 1.0 / rates[k], r->omega_dt, r->steps, r->unstable ? 1e3 : fmax(r->error, 1e-17),
				        r->ns_per_step, 1e-3 * r->ns_per_step * rates[k], r->unstable ? 1 : 0,
				        r->omega_dt >= 2.0 ? 1 : 0);
			}
	fclose(csv);

	printf("\n== 3. Speed against error: error in m / ns per step (median of %d batches) ==\n", opts->reps);
	printf("'!' marks omega*dt >= 2 (explicit schemes' stability edge); 'UNSTABLE' = diverged or frozen by the "
	       "numeric guard.\nWith critical damping the semi-implicit Euler step has determinant 1 - 2 omega dt, so it "
	       "diverges beyond omega dt = 1;\nRK4's real-axis limit is omega dt = 2.785; exact and implicit Euler are "
	       "stable at any dt.\n");
	for (int p = 0; p < N_PROBLEMS; ++p) {
		printf("\n%s", problem_titles[p]);
		if (p == P_HANGING || p == P_SWING)
			printf("; omega = %.1f rad/s", res[p][I_EXACT][0].omega_dt * rates[0]);
		printf("\n%6s %7s", "fps", "w*dt");
		for (int i = 0; i < N_INTEGRATORS; ++i)
			if (res[p][i][0].run)
				printf(" | %21s", integrator_names[i]);
		printf("\n");
		for (int k = 0; k < N_RATES; ++k) {
			double wdt = res[p][I_EXACT][k].omega_dt;
			printf("%6g %6.3f%s", rates[k], wdt, wdt >= 2.0 ? "!" : " ");
			for (int i = 0; i < N_INTEGRATORS; ++i) {
				const acc_result *r = &res[p][i][k];
				if (!r->run)
					continue;
				if (r->unstable)
					printf(" | %9s %7.0f ns", "UNSTABLE", r->ns_per_step);
				else
					printf(" | %9.2e %7.0f ns", r->error, r->ns_per_step);
			}
			printf("\n");
		}
	}

	// the summary: the spring step (the library's default, exact) bounded at every dt, 1 mm at 1/60
	char value[96];
	int k60 = 4;
	bool bounded = true;
	for (int p = P_HANGING; p <= P_SWING; ++p)
		for (int k = 0; k < N_RATES; ++k)
			bounded = bounded && !res[p][I_EXACT][k].unstable && !res[p][I_IMPLICIT][k].unstable;
	double e60 = res[P_HANGING][I_EXACT][k60].error;
	snprintf(value, sizeof value, "%s; %.2e m at 1/60 s", bounded ? "bounded 1/12..1/2000 s" : "UNBOUNDED", e60);
	bench_summary_add("target", "spring step bounded, critically damped <= 1 mm at 1/60 s", value,
	                  bounded && e60 <= 1e-3 ? BENCH_MET : BENCH_NOT_MET);
	for (int i = I_SEMI; i <= I_RK4; ++i) {
		double first = 0.0; // the smallest ω Δt at which the run diverged (rates ascend, ω Δt descends)
		for (int k = 0; k < N_RATES; ++k)
			if (res[P_HANGING][i][k].unstable)
				first = res[P_HANGING][i][k].omega_dt;
		snprintf(value, sizeof value, first > 0.0 ? "unstable from omega*dt = %.2f (hanging)" : "stable at every dt",
		         first);
		bench_summary_add("3 accuracy", integrator_names[i], value, BENCH_INFO);
	}
	snprintf(value, sizeof value, "%.1e / %.1e / %.1e m (exact / impl. Euler / swing exact)",
	         res[P_PROJECTILE][I_VERLET][k60].error, res[P_PROJECTILE][I_IMPLICIT][k60].error,
	         res[P_SWING][I_EXACT][k60].error);
	bench_summary_add("3 accuracy", "errors at 1/60 s: projectile Verlet / Euler; swing", value, BENCH_INFO);
	snprintf(value, sizeof value, "%.0f / %.0f ns (Verlet / exact spring, hanging)", res[P_PROJECTILE][I_VERLET][k60].ns_per_step,
	         res[P_HANGING][I_EXACT][k60].ns_per_step);
	bench_summary_add("3 accuracy", "ns per step of a 1-object world at 1/60 s", value, BENCH_INFO);
	shared->projectile_error_60 = res[P_PROJECTILE][I_VERLET][k60].error;
}
