// joint_file.c — reading a joint recording, version 2 of the format (scenarios/README.md,
// "Recorded joint positions"): '#' comments and blank lines anywhere; directives `@frame`,
// `@units`, `@hand`, `@source` before the header; the MediaPipe (21 landmarks) or OpenXR (26
// joints) header, then optionally the columns `tracked` and `confidence`; one sample per line,
// a cell empty or nan when its value is missing. A version 1 file (a header and full rows) is a
// version 2 file that uses none of this, and reads as it always did.
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "file_read.h"
#include "joint_file.h"
#include "number.h"
#include "record.h"

#define MAX_JOINT_ROWS 1000000
#define MEDIAPIPE_COLUMNS (1 + 21 * 3)
#define OPENXR_COLUMNS (1 + 26 * 7)
static const double MAX_POSITION = 1000.0; // m, as for every recorded position
static const char *const WHAT = "recorded joint positions";
static const char *const SHOWN[3] = {"", "t,x0,y0,z0,...,x20,y20,z20 (MediaPipe Hands)",
                                     "t,px0,py0,pz0,qw0,qx0,qy0,qz0,...,qz25 (OpenXR hand joints)"};
// OpenXR joints that are check points: thumb metacarpal, proximal, distal, tip; then per finger
// proximal, intermediate, distal, tip (the fingers' metacarpals, the palm and the wrist are not)
static const int openxr_point[HS_HAND_POINTS] = {2, 3, 4, 5, 7, 8, 9, 10, 12, 13, 14, 15, 17, 18, 19, 20, 22, 23, 24, 25};

// The columns of a file: its format's, then the optional ones.
typedef struct layout {
	hs_joint_format format;
	int columns;             // in all
	int tracked, confidence; // their column (from 0), -1: absent
	char shown[160];         // how messages write the header
} layout;

void hs_joint_header(hs_joint_format format, char *out, size_t size) {
	size_t n = (size_t)snprintf(out, size, "t");
	for (int j = 0; format == HS_JOINTS_MEDIAPIPE && j < 21 && n < size; ++j)
		n += (size_t)snprintf(out + n, size - n, ",x%d,y%d,z%d", j, j, j);
	for (int j = 0; format == HS_JOINTS_OPENXR && j < 26 && n < size; ++j)
		n += (size_t)snprintf(out + n, size - n, ",px%d,py%d,pz%d,qw%d,qx%d,qy%d,qz%d", j, j, j, j, j, j, j);
}

static int clip(size_t n) { return n > 40 ? 40 : (int)n; }

// `@key value`: frame, units and hand once each; source is free text for people.
static bool read_directive(const char *path, long number, const char *line, hs_joint_file *f, hs_error *err) {
	static const char *const keys[4] = {"frame", "units", "hand", "source"}, *const sides[2] = {"right", "left"};
	const char *key = line + 1, *value = key + strcspn(key, " \t");
	size_t k = (size_t)(value - key);
	value += strspn(value, " \t");
	size_t v = strlen(value);
	while (v > 0 && (value[v - 1] == ' ' || value[v - 1] == '\t'))
		--v;
	int which = hs_joint_word(key, k, keys, 4);
	if (which < 0)
		return hs_set_error(err, path, (unsigned long)number,
		                    "unknown directive '@%.*s' (the directives are @frame, @units, @hand and @source)", clip(k),
		                    key);
	if (which == 3)
		return true;
	hs_joint_said *said = which == 0 ? &f->frame : which == 1 ? &f->units : &f->hand;
	if (said->value >= 0)
		return hs_set_error(err, path, (unsigned long)number, "@%s is given twice (line %lu and here)", keys[which],
		                    said->line);
	const char *const *names = which == 0 ? hs_joint_frame_names : which == 1 ? hs_joint_unit_names : sides;
	int index = hs_joint_word(value, v, names, which == 0 ? HS_JOINT_FRAMES : which == 1 ? HS_JOINT_UNIT_COUNT : 2);
	if (index < 0)
		return hs_set_error(err, path, (unsigned long)number, "@%s must be %s, got '%.*s'", keys[which],
		                    which == 0 ? HS_JOINT_FRAME_LIST : which == 1 ? HS_JOINT_UNIT_LIST : "right or left",
		                    clip(v), value);
	said->value = index;
	said->line = (unsigned long)number;
	return true;
}

