// bench_cmd.c — `handspring bench FILE [--frames N] [--repeat K] [--instr]`: a scenario's frames
// timed. The scenario is built as `run` builds it (hs_scenario_load); only its steps are timed
// (hs_scenario_step: the scripts set the hands and stylus, the world steps, the expectations record
// what they need), in CPU time of the process, K times on a freshly loaded scenario; loading and the
// expectation check are outside the clock. --instr runs one repeat again under callgrind, counting
// the measured frames only (--toggle-collect on hs_bench_cmd_frames), and splits the frame into
// the stages hs_scenario_step and the world's step pipeline call (model/step/world_step.c, step_hand.c).
#include "bench_cmd.h"

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "callgrind.h"
#include "hs_harness.h"

enum { BENCH_OK = 0, BENCH_CANNOT = 1, BENCH_USAGE = 2 };
#define BENCH_MAX_FRAMES 100000000L
#define BENCH_MAX_REPEAT 1000L

const char *const hs_bench_usage =
    "usage: handspring bench FILE [--frames N] [--repeat K] [--instr]\n"
    "Times the frames of the scenario FILE: it is loaded as 'run' loads it, then N frames are stepped\n"
    "(the scripts set the hands and the stylus, the world steps, the expectations record what they\n"
    "need) and timed in CPU time of the process; loading and the expectation check are not timed.\n"
    "Prints the frames, the median time a frame and its spread over the K repeats, frames per second,\n"
    "the final state hash and how many expectations hold.\n"
    "  --frames N   frames a repeat, 1 to 100000000 (default: the scenario's own); past the scenario's\n"
    "               end it is loaded again (not timed) and stepped on from its start\n"
    "  --repeat K   repeats, each on a freshly loaded scenario, 1 to 1000 (default 5)\n"
    "  --instr      also run one repeat under valgrind's callgrind: instructions a frame (the measured\n"
    "               frames only) and the share of the frame in each stage of the step\n"
    "Exit status: 0 measured, 1 the scenario cannot be loaded or stepped (one error line), 2 bad usage.\n";

typedef struct bench_args {
	const char *file;
	long frames; // 0: the scenario's own
	long repeat;
	bool instr;
} bench_args;

static int bench_usage_error(const char *fmt, const char *arg) {
	fprintf(stderr, "handspring bench: ");
	fprintf(stderr, fmt, arg);
	fprintf(stderr, "\n%s", hs_bench_usage);
	return BENCH_USAGE;
}

// A whole number within [1, max] (all of the text), else false.
static bool parse_count(const char *text, long max, long *out) {
	char *end;
	errno = 0;
	long v = strtol(text, &end, 10);
	if (errno != 0 || end == text || *end != '\0' || v < 1 || v > max)
		return false;
	*out = v;
	return true;
}

// "--name N" or "--name=N" at argv[*i]: -1 not this option, else the usage status (-2: taken).
static int count_option(int argc, char **argv, int *i, const char *name, long max, long *out) {
	size_t n = strlen(name);
	if (strncmp(argv[*i], name, n) != 0 || (argv[*i][n] != '\0' && argv[*i][n] != '='))
		return -1;
	const char *value = argv[*i][n] == '=' ? argv[*i] + n + 1 : *i + 1 < argc ? argv[++*i] : NULL;
	if (!value || !parse_count(value, max, out)) {
		char what[160];
		snprintf(what, sizeof what, "%s takes a whole number from 1 to %ld, got '%%s'", name, max);
		return bench_usage_error(what, value ? value : "(nothing)");
	}
	return -2;
}

static int parse_args(int argc, char **argv, bench_args *a) {
	memset(a, 0, sizeof *a);
	a->repeat = 5;
	for (int i = 0; i < argc; ++i) {
		if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
			fputs(hs_bench_usage, stdout);
			return BENCH_OK;
		}
		int st = count_option(argc, argv, &i, "--frames", BENCH_MAX_FRAMES, &a->frames);
		if (st == -1)
			st = count_option(argc, argv, &i, "--repeat", BENCH_MAX_REPEAT, &a->repeat);
		if (st >= 0)
			return st;
		if (st == -2)
			continue;
		if (strcmp(argv[i], "--instr") == 0)
			a->instr = true;
		else if (argv[i][0] == '-' || a->file)
			return bench_usage_error(argv[i][0] == '-' ? "unknown option '%s'" : "one scenario FILE only, got also '%s'",
			                         argv[i]);
		else
			a->file = argv[i];
	}
	return a->file ? -1 : bench_usage_error("%s", "missing the scenario FILE");
}

// The measured frames: not inlined, so that callgrind's --toggle-collect counts exactly these.
__attribute__((noinline)) long hs_bench_cmd_frames(hs_scenario *s, long n);
long hs_bench_cmd_frames(hs_scenario *s, long n) {
	long k = 0;
	while (k < n && hs_scenario_step(s))
		k++;
	return k;
}

