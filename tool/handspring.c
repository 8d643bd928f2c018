// handspring — the command-line tool: a thin shell over the library (handspring.h).
//
//   handspring list [--dir DIR]                         the catalog, one scenario per line
//   handspring run FILE [--out TRAJ.csv] [--hands-out HANDS.csv] [--save-at FRAME --state-out PATH]
//                  [--resume PATH] [--dt DT] [--noise-seed N]
//                                                        one scenario: summary, expectations, hash
//   handspring all [--dir DIR] [--out-dir DIR] [--golden-dir DIR]
//                                                        the whole catalog and a summary table
//   handspring sweep FILE                                the scenario's robust matrix (dt x noise seeds)
//   handspring campaign FILE ...                         many trials over axes of options (campaign_cmd.c)
//   handspring bench FILE [--frames N] [--repeat K] [--instr]
//                                                        a scenario's frames timed (bench_cmd.c)
//
// Exit status: 0 all expectations pass, 1 an expectation failed, 2 bad input or usage.
#include <errno.h>
#include <inttypes.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "hs_harness.h"
#include "bench_cmd.h"
#include "golden.h"
#include "golden_dir.h"
#include "hand_cmd.h"
#include "outsel.h"
#include "output.h"
#include "campaign_cmd.h"
#include "view.h"

enum { EXIT_PASS = 0, EXIT_FAILED = 1, EXIT_BAD_INPUT = 2 };

static const char *const usage_main =
    "usage: handspring <command> [options]\n"
    "commands:\n"
    "  list [--dir DIR]                                   list the scenarios of a catalog\n"
    "  run FILE [--out TRAJ.csv] [--save-at FRAME --state-out PATH] [--resume PATH]\n"
    "                                                     run one scenario and check its expectations\n"
    "  all [--dir DIR] [--out-dir DIR] [--golden-dir DIR] run every scenario of a catalog\n"
    "  sweep FILE                                         run a scenario's robust matrix (dt x noise seeds)\n"
    "  campaign FILE [--out TRIALS.csv] [--summary S.csv] many trials over axes of options (docs/campaigns.md)\n"
    "  hand [--posture P] [--amount A]                    the hand's check points in the wrist frame\n"
    "  joints FILE --format mediapipe|openxr --out OUT    a scenario's hand as a joint recording\n"
    "  check DIR [--golden GDIR]                          compare a folder of scenarios with their goldens\n"
    "  golden DIR [--golden GDIR] [--force]               write a folder's goldens (default: DIR/golden)\n"
    "  view FILE [--gif OUT] [--strip OUT --at T,...] [--html OUT]\n"
    "                                                     draw a scenario in 3-D with gnuplot\n"
    "  bench FILE [--frames N] [--repeat K] [--instr]     time a scenario's frames (and count instructions)\n"
    "Run 'handspring <command> --help' for the options of a command.\n";

static const char *const usage_list =
    "usage: handspring list [--dir DIR]\n"
    "Lists every scenario below DIR (default: scenarios): its name, then its description.\n";

static const char *const usage_run =
    "usage: handspring run FILE [--out TRAJ.csv] [--hands-out HANDS.csv] [--save-at FRAME --state-out PATH]\n"
    "                           [--resume PATH] [--dt DT] [--noise-seed N] [--phase F] [--strict]\n"
    "Runs the scenario FILE and prints its name, frames, objects, one PASS/FAIL line per expectation\n"
    "with the measured value, and the final state hash.\n"
    "  --out TRAJ.csv     also write the trajectory (one row per object per frame, frame 0 included);\n"
    "                     '-' writes it to stdout (the summary then goes to stderr)\n"
    "  --hands-out FILE   also write what the hands and the stylus do, per frame (frame 0 included), one\n"
    "                     row per thing, its `kind` first: each check point as the glove and tracker\n"
    "                     put it and as rectification draws it back to a surface, each contact with its\n"
    "                     object and that object's contact state; in spring worlds the stylus, the\n"
    "                     spring's ends and extension, the selection candidate (scenarios/README.md)\n"
    "  --save-at FRAME    with --state-out: when frame FRAME (0 to the scenario's frames) has run,\n"
    "  --state-out PATH   write the run's state to PATH (the world, the input noise generator, what\n"
    "                     the expectations captured so far), then run on to the end\n"
    "  --resume PATH      load FILE, restore the state saved in PATH (saved from the same file) and\n"
    "                     run the remaining frames; --out then holds the header and those frames only:\n"
    "                     the same bytes as the full run's rows after the saved frame. The report is\n"
    "                     the full run's.\n"
    "  --dt DT            replace the file's dt: a number or a fraction like 1/12, within [1/2000, 1/12] s;\n"
    "                     the frames are round(duration / DT), clause times are converted with it\n"
    HS_OUTSEL_USAGE
    "  --noise-seed N     draw realistic input noise with seed N (0 to 4294967295): hands a glove's\n"
    "                     +-4 units per sensor and the tracker's 0.762 mm, 0.15 deg on the wrist (or the\n"
    "                     levels of the file's robust block or model.input_noise), a stylus the tracker's\n"
    "                     noise. Neither goes with --save-at or --resume (a state file names the file only).\n"
    "  --phase F          run the input scripts F of a frame late (0 <= F < 1): the same motions with\n"
    "                     the frames falling elsewhere on them (as a sweep's seeds do); not with --resume\n"
    "  --strict           treat the load's warnings (an object under the floor, objects overlapping at\n"
    "                     the start, a hand under the floor, a sphere in a hand world) as bad input:\n"
    "                     they are printed and the scenario is not run (exit status 2)\n"
    "Bad input is one line on stderr, FILE:LINE: what is wrong, with \"did you mean 'X'?\" for a\n"
    "misspelt key, object or shape; warnings are lines FILE:LINE: warning: ..., and the run goes on.\n"
    "Exit status: 0 every expectation passed, 1 one failed, 2 bad input (one error line on stderr).\n";

