// cli.c — what the tool's commands share: usage errors, options, the trajectory written while a
// scenario runs (cli.h).
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "output.h"

int hs_cli_usage_error(const char *command, const char *usage, const char *fmt, const char *arg) {
	fprintf(stderr, "handspring%s%s: ", command ? " " : "", command ? command : "");
	fprintf(stderr, fmt, arg);
	fprintf(stderr, "\n%s", usage);
	return EXIT_BAD_INPUT;
}

bool hs_cli_is_help(const char *arg) { return strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0; }

// "--name VALUE" or "--name=VALUE" at argv[*i]; advances *i past the value.
bool hs_cli_option_value(int argc, char **argv, int *i, const char *name, const char **value, bool *missing) {
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

char *hs_cli_join_csv(const char *dir, const char *name) {
	size_t n = strlen(dir) + strlen(name) + 6;
	char *r = malloc(n);
	if (r)
		snprintf(r, n, "%s/%s.csv", dir, name);
	return r;
}

// Runs every frame, writing the trajectory to each open file.
// Runs a scenario writing its trajectory to outs[k] (the first one, and `hands`, through `sel`;
// the others whole: goldens).
void hs_cli_run_scenario(hs_scenario *s, FILE **outs, int out_count, FILE *hands, hs_outsel *sel) {
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

bool hs_cli_dir_option(int argc, char **argv, int *i, const char *name, const char **value, int *status,
                             const char *command, const char *usage) {
	bool missing = false;
	if (!hs_cli_option_value(argc, argv, i, name, value, &missing))
		return false;
	if (missing)
		*status = hs_cli_usage_error(command, usage, "%s needs a folder", name);
	return true;
}

void hs_cli_add_inputs(const hs_scenario *s) {
	for (int i = 0; i < hs_scenario_input_count(s); ++i)
		output_input(hs_scenario_input_path(s, i));
}