// The header: a format's columns, then `tracked` and `confidence` in any order, once each.
static bool read_header(const char *path, long number, const char *line, layout *l, hs_error *err) {
	unsigned long at = (unsigned long)number;
	l->format = strncmp(line, "t,x0,", 5) == 0    ? HS_JOINTS_MEDIAPIPE
	            : strncmp(line, "t,px0,", 6) == 0 ? HS_JOINTS_OPENXR
	                                              : HS_JOINTS_NONE;
	if (l->format == HS_JOINTS_NONE)
		return hs_set_error(err, path, at, "the header must be %s or %s, then optionally the columns tracked and confidence",
		                    SHOWN[1], SHOWN[2]);
	char base[4096];
	hs_joint_header(l->format, base, sizeof base);
	size_t n = strlen(base);
	if (strncmp(line, base, n) != 0 || (line[n] != '\0' && line[n] != ','))
		return hs_set_error(err, path, at, "the header must be %s, then optionally the columns tracked and confidence",
		                    SHOWN[l->format]);
	l->columns = l->format == HS_JOINTS_MEDIAPIPE ? MEDIAPIPE_COLUMNS : OPENXR_COLUMNS;
	l->tracked = l->confidence = -1;
	size_t shown = (size_t)snprintf(l->shown, sizeof l->shown, "%s", SHOWN[l->format]);
	for (const char *c = line + n; *c == ',';) {
		size_t k = strcspn(++c, ",");
		int *slot = k == 7 && memcmp(c, "tracked", 7) == 0       ? &l->tracked
		            : k == 10 && memcmp(c, "confidence", 10) == 0 ? &l->confidence
		                                                          : NULL;
		if (!slot || *slot >= 0)
			return hs_set_error(err, path, at,
			                    "after the coordinates the header may name the columns tracked and confidence, once "
			                    "each; got '%.*s'",
			                    clip(k), c);
		*slot = l->columns++;
		shown += (size_t)snprintf(l->shown + shown, sizeof l->shown - shown, ",%.*s", (int)k, c);
		c += k;
	}
	return true;
}

// The scenario's options against the file's directives: one place may say a setting, or both
// the same; the hand's side must be the recording's.
static bool resolve(const char *path, const hs_joint_options *o, bool left, hs_joint_file *f, hs_error *err) {
	static const char *const keys[2] = {"frame", "units"}, *const sides[2] = {"right", "left"};
	const hs_joint_said *in_file[2] = {&f->frame, &f->units}, *in_scenario[2] = {&o->frame, &o->units};
	const char *const *names[2] = {hs_joint_frame_names, hs_joint_unit_names};
	char shown[HS_SHOWN_PATH + 4];
	for (int k = 0; k < 2; ++k)
		if (in_file[k]->value >= 0 && in_scenario[k]->value >= 0 && in_file[k]->value != in_scenario[k]->value)
			return hs_set_error(err, path, in_file[k]->line,
			                    "@%s %s disagrees with the scenario's %s: %s (%s:%lu): say it in one place, or the same "
			                    "in both",
			                    keys[k], names[k][in_file[k]->value], keys[k], names[k][in_scenario[k]->value],
			                    hs_shown_path(o->scenario, shown), in_scenario[k]->line);
	if (f->hand.value >= 0 && (f->hand.value == 1) != left)
		return hs_set_error(err, path, f->hand.line,
		                    "@hand %s, but the scenario's hand '%s' is a %s hand (%s): give it side: %s, or use a "
		                    "recording of its own hand",
		                    sides[f->hand.value], o->hand, sides[left], o->side_given ? "its side" : "right by default",
		                    sides[f->hand.value]);
	int frame = f->frame.value >= 0 ? f->frame.value : o->frame.value;
	int units = f->units.value >= 0 ? f->units.value : o->units.value;
	f->frame_assumed = frame < 0;
	f->units_assumed = units < 0;
	f->place.frame = frame < 0 ? HS_JOINT_Z_UP : (hs_joint_frame)frame;
	f->place.units = units < 0 ? HS_JOINT_M : (hs_joint_units)units;
	f->place.placed = o->placed;
	f->place.origin = o->origin;
	f->place.rot = o->rot;
	return true;
}

// A cell: a number, or missing (empty, nan in any case, with a sign or not: stored as NaN).
static hs_number_kind read_cell(const char *s, size_t n, double *v) {
	size_t sign = (size_t)(n > 0 && (s[0] == '-' || s[0] == '+'));
	if (n == 0 || (n == sign + 3 && (s[sign] | 0x20) == 'n' && (s[sign + 1] | 0x20) == 'a' &&
	                  (s[sign + 2] | 0x20) == 'n')) {
		*v = NAN;
		return HS_NUMBER_OK;
	}
	return hs_parse_number(s, n, v);
}

