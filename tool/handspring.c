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
#include "all_cmd.h"
#include "bench_cmd.h"
#include "cli.h"
#include "golden.h"
#include "golden_dir.h"
#include "hand_cmd.h"
#include "outsel.h"
#include "output.h"
#include "campaign_cmd.h"
#include "view.h"


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
    "                           [--resume PATH] [--dt DT] [--noise-seed N] [--phase F] [--letter L] [--strict]\n"
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
    "  --letter L         run the scenario under a paper's letter, every departure of that model off\n"
    "                     (hand1999 or workbench; none: the defaults), whatever the file's model says;\n"
    "                     the file's own model keys give way to it (docs/model.md §11)\n"
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

// --dt, --noise-seed, --phase and --letter at argv[*i]: true when it was one of them (*status set on a usage error).
static bool parse_load_option(int argc, char **argv, int *i, hs_scenario_options *o, int *status) {
	bool missing = false;
	const char *v = NULL;
	if (hs_cli_option_value(argc, argv, i, "--dt", &v, &missing)) {
		if (missing || !hs_scenario_parse_dt(v, &o->dt))
			*status = hs_cli_usage_error("run", usage_run, "%s needs a frame time within [1/2000, 1/12] s (e.g. 1/60)", "--dt");
		return true;
	}
	if (hs_cli_option_value(argc, argv, i, "--phase", &v, &missing)) {
		char *end = NULL;
		o->phase = missing ? -1.0 : strtod(v, &end);
		if (missing || end == v || *end || !(o->phase >= 0.0 && o->phase < 1.0))
			*status = hs_cli_usage_error("run", usage_run, "%s needs a fraction of a frame within [0, 1)", "--phase");
		return true;
	}
	if (hs_cli_option_value(argc, argv, i, "--letter", &v, &missing)) {
		static const char *const texts[] = {"{letter: none}", "{letter: hand1999}", "{letter: workbench}"};
		static const char *const names[] = {"none", "hand1999", "workbench"};
		o->model_count = 0;
		for (int k = 0; k < 3 && !missing; ++k)
			if (strcmp(v, names[k]) == 0) {
				o->model_texts = &texts[k];
				o->model_count = 1;
				o->model_path = "--letter";
			}
		if (o->model_count == 0)
			*status = hs_cli_usage_error("run", usage_run, "%s needs none, hand1999 or workbench", "--letter");
		return true;
	}
	if (hs_cli_option_value(argc, argv, i, "--noise-seed", &v, &missing)) {
		o->noise = true;
		if (missing || !parse_seed(v, &o->noise_seed))
			*status = hs_cli_usage_error("run", usage_run, "%s needs a seed within [0, 4294967295]", "--noise-seed");
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
		if (hs_cli_is_help(argv[i])) {
			fputs(usage_run, stdout);
			return EXIT_PASS;
		} else if (hs_outsel_option(&o->sel, argc, argv, &i, why, sizeof why)) {
			if (why[0])
				return hs_cli_usage_error("run", usage_run, "%s", why);
		} else if (hs_cli_option_value(argc, argv, &i, "--out", &o->out, &missing) ||
		           hs_cli_option_value(argc, argv, &i, "--hands-out", &o->hands_out, &missing) ||
		           hs_cli_option_value(argc, argv, &i, "--state-out", &o->state_out, &missing) ||
		           hs_cli_option_value(argc, argv, &i, "--resume", &o->resume, &missing)) {
			if (missing)
				return hs_cli_usage_error("run", usage_run, "%s needs a file name", argv[i]);
		} else if (hs_cli_option_value(argc, argv, &i, "--save-at", &frame, &missing)) {
			if (missing || !parse_frame(frame, &o->save_at))
				return hs_cli_usage_error("run", usage_run, "%s needs a frame number (0, 1, 2, ...)", "--save-at");
		} else if (strcmp(argv[i], "--strict") == 0) {
			o->strict = true;
		} else if (parse_load_option(argc, argv, &i, &o->load, &status)) {
			if (status >= 0)
				return status;
		} else if (argv[i][0] == '-' && argv[i][1] != '\0') {
			return hs_cli_usage_error("run", usage_run, "unknown option '%s'", argv[i]);
		} else if (o->file) {
			return hs_cli_usage_error("run", usage_run, "one scenario file only, got also '%s'", argv[i]);
		} else {
			o->file = argv[i];
		}
	}
	if (!o->file)
		return hs_cli_usage_error("run", usage_run, "%s", "missing the scenario FILE");
	if ((o->save_at >= 0) != (o->state_out != NULL))
		return hs_cli_usage_error("run", usage_run, "%s", "--save-at and --state-out go together");
	if ((o->load.dt > 0.0 || o->load.noise || o->load.phase > 0.0 || o->load.model_count > 0) && (o->state_out || o->resume))
		return hs_cli_usage_error("run", usage_run, "%s", "--dt, --noise-seed, --phase and --letter do not go with --save-at or --resume");
	return -1;
}

// The scenario's files (its own and those it names): no output may overwrite one.

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
	hs_cli_add_inputs(s);
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


