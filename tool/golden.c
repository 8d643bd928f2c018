// golden.c — `handspring check DIR [--golden GDIR]` (docs/tool.md): every scenario below DIR
// against its golden trajectory, the way `make check` does the catalog (tests/test_golden.c): the
// trajectory within HS_GOLDEN_TOLERANCE, contact states and rows exactly, every expectation, and a
// second run's per-frame state hashes equal to the first's.
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "golden.h"
#include "golden_dir.h"

const char *const hs_check_usage =
    "usage: handspring check DIR [--golden GDIR]\n"
    "Runs every scenario below DIR (*.yaml, recursively) and compares it with its golden trajectory\n"
    "GDIR/<name>.csv (default: DIR/golden, or for a folder named 'scenarios' the folder 'golden' beside\n"
    "it: where 'handspring golden DIR' writes them), as 'make check' does the catalog:\n"
    "numbers within 1e-12, contact states and rows exactly, every expectation passing, and a second\n"
    "run's state hashes equal to the first's, frame by frame. 'handspring golden DIR' writes them.\n"
    "Exit status: 0 all match, 1 one does not, 2 bad input (a folder or file that cannot be read).\n";

// Runs s to the end: its trajectory into *text, its per-frame hashes into *hashes (frame 0 first).
static long run_one(hs_scenario *s, char **text, size_t *size, uint64_t **hashes) {
	long cap = hs_scenario_frame_count(s) + 1, n = 0;
	*hashes = malloc((size_t)cap * sizeof **hashes);
	FILE *out = text ? open_memstream(text, size) : NULL;
	if (!*hashes || (text && !out)) {
		fprintf(stderr, "handspring check: out of memory\n");
		exit(2);
	}
	hs_world *w = hs_scenario_world(s);
	hs_trajectory_write_header(out);
	hs_trajectory_write_frame(out, s);
	(*hashes)[n++] = hs_world_hash(w);
	while (hs_scenario_step(s) && n < cap) {
		hs_trajectory_write_frame(out, s);
		(*hashes)[n++] = hs_world_hash(w);
	}
	if (out)
		fclose(out);
	return n;
}

// One scenario: true when it matches; why says what does not.
static bool check_one(const char *name, const char *path, const char *gdir, char *why, size_t why_size, bool *bad) {
	hs_error err;
	hs_scenario *s = hs_scenario_load(path, &err);
	if (!s) {
		snprintf(why, why_size, "%s", err.message);
		*bad = true;
		return false;
	}
	char *text = NULL, *report = NULL;
	size_t size = 0, report_size = 0;
	uint64_t *first = NULL, *second = NULL;
	long n = run_one(s, &text, &size, &first);
	FILE *r = open_memstream(&report, &report_size);
	int failed = hs_scenario_check(s, r);
	if (r)
		fclose(r);
	hs_scenario_destroy(s);
	char *golden_path = malloc(strlen(gdir) + strlen(name) + 6);
	sprintf(golden_path, "%s/%s.csv", gdir, name);
	FILE *golden = fopen(golden_path, "r");
	bool same = false;
	if (!golden) {
		snprintf(why, why_size, "%s missing: write it with 'handspring golden'", golden_path);
	} else {
		FILE *now = fmemopen(text, size, "r");
		same = now && hs_trajectory_compare(golden, now, HS_GOLDEN_TOLERANCE, name, why, why_size);
		if (now)
			fclose(now);
		fclose(golden);
	}
	if (same && failed) {
		const char *line = report ? strstr(report, "FAIL") : NULL;
		const char *end = line ? strchr(line, '\n') : NULL;
		snprintf(why, why_size, "%s: %d expectation(s) failed: %.*s", name, failed,
		         line ? (int)(end ? end - line : (long)strlen(line)) : 0, line ? line : "");
		same = false;
	}
	if (same) { // the second run: the same state hashes, frame by frame
		s = hs_scenario_load(path, &err);
		long m = s ? run_one(s, NULL, NULL, &second) : -1;
		if (s)
			hs_scenario_destroy(s);
		for (long f = 0; same && f < n; ++f)
			if (m != n || second[f] != first[f]) {
				snprintf(why, why_size, "%s: frame %ld: the second run's state hash differs from the first's", name, f);
				same = false;
			}
	}
	free(golden_path);
	free(text);
	free(report);
	free(first);
	free(second);
	return same;
}

int hs_check_main(int argc, char **argv) {
	const char *dir = NULL, *gdir = NULL;
	for (int i = 0; i < argc; ++i) {
		if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
			fputs(hs_check_usage, stdout);
			return 0;
		}
		if (strcmp(argv[i], "--golden") == 0 || strcmp(argv[i], "--golden-dir") == 0) {
			if (i + 1 >= argc) {
				fprintf(stderr, "handspring check: --golden needs a folder\n%s", hs_check_usage);
				return 2;
			}
			gdir = argv[++i];
		} else if (argv[i][0] == '-' || dir) {
			fprintf(stderr, "handspring check: %s '%s'\n%s", argv[i][0] == '-' ? "unknown option" : "unexpected argument",
			        argv[i], hs_check_usage);
			return 2;
		} else {
			dir = argv[i];
		}
	}
	if (!dir) {
		fprintf(stderr, "handspring check: missing the scenario folder DIR\n%s", hs_check_usage);
		return 2;
	}
	char *beside = gdir ? NULL : hs_golden_default(dir);
	if (!gdir)
		gdir = beside;
	hs_catalog catalog;
	hs_error err;
	if (!hs_catalog_load(dir, &catalog, &err)) {
		fprintf(stderr, "%s\n", err.message);
		free(beside);
		return 2;
	}
	if (catalog.count == 0) {
		fprintf(stderr, "%s: no scenario files (*.yaml)\n", dir);
		hs_catalog_free(&catalog);
		free(beside);
		return 2;
	}
	int passed = 0, failed = 0, bad = 0;
	for (int i = 0; i < catalog.count; ++i) {
		char why[2048] = "";
		bool is_bad = false;
		if (check_one(catalog.names[i], catalog.paths[i], gdir, why, sizeof why, &is_bad)) {
			printf("%-40s  PASS\n", catalog.names[i]);
			passed++;
		} else {
			printf("%-40s  %s\n  %s\n", catalog.names[i], is_bad ? "BAD INPUT" : "FAIL", why);
			if (is_bad)
				bad++;
			else
				failed++;
		}
	}
	printf("\n%d scenarios against %s/: %d match, %d differ", catalog.count, gdir, passed, failed);
	if (bad)
		printf(", %d bad input", bad);
	printf("\n");
	hs_catalog_free(&catalog);
	free(beside);
	return bad ? 2 : failed ? 1 : 0;
}