static const char *const usage_sweep =
    "usage: handspring sweep FILE\n"
    "Runs the matrix of the scenario's 'robust' block in-process: the nominal run (the file's dt and noise,\n"
    "every clause must pass), then every dt of robust.dt x every seed 1..robust.seeds with the input noise on\n"
    "(the clauses marked 'robust: true' must pass). Prints one row per dt, one column per seed; a cell is\n"
    "'ok', 'L<line>' (the first failing robust clause) or 'fault' (the world failed to step or caught a\n"
    "non-finite value); then 'sweep: N of M cells pass'.\n"
    "Exit status: 0 every cell and the nominal run pass, 1 any fails, 2 bad input (no robust block too).\n";

static const char *const usage_golden =
    "usage: handspring golden DIR [--golden GDIR] [--force] [--strict]\n"
    "Runs every scenario below DIR and writes its trajectory as the golden GDIR/<name>.csv, whose header\n"
    "names the command that writes it again; 'handspring check DIR' then compares runs with them.\n"
    "GDIR is by default DIR/golden (for a folder named 'scenarios', the folder 'golden' beside it, the\n"
    "catalog's layout). A catalog's goldens folder (a folder 'golden' with 'scenarios' beside it) is\n"
    "refused for any other DIR: a scenario named like a catalog one never overwrites the catalog's golden.\n"
    "  --golden GDIR  write the goldens there instead (also --golden-dir)\n"
    "  --force        also write the golden of a scenario whose expectations fail (a warning on stderr;\n"
    "                 without it such a golden is not written and the message says so)\n"
    "  --strict       a scenario with load warnings is bad input (see 'handspring run --help')\n"
    "Exit status: 0 written and every expectation passed, 1 one failed, 2 bad input or a refused GDIR.\n";

static const char *const usage_all =
    "usage: handspring all [--dir DIR] [--out-dir DIR] [--golden-dir DIR] [--hands-dir DIR] [--force] [--strict]\n"
    "Runs every scenario below --dir (default: scenarios) and prints a summary table.\n"
    "  --out-dir DIR     write each trajectory to DIR/<name>.csv (subfolders are created)\n"
    "  --golden-dir DIR  write each trajectory as a golden file DIR/<name>.csv (what 'make golden' does),\n"
    "                    only for the scenarios whose expectations pass; a catalog's goldens folder only\n"
    "                    for that catalog (as 'handspring golden')\n"
    "  --force           write the goldens of failing scenarios too (a warning on stderr for each)\n"
    "  --strict          a scenario with load warnings is bad input (see 'handspring run --help')\n"
    "  --hands-dir DIR   write each scenario's hands and stylus (as run --hands-out) to DIR/<name>.csv\n"
    "the --out-dir and --hands-dir files only (not the goldens), objects a scenario lacks passed over:\n"
    HS_OUTSEL_USAGE
    "Exit status: 0 every scenario passed, 1 one failed, 2 bad input.\n";

static int usage_error(const char *command, const char *usage, const char *fmt, const char *arg) {
	fprintf(stderr, "handspring%s%s: ", command ? " " : "", command ? command : "");
	fprintf(stderr, fmt, arg);
	fprintf(stderr, "\n%s", usage);
	return EXIT_BAD_INPUT;
}

static bool is_help(const char *arg) { return strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0; }

// "--name VALUE" or "--name=VALUE" at argv[*i]; advances *i past the value.
static bool option_value(int argc, char **argv, int *i, const char *name, const char **value, bool *missing) {
	size_t n = strlen(name);
	if (strncmp(argv[*i], name, n) != 0)
		return false;
	if (argv[*i][n] == '=') {
		*value = argv[*i] + n + 1;
		*missing = **value == '\0';
		return true;
	}
	if (argv[*i][n] != '\0')
		return false;
	if (*i + 1 >= argc) {
		*missing = true;
		return true;
	}
	*value = argv[++*i];
	*missing = false;
	return true;
}

static char *join_csv(const char *dir, const char *name) {
	size_t n = strlen(dir) + strlen(name) + 6;
	char *r = malloc(n);
	if (r)
		snprintf(r, n, "%s/%s.csv", dir, name);
	return r;
}

// Runs every frame, writing the trajectory to each open file.
// Runs a scenario writing its trajectory to outs[k] (the first one, and `hands`, through `sel`;
// the others whole: goldens).
static void run_scenario(hs_scenario *s, FILE **outs, int out_count, FILE *hands, hs_outsel *sel) {
	hs_world *w = hs_scenario_world(s);
	long frames = hs_scenario_frame_count(s);
	for (long f = 0;; ++f) {
		bool keep = hs_outsel_keep(sel, f);
		for (int k = 0; k < out_count; ++k)
			if (outs[k]) {
				if (f == 0)
					hs_trajectory_write_header(outs[k]);
				if (k > 0)
					hs_trajectory_write_frame(outs[k], s);
				else if (keep)
					hs_trajectory_write_selected(outs[k], s, sel->selected);
			}
		if (f == 0)
			hs_hand_trace_write_header(hands);
		if (keep)
			hs_hand_trace_write_frame(hands, s);
		hs_outsel_progress(sel, hs_world_frame(w), frames);
		if (!hs_scenario_step(s))
			break;
	}
}

