// outsel.c — what `run` and `all` write of a run: objects, frames, progress (outsel.h).
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "outsel.h"

static double now(void) {
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void hs_outsel_init(hs_outsel *sel) {
	memset(sel, 0, sizeof *sel);
	sel->every = 1;
	sel->to = -1.0;
	sel->started = now();
	sel->progress = isatty(2) != 0;
}

static bool number(const char *text, double *out) {
	char *end;
	*out = strtod(text, &end);
	return *text && !*end && isfinite(*out);
}

bool hs_outsel_option(hs_outsel *sel, int argc, char **argv, int *i, char *error, size_t error_size) {
	const char *a = argv[*i];
	if (strcmp(a, "--objects") != 0 && strcmp(a, "--every") != 0 && strcmp(a, "--from") != 0 && strcmp(a, "--to") != 0)
		return false;
	error[0] = '\0';
	if (*i + 1 >= argc) {
		snprintf(error, error_size, "%s needs a value", a);
		return true;
	}
	const char *v = argv[++*i];
	double x;
	if (strcmp(a, "--objects") == 0) {
		if (!*v || v[0] == ',' || v[strlen(v) - 1] == ',' || strstr(v, ",,"))
			snprintf(error, error_size, "--objects needs object names, comma-separated, got '%s'", v);
		sel->objects = v;
	} else if (strcmp(a, "--every") == 0) {
		char *end;
		long n = strtol(v, &end, 10);
		if (!*v || *end || n < 1 || n > 1000000000L)
			snprintf(error, error_size, "--every needs a whole number of frames within [1, 1000000000], got '%s'", v);
		sel->every = n;
	} else if (!number(v, &x) || x < 0.0) {
		snprintf(error, error_size, "%s needs a time in s, >= 0, got '%s'", a, v);
	} else if (strcmp(a, "--from") == 0) {
		sel->from = x;
	} else {
		sel->to = x;
	}
	return true;
}

bool hs_outsel_bind(hs_outsel *sel, hs_scenario *scenario, bool lenient, char *error, size_t error_size) {
	int n = hs_scenario_object_count(scenario);
	double dt = hs_scenario_dt(scenario);
	sel->from_frame = (long)ceil(sel->from / dt - 1e-9);
	sel->to_frame = sel->to < 0.0 ? hs_scenario_frame_count(scenario) : (long)floor(sel->to / dt + 1e-9);
	if (sel->to >= 0.0 && sel->to < sel->from) {
		snprintf(error, error_size, "--to (%g s) is before --from (%g s)", sel->to, sel->from);
		return false;
	}
	free(sel->selected);
	sel->selected = NULL;
	if (!sel->objects)
		return true;
	sel->selected = calloc((size_t)n + 1, 1);
	if (!sel->selected) {
		snprintf(error, error_size, "out of memory");
		return false;
	}
	for (const char *p = sel->objects; *p;) {
		const char *end = strchr(p, ',');
		size_t len = end ? (size_t)(end - p) : strlen(p);
		int found = -1;
		for (int i = 0; i < n && found < 0; ++i) {
			const char *name = hs_scenario_object_name(scenario, i);
			if (name && strlen(name) == len && strncmp(name, p, len) == 0)
				found = i;
		}
		if (found < 0 && !lenient) {
			snprintf(error, error_size, "--objects: %s has no object '%.*s'", hs_scenario_name(scenario), (int)len, p);
			return false;
		}
		if (found >= 0)
			sel->selected[found] = 1;
		p = end ? end + 1 : p + len;
	}
	return true;
}

bool hs_outsel_keep(const hs_outsel *sel, long frame) {
	return frame >= sel->from_frame && frame <= sel->to_frame && (frame - sel->from_frame) % sel->every == 0;
}

void hs_outsel_progress(hs_outsel *sel, long frame, long frames) {
	if (!sel->progress)
		return;
	double t = now(), run = t - sel->started;
	if (frame >= frames) {
		if (sel->shown > 0.0)
			fprintf(stderr, "\rhandspring: frame %ld of %ld, %.1f s%20s\n", frame, frames, run, "");
		return;
	}
	if (run < 1.0 || t - sel->shown < 0.5 || frame <= 0)
		return;
	sel->shown = t;
	double left = run / (double)frame * (double)(frames - frame);
	fprintf(stderr, "\rhandspring: frame %ld of %ld (%.0f%%), about %.0f s left   ", frame, frames,
	        100.0 * (double)frame / (double)frames, left);
	fflush(stderr);
}

void hs_outsel_free(hs_outsel *sel) {
	free(sel->selected);
	sel->selected = NULL;
}
