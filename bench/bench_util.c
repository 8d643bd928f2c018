// bench_util.c — timing, statistics, progress, CSV files and the summary of `make bench`.
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "bench.h"

double bench_now(void) {
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double bench_cpu_now(void) {
	struct timespec ts;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int compare_double(const void *a, const void *b) {
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

double bench_median(const double *values, int n) {
	double copy[64];
	if (n <= 0)
		return 0.0;
	n = n > 64 ? 64 : n;
	memcpy(copy, values, (size_t)n * sizeof *copy);
	qsort(copy, (size_t)n, sizeof *copy, compare_double);
	return n % 2 ? copy[n / 2] : 0.5 * (copy[n / 2 - 1] + copy[n / 2]);
}

// Warm-up: double the batch until it takes a quarter of the target (caches, branch predictors, page
// faults of the first touches all happen here); returns the batch that takes about batch_s.
static long warm_up(bench_step_fn step, void *state, const bench_opts *opts) {
	long n = 16;
	double per = 0.0;
	for (;;) {
		double t0 = bench_now();
		step(state, n);
		double el = bench_now() - t0;
		per = el / (double)n;
		if (el >= 0.25 * opts->batch_s || n >= (1L << 40))
			break;
		n *= 2;
	}
	long batch = per > 0.0 ? (long)(opts->batch_s / per) : n;
	return batch < 16 ? 16 : batch;
}

static int reps_of(const bench_opts *opts) { return opts->reps < 5 ? 5 : (opts->reps > 64 ? 64 : opts->reps); }

static bench_stats stats_of(const double *times, int reps, long batch) {
	bench_stats st;
	st.median = bench_median(times, reps);
	st.min = st.max = times[0];
	for (int r = 1; r < reps; ++r) {
		st.min = times[r] < st.min ? times[r] : st.min;
		st.max = times[r] > st.max ? times[r] : st.max;
	}
	st.steps = batch;
	st.reps = reps;
	return st;
}

static double time_batch_on(double (*clock)(void), bench_step_fn step, void *state, long batch) {
	double t0 = clock();
	step(state, batch);
	return (clock() - t0) / (double)batch;
}

static double time_batch(bench_step_fn step, void *state, long batch) { return time_batch_on(bench_now, step, state, batch); }

bench_stats bench_measure(bench_step_fn step, void *state, const bench_opts *opts) {
	long batch = warm_up(step, state, opts);
	double times[64];
	int reps = reps_of(opts);
	for (int r = 0; r < reps; ++r)
		times[r] = time_batch(step, state, batch);
	return stats_of(times, reps, batch);
}

double bench_measure_pair(bench_step_fn step_a, void *a, bench_step_fn step_b, void *b, const bench_opts *opts,
                          bench_stats *out_a, bench_stats *out_b) {
	long batch_a = warm_up(step_a, a, opts), batch_b = warm_up(step_b, b, opts);
	double times_a[64], times_b[64], ratios[64];
	int reps = reps_of(opts);
	for (int r = 0; r < reps; ++r) {
		times_a[r] = time_batch(step_a, a, batch_a);
		times_b[r] = time_batch(step_b, b, batch_b);
		ratios[r] = times_a[r] / times_b[r];
	}
	*out_a = stats_of(times_a, reps, batch_a);
	*out_b = stats_of(times_b, reps, batch_b);
	return bench_median(ratios, reps);
}

bench_pair bench_measure_pair_cpu(bench_step_fn step_a, void *a, bench_step_fn step_b, void *b, const bench_opts *opts) {
	long batch_a = warm_up(step_a, a, opts), batch_b = warm_up(step_b, b, opts);
	double times_a[64], times_b[64], ratios[64];
	int reps = reps_of(opts) < 7 ? 7 : reps_of(opts);
	bench_pair p;
	for (int r = 0; r < reps; ++r) {
		times_a[r] = time_batch_on(bench_cpu_now, step_a, a, batch_a);
		times_b[r] = time_batch_on(bench_cpu_now, step_b, b, batch_b);
		ratios[r] = times_a[r] / times_b[r];
	}
	p.a = stats_of(times_a, reps, batch_a);
	p.b = stats_of(times_b, reps, batch_b);
	bench_stats r = stats_of(ratios, reps, 0);
	p.ratio = r.median, p.ratio_min = r.min, p.ratio_max = r.max;
	p.pairs = reps;
	return p;
}

// ---------------------------------------------------------------------------------------------
// Callgrind: this program run again under valgrind, one profiling flag, the toggled function only

#define CG_CACHE 16
static struct {
	char args[96];
	double instr;
} cg_cache[CG_CACHE];
static int cg_cached;

static double callgrind_total(const char *path) {
	FILE *f = fopen(path, "r");
	if (!f)
		return -1.0;
	char line[512];
	double total = -1.0;
	while (fgets(line, sizeof line, f)) // the last totals: or summary: line
		if (strncmp(line, "totals:", 7) == 0 || strncmp(line, "summary:", 8) == 0)
			total = strtod(strchr(line, ':') + 1, NULL);
	fclose(f);
	return total;
}

bool bench_have_valgrind(void) { return system("command -v valgrind > /dev/null 2>&1") == 0; }

// Where the run for `args` writes: out_dir/cg + the flags' letters and digits (+ .cg, .txt, .log).
static void cg_out(const bench_opts *opts, const char *args, char *out, size_t size) {
	char name[96];
	snprintf(name, sizeof name, "%s", args);
	for (char *c = name; *c; ++c)
		if (!((*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9')))
			*c = '_';
	snprintf(out, size, "%s/cg%s", opts->out_dir, name);
}

double bench_callgrind(const bench_opts *opts, const char *args, const char *toggle) {
	for (int i = 0; i < cg_cached; ++i)
		if (strcmp(cg_cache[i].args, args) == 0)
			return cg_cache[i].instr;
	char self[512], cmd[8192], out[768];
	ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
	if (n <= 0 || !bench_have_valgrind())
		return -1.0;
	self[n] = 0;
	cg_out(opts, args, out, sizeof out);
	int len = snprintf(cmd, sizeof cmd,
	         "valgrind --tool=callgrind --callgrind-out-file='%s.cg' --toggle-collect=%s '%s' --out '%s' %s > '%s.txt' 2> "
	         "'%s.log'",
	                   out, toggle, self, opts->out_dir, args, out, out);
	if (len < 0 || (size_t)len >= sizeof cmd)
		return -1.0;
	bench_progress("[callgrind] %s (toggle %s)\n", args, toggle);
	char path[800];
	snprintf(path, sizeof path, "%s.cg", out);
	double total = system(cmd) == 0 ? callgrind_total(path) : -1.0;
	if (cg_cached < CG_CACHE) {
		snprintf(cg_cache[cg_cached].args, sizeof cg_cache[cg_cached].args, "%s", args);
		cg_cache[cg_cached++].instr = total;
	}
	return total;
}

double bench_callgrind_fn(const bench_opts *opts, const char *args, const char *fn) {
	char out[768], cmd[1024], line[1024], key[128];
	cg_out(opts, args, out, sizeof out);
	// a symbol's own line ends "file:fn [binary]"; the lines of code inlined into it have no brackets
	snprintf(key, sizeof key, ":%s [", fn);
	int len = snprintf(cmd, sizeof cmd, "callgrind_annotate --inclusive=yes --threshold=100 '%s.cg' 2>/dev/null", out);
	if (len < 0 || (size_t)len >= sizeof cmd)
		return -1.0;
	FILE *p = popen(cmd, "r");
	if (!p)
		return -1.0;
	double found = -1.0;
	while (fgets(line, sizeof line, p))
		if (found < 0.0 && strstr(line, key)) {
			double v = 0.0; // "12,345,678 (12.3%)  file:fn [binary]"
			for (const char *c = line; *c == ' ' || *c == ',' || (*c >= '0' && *c <= '9'); ++c)
				if (*c >= '0' && *c <= '9')
					v = 10.0 * v + (*c - '0');
			found = v;
		}
	pclose(p);
	return found;
}

void bench_progress(const char *fmt, ...) {
	va_list ap;
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fflush(stderr);
}

static FILE *open_out(const bench_opts *opts, const char *name, const char *mode) {
	char path[1024];
	snprintf(path, sizeof path, "%s/%s", opts->out_dir, name);
	FILE *f = fopen(path, mode);
	if (!f) {
		fprintf(stderr, "bench: cannot write %s: %s\n", path, strerror(errno));
		exit(2);
	}
	return f;
}

// A CSV whose first line is its header row (csv.DictReader and pandas read it as it is); what it
// holds goes to meta.txt, with the machine, date, compiler, flags and QUICK (bench_meta_start).
FILE *bench_csv(const bench_opts *opts, const char *name, const char *about) {
	FILE *meta = open_out(opts, "meta.txt", "a");
	fprintf(meta, "%-16s: %s\n", name, about);
	fclose(meta);
	return open_out(opts, name, "w");
}

uint64_t bench_mix(uint64_t h, double x) {
	unsigned char b[sizeof x];
	memcpy(b, &x, sizeof x);
	for (size_t i = 0; i < sizeof x; ++i) {
		h ^= b[i];
		h *= 1099511628211ull;
	}
	return h;
}

// ---------------------------------------------------------------------------------------------
// Summary

#define SUMMARY_MAX 64

typedef struct summary_row {
	char section[32], what[96], value[96];
	bench_verdict verdict;
} summary_row;

static summary_row summary[SUMMARY_MAX];
static int summary_count;

void bench_summary_add(const char *section, const char *what, const char *value, bench_verdict verdict) {
	if (summary_count >= SUMMARY_MAX)
		return;
	summary_row *r = &summary[summary_count++];
	snprintf(r->section, sizeof r->section, "%s", section);
	snprintf(r->what, sizeof r->what, "%s", what);
	snprintf(r->value, sizeof r->value, "%s", value);
	r->verdict = verdict;
}

static void read_cpu_model(char *out, size_t size) {
	snprintf(out, size, "unknown");
	FILE *f = fopen("/proc/cpuinfo", "r");
	if (!f)
		return;
	char line[512];
	while (fgets(line, sizeof line, f)) {
		if (strncmp(line, "model name", 10) == 0) {
			char *colon = strchr(line, ':');
			if (colon) {
				colon++;
				while (*colon == ' ' || *colon == '\t')
					colon++;
				colon[strcspn(colon, "\n")] = '\0';
				snprintf(out, size, "%s", colon);
			}
			break;
		}
	}
	fclose(f);
}

static void read_loadavg(char *out, size_t size) {
	snprintf(out, size, "?");
	FILE *f = fopen("/proc/loadavg", "r");
	if (!f)
		return;
	double one = 0.0;
	if (fscanf(f, "%lf", &one) == 1)
		snprintf(out, size, "%.2f", one);
	fclose(f);
}

static char load_at_start[32] = "?";

void bench_note_start(void) { read_loadavg(load_at_start, sizeof load_at_start); }

static void read_command(const char *cmd, char *out, size_t size) {
	snprintf(out, size, "unknown");
	FILE *p = popen(cmd, "r");
	if (!p)
		return;
	if (fgets(out, (int)size, p))
		out[strcspn(out, "\n")] = '\0';
	pclose(p);
}

#ifndef HS_BENCH_CC
#define HS_BENCH_CC "cc"
#endif
#ifndef HS_BENCH_FLAGS
#define HS_BENCH_FLAGS "(unknown)"
#endif

static const char *verdict_name(bench_verdict v) {
	switch (v) {
	case BENCH_MET:
		return "MET";
	case BENCH_NOT_MET:
		return "NOT MET";
	case BENCH_UNKNOWN:
		return "n/a";
	case BENCH_INFO:
		break;
	}
	return "";
}

// The run's circumstances: machine, compiler, flags, date, QUICK.
static void describe_run(FILE *out, const bench_opts *opts) {
	char cpu[256], uname[512], compiler[256], date[64], load_end[32];
	read_cpu_model(cpu, sizeof cpu);
	read_loadavg(load_end, sizeof load_end);
	read_command("uname -srm", uname, sizeof uname);
	read_command(HS_BENCH_CC " --version 2>/dev/null", compiler, sizeof compiler);
	time_t now = time(NULL);
	struct tm tm_now;
	gmtime_r(&now, &tm_now);
	strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", &tm_now);
	fprintf(out, "machine  : %s; %s; %ld CPUs online; load average %s at the start, %s now\n", uname, cpu,
	        sysconf(_SC_NPROCESSORS_ONLN), load_at_start, load_end);
	fprintf(out, "compiler : %s\n", compiler);
	fprintf(out, "flags    : %s\n", HS_BENCH_FLAGS);
	fprintf(out, "date     : %s; batches of %.0f ms, median of %d after a warm-up\n", date, 1e3 * opts->batch_s,
	        opts->reps);
	fprintf(out, "quick    : %s\n", opts->quick ? "yes (QUICK=1: fewer batches and sizes; the figures are rougher)" : "no");
}

void bench_meta_start(const bench_opts *opts) {
	FILE *meta = open_out(opts, "meta.txt", "w");
	describe_run(meta, opts);
	fprintf(meta, "files    : every CSV starts with its header row; what each holds:\n");
	fclose(meta);
}

void bench_summary_print(FILE *out, const bench_opts *opts) {
	fprintf(out, "\n== handspring bench summary%s ==\n", opts->quick ? " (QUICK=1)" : "");
	describe_run(out, opts);
	size_t wsec = 7, wwhat = 4, wval = 5;
	for (int i = 0; i < summary_count; ++i) {
		size_t a = strlen(summary[i].section), b = strlen(summary[i].what), c = strlen(summary[i].value);
		wsec = a > wsec ? a : wsec;
		wwhat = b > wwhat ? b : wwhat;
		wval = c > wval ? c : wval;
	}
	fprintf(out, "%-*s | %-*s | %-*s | target\n", (int)wsec, "section", (int)wwhat, "what", (int)wval, "value");
	for (size_t k = 0; k < wsec + wwhat + wval + 16; ++k)
		fputc('-', out);
	fputc('\n', out);
	// the figures in the order they were measured, then the targets together
	for (int pass = 0; pass < 2; ++pass) {
		if (pass == 1) {
			for (size_t k = 0; k < wsec + wwhat + wval + 16; ++k)
				fputc('-', out);
			fputc('\n', out);
		}
		for (int i = 0; i < summary_count; ++i)
			if ((summary[i].verdict != BENCH_INFO) == (pass == 1))
				fprintf(out, "%-*s | %-*s | %-*s |%s%s\n", (int)wsec, summary[i].section, (int)wwhat, summary[i].what,
				        (int)wval, summary[i].value, summary[i].verdict != BENCH_INFO ? " " : "",
				        verdict_name(summary[i].verdict));
	}
}

// ---------------------------------------------------------------------------------------------
// The seed scene's grid and hand path, the projectile

hs_vec3 bench_cell(int i, int j) {
	return hs_v3(((double)i - 4.5) * BENCH_SPACING, BENCH_ROW_Y - (double)j * BENCH_SPACING, 0.5 * BENCH_CUBE);
}

hs_vec3 bench_path(int k) {
	// θ runs once round the loop; s = (1 − cos θ)/2 lifts 0 → 1 → 0. The sideways swing goes with
	// s³, so while the held cubes are still below the neighbours' tops (s < 0.25 at a 0.2 m lift)
	// they move sideways by under 2 mm, less than the 1 cm gaps.
	double th = 2.0 * HS_PI * (double)k / (double)BENCH_PATH_FRAMES;
	double s = 0.5 * (1.0 - cos(th)), s3 = s * s * s;
	return hs_v3(0.10 * sin(th) * s3, 0.05 * sin(2.0 * th) * s3, 0.20 * s);
}

double bench_projectile_range(void) {
	// z0 + vz t − g t²/2 = plane
	double a = 0.5 * BENCH_G, b = -BENCH_PROJ_VZ, c = BENCH_PROJ_PLANE - BENCH_PROJ_Z0;
	double t = (-b + sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
	return BENCH_PROJ_VX * t;
}

double bench_crossing_x(const double *x, const double *z, int n, double plane) {
	// Lagrange quadratic in s = (t − t_{n−1}) / dt through s = −2, −1, 0
	double z0 = z[n - 3], z1 = z[n - 2], z2 = z[n - 1];
	double x0 = x[n - 3], x1 = x[n - 2], x2 = x[n - 1];
	// z(s) = A s² + B s + C
	double a = 0.5 * (z0 - 2.0 * z1 + z2), b = 0.5 * (z0 - 4.0 * z1 + 3.0 * z2), c = z2 - plane;
	double s;
	if (fabs(a) < 1e-300) {
		s = -c / b;
	} else { // the root in [−1, 0]
		double disc = sqrt(fmax(b * b - 4.0 * a * c, 0.0));
		double r1 = (-b + disc) / (2.0 * a), r2 = (-b - disc) / (2.0 * a);
		s = (r1 >= -1.0 - 1e-9 && r1 <= 1e-9) ? r1 : r2;
	}
	double ax = 0.5 * (x0 - 2.0 * x1 + x2), bx = 0.5 * (x0 - 4.0 * x1 + 3.0 * x2);
	return ax * s * s + bx * s + x2;
}

void bench_split_spec(const char *spec, char *name, size_t size, const char **first, const char **second) {
	const char *comma = strchr(spec, ',');
	size_t len = comma ? (size_t)(comma - spec) : strlen(spec);
	len = len < size - 1 ? len : size - 1;
	memcpy(name, spec, len);
	name[len] = 0;
	*first = comma ? comma + 1 : NULL;
	*second = comma ? strchr(comma + 1, ',') : NULL;
	if (*second)
		++*second;
}

void bench_grasp_start(hs_world_def *wd) {
	wd->grasp_opposed = false;
	wd->grasp_close_mm = 0.0;
}