typedef struct run_options {
	const char *file, *out, *hands_out, *state_out, *resume;
	long save_at; // -1: no state saved
	bool strict;  // --strict: a scenario with warnings is bad input
	hs_scenario_options load; // --dt, --noise-seed
	hs_outsel sel; // --objects, --every, --from, --to
} run_options;

// A noise seed: decimal digits, at most 4294967295 (unsigned long is 32 bits on i386).
static bool parse_seed(const char *text, unsigned long *seed) {
	unsigned long long v = 0;
	for (const char *c = text; *c; ++c) {
		if (*c < '0' || *c > '9' || (v = v * 10 + (unsigned long long)(*c - '0')) > 4294967295ull)
			return false;
	}
	*seed = (unsigned long)v;
	return *text != '\0';
}

// --dt, --noise-seed and --phase at argv[*i]: true when it was one of them (*status set on a usage error).
static bool parse_load_option(int argc, char **argv, int *i, hs_scenario_options *o, int *status) {
	bool missing = false;
	const char *v = NULL;
	if (option_value(argc, argv, i, "--dt", &v, &missing)) {
		if (missing || !hs_scenario_parse_dt(v, &o->dt))
			*status = usage_error("run", usage_run, "%s needs a frame time within [1/2000, 1/12] s (e.g. 1/60)", "--dt");
		return true;
	}
	if (option_value(argc, argv, i, "--phase", &v, &missing)) {
		char *end = NULL;
		o->phase = missing ? -1.0 : strtod(v, &end);
		if (missing || end == v || *end || !(o->phase >= 0.0 && o->phase < 1.0))
			*status = usage_error("run", usage_run, "%s needs a fraction of a frame within [0, 1)", "--phase");
		return true;
	}
	if (option_value(argc, argv, i, "--noise-seed", &v, &missing)) {
		o->noise = true;
		if (missing || !parse_seed(v, &o->noise_seed))
			*status = usage_error("run", usage_run, "%s needs a seed within [0, 4294967295]", "--noise-seed");
		return true;
	}
	return false;
}

// A frame number: decimal digits only.
static bool parse_frame(const char *text, long *frame) {
	char *end;
	errno = 0;
	long v = strtol(text, &end, 10);
	if (!*text || *end || errno || v < 0 || text[0] == '+' || text[0] == '-')
		return false;
	*frame = v;
	return true;
}

// The options of `run`: -1 to go on, else the exit status (usage errors, --help).
static int parse_run(int argc, char **argv, run_options *o) {
	int status = -1;
	memset(o, 0, sizeof *o);
	o->save_at = -1;
	hs_outsel_init(&o->sel);
	for (int i = 0; i < argc; ++i) {
		bool missing = false;
		const char *frame = NULL;
		char why[160];
		if (is_help(argv[i])) {
			fputs(usage_run, stdout);
			return EXIT_PASS;
		} else if (hs_outsel_option(&o->sel, argc, argv, &i, why, sizeof why)) {
			if (why[0])
				return usage_error("run", usage_run, "%s", why);
		} else if (option_value(argc, argv, &i, "--out", &o->out, &missing) ||
		           option_value(argc, argv, &i, "--hands-out", &o->hands_out, &missing) ||
		           option_value(argc, argv, &i, "--state-out", &o->state_out, &missing) ||
		           option_value(argc, argv, &i, "--resume", &o->resume, &missing)) {
			if (missing)
				return usage_error("run", usage_run, "%s needs a file name", argv[i]);
		} else if (option_value(argc, argv, &i, "--save-at", &frame, &missing)) {
			if (missing || !parse_frame(frame, &o->save_at))
				return usage_error("run", usage_run, "%s needs a frame number (0, 1, 2, ...)", "--save-at");
		} else if (strcmp(argv[i], "--strict") == 0) {
			o->strict = true;
		} else if (parse_load_option(argc, argv, &i, &o->load, &status)) {
			if (status >= 0)
				return status;
		} else if (argv[i][0] == '-' && argv[i][1] != '\0') {
			return usage_error("run", usage_run, "unknown option '%s'", argv[i]);
		} else if (o->file) {
			return usage_error("run", usage_run, "one scenario file only, got also '%s'", argv[i]);
		} else {
			o->file = argv[i];
		}
	}
	if (!o->file)
		return usage_error("run", usage_run, "%s", "missing the scenario FILE");
	if ((o->save_at >= 0) != (o->state_out != NULL))
		return usage_error("run", usage_run, "%s", "--save-at and --state-out go together");
	if ((o->load.dt > 0.0 || o->load.noise || o->load.phase > 0.0) && (o->state_out || o->resume))
		return usage_error("run", usage_run, "%s", "--dt, --noise-seed and --phase do not go with --save-at or --resume");
	return -1;
}

// The scenario's files (its own and those it names): no output may overwrite one.
static void add_inputs(const hs_scenario *s) {
	for (int i = 0; i < hs_scenario_input_count(s); ++i)
		output_input(hs_scenario_input_path(s, i));
}

// --state-out is refused before the run when it names an input (it is written at --save-at).
static bool check_state_out(const char *path) {
	char why[512];
	if (!path || output_check(path, why, sizeof why))
		return true;
	fprintf(stderr, "handspring: %s\n", why);
	return false;
}

// Writes the run's state to `path` (complete or not at all).
static bool save_state(hs_scenario *s, const char *path) {
	output o;
	hs_error err;
	bool opened = output_open(&o, path), saved = opened && hs_scenario_save(s, o.file, &err) == HS_OK;
	bool ok = output_close(&o, saved) && saved; // a write error shows here, whatever the save said
	if (!opened || o.error[0])
		fprintf(stderr, "handspring: %s\n", o.error);
	else if (!saved)
		fprintf(stderr, "%s: %s\n", path, err.message);
	output_free(&o);
	return ok;
}

