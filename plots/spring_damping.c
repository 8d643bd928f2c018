// spring_damping.c — data for the damping figure (workbench paper §4.3, Fig. 2): the spring-damper
// m x'' + c x' + k x = 0 released from x(0) = 0.2 x0 at rest, as under-, critically and over-damped
// responses (damping ratio zeta = c / 2 sqrt(k m) = 0.25, 1, 2) against their closed forms.
//
// The library damps critically, always (§4.4: "both linear and pendulum oscillations are damped
// critically"), so only the zeta = 1 points come from it: a 1000 kg sphere (x0 = 1 m, k = m g / 0.2 x0,
// w = sqrt(k / m) = 7.004 rad/s) on its spring in a world without gravity, the stylus held still,
// stepped by hs_world_step with each of the four integrators. The zeta = 0.25 and 2 points are a
// classic RK4 of the same equation in this file, at the same dt, to show the closed forms used.
//
// usage: spring_damping OUTDIR — writes OUTDIR/spring_damping_curves.csv (closed forms, fine),
// OUTDIR/spring_damping_points.csv (simulations at dt = 1/30 s) and
// OUTDIR/spring_damping_integrators.csv (the library's four integrators at dt = 1/12 s), each with
// its sidecar NAME.txt (w and what the columns are), and prints each integrator's largest error
// against the closed form at dt = 1/12, 1/60 and 1/1000 s.
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "handspring.h"
#include "plot_run.h"

#define MASS 1000.0     // kg
#define START 0.2       // x(0) / x0: the stretch a hanging object would have (§4.2)
#define DURATION 2.5    // s
#define STYLUS_Z 5.0    // m: far above the floor

static const char *const integrator_names[4] = {"exact", "implicit_euler", "semi_implicit_euler", "rk4"};

// x(t) / x(0) of m x'' + 2 zeta w m x' + w^2 m x = 0 with x'(0) = 0
static double closed_form(double zeta, double w, double t) {
	if (zeta < 1.0) {
		double wd = w * sqrt(1.0 - zeta * zeta);
		return exp(-zeta * w * t) * (cos(wd * t) + zeta / sqrt(1.0 - zeta * zeta) * sin(wd * t));
	}
	if (zeta == 1.0)
		return exp(-w * t) * (1.0 + w * t);
	double s = sqrt(zeta * zeta - 1.0), r1 = w * (-zeta + s), r2 = w * (-zeta - s);
	return (r1 * exp(r2 * t) - r2 * exp(r1 * t)) / (r1 - r2);
}

// A world without gravity holding one 1000 kg sphere with G at height z below the stylus; NULL on error.
static hs_world *make_world(hs_integrator integrator, double dt, double z, hs_object_id *id) {
	hs_status st = HS_OK;
	hs_world_def wd = hs_default_world_def();
	wd.dt = dt;
	wd.gravity = hs_v3(0.0, 0.0, 0.0); // k is sized with standard gravity; no weight: equilibrium at x0
	wd.kind = HS_WORLD_SPRING;
	wd.spring.integrator = integrator;
	hs_world *w = hs_world_create(&wd, &st);
	hs_shape *ball = hs_shape_sphere(0.3, &st);
	if (!w || !ball) {
		fprintf(stderr, "spring_damping: cannot make a spring world: %s\n", hs_status_string(st));
		hs_shape_destroy(ball);
		hs_world_destroy(w);
		return NULL;
	}
	hs_object_def od = hs_default_object_def();
	od.shape = hs_world_add_shape(w, ball, &st);
	od.density = MASS / ball->volume;
	od.position = hs_v3(0.0, 0.0, z);
	hs_shape_destroy(ball);
	*id = hs_world_add_object(w, &od, &st);
	if (!id->index1 || hs_world_set_stylus(w, hs_v3(0.0, 0.0, STYLUS_Z), hs_quat_identity(), false) != HS_OK ||
	    hs_world_spring_attach(w, *id) != HS_OK) {
		fprintf(stderr, "spring_damping: cannot add the object on its spring: %s\n", hs_status_string(st));
		hs_world_destroy(w);
		return NULL;
	}
	return w;
}

