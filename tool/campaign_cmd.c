// campaign_cmd.c — `handspring campaign FILE`: the whole campaign in this process (its trial CSV,
// its summary), a slice of its trials as rows for a job of GNU parallel or a Slurm array
// (scripts/campaign.sh), or the summary of rows merged from such jobs (docs/campaigns.md).
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "campaign_cmd.h"
#include "hs_harness.h"
#include "output.h"

enum { EXIT_PASS = 0, EXIT_FAULTED = 1, EXIT_BAD_INPUT = 2 };

static const char *const usage =
    "usage: handspring campaign FILE [--out TRIALS.csv] [--summary SUMMARY.csv] [--progress]\n"
    "       handspring campaign FILE --trials A:B [--out ROWS.csv]\n"
    "       handspring campaign FILE --summarize TRIALS.csv [--summary SUMMARY.csv]\n"
    "       handspring campaign FILE --count | --header\n"
    "Runs the campaign FILE (docs/campaigns.md): every trial of every cell, then prints a table per\n"
    "cell (hits, rate, Wilson 95 % interval, mean distance to the target; with a thrower, the misses\n"
    "whose grasp was lost in the swing apart from the thrower's misses, and the rate per visitor of\n"
    "visitor_throws throws, hit when any hits, beside the binomial 1 - (1 - rate)^N).\n"
    "  --out FILE         write the trial CSV (header, one row per trial in trial order)\n"
    "  --summary FILE     write the per-cell summary CSV\n"
    "  --trials A:B       run trials A to B-1 only and write their rows, no header (a job's slice:\n"
    "                     scripts/campaign.sh and scripts/campaign.sbatch); --rows: every trial so\n"
    "  --summarize FILE   read a merged trial CSV (header, then every trial in order) and summarise it\n"
    "  --count            print the number of trials; --header: the trial CSV's header line\n"
    "  --progress         trials done, trials/s and the time left on stderr (default: when a terminal)\n"
    "Trial i's row depends only on FILE and i. Exit status: 0 done, 1 done but a trial's run faulted (a step\n"
    "failed or a value went non-finite: its clauses column says fault), 2 bad input.\n";

typedef struct campaign_args {
	const char *file, *out, *summary, *summarize;
	long first, last; // trials [first, last); last < 0: all
	bool rows, count, header, progress;
} campaign_args;

static int usage_error(const char *fmt, const char *arg) {
	fputs("handspring campaign: ", stderr);
	fprintf(stderr, fmt, arg);
	fprintf(stderr, "\n%s", usage);
	return EXIT_BAD_INPUT;
}

// "A:B" with 0 <= A < B
static bool parse_range(const char *text, long *a, long *b) {
	char *end;
	*a = strtol(text, &end, 10);
	if (end == text || *end != ':' || *a < 0)
		return false;
	const char *second = end + 1;
	*b = strtol(second, &end, 10);
	return end != second && !*end && *b > *a;
}

// The value of an option at argv[*i] (advancing past it); NULL when it is missing.
static const char *value_of(int argc, char **argv, int *i) { return *i + 1 < argc ? argv[++*i] : NULL; }