static bool resume_state(hs_scenario *s, const char *path) {
	FILE *in = fopen(path, "rb");
	if (!in) {
		fprintf(stderr, "%s: cannot read: %s\n", path, strerror(errno));
		return false;
	}
	hs_error err;
	bool ok = hs_scenario_resume(s, in, &err) == HS_OK;
	if (!ok)
		fprintf(stderr, "%s: %s\n", path, err.message);
	fclose(in);
	return ok;
}

// Steps to the end, writing the trajectory (a resumed run: only the frames it runs) and the state
// at the frame asked for. False when the state could not be written or its frame was never reached.
static bool run_saving(hs_scenario *s, FILE *traj, FILE *hands, const run_options *o) {
	hs_world *world = hs_scenario_world(s);
	hs_outsel *sel = (hs_outsel *)&o->sel;
	long frames = hs_scenario_frame_count(s);
	if (traj) {
		hs_trajectory_write_header(traj);
		if (!o->resume && hs_outsel_keep(sel, hs_world_frame(world)))
			hs_trajectory_write_selected(traj, s, sel->selected);
	}
	if (hands) {
		hs_hand_trace_write_header(hands);
		if (!o->resume && hs_outsel_keep(sel, hs_world_frame(world)))
			hs_hand_trace_write_frame(hands, s);
	}
	bool saved = o->save_at < 0;
	for (;;) { // the state after frame F: before stepping on (F = 0: before any step)
		if (!saved && hs_world_frame(world) == o->save_at) {
			if (!save_state(s, o->state_out))
				return false;
			saved = true;
		}
		if (!hs_scenario_step(s))
			break;
		bool keep = hs_outsel_keep(sel, hs_world_frame(world));
		if (traj && keep)
			hs_trajectory_write_selected(traj, s, sel->selected);
		if (hands && keep)
			hs_hand_trace_write_frame(hands, s);
		hs_outsel_progress(sel, hs_world_frame(world), frames);
	}
	if (!saved)
		fprintf(stderr, "handspring: the run ended at frame %ld, before frame %ld: no state written\n",
		        hs_world_frame(world), o->save_at);
	return saved;
}

static int print_summary(FILE *report, hs_scenario *s, const run_options *o) {
	hs_world *world = hs_scenario_world(s);
	fprintf(report, "scenario: %s\n", hs_scenario_name(s));
	fprintf(report, "  %s\n", hs_scenario_description(s));
	fprintf(report, "frames:   %ld (dt %.9g s, %.9g s)\n", hs_world_frame(world), hs_scenario_dt(s),
	        (double)hs_world_frame(world) * hs_scenario_dt(s));
	fprintf(report, "objects:  %d\n", hs_scenario_object_count(s));
	for (int h = 0; h < hs_scenario_hand_count(s); ++h) { // hands driven by joint recordings
		double rms;
		long samples;
		const char *record;
		if (hs_scenario_hand_fit(s, h, &rms, &samples, &record))
			fprintf(report, "hand %s: fitted from %ld samples of %s: RMS %.1f mm\n", hs_scenario_hand_name(s, h),
			        samples, record, rms);
	}
	int failed = hs_scenario_check(s, report);
	int total = hs_scenario_expectation_count(s);
	fprintf(report, "expectations: %d/%d passed\n", total - failed, total);
	fprintf(report, "final hash: %016" PRIx64 "\n", hs_world_hash(world));
	if (o->resume)
		fprintf(report, "resumed from: %s\n", o->resume);
	if (o->state_out)
		fprintf(report, "state: %s (frame %ld)\n", o->state_out, o->save_at);
	if (o->out)
		fprintf(report, "trajectory: %s\n", strcmp(o->out, "-") == 0 ? "stdout" : o->out);
	fprintf(report, "%s\n", failed ? "FAIL" : "PASS");
	return failed;
}

static int cmd_run(int argc, char **argv) {
	run_options o;
	int status = parse_run(argc, argv, &o);
	if (status >= 0)
		return status;
	hs_error err;
	hs_scenario *s = hs_scenario_load_with(o.file, &o.load, &err);
	if (!s) {
		fprintf(stderr, "%s\n", err.message);
		return EXIT_BAD_INPUT;
	}
	fputs(hs_scenario_warnings(s), stderr);
	char why[160];
	if (o.strict && hs_scenario_warnings(s)[0]) { // said above: one line each
		hs_outsel_free(&o.sel);
		hs_scenario_destroy(s);
		return EXIT_BAD_INPUT;
	}
	if (!hs_outsel_bind(&o.sel, s, false, why, sizeof why)) {
		fprintf(stderr, "handspring run: %s\n", why);
		hs_outsel_free(&o.sel);
		hs_scenario_destroy(s);
		return EXIT_BAD_INPUT;
	}
	if (o.save_at > hs_scenario_frame_count(s)) {
		fprintf(stderr, "handspring run: --save-at must be within [0, %ld] (the scenario's frames), got %ld\n",
		        hs_scenario_frame_count(s), o.save_at);
		hs_scenario_destroy(s);
		return EXIT_BAD_INPUT;
	}
	bool to_stdout = o.out && strcmp(o.out, "-") == 0; // the trajectory on stdout, the summary on stderr
	output traj, hands;
	memset(&traj, 0, sizeof traj);
	memset(&hands, 0, sizeof hands);
	add_inputs(s);
	output_input(o.resume);
	bool ok = !o.resume || resume_state(s, o.resume);
	if (ok && o.out && !(ok = output_open(&traj, o.out)))
		fprintf(stderr, "handspring: %s\n", traj.error);
	if (ok && o.hands_out && !(ok = output_open(&hands, o.hands_out)))
		fprintf(stderr, "handspring: %s\n", hands.error);
	ok = ok && check_state_out(o.state_out);
	ok = ok && run_saving(s, traj.file, hands.file, &o);
	if (!output_close(&traj, ok) && ok) {
		fprintf(stderr, "handspring: %s\n", traj.error);
		ok = false;
	}
	if (!output_close(&hands, ok) && ok) {
		fprintf(stderr, "handspring: %s\n", hands.error);
		ok = false;
	}
	output_free(&traj);
	output_free(&hands);
	int failed = ok ? print_summary(to_stdout ? stderr : stdout, s, &o) : 0;
	hs_outsel_free(&o.sel);
	hs_scenario_destroy(s);
	return !ok ? EXIT_BAD_INPUT : failed ? EXIT_FAILED : EXIT_PASS;
}

