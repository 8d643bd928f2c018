// trajectory.c — trajectories as CSV (one row per object per frame) and their comparison with
// a golden file. Only the public API is used: a trajectory is what any caller could write.
#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "hs_harness.h"

#define TRAJECTORY_HEADER "frame,t,object,x,y,z,qw,qx,qy,qz,contact,floor,resting,hash"

enum {
	FIELD_COUNT = 14,
	F_FRAME = 0,
	F_T = 1,
	F_OBJECT = 2,
	F_CONTACT = 10,
	F_FLOOR = 11,
	F_RESTING = 12,
	F_HASH = 13
};

static const char *const field_names[FIELD_COUNT] = {"frame", "t",  "object",  "x",     "y",       "z",   "qw",
                                                     "qx",    "qy", "qz",      "contact", "floor", "resting", "hash"};

void hs_trajectory_write_header(FILE *out) {
	if (out)
		fputs(TRAJECTORY_HEADER "\n", out);
}

void hs_trajectory_write_frame(FILE *out, hs_scenario *scenario) { hs_trajectory_write_selected(out, scenario, NULL); }

void hs_trajectory_write_selected(FILE *out, hs_scenario *scenario, const uint8_t *selected) {
	hs_world *world = hs_scenario_world(scenario);
	if (!out || !world)
		return;
	long frame = hs_world_frame(world);
	double t = (double)frame * hs_world_dt(world);
	uint64_t hash = hs_world_hash(world);
	int n = hs_world_object_count(world);
	for (int i = 0; i < n; ++i) {
		if (selected && !selected[i])
			continue;
		hs_object_state st;
		memset(&st, 0, sizeof st);
		hs_world_object_state(world, hs_world_object_at(world, i), &st);
		const char *name = hs_scenario_object_name(scenario, i);
		// 17 significant digits: every double reads back to the same bits
		fprintf(out, "%ld,%.17g,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d,%d,%016" PRIx64 "\n", frame, t,
		        name ? name : "?", st.position.x, st.position.y, st.position.z, st.orientation.w, st.orientation.x,
		        st.orientation.y, st.orientation.z, (int)st.contact, st.floor_contacts, st.resting ? 1 : 0, hash);
	}
}

// One side of the comparison: a file read row by row, '#' comments and blank lines skipped.
typedef struct reader {
	FILE *file;
	const char *side; // "golden" or "now"
	char *line;
	size_t capacity;
	long line_number;
	long rows;
	long frames;      // distinct frames seen so far (a new frame starts when the frame field changes)
	char last_frame[32];
	char *field[FIELD_COUNT];
} reader;

// Next data line into r->line without its line end; false at the end of the file.
static bool next_line(reader *r) {
	for (;;) {
		ssize_t n = getline(&r->line, &r->capacity, r->file);
		if (n < 0)
			return false;
		r->line_number++;
		while (n > 0 && (r->line[n - 1] == '\n' || r->line[n - 1] == '\r'))
			r->line[--n] = '\0';
		if (n > 0 && r->line[0] != '#')
			return true;
	}
}

static void count_frame(reader *r) {
	r->rows++;
	if (r->frames == 0 || strcmp(r->field[F_FRAME], r->last_frame) != 0) {
		r->frames++;
		snprintf(r->last_frame, sizeof r->last_frame, "%s", r->field[F_FRAME]);
	}
}

// Splits the current line into FIELD_COUNT fields; the count found when it is not that.
static int split(reader *r) {
	int n = 0;
	char *p = r->line;
	for (;;) {
		char *comma = strchr(p, ',');
		if (n < FIELD_COUNT)
			r->field[n] = p;
		n++;
		if (!comma)
			break;
		*comma = '\0';
		p = comma + 1;
	}
	return n;
}

static bool parse_double(const char *s, double *out) {
	char *end;
	if (!*s)
		return false;
	*out = strtod(s, &end);
	return *end == '\0';
}

typedef struct comparison {
	const char *label;
	char *why;
	size_t why_size;
} comparison;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static bool mismatch(const comparison *c, const char *fmt, ...) {
	if (c->why && c->why_size > 0) {
		int n = snprintf(c->why, c->why_size, "%s: ", c->label);
		if (n >= 0 && (size_t)n < c->why_size) {
			va_list ap;
			va_start(ap, fmt);
			vsnprintf(c->why + n, c->why_size - (size_t)n, fmt, ap);
			va_end(ap);
		}
	}
	return false;
}

