// trajectory.c — trajectories as CSV (one row per object per frame) and their comparison with
// a golden file. Writing uses the public API only: a trajectory is what any caller could write.
// Reading is bounded (file_read.h): a row longer than TRAJ_MAX_LINE bytes or a file larger than
// HS_MAX_INPUT_BYTES ends the comparison with a mismatch that says so, so a golden that is
// /dev/zero or an endless stream fails at once.
#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "file_read.h"
#include "hs_harness.h"

#define TRAJECTORY_HEADER "frame,t,object,x,y,z,qw,qx,qy,qz,contact,floor,resting,hash"

// A row: 14 fields, an object name of at most 64 bytes and 13 numbers of at most 25 characters
// fit many times over.
#define TRAJ_MAX_LINE ((size_t)64 << 10)

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
	hs_line_reader lines; // its file is the caller's: not closed here
	const char *side;     // "golden" or "now"
	char *line;
	long line_number;
	long rows;
	long frames;      // distinct frames seen so far (a new frame starts when the frame field changes)
	char last_frame[32];
	char *field[FIELD_COUNT];
	char failed[96];  // why the file could not be read on (a limit, a read error); empty: it ended
} reader;

static void reader_open(reader *r, FILE *file, const char *side) {
	memset(r, 0, sizeof *r);
	r->side = side;
	hs_line_reader_open(&r->lines, file);
	hs_line_reader_limit(&r->lines, TRAJ_MAX_LINE, HS_MAX_INPUT_BYTES);
}

static void reader_close(reader *r) {
	r->lines.file = NULL; // the caller's
	hs_line_reader_close(&r->lines);
}

// Next data line into r->line without its line end; false at the end of the file or when it
// cannot be read on (r->failed says why).
static bool next_line(reader *r) {
	for (;;) {
		size_t n;
		hs_line_status status = hs_line_next(&r->lines, &r->line, &n);
		if (status == HS_LINE_END)
			return false;
		if (status != HS_LINE_OK) {
			hs_line_status_text(&r->lines, status, r->failed, sizeof r->failed);
			return false;
		}
		r->line_number++;
		while (n > 0 && r->line[n - 1] == '\r')
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

// A side that could not be read on: its next line and why.
static bool unreadable(const comparison *c, const reader *r) {
	return mismatch(c, "%s line %ld: %s", r->side, r->line_number + 1, r->failed);
}

// Reads the rest of a file only to count its frames.
static bool count_rest(const comparison *c, reader *r) {
	while (next_line(r)) {
		int n = split(r);
		if (n != FIELD_COUNT)
			return mismatch(c, "%s line %ld: expected %d fields, got %d", r->side, r->line_number, FIELD_COUNT, n);
		count_frame(r);
	}
	return !r->failed[0] || unreadable(c, r);
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

// The header lines of both sides (read first).
static bool compare_headers(const comparison *c, reader *g, reader *n) {
	bool has_g = next_line(g), has_n = next_line(n);
	if (g->failed[0] || n->failed[0])
		return unreadable(c, g->failed[0] ? g : n);
	if (!has_g || !has_n)
		return has_g == has_n ? mismatch(c, "both files are empty")
		                      : mismatch(c, "%s file is empty (no header)", has_g ? "now" : "golden");
	if (strcmp(g->line, TRAJECTORY_HEADER) != 0)
		return mismatch(c, "golden line %ld: header is not '%s'", g->line_number, TRAJECTORY_HEADER);
	if (strcmp(n->line, TRAJECTORY_HEADER) != 0)
		return mismatch(c, "now line %ld: header is not '%s'", n->line_number, TRAJECTORY_HEADER);
	return true;
}

// The rows after the headers, pair by pair; when one side ends, the other's frames are counted.
static bool compare_bodies(const comparison *c, reader *g, reader *n, double tolerance) {
	for (;;) {
		bool has_g = next_line(g), has_n = next_line(n);
		if (g->failed[0] || n->failed[0])
			return unreadable(c, g->failed[0] ? g : n);
		int fg = has_g ? split(g) : FIELD_COUNT, fn = has_n ? split(n) : FIELD_COUNT;
		if (fg != FIELD_COUNT)
			return mismatch(c, "golden line %ld: expected %d fields, got %d", g->line_number, FIELD_COUNT, fg);
		if (fn != FIELD_COUNT)
			return mismatch(c, "now line %ld: expected %d fields, got %d", n->line_number, FIELD_COUNT, fn);
		if (!has_g && !has_n)
			return true;
		if (has_g)
			count_frame(g);
		if (has_n)
			count_frame(n);
		if (has_g && has_n) {
			if (!compare_rows(c, g, n, tolerance))
				return false;
			continue;
		}
		if (!count_rest(c, has_g ? g : n))
			return false;
		if (g->frames != n->frames)
			return mismatch(c, "golden has %ld frames, now %ld", g->frames, n->frames);
		return mismatch(c, "golden has %ld rows, now %ld", g->rows, n->rows);
	}
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
	reader g, n;
	reader_open(&g, golden, "golden");
	reader_open(&n, actual, "now");
	bool ok = compare_headers(&c, &g, &n) && compare_bodies(&c, &g, &n, tolerance);
	reader_close(&g);
	reader_close(&n);
	return ok;
}