static int parse_args(int argc, char **argv, campaign_args *a) {
	memset(a, 0, sizeof *a);
	a->last = -1;
	a->progress = isatty(STDERR_FILENO);
	for (int i = 0; i < argc; ++i) {
		const char *arg = argv[i], **target = NULL;
		if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0)
			return fputs(usage, stdout), -1;
		if (strcmp(arg, "--out") == 0)
			target = &a->out;
		else if (strcmp(arg, "--summary") == 0)
			target = &a->summary;
		else if (strcmp(arg, "--summarize") == 0)
			target = &a->summarize;
		if (target) {
			if (!(*target = value_of(argc, argv, &i)))
				return usage_error("'%s' needs a file", arg);
		} else if (strcmp(arg, "--trials") == 0) {
			const char *v = value_of(argc, argv, &i);
			if (!v || !parse_range(v, &a->first, &a->last))
				return usage_error("'--trials' needs A:B with 0 <= A < B, got '%s'", v ? v : "");
			a->rows = true;
		} else if (strcmp(arg, "--rows") == 0 || strcmp(arg, "--count") == 0 || strcmp(arg, "--header") == 0) {
			bool *flag = arg[2] == 'r' ? &a->rows : arg[2] == 'c' ? &a->count : &a->header;
			*flag = true;
		} else if (strcmp(arg, "--progress") == 0) {
			a->progress = true;
		} else if (arg[0] == '-' && arg[1]) {
			return usage_error("unknown option '%s'", arg);
		} else if (a->file) {
			return usage_error("one campaign file only, got also '%s'", arg);
		} else {
			a->file = arg;
		}
	}
	if (!a->file)
		return usage_error("%s", "missing the campaign FILE");
	if (a->rows + a->count + a->header + (a->summarize != NULL) > 1 || (a->rows && a->summary))
		return usage_error("%s", "--trials/--rows, --summarize, --count and --header go alone (with --out)");
	return EXIT_PASS;
}