static bool parse_dir_option(int argc, char **argv, int *i, const char *name, const char **value, int *status,
                             const char *command, const char *usage) {
	bool missing = false;
	if (!option_value(argc, argv, i, name, value, &missing))
		return false;
	if (missing)
		*status = usage_error(command, usage, "%s needs a folder", name);
	return true;
}

static int cmd_list(int argc, char **argv) {
	const char *dir = "scenarios";
	for (int i = 0; i < argc; ++i) {
		int status = -1;
		if (is_help(argv[i])) {
			fputs(usage_list, stdout);
			return EXIT_PASS;
		}
		if (parse_dir_option(argc, argv, &i, "--dir", &dir, &status, "list", usage_list)) {
			if (status >= 0)
				return status;
			continue;
		}
		return usage_error("list", usage_list, argv[i][0] == '-' ? "unknown option '%s'" : "unexpected argument '%s'",
		                   argv[i]);
	}
	hs_catalog catalog;
	hs_error err;
	if (!hs_catalog_load(dir, &catalog, &err)) {
		fprintf(stderr, "%s\n", err.message);
		return EXIT_BAD_INPUT;
	}
	int width = 4;
	for (int i = 0; i < catalog.count; ++i)
		if ((int)strlen(catalog.names[i]) > width)
			width = (int)strlen(catalog.names[i]);
	int status = EXIT_PASS;
	for (int i = 0; i < catalog.count; ++i) {
		hs_scenario *s = hs_scenario_load(catalog.paths[i], &err);
		if (!s) {
			fprintf(stderr, "%s\n", err.message);
			printf("%-*s  (cannot load: see the error above)\n", width, catalog.names[i]);
			status = EXIT_BAD_INPUT;
			continue;
		}
		printf("%-*s  %s\n", width, catalog.names[i], hs_scenario_description(s));
		hs_scenario_destroy(s);
	}
	hs_catalog_free(&catalog);
	return status;
}

// What `all` and `golden` do: the folders written and the goldens' rules.
typedef struct all_job {
	const char *command; // "all" or "golden": names the messages
	const char *dir, *out_dir, *golden_dir, *hands_dir;
	const char *golden_given; // `golden --golden GDIR` as given (NULL: the default)
	char regenerate[600];     // the goldens' header: the command that writes them again
	bool force, strict;       // --force: goldens of failing scenarios too; --strict: warnings refuse
	hs_outsel sel;
} all_job;

// `all`'s options; -1 to go on, else the exit status.
static int all_options(int argc, char **argv, all_job *job) {
	for (int i = 0; i < argc; ++i) {
		int status = -1;
		char why[160];
		if (is_help(argv[i])) {
			fputs(usage_all, stdout);
			return EXIT_PASS;
		}
		if (hs_outsel_option(&job->sel, argc, argv, &i, why, sizeof why)) {
			if (why[0])
				return usage_error("all", usage_all, "%s", why);
			continue;
		}
		if (strcmp(argv[i], "--force") == 0 || strcmp(argv[i], "--strict") == 0) {
			*(argv[i][2] == 'f' ? &job->force : &job->strict) = true;
			continue;
		}
		if (parse_dir_option(argc, argv, &i, "--dir", &job->dir, &status, "all", usage_all) ||
		    parse_dir_option(argc, argv, &i, "--out-dir", &job->out_dir, &status, "all", usage_all) ||
		    parse_dir_option(argc, argv, &i, "--golden-dir", &job->golden_dir, &status, "all", usage_all) ||
		    parse_dir_option(argc, argv, &i, "--hands-dir", &job->hands_dir, &status, "all", usage_all)) {
			if (status >= 0)
				return status;
			continue;
		}
		return usage_error("all", usage_all, argv[i][0] == '-' ? "unknown option '%s'" : "unexpected argument '%s'",
		                   argv[i]);
	}
	return -1;
}

// The goldens' header line: `make golden` for the catalog's own, else the command as given, on one
// line whatever the folders' names hold.
static void set_regenerate(all_job *job) {
	char *r = job->regenerate;
	size_t n = sizeof job->regenerate;
	if (hs_golden_is_make_golden(job->dir, job->golden_dir))
		snprintf(r, n, "make golden");
	else if (strcmp(job->command, "golden") == 0)
		snprintf(r, n, "handspring golden %s%s%s%s", job->dir, job->golden_given ? " --golden " : "",
		         job->golden_given ? job->golden_given : "", job->force ? " --force" : "");
	else
		snprintf(r, n, "handspring all --dir %s --golden-dir %s%s", job->dir, job->golden_dir,
		         job->force ? " --force" : "");
	for (; *r; ++r)
		if ((unsigned char)*r < 0x20 || *r == 0x7f)
			*r = '?';
}