// One run of the library: the extension / x(0) after every frame (frame 0 first), n + 1 values.
static bool library_response(hs_integrator integrator, double dt, long n, double *out, double *omega) {
	hs_object_id id;
	hs_spring_object info;
	hs_world *w = make_world(integrator, dt, STYLUS_Z - 2.0, &id); // first only to learn x0 ...
	if (!w || hs_world_spring_object(w, id, &info) != HS_OK) {
		hs_world_destroy(w);
		return false;
	}
	hs_world_destroy(w);
	w = make_world(integrator, dt, STYLUS_Z - (1.0 + START) * info.rest_length, &id); // ... then stretched by START x0
	if (!w)
		return false;
	*omega = info.omega;
	hs_spring_state ss;
	for (long f = 0; f <= n; ++f) {
		if (f > 0 && hs_world_step(w) != HS_OK) {
			hs_world_destroy(w);
			return false;
		}
		hs_world_spring_state(w, &ss);
		out[f] = ss.extension / (START * info.rest_length);
	}
	hs_world_destroy(w);
	return true;
}

// classic RK4 of x'' = -2 zeta w x' - w^2 x, from x = 1, v = 0
static void rk4_response(double zeta, double w, double dt, long n, double *out) {
	double x = 1.0, v = 0.0;
	out[0] = x;
	for (long f = 1; f <= n; ++f) {
		double k1x = v, k1v = -2.0 * zeta * w * v - w * w * x;
		double x2 = x + 0.5 * dt * k1x, v2 = v + 0.5 * dt * k1v;
		double k2x = v2, k2v = -2.0 * zeta * w * v2 - w * w * x2;
		double x3 = x + 0.5 * dt * k2x, v3 = v + 0.5 * dt * k2v;
		double k3x = v3, k3v = -2.0 * zeta * w * v3 - w * w * x3;
		double x4 = x + dt * k3x, v4 = v + dt * k3v;
		double k4x = v4, k4v = -2.0 * zeta * w * v4 - w * w * x4;
		x += dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
		v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
		out[f] = x;
	}
}

static FILE *open_out(const char *dir, const char *name) {
	char path[4096];
	snprintf(path, sizeof path, "%s/%s", dir, name);
	FILE *f = fopen(path, "w");
	if (!f)
		perror(path);
	return f;
}

// The three CSVs' sidecars OUTDIR/spring_damping_{points,curves,integrators}.txt; 0 or 1.
static int write_about(const char *dir, double omega) {
	return plot_run_about(dir, "spring_damping_points",
	                      "spring_damping_points.csv: x(t) / x(0), simulated at dt = 1/30 s; w = %.9g rad/s (1000 kg, x0 = 1 m)\n"
	                      "t: time, s\n"
	                      "critical_library: damping ratio 1, the library (exact integrator)\n"
	                      "under_rk4, over_rk4: damping ratio 0.25 and 2, classic RK4 of the same equation\n",
	                      omega) ||
	       plot_run_about(dir, "spring_damping_curves",
	                      "spring_damping_curves.csv: x(t) / x(0), closed forms; w = %.9g rad/s\n"
	                      "t: time, s\n"
	                      "under, critical, over: damping ratio 0.25, 1 and 2\n",
	                      omega) ||
	       plot_run_about(dir, "spring_damping_integrators",
	                      "spring_damping_integrators.csv: x(t) / x(0), critically damped, the library's integrators\n"
	                      "at dt = 1/12 s (w dt = %.3g)\n"
	                      "t: time, s\n"
	                      "exact, implicit_euler, semi_implicit_euler, rk4: the integrator\n",
	                      omega / 12.0);
}