// Reads the rest of a file only to count its frames.
static bool count_rest(const comparison *c, reader *r) {
	while (next_line(r)) {
		int n = split(r);
		if (n != FIELD_COUNT)
			return mismatch(c, "%s line %ld: expected %d fields, got %d", r->side, r->line_number, FIELD_COUNT, n);
		count_frame(r);
	}
	return true;
}

static bool same_number(double g, double n, double tolerance) {
	if (g == n || (isnan(g) && isnan(n)))
		return true;
	return fabs(n - g) <= tolerance; // false for NaN against a number, and for infinities of either sign
}

static bool compare_rows(const comparison *c, reader *g, reader *n, double tolerance) {
	for (int i = 0; i < FIELD_COUNT; ++i) {
		if (i == F_HASH) // the hash catches any bit change; the tolerance exists for libm differences
			continue;
		const char *a = g->field[i], *b = n->field[i];
		bool exact = i == F_FRAME || i == F_OBJECT || i == F_CONTACT || i == F_FLOOR || i == F_RESTING;
		double x = 0.0, y = 0.0;
		bool numeric = i != F_OBJECT;
		if (numeric && !parse_double(a, &x))
			return mismatch(c, "golden line %ld: field %s is not a number: '%s'", g->line_number, field_names[i], a);
		if (numeric && !parse_double(b, &y))
			return mismatch(c, "now line %ld: field %s is not a number: '%s'", n->line_number, field_names[i], b);
		bool same = exact ? strcmp(a, b) == 0 : same_number(x, y, tolerance);
		if (same)
			continue;
		if (!numeric)
			return mismatch(c, "frame %s, object %s, field %s: golden %s, now %s", g->field[F_FRAME],
			                g->field[F_OBJECT], field_names[i], a, b);
		return mismatch(c, "frame %s, object %s, field %s: golden %s, now %s (difference %.3g)", g->field[F_FRAME],
		                g->field[F_OBJECT], field_names[i], a, b, y - x);
	}
	return true;
}

bool hs_trajectory_compare(FILE *golden, FILE *actual, double tolerance, const char *label, char *why,
                           size_t why_size) {
	comparison c = {label ? label : "trajectory", why, why_size};
	if (why && why_size > 0)
		why[0] = '\0';
	if (!golden || !actual)
		return mismatch(&c, "no %s file to compare", golden ? "current" : "golden");
	if (!(tolerance >= 0.0))
		return mismatch(&c, "tolerance must be >= 0");
	reader g = {.file = golden, .side = "golden"}, n = {.file = actual, .side = "now"};
	bool ok = true;
	bool has_g = next_line(&g), has_n = next_line(&n);
	if (!has_g || !has_n) {
		ok = has_g == has_n ? mismatch(&c, "both files are empty")
		                    : mismatch(&c, "%s file is empty (no header)", has_g ? "now" : "golden");
	} else if (strcmp(g.line, TRAJECTORY_HEADER) != 0) {
		ok = mismatch(&c, "golden line %ld: header is not '%s'", g.line_number, TRAJECTORY_HEADER);
	} else if (strcmp(n.line, TRAJECTORY_HEADER) != 0) {
		ok = mismatch(&c, "now line %ld: header is not '%s'", n.line_number, TRAJECTORY_HEADER);
	}
	while (ok) {
		has_g = next_line(&g);
		has_n = next_line(&n);
		int fg = has_g ? split(&g) : FIELD_COUNT, fn = has_n ? split(&n) : FIELD_COUNT;
		if (fg != FIELD_COUNT)
			ok = mismatch(&c, "golden line %ld: expected %d fields, got %d", g.line_number, FIELD_COUNT, fg);
		else if (fn != FIELD_COUNT)
			ok = mismatch(&c, "now line %ld: expected %d fields, got %d", n.line_number, FIELD_COUNT, fn);
		if (!ok || (!has_g && !has_n))
			break;
		if (has_g)
			count_frame(&g);
		if (has_n)
			count_frame(&n);
		if (has_g && has_n) {
			ok = compare_rows(&c, &g, &n, tolerance);
			continue;
		}
		// one file ended: count the other's frames for the message
		ok = count_rest(&c, has_g ? &g : &n);
		if (ok && g.frames != n.frames)
			ok = mismatch(&c, "golden has %ld frames, now %ld", g.frames, n.frames);
		else if (ok)
			ok = mismatch(&c, "golden has %ld rows, now %ld", g.rows, n.rows);
	}
	free(g.line);
	free(n.line);
	return ok;
}