// One line's cells into v; the time must be there and increase.
static bool read_cells(const char *path, long number, const char *line, const layout *l, const hs_joint_file *f,
                       double *v, hs_error *err) {
	unsigned long at = (unsigned long)number;
	const char *cursor = line;
	for (int k = 0; k < l->columns; ++k) {
		size_t n = strcspn(cursor, ",");
		hs_number_kind kind = read_cell(cursor, n, &v[k]);
		if (kind == HS_NUMBER_NOT_FINITE)
			return hs_set_error(err, path, at, "column %d must be finite (or empty or nan: missing), got %.*s", k + 1,
			                    clip(n), cursor);
		if (kind != HS_NUMBER_OK || (k == 0 && isnan(v[0])))
			return hs_set_error(err, path, at, "expected %d numbers (%s), column %d is %s", l->columns, l->shown, k + 1,
			                    kind == HS_NUMBER_OK ? "missing: every sample needs its time" : "not a number");
		if ((k < l->columns - 1 && cursor[n] != ',') || (k == l->columns - 1 && cursor[n] != '\0'))
			return hs_set_error(err, path, at, "expected %d numbers (%s), got %s", l->columns, l->shown,
			                    k < l->columns - 1 ? "fewer" : "more");
		cursor += n + (cursor[n] == ',');
	}
	if (f->count > 0 && !(v[0] > f->samples[f->count - 1].t))
		return hs_set_error(err, path, at, "time %.17g does not increase (previous sample at %.17g)", v[0],
		                    f->samples[f->count - 1].t);
	return true;
}

// A joint's position (and OpenXR orientation) at column c: all of it or none; positions within
// ±1000 m in the file's units. *given: the position is there.
static bool read_joint(const char *path, unsigned long at, const double *v, int c, bool orientation,
                       hs_joint_units units, int joint, bool *given, hs_error *err) {
	int missing = isnan(v[c]) + isnan(v[c + 1]) + isnan(v[c + 2]);
	if (missing == 1 || missing == 2)
		return hs_set_error(err, path, at, "joint %d (columns %d-%d) has %d of its 3 coordinates missing: give all or none",
		                    joint, c + 1, c + 3, missing);
	for (int k = 0; k < 3 && !missing; ++k)
		if (!(fabs(hs_joint_metres(units, v[c + k])) <= MAX_POSITION))
			return units == HS_JOINT_M
			           ? hs_set_error(err, path, at, "column %d (position) must be within [-1000, 1000] m, got %.17g",
			                          c + k + 1, v[c + k])
			           : hs_set_error(err, path, at, "column %d (position) must be within ±%g %s (1000 m), got %.17g",
			                          c + k + 1, units == HS_JOINT_CM ? 1e5 : 1e6, hs_joint_unit_names[units], v[c + k]);
	*given = missing == 0;
	if (!orientation)
		return true;
	int gone = isnan(v[c + 3]) + isnan(v[c + 4]) + isnan(v[c + 5]) + isnan(v[c + 6]);
	double norm;
	hs_quat q;
	if (gone > 0 && gone < 4)
		return hs_set_error(err, path, at, "joint %d's orientation (columns %d-%d) has %d of 4 values missing: give all or none",
		                    joint, c + 4, c + 7, gone);
	if (gone == 0 && !hs_unit_quat(v + c + 3, &norm, &q))
		return hs_set_error(err, path, at, "orientation in columns %d-%d is not a unit quaternion (norm %.6g)", c + 4,
		                    c + 7, norm);
	return true;
}

// The check point a joint is, or -1: MediaPipe landmark 1 + i, OpenXR joint openxr_point[i].
static int point_of(hs_joint_format format, int joint) {
	if (format == HS_JOINTS_MEDIAPIPE)
		return joint - 1;
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		if (openxr_point[i] == joint)
			return i;
	return -1;
}

// A line's cells as a sample.
static bool take_sample(const char *path, long number, const layout *l, hs_joint_units units, const double *v,
                        hs_joint_sample *s, hs_error *err) {
	unsigned long at = (unsigned long)number;
	bool xr = l->format == HS_JOINTS_OPENXR;
	memset(s, 0, sizeof *s);
	s->t = v[0];
	s->line = number;
	for (int j = 0; j < (xr ? 26 : 21); ++j) {
		bool given = false;
		int c = 1 + (xr ? 7 : 3) * j, i = point_of(l->format, j);
		if (!read_joint(path, at, v, c, xr, units, j, &given, err))
			return false;
		if (i >= 0 && given) {
			s->present |= 1u << i;
			s->points[i] = hs_v3(v[c], v[c + 1], v[c + 2]);
		}
	}
	double tracked = l->tracked >= 0 ? v[l->tracked] : NAN;
	if (!isnan(tracked) && tracked != 0.0 && tracked != 1.0)
		return hs_set_error(err, path, at, "column %d (tracked) must be 0 or 1 (or empty: not said), got %.17g",
		                    l->tracked + 1, tracked);
	s->tracked_cell = (int8_t)(isnan(tracked) ? -1 : tracked == 1.0);
	s->confidence = l->confidence >= 0 ? v[l->confidence] : NAN;
	if (!isnan(s->confidence) && !(s->confidence >= 0.0 && s->confidence <= 1.0))
		return hs_set_error(err, path, at, "column %d (confidence) must be within [0, 1] (or empty: not said), got %.17g",
		                    l->confidence + 1, s->confidence);
	return true;
}

