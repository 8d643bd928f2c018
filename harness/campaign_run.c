// campaign_run.c — one trial of a campaign: its cell's options, its seed and the thrower's draws,
// the run, and its CSV row. A trial's row depends only on the campaign file and its index: the
// seed comes from the file's seed and the trial's index within its cell, so trial k of every cell
// meets the same thrower and the same noise sequence (common random numbers: cells differ by
// their options, not by luck).
#include <math.h>
#include <string.h>

#include "campaign_internal.h"
#include "expect.h"
#include "noise.h"
#include "scenario_internal.h"

// splitmix64's finaliser: a bijection that spreads consecutive indices over all 64 bits.
static uint64_t mix64(uint64_t x) {
	x += 0x9E3779B97F4A7C15ull;
	x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
	x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
	return x ^ (x >> 31);
}

static double cut(double g) {
	return g > HS_CAMPAIGN_TRUNCATE ? HS_CAMPAIGN_TRUNCATE : g < -HS_CAMPAIGN_TRUNCATE ? -HS_CAMPAIGN_TRUNCATE : g;
}

// The thrower's four errors: N(0, 1) each (Box-Muller through the library's own log, cos and sin,
// so the same on every machine), cut at HS_CAMPAIGN_TRUNCATE, times the SDs and the scale.
// With `phase`, a fifth draw, uniform: the script starts that fraction of a frame late.
static void draw_thrower(const hs_thrower_spec *spec, uint64_t seed, double scale, double dt, hs_throw_error *e) {
	double g[4] = {0, 0, 0, 0}, u = 0.0;
	hs_noise *rng = hs_noise_create((unsigned long)(seed >> 32));
	if (rng) { // out of memory: no error drawn (the trial's load then fails on memory too)
		hs_noise_gaussian_pair(rng, &g[0], &g[1]);
		hs_noise_gaussian_pair(rng, &g[2], &g[3]);
		u = spec->phase ? hs_noise_uniform(rng) : 0.0;
		hs_noise_destroy(rng);
	}
	*e = (hs_throw_error){.from = spec->from, .release = spec->release, .delay = u * dt};
	e->timing = spec->timing * scale * cut(g[0]);
	e->speed = spec->speed * scale * cut(g[1]);
	e->azimuth = spec->angle * scale * cut(g[2]);
	e->elevation = spec->angle * scale * cut(g[3]);
}

void hs_trial_prepare(const hs_campaign *c, long index, hs_trial *t) {
	memset(t, 0, sizeof *t);
	t->index = index;
	t->cell = index / c->per_cell;
	t->k = index % c->per_cell;
	long rest = t->cell; // the last axis turns fastest
	for (int a = c->axis_count - 1; a >= 0; --a) {
		t->value[a] = (int)(rest % c->axes[a].count);
		rest /= c->axes[a].count;
	}
	t->seed = mix64(mix64(c->seed) + (uint64_t)t->k);
	hs_scenario_options *o = &t->options;
	o->noise_seed = (unsigned long)(t->seed & 0xFFFFFFFFu);
	o->model_path = c->path;
	o->model_texts = t->models;
	double scale = 1.0;
	for (int a = 0; a < c->axis_count; ++a) {
		const hs_axis *axis = &c->axes[a];
		double v = axis->value[t->value[a]];
		if (axis->kind == HS_AXIS_DT)
			o->dt = v;
		else if (axis->kind == HS_AXIS_NOISE && v > 0.0)
			o->noise = true, o->noise_scale = v;
		else if (axis->kind == HS_AXIS_THROW_SCALE)
			scale = v;
		else if (axis->kind == HS_AXIS_MODEL)
			t->models[o->model_count++] = axis->model[t->value[a]];
		else if (axis->kind == HS_AXIS_SCENARIO)
			t->scenario_index = t->value[a];
	}
	if (c->thrower.given) {
		draw_thrower(&c->thrower, t->seed, scale, o->dt > 0.0 ? o->dt : c->dt[t->scenario_index], &t->error);
		t->error.hand = c->thrower.hand[t->scenario_index];
		o->throw_error = &t->error;
	}
}

// Appends to a text of `size` bytes (truncating; the header fits: 8 axes of 48-byte names).
static void append(char *text, size_t size, const char *part) {
	size_t n = strlen(text);
	snprintf(text + n, size - n, "%s", part);
}

double hs_campaign_trial_frames(const hs_campaign *c, long trial) {
	if (!c || trial < 0 || trial >= c->trials)
		return 0.0;
	hs_trial t;
	hs_trial_prepare(c, trial, &t);
	double dt = t.options.dt > 0.0 ? t.options.dt : c->dt[t.scenario_index];
	return c->duration[t.scenario_index] / dt;
}