int main(int argc, char **argv) {
	if (argc != 2) {
		fprintf(stderr, "usage: spring_damping OUTDIR\n");
		return 2;
	}
	const char *dir = argv[1];
	double omega = 0.0;
	// the points: dt = 1/30 s
	const double dt_points = 1.0 / 30.0;
	long n = lround(DURATION / dt_points);
	double *crit = malloc((size_t)(n + 1) * sizeof *crit), *under = malloc((size_t)(n + 1) * sizeof *under),
	       *over = malloc((size_t)(n + 1) * sizeof *over);
	if (!crit || !under || !over || !library_response(HS_INTEGRATOR_EXACT, dt_points, n, crit, &omega))
		return 1;
	rk4_response(0.25, omega, dt_points, n, under);
	rk4_response(2.0, omega, dt_points, n, over);
	if (write_about(dir, omega))
		return 1;
	FILE *f = open_out(dir, "spring_damping_points.csv");
	if (!f)
		return 1;
	fprintf(f, "t,critical_library,under_rk4,over_rk4\n");
	for (long i = 0; i <= n; ++i)
		fprintf(f, "%.9g,%.9g,%.9g,%.9g\n", (double)i * dt_points, crit[i], under[i], over[i]);
	fclose(f);
	free(crit);
	free(under);
	free(over);

	f = open_out(dir, "spring_damping_curves.csv");
	if (!f)
		return 1;
	fprintf(f, "t,under,critical,over\n");
	for (int i = 0; i <= 1000; ++i) {
		double t = DURATION * i / 1000.0;
		fprintf(f, "%.9g,%.9g,%.9g,%.9g\n", t, closed_form(0.25, omega, t), closed_form(1.0, omega, t),
		        closed_form(2.0, omega, t));
	}
	fclose(f);

	// the library's integrators against the closed form
	const double dts[3] = {1.0 / 12.0, 1.0 / 60.0, 1.0 / 1000.0};
	const char *dt_names[3] = {"1/12", "1/60", "1/1000"};
	long n12 = lround(DURATION / dts[0]);
	double *runs[4];
	for (int ig = 0; ig < 4; ++ig) {
		runs[ig] = malloc((size_t)(n12 + 1) * sizeof **runs);
		if (!runs[ig] || !library_response((hs_integrator)ig, dts[0], n12, runs[ig], &omega))
			return 1;
	}
	f = open_out(dir, "spring_damping_integrators.csv");
	if (!f)
		return 1;
	fprintf(f, "t,exact,implicit_euler,semi_implicit_euler,rk4\n");
	for (long i = 0; i <= n12; ++i)
		fprintf(f, "%.9g,%.9g,%.9g,%.9g,%.9g\n", (double)i * dts[0], runs[0][i], runs[1][i], runs[2][i], runs[3][i]);
	fclose(f);
	for (int ig = 0; ig < 4; ++ig)
		free(runs[ig]);

	printf("spring_damping: critically damped response of a %.0f kg object (w = %.4g rad/s) from x(0) = %.1f x0 at rest,\n"
	       "  largest |x_sim - x_closed| / x(0) over %.1f s:\n  %-20s", MASS, omega, START, DURATION, "integrator");
	for (int id = 0; id < 3; ++id)
		printf(" %12s", dt_names[id]);
	printf("\n");
	for (int ig = 0; ig < 4; ++ig) {
		printf("  %-20s", integrator_names[ig]);
		for (int id = 0; id < 3; ++id) {
			long m = lround(DURATION / dts[id]);
			double *x = malloc((size_t)(m + 1) * sizeof *x);
			if (!x || !library_response((hs_integrator)ig, dts[id], m, x, &omega))
				return 1;
			double worst = 0.0;
			for (long i = 0; i <= m; ++i)
				worst = fmax(worst, fabs(x[i] - closed_form(1.0, omega, (double)i * dts[id])));
			printf(" %12.3e", worst);
			free(x);
		}
		printf("\n");
	}
	return 0;
}
