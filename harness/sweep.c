// sweep.c — a scenario's robustness matrix, run in-process: the nominal run judged on every
// clause, then each frame time of the `robust` block × noise seeds 1..seeds judged on the clauses
// marked `robust: true` (exact closed-form clauses hold only at the nominal dt and without noise).
// Each cell is a fresh load of the file with the overrides: nothing carries from one cell to the next.
// With `phases: true`, seed k also shifts the input scripts by (k - 1) / seeds of a frame
// (hs_scenario_options.phase), so no outcome may hang on where the frames fall relative to a stroke.
#include <string.h>

#include "expect.h"
#include "scenario_internal.h"

// One run to its end: "ok", "L<line>" of the first failing clause, or "fault" (the world failed to
// step or caught a non-finite value); false when the run passed.
static bool run_cell(hs_scenario *s, bool robust_only, char cell[24]) {
	while (hs_scenario_step(s)) {
	}
	unsigned long line = hs_expect_first_failure(s, robust_only);
	if (s->step_status != HS_OK || hs_scenario_faults(s) > 0)
		snprintf(cell, 24, "fault");
	else if (line > 0)
		snprintf(cell, 24, "L%lu", line);
	else
		snprintf(cell, 24, "ok");
	return strcmp(cell, "ok") != 0;
}

// The header: what is swept and how much noise the cells draw.
static void print_header(FILE *out, const hs_scenario *s, const hs_robust *r) {
	const hs_noise_options *n = &r->levels;
	fprintf(out, "sweep %s: %d dt x %d seeds", s->name, r->dt_count, r->seeds);
	if (r->phases)
		fprintf(out, " (seed k: the scripts (k - 1)/%d of a frame late)", r->seeds);
	if (s->springs)
		fprintf(out, ", stylus noise (0.03 inch, 0.15 deg RMS)\n");
	else if (s->hands.count == 0)
		fprintf(out, ", no hand or stylus input to add noise to\n");
	else if (r->has_levels) {
		fprintf(out, ", glove +-%d units, wrist +-%g mm, +-%g deg", n->glove_units, n->wrist * 1e3,
		        n->wrist_rotation * (180.0 / HS_PI));
		if (n->joint > 0.0)
			fprintf(out, ", joints +-%g mm", n->joint * 1e3);
		fprintf(out, "\n");
	} else
		fprintf(out, ", the scenario's input noise or the paper's (glove +-4 units, wrist +-0.762 mm, +-0.15 deg)\n");
	fprintf(out, "%-10s", "dt");
	for (int k = 1; k <= r->seeds; ++k)
		fprintf(out, " %6d", k);
	fprintf(out, "\n");
}

// One row: every seed at one frame time. Returns the cells that pass; -1 when a cell fails to load.
static int sweep_row(const char *path, const hs_robust *r, int row, FILE *out, hs_error *err) {
	int pass = 0;
	fprintf(out, "%-10s", r->dt_text[row]);
	for (int k = 1; k <= r->seeds; ++k) {
		// with `phases`, seed k runs the scripts (k - 1) / seeds of a frame late: each row sees as many
		// phases as seeds
		hs_scenario_options o = {.dt = r->dts[row], .noise = true, .noise_seed = (unsigned long)k,
		                         .phase = r->phases ? (double)(k - 1) / r->seeds : 0.0};
		hs_scenario *cell = hs_scenario_load_with(path, &o, err);
		if (!cell) {
			fprintf(out, "\n");
			return -1;
		}
		char text[24];
		pass += !run_cell(cell, true, text);
		fprintf(out, " %6s", text);
		hs_scenario_destroy(cell);
	}
	fprintf(out, "\n");
	fflush(out);
	return pass;
}

int hs_scenario_sweep(const char *path, FILE *out, hs_error *err) {
	hs_scenario *s = hs_scenario_load(path, err);
	if (!s)
		return 2;
	hs_robust r = s->robust;
	if (!r.given) {
		snprintf(err->message, sizeof err->message, "%s: no 'robust' block: nothing to sweep", path);
		hs_scenario_destroy(s);
		return 2;
	}
	print_header(out, s, &r);
	char nominal[24];
	bool nominal_failed = run_cell(s, false, nominal);
	hs_scenario_destroy(s);
	int pass = 0, cells = r.dt_count * r.seeds;
	for (int i = 0; i < r.dt_count; ++i) {
		int row = sweep_row(path, &r, i, out, err);
		if (row < 0)
			return 2;
		pass += row;
	}
	fprintf(out, "nominal (the file's dt, every clause): %s\n", nominal);
	fprintf(out, "sweep: %d of %d cells pass\n", pass, cells);
	return pass == cells && !nominal_failed ? 0 : 1;
}