void hs_campaign_header(const hs_campaign *c, char *text, size_t size) {
	text[0] = '\0';
	append(text, size, "trial,cell,k,seed");
	for (int a = 0; a < c->axis_count; ++a) {
		append(text, size, ",");
		append(text, size, c->axes[a].name);
	}
	if (c->thrower.given)
		append(text, size, ",timing_ms,speed,azimuth_deg,elevation_deg,delay_ms");
	if (c->target.given)
		append(text, size, ",distance");
	if (hs_campaign_watches_grasp(c))
		append(text, size, ",grasp_lost");
	append(text, size, ",hit,clauses");
}

void hs_campaign_write_header(const hs_campaign *c, FILE *out) {
	char text[HS_CAMPAIGN_HEADER];
	hs_campaign_header(c, text, sizeof text);
	fprintf(out, "%s\n", text);
}

// The row: the trial, its cell's values, the draws, then the outcome.
static void write_row(const hs_campaign *c, const hs_trial *t, double distance, bool lost, bool hit,
                      const char *clauses, FILE *out) {
	fprintf(out, "%ld,%ld,%ld,%llu", t->index, t->cell, t->k, (unsigned long long)t->seed);
	for (int a = 0; a < c->axis_count; ++a) {
		const hs_axis *axis = &c->axes[a];
		if (axis->kind == HS_AXIS_MODEL || axis->kind == HS_AXIS_SCENARIO)
			fprintf(out, ",%s", axis->text[t->value[a]]);
		else
			fprintf(out, ",%.17g", axis->value[t->value[a]]);
	}
	if (c->thrower.given) {
		const hs_throw_error *e = &t->error;
		double deg = 180.0 / HS_PI;
		fprintf(out, ",%.17g,%.17g,%.17g,%.17g,%.17g", e->timing * 1e3, e->speed, e->azimuth * deg,
		        e->elevation * deg, e->delay * 1e3);
	}
	if (c->target.given)
		fprintf(out, ",%.17g", distance);
	if (hs_campaign_watches_grasp(c))
		fprintf(out, ",%d", lost ? 1 : 0);
	fprintf(out, ",%d,%s\n", hit ? 1 : 0, clauses);
}

// Runs the trial to its end; returns whether the thrown object was out of a grasp at a frame of
// the swing before the hand began to open (from `from` to `opens`, both moved by the trial's clock
// phase, the opening also by its timing error): the grasp was lost, or never made, and the thrower
// did not throw it. A thrower's miss is a throw that held to the opening and landed outside.
static bool run_watching_grasp(hs_scenario *s, const hs_campaign *c, const hs_trial *t) {
	bool watch = hs_campaign_watches_grasp(c), lost = false;
	const hs_throw_error *e = &t->error;
	double from = c->thrower.from + e->delay, opens = c->thrower.opens[t->scenario_index] + e->timing + e->delay;
	int object = watch ? c->target.object[t->scenario_index] : 0;
	while (hs_scenario_step(s)) {
		double time = ((double)s->frame - s->phase) * s->dt; // the scripts' clock, as the inputs'
		if (watch && !lost && time >= from - 1e-9 && time < opens - 1e-9)
			lost = hs_scenario_state_of(s, object).contact != HS_CONTACT_GRASP;
	}
	return lost;
}

bool hs_campaign_run_trial(hs_campaign *c, long trial, FILE *out, hs_error *err) {
	if (!c || trial < 0 || trial >= c->trials)
		return hs_set_error(err, c ? c->path : "(null)", 1, "trial %ld is not one of the campaign's 0..%ld", trial,
		                    c ? c->trials - 1 : -1L);
	hs_trial t;
	hs_trial_prepare(c, trial, &t);
	hs_scenario *s = hs_scenario_load_source(&c->source[t.scenario_index], &t.options, err);
	if (!s)
		return false;
	bool lost = run_watching_grasp(s, c, &t);
	char clauses[24] = "fault";
	bool fault = s->step_status != HS_OK || hs_scenario_faults(s) > 0;
	unsigned long line = fault ? 0 : hs_expect_first_failure(s, !c->judge_all);
	if (!fault)
		snprintf(clauses, sizeof clauses, line ? "L%lu" : "ok", line);
	double distance = 0.0;
	bool hit = !fault && line == 0;
	if (c->target.given) { // on the floor: x and y only (sqrt is exact; hypot is libm's)
		hs_vec3 p = hs_scenario_state_of(s, c->target.object[t.scenario_index]).position;
		double dx = p.x - c->target.x, dy = p.y - c->target.y;
		distance = sqrt(dx * dx + dy * dy);
		hit = !fault && distance <= c->target.radius;
	}
	write_row(c, &t, distance, lost, hit, clauses, out);
	hs_scenario_destroy(s);
	return true;
}