// Runs one loaded scenario writing its trajectory to the job's out_dir and hands_dir (closed here)
// and golden_dir (left open in *golden: it is kept only if the scenario passes); false on a write
// error (said on stderr).
static bool all_run_one(hs_scenario *s, const char *name, all_job *job, output *golden) {
	output outs[3];
	memset(outs, 0, sizeof outs);
	const char *dirs[3] = {job->out_dir, job->golden_dir, job->hands_dir};
	bool io_ok = true;
	for (int k = 0; k < 3 && io_ok; ++k) {
		if (!dirs[k])
			continue;
		char *csv = join_csv(dirs[k], name);
		io_ok = csv && output_open(&outs[k], csv);
		if (!io_ok)
			fprintf(stderr, "handspring: %s\n", csv ? outs[k].error : "out of memory");
		free(csv);
	}
	FILE *files[2] = {outs[0].file, outs[1].file};
	if (io_ok)
		run_scenario(s, files, 2, outs[2].file, &job->sel);
	for (int k = 0; k < 3; k += 2) {
		if (!output_close(&outs[k], io_ok) && io_ok) {
			fprintf(stderr, "handspring: %s\n", outs[k].error);
			io_ok = false;
		}
		output_free(&outs[k]);
	}
	*golden = outs[1];
	return io_ok;
}

// Keeps a scenario's golden when its expectations passed (or with --force, warned of); false on a
// write error. *written says whether it was kept.
static bool all_finish_golden(const all_job *job, const char *name, output *golden, int fails, bool io_ok,
                              bool *written) {
	*written = false;
	if (!job->golden_dir)
		return io_ok;
	bool keep = io_ok && (fails == 0 || job->force);
	if (io_ok && fails && job->force)
		fprintf(stderr, "handspring %s: warning: %s: %d expectation(s) failed: its golden is written anyway (--force)\n",
		        job->command, name, fails);
	else if (io_ok && fails)
		fprintf(stderr, "handspring %s: %s: %d expectation(s) failed: its golden is not written (--force writes it)\n",
		        job->command, name, fails);
	bool ok = output_close(golden, keep);
	if (!ok && keep)
		fprintf(stderr, "handspring: %s\n", golden->error);
	output_free(golden);
	*written = keep && ok;
	return io_ok && (ok || !keep);
}

// Checks a run scenario: its table row on stdout, its FAIL lines into log. Returns the failures.
static int all_report(hs_scenario *s, const char *name, int width, FILE *log) {
	char *report = NULL;
	size_t report_size = 0;
	FILE *r = open_memstream(&report, &report_size);
	int fails = hs_scenario_check(s, r);
	if (r)
		fclose(r);
	int total = hs_scenario_expectation_count(s);
	char expect[32];
	snprintf(expect, sizeof expect, "%d/%d", total - fails, total);
	printf("%-*s  %9ld  %7d  %11s  %016" PRIx64 "  %s\n", width, name, hs_world_frame(hs_scenario_world(s)),
	       hs_scenario_object_count(s), expect, hs_world_hash(hs_scenario_world(s)), fails ? "FAIL" : "PASS");
	fflush(stdout);
	for (char *line = report; fails && line && *line;) { // keep only the FAIL lines
		char *end = strchr(line, '\n');
		size_t n = end ? (size_t)(end - line) : strlen(line);
		if (log && strncmp(line, "FAIL", 4) == 0)
			fprintf(log, "%s: %.*s\n", name, (int)n, line);
		line = end ? end + 1 : line + n;
	}
	free(report);
	return fails;
}

// A scenario of the catalog loaded for `all`: its warnings said (with --strict they refuse it), its
// output selection bound, its files recorded as inputs; NULL on bad input.
static hs_scenario *all_load(all_job *job, const char *name, const char *path) {
	hs_error err;
	hs_scenario *s = hs_scenario_load(path, &err);
	if (!s) {
		fprintf(stderr, "%s\n", err.message);
		return NULL;
	}
	fputs(hs_scenario_warnings(s), stderr);
	char why[160];
	if (job->strict && hs_scenario_warnings(s)[0]) {
		fprintf(stderr, "handspring %s: %s: refused: it has warnings (--strict)\n", job->command, name);
		hs_scenario_destroy(s);
		return NULL;
	}
	if (!hs_outsel_bind(&job->sel, s, true, why, sizeof why)) {
		fprintf(stderr, "handspring %s: %s: %s\n", job->command, name, why);
		hs_scenario_destroy(s);
		return NULL;
	}
	add_inputs(s);
	return s;
}

typedef struct all_counts {
	int passed, failed, bad, goldens;
} all_counts;

// One scenario of the catalog: loaded, run, its row printed, its golden kept or not.
static void all_one(all_job *job, const hs_catalog *catalog, int i, int width, FILE *log, all_counts *c) {
	const char *name = catalog->names[i];
	hs_scenario *s = all_load(job, name, catalog->paths[i]);
	output golden;
	memset(&golden, 0, sizeof golden);
	bool io_ok = s && all_run_one(s, name, job, &golden);
	int fails = io_ok ? all_report(s, name, width, log) : 0;
	bool written = false;
	if (s && !all_finish_golden(job, name, &golden, fails, io_ok, &written))
		io_ok = false;
	if (!io_ok) {
		printf("%-*s  %9s  %7s  %11s  %-16s  %s\n", width, name, "-", "-", "-", "-", s ? "WRITE ERROR" : "BAD INPUT");
		c->bad++;
	} else if (fails) {
		c->failed++;
	} else {
		c->passed++;
	}
	c->goldens += written;
	hs_scenario_destroy(s);
}