static int cmd_list(int argc, char **argv) {
	const char *dir = "scenarios";
	for (int i = 0; i < argc; ++i) {
		int status = -1;
		if (hs_cli_is_help(argv[i])) {
			fputs(usage_list, stdout);
			return EXIT_PASS;
		}
		if (hs_cli_dir_option(argc, argv, &i, "--dir", &dir, &status, "list", usage_list)) {
			if (status >= 0)
				return status;
			continue;
		}
		return hs_cli_usage_error("list", usage_list, argv[i][0] == '-' ? "unknown option '%s'" : "unexpected argument '%s'",
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


// `handspring joints`: a scenario's hand as a joint recording (scripts/joint_recordings.sh writes
// the catalog's with it).
static const char *const usage_joints =
    "usage: handspring joints FILE --format mediapipe|openxr --out OUT.csv [--hand N] [--rate HZ]\n"
    "Writes hand N (1: the first) of the scenario FILE as a recording of joint positions, one sample\n"
    "per frame: MediaPipe Hands' 21 landmarks or OpenXR's 26 hand joints (with orientations), the\n"
    "glove model's check points for the scenario's own input, --rate samples per second (default:\n"
    "the scenario's frame rate), in the library's frame (@frame z_up, @units m, @hand; a tracked\n"
    "column when the hand has untracked samples). A hand's 'record:' reads them back.\n"
    "Exit status: 0 written, 2 bad input.\n";

static int cmd_joints(int argc, char **argv) {
	const char *file = NULL, *format = NULL, *out = NULL, *rate_text = NULL;
	long hand = 1;
	for (int i = 0; i < argc; ++i) {
		bool missing = false;
		const char *h = NULL;
		if (hs_cli_is_help(argv[i])) {
			fputs(usage_joints, stdout);
			return EXIT_PASS;
		}
		if (hs_cli_option_value(argc, argv, &i, "--format", &format, &missing) ||
		    hs_cli_option_value(argc, argv, &i, "--out", &out, &missing) ||
		    hs_cli_option_value(argc, argv, &i, "--rate", &rate_text, &missing)) {
			if (missing)
				return hs_cli_usage_error("joints", usage_joints, "%s needs a value", argv[i]);
		} else if (hs_cli_option_value(argc, argv, &i, "--hand", &h, &missing)) {
			if (missing || !parse_frame(h, &hand) || hand < 1)
				return hs_cli_usage_error("joints", usage_joints, "%s needs a hand number (1, 2, ...)", "--hand");
		} else if (argv[i][0] == '-' || file) {
			return hs_cli_usage_error("joints", usage_joints, argv[i][0] == '-' ? "unknown option '%s'" : "unexpected argument '%s'",
			                   argv[i]);
		} else {
			file = argv[i];
		}
	}
	if (!file || !format || !out)
		return hs_cli_usage_error("joints", usage_joints, "%s", "needs FILE, --format and --out");
	hs_error err;
	hs_scenario *s = hs_scenario_load(file, &err);
	if (!s) {
		fprintf(stderr, "%s\n", err.message);
		return EXIT_BAD_INPUT;
	}
	fputs(hs_scenario_warnings(s), stderr);
	output o;
	hs_cli_add_inputs(s);
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
		if (hs_cli_is_help(argv[i])) {
			fputs(usage_sweep, stdout);
			return EXIT_PASS;
		}
		if (argv[i][0] == '-' && argv[i][1] != '\0')
			return hs_cli_usage_error("sweep", usage_sweep, "unknown option '%s'", argv[i]);
		if (file)
			return hs_cli_usage_error("sweep", usage_sweep, "one scenario file only, got also '%s'", argv[i]);
		file = argv[i];
	}
	if (!file)
		return hs_cli_usage_error("sweep", usage_sweep, "%s", "missing the scenario FILE");
	hs_error err;
	int status = hs_scenario_sweep(file, stdout, &err);
	if (status == EXIT_BAD_INPUT)
		fprintf(stderr, "%s\n", err.message);
	return status;
}

int main(int argc, char **argv) {
	if (argc < 2)
		return hs_cli_usage_error(NULL, usage_main, "%s", "missing a command");
	const char *command = argv[1];
	if (hs_cli_is_help(command) || strcmp(command, "help") == 0) {
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
	} commands[] = {{"list", cmd_list},    {"run", cmd_run},           {"all", hs_cmd_all},
	                {"sweep", cmd_sweep},  {"view", hs_view_main},     {"joints", cmd_joints},
	                {"hand", hs_hand_main}, {"check", hs_check_main},  {"golden", hs_cmd_golden},
	                {"campaign", hs_campaign_main}, {"bench", hs_bench_main}};
	// `| head` closing the pipe ends the tool quietly (an inherited SIG_IGN would turn each later
	// write into an EPIPE error instead)
	signal(SIGPIPE, SIG_DFL);
	for (size_t k = 0; k < sizeof commands / sizeof commands[0]; ++k)
		if (strcmp(command, commands[k].name) == 0) {
			int status = commands[k].run(argc - 2, argv + 2);
			return output_stdout_ok() ? status : EXIT_BAD_INPUT;
		}
	return hs_cli_usage_error(NULL, usage_main, "unknown command '%s'", command);
}