static double now(void) {
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

// "done of total, trials/s, time left" on stderr, at most twice a second and at the end. The time
// left weighs each trial by its frames plus LOAD_FRAMES (a trial builds its world, which costs
// about that many frames: campaigns/exp2.yaml's trials take 0.43 ms and 2 us a frame).
#define LOAD_FRAMES 200.0

typedef struct progress {
	long done, total;
	double frames_done, frames_total, started, shown;
} progress;

static void show_progress(progress *p, double frames) {
	p->done++;
	p->frames_done += frames;
	double t = now();
	if (p->done < p->total && t - p->shown < 0.5)
		return;
	p->shown = t;
	double spent = t - p->started > 1e-9 ? t - p->started : 1e-9;
	double left = spent * (p->frames_total - p->frames_done) / (p->frames_done > 0.0 ? p->frames_done : 1.0);
	fprintf(stderr, "\rcampaign: %ld of %ld trials, %.0f trials/s, %.0f s left   %s", p->done, p->total,
	        (double)p->done / spent, left, p->done == p->total ? "\n" : "");
}

// Trials [first, last) as rows to `out`.
static bool run_trials(hs_campaign *c, long first, long last, FILE *out, bool show, hs_error *err) {
	progress p = {.total = last - first, .started = now()};
	p.shown = p.started;
	for (long i = first; show && i < last; ++i)
		p.frames_total += hs_campaign_trial_frames(c, i) + LOAD_FRAMES;
	for (long i = first; i < last; ++i) {
		if (!hs_campaign_run_trial(c, i, out, err))
			return false;
		if (show)
			show_progress(&p, hs_campaign_trial_frames(c, i) + LOAD_FRAMES);
	}
	return true;
}

// The summary of the trial CSV `in`: the table to stdout, the CSV to `summary_path` when given.
static int summarize(const hs_campaign *c, FILE *in, const char *in_path, const char *summary_path) {
	output o = {0};
	if (summary_path && !output_open(&o, summary_path)) {
		fprintf(stderr, "handspring: %s\n", o.error);
		output_free(&o);
		return EXIT_BAD_INPUT;
	}
	hs_error err = {{0}};
	int status = hs_campaign_summarize(c, in, in_path, o.file, stdout, &err);
	if (status != EXIT_PASS)
		fprintf(stderr, "%s\n", err.message);
	if (summary_path && !output_close(&o, status != EXIT_BAD_INPUT) && status != EXIT_BAD_INPUT) {
		fprintf(stderr, "handspring: %s\n", o.error);
		status = EXIT_BAD_INPUT;
	}
	output_free(&o);
	return status;
}

// Copies the whole of `from` (rewound) to `to`.
static bool copy_file(FILE *from, FILE *to) {
	char buf[1 << 16];
	size_t n;
	rewind(from);
	while ((n = fread(buf, 1, sizeof buf, from)) > 0)
		if (fwrite(buf, 1, n, to) != n)
			return false;
	return !ferror(from);
}

// Every trial: the trial CSV into a temporary file (copied to --out), then its summary read back.
static int run_all(hs_campaign *c, const campaign_args *a, hs_error *err) {
	FILE *rows = tmpfile();
	if (!rows)
		return fprintf(stderr, "%s: cannot make a temporary file\n", a->file), EXIT_BAD_INPUT;
	hs_campaign_write_header(c, rows);
	int status = run_trials(c, 0, hs_campaign_trials(c), rows, a->progress, err) ? EXIT_PASS : EXIT_BAD_INPUT;
	if (status == EXIT_PASS && (fflush(rows) != 0 || ferror(rows))) // the temporary folder's disk full
		status = (fprintf(stderr, "handspring: cannot write the trial rows to a temporary file: %s\n",
		                  strerror(errno ? errno : EIO)), EXIT_BAD_INPUT);
	output o = {0};
	if (status == EXIT_PASS && a->out) {
		if (!output_open(&o, a->out))
			status = (fprintf(stderr, "handspring: %s\n", o.error), EXIT_BAD_INPUT);
		else {
			bool copied = copy_file(rows, o.file); // a write error shows at the close: it checks every one
			if (!output_close(&o, copied) || !copied) {
				fprintf(stderr, "handspring: %s\n", o.error[0] ? o.error : "the trial rows cannot be read back");
				status = EXIT_BAD_INPUT;
			}
		}
		output_free(&o);
	}
	if (status == EXIT_PASS) {
		rewind(rows);
		status = summarize(c, rows, a->out ? a->out : "(trials)", a->summary); // EXIT_FAULTED: written
	}
	fclose(rows);
	return status;
}

static int run_campaign(hs_campaign *c, const campaign_args *a) {
	if (a->count || a->header) {
		if (a->count)
			printf("%ld\n", hs_campaign_trials(c));
		else
			hs_campaign_write_header(c, stdout);
		return EXIT_PASS;
	}
	if (a->summarize) {
		FILE *in = fopen(a->summarize, "r");
		if (!in)
			return fprintf(stderr, "%s:1: cannot read\n", a->summarize), EXIT_BAD_INPUT;
		int status = summarize(c, in, a->summarize, a->summary);
		fclose(in);
		return status;
	}
	hs_error err = {{0}};
	int status = EXIT_BAD_INPUT;
	if (!a->rows) {
		status = run_all(c, a, &err);
	} else {
		long last = a->last < 0 ? hs_campaign_trials(c) : a->last;
		if (last > hs_campaign_trials(c))
			return fprintf(stderr, "%s: --trials reaches %ld, the campaign has %ld trials\n", a->file, last,
			               hs_campaign_trials(c)), EXIT_BAD_INPUT;
		output o = {0};
		if (!output_open(&o, a->out ? a->out : "-"))
			return fprintf(stderr, "handspring: %s\n", o.error), output_free(&o), EXIT_BAD_INPUT;
		status = run_trials(c, a->first, last, o.file, a->progress, &err) ? EXIT_PASS : EXIT_BAD_INPUT;
		if (!output_close(&o, status == EXIT_PASS) && status == EXIT_PASS)
			status = (fprintf(stderr, "handspring: %s\n", o.error), EXIT_BAD_INPUT);
		output_free(&o);
	}
	if (status != EXIT_PASS && err.message[0])
		fprintf(stderr, "%s\n", err.message);
	return status;
}

int hs_campaign_main(int argc, char **argv) {
	campaign_args a;
	int status = parse_args(argc, argv, &a);
	if (status != EXIT_PASS)
		return status < 0 ? EXIT_PASS : status;
	hs_error err = {{0}};
	hs_campaign *c = hs_campaign_load(a.file, &err);
	if (!c) {
		fprintf(stderr, "%s\n", err.message);
		return EXIT_BAD_INPUT;
	}
	for (int i = 0; i < hs_campaign_input_count(c); ++i) // no output may overwrite what the campaign read
		output_input(hs_campaign_input_path(c, i));
	output_input(a.summarize);
	status = run_campaign(c, &a);
	hs_campaign_destroy(c);
	return status;
}