// The goldens' folder says what its files are and the command that writes them again (README.md:
// the CSVs themselves start with their header row, for any CSV reader). False on a write error.
static bool write_golden_readme(const all_job *job) {
	size_t n = strlen(job->golden_dir) + sizeof "/README.md";
	char *path = malloc(n);
	if (!path)
		return false;
	snprintf(path, n, "%s/README.md", job->golden_dir);
	output o;
	bool ok = output_open(&o, path);
	if (ok) {
		fprintf(o.file,
		        "# Golden trajectories\n\nOne CSV per scenario of `%s` (the folder's tree), written by handspring from a run\n"
		        "whose expectations all passed: every object's pose, contact state and state hash at every frame,\n"
		        "its header row first. Regenerate with `%s`.\n",
		        job->dir, job->regenerate);
		ok = output_close(&o, true);
	}
	if (!ok)
		fprintf(stderr, "handspring: %s\n", o.error);
	output_free(&o);
	free(path);
	return ok;
}

static int all_run(all_job *job) {
	char why[1024];
	if (job->golden_dir && !hs_golden_dir_allowed(job->dir, job->golden_dir, why, sizeof why)) {
		fprintf(stderr, "handspring %s: %s\n", job->command, why);
		return EXIT_BAD_INPUT;
	}
	if (job->golden_dir)
		set_regenerate(job);
	hs_catalog catalog;
	hs_error err;
	if (!hs_catalog_load(job->dir, &catalog, &err)) {
		fprintf(stderr, "%s\n", err.message);
		return EXIT_BAD_INPUT;
	}
	if (catalog.count == 0) { // an empty run proves nothing: say so
		fprintf(stderr, "%s: no scenario files (*.yaml)\n", job->dir);
		hs_catalog_free(&catalog);
		return EXIT_BAD_INPUT;
	}
	int width = 8;
	for (int i = 0; i < catalog.count; ++i)
		if ((int)strlen(catalog.names[i]) > width)
			width = (int)strlen(catalog.names[i]);
	printf("%-*s  %9s  %7s  %11s  %-16s  %s\n", width, "scenario", "frames", "objects", "expect", "final hash", "result");
	all_counts c = {0, 0, 0, 0};
	char *details = NULL; // FAIL lines, printed under the table
	size_t details_size = 0;
	FILE *log = open_memstream(&details, &details_size);
	for (int i = 0; i < catalog.count; ++i)
		all_one(job, &catalog, i, width, log, &c);
	if (log)
		fclose(log);
	if (details && details_size > 0)
		printf("\n%s", details);
	free(details);
	printf("\n%d scenarios: %d passed, %d failed", catalog.count, c.passed, c.failed);
	if (c.bad)
		printf(", %d bad input", c.bad);
	printf("\n");
	if (job->golden_dir)
		printf("%d golden%s written to %s/%s\n", c.goldens, c.goldens == 1 ? "" : "s", job->golden_dir,
		       c.goldens < catalog.count ? " (none for a scenario that failed or could not run)" : "");
	hs_catalog_free(&catalog);
	if (job->golden_dir && c.goldens > 0 && !write_golden_readme(job))
		return EXIT_BAD_INPUT;
	return c.bad ? EXIT_BAD_INPUT : c.failed ? EXIT_FAILED : EXIT_PASS;
}

static int cmd_all(int argc, char **argv) {
	all_job job;
	memset(&job, 0, sizeof job);
	job.command = "all";
	job.dir = "scenarios";
	hs_outsel_init(&job.sel);
	int status = all_options(argc, argv, &job);
	if (status < 0)
		status = all_run(&job);
	hs_outsel_free(&job.sel);
	return status;
}

// `handspring golden DIR [--golden GDIR] [--force] [--strict]`: `all --dir DIR --golden-dir GDIR`,
// GDIR by default DIR/golden (hs_golden_default).
static int cmd_golden(int argc, char **argv) {
	all_job job;
	memset(&job, 0, sizeof job);
	job.command = "golden";
	for (int i = 0; i < argc; ++i) {
		bool missing = false;
		if (is_help(argv[i])) {
			fputs(usage_golden, stdout);
			return EXIT_PASS;
		}
		if (option_value(argc, argv, &i, "--golden", &job.golden_given, &missing) ||
		    option_value(argc, argv, &i, "--golden-dir", &job.golden_given, &missing)) {
			if (missing)
				return usage_error("golden", usage_golden, "%s needs a folder", argv[i]);
		} else if (strcmp(argv[i], "--force") == 0 || strcmp(argv[i], "--strict") == 0) {
			*(argv[i][2] == 'f' ? &job.force : &job.strict) = true;
		} else if (argv[i][0] == '-' || job.dir) {
			return usage_error("golden", usage_golden, argv[i][0] == '-' ? "unknown option '%s'" : "unexpected argument '%s'",
			                   argv[i]);
		} else {
			job.dir = argv[i];
		}
	}
	if (!job.dir)
		return usage_error("golden", usage_golden, "%s", "missing the scenario folder DIR");
	char *fallback = job.golden_given ? NULL : hs_golden_default(job.dir);
	job.golden_dir = job.golden_given ? job.golden_given : fallback;
	hs_outsel_init(&job.sel);
	int status = job.golden_dir ? all_run(&job) : EXIT_BAD_INPUT;
	hs_outsel_free(&job.sel);
	free(fallback);
	return status;
}