// One sample line, appended to the file's samples.
static bool read_row(const char *path, long number, const char *line, const layout *l, hs_joint_file *f,
                     long *capacity, hs_error *err) {
	double v[HS_RECORD_MAX_COLUMNS];
	if (f->count >= MAX_JOINT_ROWS)
		return hs_set_error(err, path, (unsigned long)number, "more than %d samples", MAX_JOINT_ROWS);
	if (!read_cells(path, number, line, l, f, v, err))
		return false;
	if (f->count == *capacity) { // loading, not stepping: growing here is fine
		long grown = *capacity ? *capacity * 2 : 256;
		hs_joint_sample *more = realloc(f->samples, (size_t)grown * sizeof *more);
		if (!more)
			return hs_set_error(err, path, (unsigned long)number, "out of memory");
		f->samples = more;
		*capacity = grown;
	}
	if (!take_sample(path, number, l, f->place.units, v, &f->samples[f->count], err))
		return false;
	f->count++;
	return true;
}

// One line of the file: a comment or blank, a directive (before the header), the header, a sample.
static bool read_line(const char *path, long number, char *line, size_t len, const hs_joint_options *o, bool left,
                      layout *l, hs_joint_file *f, long *capacity, hs_error *err) {
	if (memchr(line, '\0', len))
		return hs_set_error(err, path, (unsigned long)number, "not a text file (NUL byte)");
	while (len > 0 && line[len - 1] == '\r')
		line[--len] = '\0';
	if (len == 0 || line[0] == '#')
		return true;
	if (line[0] == '@' && f->header_line > 0)
		return hs_set_error(err, path, (unsigned long)number, "a directive must come before the header (line %lu)",
		                    f->header_line);
	if (line[0] == '@')
		return read_directive(path, number, line, f, err);
	if (f->header_line > 0)
		return read_row(path, number, line, l, f, capacity, err);
	f->header_line = (unsigned long)number;
	if (!read_header(path, number, line, l, err))
		return false;
	f->format = l->format;
	return resolve(path, o, left, f, err);
}

bool hs_joint_file_read(const char *path, const hs_joint_options *options, bool left, hs_joint_file *f,
                        hs_error *err) {
	memset(f, 0, sizeof *f);
	f->frame.value = f->units.value = f->hand.value = -1;
	FILE *in = hs_open_input(path);
	if (!in)
		return hs_set_error(err, path, 1, "cannot read %s: %s", WHAT, strerror(errno));
	hs_line_reader reader;
	hs_line_reader_open(&reader, in);
	layout l;
	memset(&l, 0, sizeof l);
	long capacity = 0;
	bool ok = true;
	char *line;
	size_t len;
	hs_line_status status = HS_LINE_END;
	while (ok && (status = hs_line_next(&reader, &line, &len)) == HS_LINE_OK)
		ok = read_line(path, reader.number, line, len, options, left, &l, f, &capacity, err);
	if (ok && status != HS_LINE_END)
		ok = hs_record_reader_failure(status, path, reader.number + 1, WHAT, err);
	else if (ok && f->header_line == 0)
		ok = hs_set_error(err, path, (unsigned long)(reader.number > 0 ? reader.number : 1),
		                  "%s without a header: it must be %s or %s", WHAT, SHOWN[1], SHOWN[2]);
	else if (ok && f->count == 0)
		ok = hs_set_error(err, path, (unsigned long)reader.number, "%s has a header but no samples", WHAT);
	hs_line_reader_close(&reader);
	if (!ok)
		hs_joint_file_free(f);
	return ok;
}

void hs_joint_file_free(hs_joint_file *f) {
	free(f->samples);
	f->samples = NULL;
	f->count = 0;
}

bool hs_joint_file_is_joints(const char *path) {
	FILE *in = hs_open_input(path); // never waits for a FIFO's writer
	if (!in)
		return false;
	hs_line_reader reader;
	hs_line_reader_open(&reader, in);
	bool joints = false;
	char *line;
	size_t len;
	while (hs_line_next(&reader, &line, &len) == HS_LINE_OK) {
		while (len > 0 && line[len - 1] == '\r')
			line[--len] = '\0';
		if (len > 0 && line[0] != '#') {
			joints = line[0] == '@' || strncmp(line, "t,x0,", 5) == 0 || strncmp(line, "t,px0,", 6) == 0;
			break;
		}
	}
	hs_line_reader_close(&reader);
	return joints;
}
