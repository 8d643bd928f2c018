// plot_run.h — what every plot generator starts with: `NAME OUTDIR [SCENARIO]`, the scenario
// loaded and OUTDIR/NAME.csv open for writing. Included by plots/*.c only.
// Every CSV a generator writes is its header row, then data rows only (no comment lines, no blank
// lines), so that csv readers take it as it is; runs of one scenario are told apart by a column
// (fps, seed), and the title, parameters and units go to the sidecar OUTDIR/NAME.txt.
#ifndef HS_PLOT_RUN_H
#define HS_PLOT_RUN_H

#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>

#include "hs_harness.h"

// Returns 0 with *scenario and *out set, or the exit status after saying what went wrong.
static inline int plot_run_open(int argc, char **argv, const char *name, const char *default_scenario,
                                hs_scenario **scenario, FILE **out) {
	if (argc < 2 || argc > 3) {
		fprintf(stderr, "usage: %s OUTDIR [SCENARIO]\n", name);
		return 2;
	}
	hs_error err;
	*scenario = hs_scenario_load(argc == 3 ? argv[2] : default_scenario, &err);
	if (!*scenario) {
		fprintf(stderr, "%s\n", err.message);
		return 2;
	}
	char path[4096];
	snprintf(path, sizeof path, "%s/%s.csv", argv[1], name);
	*out = fopen(path, "w");
	if (!*out) {
		perror(path);
		hs_scenario_destroy(*scenario);
		return 1;
	}
	return 0;
}

// Closes the output and the scenario; 1 when the run broke one of the scenario's expectations.
static inline int plot_run_close(hs_scenario *scenario, FILE *out) {
	int failed = hs_scenario_check(scenario, NULL);
	if (failed)
		fprintf(stderr, "%s: %d expectation(s) failed\n", hs_scenario_name(scenario), failed);
	fclose(out);
	hs_scenario_destroy(scenario);
	return failed ? 1 : 0;
}

// For generators that run one scenario several times (other frame times, input noise): loads
// `path` with dt (0: the file's) and, when `noise`, realistic input noise drawn from `seed`
// (hs_scenario_load_with). NULL after saying what went wrong.
static inline hs_scenario *plot_run_load(const char *path, double dt, bool noise, unsigned long seed) {
	hs_scenario_options opts = {.dt = dt, .noise = noise, .noise_seed = seed};
	hs_error err;
	hs_scenario *s = hs_scenario_load_with(path, &opts, &err);
	if (!s)
		fprintf(stderr, "%s\n", err.message);
	return s;
}

// Opens OUTDIR/NAME.EXT for writing; NULL after saying what went wrong.
static inline FILE *plot_run_file(const char *dir, const char *name, const char *ext) {
	char path[4096];
	snprintf(path, sizeof path, "%s/%s.%s", dir, name, ext);
	FILE *f = fopen(path, "w");
	if (!f)
		perror(path);
	return f;
}

// Writes OUTDIR/NAME.txt, the sidecar of OUTDIR/NAME.csv: what the CSV is (title, parameters,
// units), printf-style. Returns 0, or 1 after saying what went wrong.
__attribute__((format(printf, 3, 4)))
static inline int plot_run_about(const char *dir, const char *name, const char *fmt, ...) {
	FILE *f = plot_run_file(dir, name, "txt");
	if (!f)
		return 1;
	va_list ap;
	va_start(ap, fmt);
	vfprintf(f, fmt, ap);
	va_end(ap);
	return fclose(f) != 0;
}

// The frame rates the papers' figures are redrawn at (1/s): the hand paper's 12–17, today's 30–120.
static const int plot_run_fps[] = {12, 17, 30, 60, 120};
enum { PLOT_RUN_RATES = sizeof plot_run_fps / sizeof plot_run_fps[0] };

// The rates as text for a sidecar: "12, 17, 30, 60, 120".
static inline const char *plot_run_rates_text(char *buf, size_t size) {
	size_t len = 0;
	buf[0] = '\0';
	for (int i = 0; i < PLOT_RUN_RATES && len < size; ++i)
		len += (size_t)snprintf(buf + len, size - len, "%s%d", i ? ", " : "", plot_run_fps[i]);
	return buf;
}

// For generators that run one scenario several times: `NAME OUTDIR [SCENARIO]`, *path the scenario
// (default_scenario when not given), OUTDIR/NAME.csv and OUTDIR/NAME.vars (gnuplot variables) open
// for writing. Returns 0, or the exit status after saying what went wrong (nothing left open).
static inline int plot_run_outputs(int argc, char **argv, const char *name, const char *default_scenario,
                                   const char **path, FILE **out, FILE **vars) {
	if (argc < 2 || argc > 3) {
		fprintf(stderr, "usage: %s OUTDIR [SCENARIO]\n", name);
		return 2;
	}
	*path = argc == 3 ? argv[2] : default_scenario;
	*out = plot_run_file(argv[1], name, "csv");
	if (!*out)
		return 1;
	*vars = plot_run_file(argv[1], name, "vars");
	if (!*vars) {
		fclose(*out);
		return 1;
	}
	return 0;
}

// Degrees an orientation has turned from q0 (the angle of the relative rotation, 0 to 180).
static inline double plot_run_turned_deg(hs_quat q0, hs_quat q) {
	double c = fabs(hs_quat_dot(q0, q));
	return 2.0 * acos(c < 1.0 ? c : 1.0) * 180.0 / 3.14159265358979323846;
}

// Writes `NAME<i> = VALUE; ` to a gnuplot .vars file (NaN when not a number: gnuplot's NaN).
static inline void plot_run_var(FILE *vars, const char *name, int i, double value) {
	if (isnan(value))
		fprintf(vars, "%s%d = NaN; ", name, i);
	else
		fprintf(vars, "%s%d = %.9g; ", name, i, value);
}

#endif