static const char *const usage_joints =
    "usage: handspring joints FILE --format mediapipe|openxr --out OUT.csv [--hand N] [--rate HZ]\n"
    "Writes hand N (1: the first) of the scenario FILE as a recording of joint positions, one sample\n"
    "per frame: MediaPipe Hands' 21 landmarks or OpenXR's 26 hand joints (with orientations), the\n"
    "glove model's check points for the scenario's own input, --rate samples per second (default:\n"
    "the scenario's frame rate), in the library's frame (@frame z_up, @units m, @hand; a tracked\n"
    "column when the hand has untracked samples). A hand's 'record:' reads them back.\n"
    "Exit status: 0 written, 2 bad input.\n";

// `handspring joints`: a scenario's hand as a joint recording (scripts/joint_recordings.sh writes
// the catalog's with it).
static int cmd_joints(int argc, char **argv) {
	const char *file = NULL, *format = NULL, *out = NULL, *rate_text = NULL;
	long hand = 1;
	for (int i = 0; i < argc; ++i) {
		bool missing = false;
		const char *h = NULL;
		if (is_help(argv[i])) {
			fputs(usage_joints, stdout);
			return EXIT_PASS;
		}
		if (option_value(argc, argv, &i, "--format", &format, &missing) ||
		    option_value(argc, argv, &i, "--out", &out, &missing) ||
		    option_value(argc, argv, &i, "--rate", &rate_text, &missing)) {
			if (missing)
				return usage_error("joints", usage_joints, "%s needs a value", argv[i]);
		} else if (option_value(argc, argv, &i, "--hand", &h, &missing)) {
			if (missing || !parse_frame(h, &hand) || hand < 1)
				return usage_error("joints", usage_joints, "%s needs a hand number (1, 2, ...)", "--hand");
		} else if (argv[i][0] == '-' || file) {
			return usage_error("joints", usage_joints, argv[i][0] == '-' ? "unknown option '%s'" : "unexpected argument '%s'",
			                   argv[i]);
		} else {
			file = argv[i];
		}
	}
	if (!file || !format || !out)
		return usage_error("joints", usage_joints, "%s", "needs FILE, --format and --out");
	hs_error err;
	hs_scenario *s = hs_scenario_load(file, &err);
	if (!s) {
		fprintf(stderr, "%s\n", err.message);
		return EXIT_BAD_INPUT;
	}
	fputs(hs_scenario_warnings(s), stderr);
	output o;
	add_inputs(s);
	bool ok = output_open(&o, out);
	if (!ok)
		fprintf(stderr, "handspring: %s\n", o.error);
	else if (!(ok = hs_scenario_export_joints(s, (int)hand - 1, format,
	                                          rate_text ? strtod(rate_text, NULL) : 1.0 / hs_scenario_dt(s), o.file, &err)))
		fprintf(stderr, "%s\n", err.message);
	if (!output_close(&o, ok) && ok) {
		fprintf(stderr, "handspring: %s\n", o.error);
		ok = false;
	}
	output_free(&o);
	hs_scenario_destroy(s);
	return ok ? EXIT_PASS : EXIT_BAD_INPUT;
}

static int cmd_sweep(int argc, char **argv) {
	const char *file = NULL;
	for (int i = 0; i < argc; ++i) {
		if (is_help(argv[i])) {
			fputs(usage_sweep, stdout);
			return EXIT_PASS;
		}
		if (argv[i][0] == '-' && argv[i][1] != '\0')
			return usage_error("sweep", usage_sweep, "unknown option '%s'", argv[i]);
		if (file)
			return usage_error("sweep", usage_sweep, "one scenario file only, got also '%s'", argv[i]);
		file = argv[i];
	}
	if (!file)
		return usage_error("sweep", usage_sweep, "%s", "missing the scenario FILE");
	hs_error err;
	int status = hs_scenario_sweep(file, stdout, &err);
	if (status == EXIT_BAD_INPUT)
		fprintf(stderr, "%s\n", err.message);
	return status;
}

int main(int argc, char **argv) {
	if (argc < 2)
		return usage_error(NULL, usage_main, "%s", "missing a command");
	const char *command = argv[1];
	if (is_help(command) || strcmp(command, "help") == 0) {
		fputs(usage_main, stdout);
		return EXIT_PASS;
	}
	if (strcmp(command, "--version") == 0) {
		printf("handspring %s\n", HS_VERSION);
		return EXIT_PASS;
	}
	static const struct {
		const char *name;
		int (*run)(int argc, char **argv);
	} commands[] = {{"list", cmd_list},    {"run", cmd_run},           {"all", cmd_all},
	                {"sweep", cmd_sweep},  {"view", hs_view_main},     {"joints", cmd_joints},
	                {"hand", hs_hand_main}, {"check", hs_check_main},  {"golden", cmd_golden},
	                {"campaign", hs_campaign_main}, {"bench", hs_bench_main}};
	// `| head` closing the pipe ends the tool quietly (an inherited SIG_IGN would turn each later
	// write into an EPIPE error instead)
	signal(SIGPIPE, SIG_DFL);
	for (size_t k = 0; k < sizeof commands / sizeof commands[0]; ++k)
		if (strcmp(command, commands[k].name) == 0) {
			int status = commands[k].run(argc - 2, argv + 2);
			return output_stdout_ok() ? status : EXIT_BAD_INPUT;
		}
	return usage_error(NULL, usage_main, "unknown command '%s'", command);
}
