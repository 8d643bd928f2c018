// test_golden.c — every catalog scenario (scenarios/) matches its golden trajectory
// (golden/<name>.csv, within 1e-12) and passes its expectations; then the whole catalog runs a
// second time and every per-frame state hash must be bit-identical to the first run. The second
// run hashes every object afresh each frame, so it also checks the digests the first run kept.
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "test_util.h"
#include "world_internal.h"

#include <stdlib.h>
#include <string.h>

#define CATALOG_DIR "scenarios"
#define GOLDEN_DIR "golden"
#define GOLDEN_TOLERANCE HS_GOLDEN_TOLERANCE

typedef struct scenario_run {
	const char *name, *path;
	uint64_t *hashes; // per frame, from the first run
	long frames;      // hashes recorded (frame 0 included)
} scenario_run;

// Runs a scenario; returns its per-frame hashes (frame 0 first) and, when `out` is not NULL,
// writes the trajectory there. `fresh`: every object's digest is made again for every hash
// instead of kept from the last one (state.c), as if nothing had been hashed before.
static uint64_t *run_scenario(hs_scenario *s, FILE *out, long *count, bool fresh) {
	long capacity = hs_scenario_frame_count(s) + 1;
	uint64_t *hashes = malloc((size_t)capacity * sizeof *hashes);
	assert_non_null(hashes);
	long n = 0;
	hs_world *world = hs_scenario_world(s);
	if (out) {
		hs_trajectory_write_header(out);
		hs_trajectory_write_frame(out, s);
	}
	hashes[n++] = hs_world_hash(world);
	while (hs_scenario_step(s)) {
		assert_true(n < capacity);
		if (fresh)
			hs_digest_all_stale(&world->cache);
		hashes[n++] = hs_world_hash(world);
		if (out)
			hs_trajectory_write_frame(out, s);
	}
	*count = n;
	return hashes;
}

static hs_scenario *load(const scenario_run *run) {
	hs_error err;
	hs_scenario *s = hs_scenario_load(run->path, &err);
	if (!s)
		fail_msg("%s", err.message);
	return s;
}

// First run: golden comparison and expectations.
static void test_golden(void **state) {
	scenario_run *run = *state;
	hs_scenario *s = load(run);
	char *text = NULL;
	size_t size = 0;
	FILE *out = open_memstream(&text, &size);
	assert_non_null(out);
	run->hashes = run_scenario(s, out, &run->frames, false);
	assert_int_equal(fclose(out), 0);

	char *report = NULL;
	size_t report_size = 0;
	FILE *r = open_memstream(&report, &report_size);
	assert_non_null(r);
	int failed = hs_scenario_check(s, r);
	assert_int_equal(fclose(r), 0);
	hs_scenario_destroy(s);

	char golden_path[1024];
	snprintf(golden_path, sizeof golden_path, GOLDEN_DIR "/%s.csv", run->name);
	FILE *golden = fopen(golden_path, "r");
	char why[2048] = "";
	bool same = false;
	if (golden) {
		FILE *now = fmemopen(text, size, "r");
		assert_non_null(now);
		same = hs_trajectory_compare(golden, now, GOLDEN_TOLERANCE, run->name, why, sizeof why);
		fclose(now);
		fclose(golden);
	} else {
		snprintf(why, sizeof why, "%s missing: run make golden", golden_path);
	}
	free(text);
	if (failed)
		print_error("%s: %d expectation(s) failed:\n%s", run->name, failed, report);
	if (!same)
		print_error("%s\n", why);
	free(report);
	assert_true(same);
	assert_int_equal(failed, 0);
}

