// all_cmd.c — `handspring all` and `handspring golden`: every scenario of a catalog run, its
// trajectories and goldens written, a summary table (docs/tool.md).
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "all_cmd.h"
#include "cli.h"
#include "golden.h"
#include "golden_dir.h"
#include "output.h"

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
		if (hs_cli_is_help(argv[i])) {
			fputs(usage_all, stdout);
			return EXIT_PASS;
		}
		if (hs_outsel_option(&job->sel, argc, argv, &i, why, sizeof why)) {
			if (why[0])
				return hs_cli_usage_error("all", usage_all, "%s", why);
			continue;
		}
		if (strcmp(argv[i], "--force") == 0 || strcmp(argv[i], "--strict") == 0) {
			*(argv[i][2] == 'f' ? &job->force : &job->strict) = true;
			continue;
		}
		if (hs_cli_dir_option(argc, argv, &i, "--dir", &job->dir, &status, "all", usage_all) ||
		    hs_cli_dir_option(argc, argv, &i, "--out-dir", &job->out_dir, &status, "all", usage_all) ||
		    hs_cli_dir_option(argc, argv, &i, "--golden-dir", &job->golden_dir, &status, "all", usage_all) ||
		    hs_cli_dir_option(argc, argv, &i, "--hands-dir", &job->hands_dir, &status, "all", usage_all)) {
			if (status >= 0)
				return status;
			continue;
		}
		return hs_cli_usage_error("all", usage_all, argv[i][0] == '-' ? "unknown option '%s'" : "unexpected argument '%s'",
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
		char *csv = hs_cli_join_csv(dirs[k], name);
		io_ok = csv && output_open(&outs[k], csv);
		if (!io_ok)
			fprintf(stderr, "handspring: %s\n", csv ? outs[k].error : "out of memory");
		free(csv);
	}
	FILE *files[2] = {outs[0].file, outs[1].file};
	if (io_ok)
		hs_cli_run_scenario(s, files, 2, outs[2].file, &job->sel);
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
	hs_cli_add_inputs(s);
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

int hs_cmd_all(int argc, char **argv) {
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
int hs_cmd_golden(int argc, char **argv) {
	all_job job;
	memset(&job, 0, sizeof job);
	job.command = "golden";
	for (int i = 0; i < argc; ++i) {
		bool missing = false;
		if (hs_cli_is_help(argv[i])) {
			fputs(usage_golden, stdout);
			return EXIT_PASS;
		}
		if (hs_cli_option_value(argc, argv, &i, "--golden", &job.golden_given, &missing) ||
		    hs_cli_option_value(argc, argv, &i, "--golden-dir", &job.golden_given, &missing)) {
			if (missing)
				return hs_cli_usage_error("golden", usage_golden, "%s needs a folder", argv[i]);
		} else if (strcmp(argv[i], "--force") == 0 || strcmp(argv[i], "--strict") == 0) {
			*(argv[i][2] == 'f' ? &job.force : &job.strict) = true;
		} else if (argv[i][0] == '-' || job.dir) {
			return hs_cli_usage_error("golden", usage_golden, argv[i][0] == '-' ? "unknown option '%s'" : "unexpected argument '%s'",
			                   argv[i]);
		} else {
			job.dir = argv[i];
		}
	}
	if (!job.dir)
		return hs_cli_usage_error("golden", usage_golden, "%s", "missing the scenario folder DIR");
	char *fallback = job.golden_given ? NULL : hs_golden_default(job.dir);
	job.golden_dir = job.golden_given ? job.golden_given : fallback;
	hs_outsel_init(&job.sel);
	int status = job.golden_dir ? all_run(&job) : EXIT_BAD_INPUT;
	hs_outsel_free(&job.sel);
	free(fallback);
	return status;
}