static double cpu_now(void) {
	struct timespec ts;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

// What one repeat gives.
typedef struct bench_repeat {
	double seconds; // CPU time of the stepped frames
	uint64_t hash;  // the state hash after the last frame
	int failed, total; // expectations of the last scenario run
} bench_repeat;

// One repeat: `frames` frames, the scenario loaded again whenever it ends. false with one error line.
static bool run_repeat(const char *file, long frames, bench_repeat *r) {
	memset(r, 0, sizeof *r);
	hs_scenario *s = NULL;
	for (long done = 0; done < frames;) {
		hs_error err;
		hs_scenario_destroy(s);
		if (!(s = hs_scenario_load(file, &err))) {
			fprintf(stderr, "%s\n", err.message);
			return false;
		}
		long want = frames - done, room = hs_scenario_frame_count(s);
		want = want < room ? want : room;
		double t0 = cpu_now();
		long got = hs_bench_cmd_frames(s, want);
		r->seconds += cpu_now() - t0;
		if (got < want) {
			fprintf(stderr, "handspring bench: %s: the world failed to step at frame %ld\n", file, got + 1);
			hs_scenario_destroy(s);
			return false;
		}
		done += got;
	}
	r->hash = hs_world_hash(hs_scenario_world(s));
	r->failed = hs_scenario_check(s, NULL);
	r->total = hs_scenario_expectation_count(s);
	hs_scenario_destroy(s);
	return true;
}

static int compare_double(const void *a, const void *b) {
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static void print_timing(const bench_args *a, long frames, const double *us, const bench_repeat *last) {
	double sorted[BENCH_MAX_REPEAT];
	memcpy(sorted, us, (size_t)a->repeat * sizeof *us);
	qsort(sorted, (size_t)a->repeat, sizeof *sorted, compare_double);
	long n = a->repeat;
	double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
	printf("us/frame   : %.3f median, %.3f-%.3f over %ld repeat%s (CPU time of the process)\n", median, sorted[0],
	       sorted[n - 1], n, n == 1 ? "" : "s");
	printf("frames/s   : %.0f (median)\n", median > 0.0 ? 1e6 / median : 0.0);
	printf("final hash : %016" PRIx64 "\n", last->hash);
	printf("expect     : %d of %d hold after frame %ld of the last load (checked after the timing)\n",
	       last->total - last->failed, last->total, frames);
}

// The tool's own path, for valgrind to run it again.
static bool self_path(char *out, size_t size) {
	ssize_t n = readlink("/proc/self/exe", out, size - 1);
	if (n <= 0)
		return false;
	out[n] = '\0';
	return true;
}

static bool on_path(const char *program) {
	const char *path = getenv("PATH");
	char dir[4096];
	while (path && *path) {
		size_t n = strcspn(path, ":");
		if (n > 0 && n < 4000) {
			snprintf(dir, sizeof dir, "%.*s/%s", (int)n, path, program);
			if (access(dir, X_OK) == 0)
				return true;
		}
		path += n + (path[n] == ':');
	}
	return false;
}

// Runs `handspring bench FILE --frames N --repeat 1` under callgrind into dir/cg.out.
static bool callgrind_run(const char *file, long frames, const char *dir) {
	char self[4096], out[4200], log[4200], count[32];
	if (!self_path(self, sizeof self)) {
		printf("instr      : not measured: cannot find the tool's own path (/proc/self/exe)\n");
		return false;
	}
	snprintf(out, sizeof out, "--callgrind-out-file=%s/cg.out", dir);
	snprintf(log, sizeof log, "--log-file=%s/valgrind.log", dir);
	snprintf(count, sizeof count, "%ld", frames);
	char *argv[] = {"valgrind", "--tool=callgrind", out, log, "--toggle-collect=hs_bench_cmd_frames", self,
	                "bench", (char *)file, "--frames", count, "--repeat", "1", NULL};
	fflush(stdout);
	pid_t pid = fork();
	if (pid == 0) {
		if (!freopen("/dev/null", "w", stdout))
			_exit(127);
		execvp(argv[0], argv);
		_exit(127);
	}
	int status = 0;
	if (pid < 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
		printf("instr      : not measured: valgrind failed (exit status %d; its log: %s/valgrind.log)\n",
		       WIFEXITED(status) ? WEXITSTATUS(status) : -1, dir);
		return false;
	}
	return true;
}

// The stages of a frame: what hs_scenario_step calls, and what the world's step calls in it: the
// hand pipeline hs_step_hand (model/step/step_hand.c, its stages inlined), or the spring one whole.
typedef struct bench_stage {
	const char *caller, *callee[2], *label;
} bench_stage;

static const bench_stage frame_stages[] = {
    {"hs_scenario_step", {"hs_hands_drive", "hs_stylus_drive"}, "inputs: hands and stylus set from their scripts"},
    {"hs_scenario_step", {"hs_world_step", NULL}, "world step (hs_world_step), of which:"},
    {"hs_step_hand", {"hs_grid_build", NULL}, "  grid rebuilt (objects added)"},
    {"hs_step_hand", {"hs_tracking_update", NULL}, "  hands' tracking (hs_tracking_update)"},
    {"hs_step_hand", {"hs_manipulate", NULL}, "  hands on objects: contacts, grasps, pushes (hs_manipulate)"},
    {"hs_world_step", {"hs_step_spring", NULL}, "  spring model (hs_step_spring)"},
    {"hs_scenario_step", {"hs_expect_capture", NULL}, "expectations record (hs_expect_capture)"},
};
#define N_STAGES ((int)(sizeof frame_stages / sizeof frame_stages[0]))

static uint64_t stage_cost(const hs_cg_profile *p, const bench_stage *st) {
	uint64_t c = 0;
	for (int k = 0; k < 2 && st->callee[k]; ++k)
		c += hs_cg_call(p, st->caller, st->callee[k]);
	return c;
}

static void print_stages(const hs_cg_profile *p, long frames) {
	uint64_t total = hs_cg_total(p), world = hs_cg_call(p, "hs_scenario_step", "hs_world_step"), top = 0, inner = 0;
	printf("instr      : %.0f instructions a frame (callgrind, the %ld measured frames only)\n",
	       (double)total / (double)frames, frames);
	for (int i = 0; i < N_STAGES; ++i) {
		uint64_t c = stage_cost(p, &frame_stages[i]);
		if (strcmp(frame_stages[i].caller, "hs_scenario_step") != 0)
			inner += c;
		else
			top += c;
		if (c > 0 || i == 1)
			printf("stage      : %5.1f %%  %s\n", total ? 100.0 * (double)c / (double)total : 0.0, frame_stages[i].label);
		if (i == N_STAGES - 2 && world >= inner) // after the world step's own stages
			printf("stage      : %5.1f %%    free objects, wake lists and the rest of the step\n",
			       total ? 100.0 * (double)(world - inner) / (double)total : 0.0);
	}
	if (total >= top)
		printf("stage      : %5.1f %%  the rest of the frame (the loop, the scenario's clock)\n",
		       total ? 100.0 * (double)(total - top) / (double)total : 0.0);
}

static void remove_dir(const char *dir) {
	char path[4200];
	const char *files[] = {"cg.out", "valgrind.log"};
	for (int i = 0; i < 2; ++i) {
		snprintf(path, sizeof path, "%s/%s", dir, files[i]);
		unlink(path);
	}
	rmdir(dir);
}

static void instr_report(const char *file, long frames) {
	if (!on_path("valgrind")) {
		printf("instr      : not measured: valgrind is not on PATH (sh scripts/deps.sh valgrind, or apt-get install "
		       "valgrind)\n");
		return;
	}
	const char *tmp = getenv("TMPDIR");
	char dir[4096];
	snprintf(dir, sizeof dir, "%s/handspring-bench-XXXXXX", tmp && *tmp ? tmp : "/tmp");
	if (!mkdtemp(dir)) {
		printf("instr      : not measured: cannot make a folder %s\n", dir);
		return;
	}
	if (!callgrind_run(file, frames, dir))
		return; // its log is kept
	char why[600], path[4200];
	snprintf(path, sizeof path, "%s/cg.out", dir);
	hs_cg_profile *p = hs_cg_load(path, why, sizeof why);
	if (p)
		print_stages(p, frames);
	else
		printf("instr      : not measured: %s\n", why);
	hs_cg_free(p);
	remove_dir(dir);
}

int hs_bench_main(int argc, char **argv) {
	bench_args a;
	int status = parse_args(argc, argv, &a);
	if (status >= 0)
		return status;
	hs_error err;
	hs_scenario *s = hs_scenario_load(a.file, &err);
	if (!s) {
		fprintf(stderr, "%s\n", err.message);
		return BENCH_CANNOT;
	}
	fputs(hs_scenario_warnings(s), stderr);
	long own = hs_scenario_frame_count(s), frames = a.frames ? a.frames : own;
	printf("scenario   : %s (%s)\n", hs_scenario_name(s), a.file);
	printf("frames     : %ld a repeat, %ld repeat%s (the scenario has %ld frames of %.6g s)\n", frames, a.repeat,
	       a.repeat == 1 ? "" : "s", own, hs_scenario_dt(s));
	hs_scenario_destroy(s);
	double us[BENCH_MAX_REPEAT];
	bench_repeat r = {0.0, 0, 0, 0};
	for (long k = 0; k < a.repeat; ++k) {
		if (!run_repeat(a.file, frames, &r))
			return BENCH_CANNOT;
		us[k] = 1e6 * r.seconds / (double)frames;
	}
	print_timing(&a, frames, us, &r);
	if (a.instr)
		instr_report(a.file, frames);
	return BENCH_OK;
}