// Second run, after the whole catalog: the same hashes, frame by frame, to the bit, each made from
// every object afresh (the first run's kept the digests of objects no step had changed).
static void test_determinism(void **state) {
	scenario_run *run = *state;
	if (!run->hashes)
		fail_msg("%s: the first run did not complete", run->name);
	hs_scenario *s = load(run);
	long frames = 0;
	uint64_t *hashes = run_scenario(s, NULL, &frames, true);
	hs_scenario_destroy(s);
	if (frames != run->frames) {
		free(hashes);
		fail_msg("%s: first run had %ld frames, second %ld", run->name, run->frames, frames);
	}
	for (long f = 0; f < frames; ++f) {
		if (hashes[f] != run->hashes[f]) {
			uint64_t a = run->hashes[f], b = hashes[f];
			free(hashes);
			fail_msg("%s: frame %ld: hash %016llx in the first run, %016llx in the second", run->name, f,
			         (unsigned long long)a, (unsigned long long)b);
		}
	}
	free(hashes);
}

// Real input: at the paper's 12 and 17 frames/s with the scenario's realistic noise (seeds 1 and
// 2), every frame's hash from the kept object digests equals the hash made from every object
// afresh (state.c), whatever wakes, touches and releases the noise brings.
static void test_noisy_digests(void **state) {
	const scenario_run *run = *state;
	const double dt[2] = {1.0 / 12.0, 1.0 / 17.0};
	for (int r = 0; r < 2; ++r)
		for (unsigned long seed = 1; seed <= 2; ++seed) {
			hs_scenario_options opt = {.dt = dt[r], .noise = true, .noise_seed = seed};
			hs_error err;
			hs_scenario *s = hs_scenario_load_with(run->path, &opt, &err);
			if (!s)
				fail_msg("%s: %s", run->name, err.message);
			hs_world *world = hs_scenario_world(s);
			long frame = 0;
			do {
				uint64_t kept = hs_world_hash(world);
				hs_digest_all_stale(&world->cache);
				if (hs_world_hash(world) != kept) {
					hs_scenario_destroy(s);
					fail_msg("%s at 1/%.0f s, seed %lu: frame %ld: the kept digests' hash differs from a fresh one",
					         run->name, 1.0 / dt[r], seed, frame);
				}
				frame++;
			} while (hs_scenario_step(s));
			hs_scenario_destroy(s);
		}
}

static void test_empty_catalog(void **state) {
	(void)state;
	fail_msg(CATALOG_DIR "/ holds no scenario files: nothing would be checked");
}

int main(void) {
	hs_catalog catalog;
	hs_error err;
	if (!hs_catalog_load(CATALOG_DIR, &catalog, &err)) {
		fprintf(stderr, "test_golden: %s (run from the top folder)\n", err.message);
		return 1;
	}
	if (catalog.count == 0) {
		const struct CMUnitTest empty[] = {cmocka_unit_test(test_empty_catalog)};
		return cmocka_run_group_tests_name("golden", empty, NULL, NULL);
	}
	size_t n = (size_t)catalog.count;
	scenario_run *runs = calloc(n, sizeof *runs);
	struct CMUnitTest *tests = calloc(3 * n, sizeof *tests);
	char **names = calloc(3 * n, sizeof *names);
	for (size_t i = 0; i < n; ++i) {
		runs[i].name = catalog.names[i];
		runs[i].path = catalog.paths[i];
		static const char *const group[3] = {"golden", "determinism", "noisy digests"};
		static void (*const test[3])(void **) = {test_golden, test_determinism, test_noisy_digests};
		for (size_t k = 0; k < 3; ++k) {
			size_t t = k * n + i; // all first runs, then all second runs, then the noisy ones
			names[t] = malloc(strlen(catalog.names[i]) + 20);
			sprintf(names[t], "%s %s", group[k], catalog.names[i]);
			tests[t].name = names[t];
			tests[t].test_func = test[k];
			tests[t].initial_state = &runs[i];
		}
	}
	int failed = _cmocka_run_group_tests("golden", tests, 3 * n, NULL, NULL);
	for (size_t i = 0; i < n; ++i)
		free(runs[i].hashes);
	for (size_t t = 0; t < 3 * n; ++t)
		free(names[t]);
	free(names);
	free(tests);
	free(runs);
	hs_catalog_free(&catalog);
	return failed;
}
