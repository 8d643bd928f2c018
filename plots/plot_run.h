// plot_run.h — what every plot generator starts with: `NAME OUTDIR [SCENARIO]`, the scenario
// loaded and OUTDIR/NAME.csv open for writing. Included by plots/*.c only.
#ifndef HS_PLOT_RUN_H
#define HS_PLOT_RUN_H

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

#endif
