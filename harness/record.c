// record.c — the reader of recorded tracker files (glove and stylus CSV): header, finite numbers,
// increasing time, bounded position, unit quaternion. Each caller checks its own columns.
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "file_read.h"
#include "number.h"
#include "record.h"

static const double MAX_RECORD_POSITION = 1000.0; // m: a hand within reach of the table, no overflow downstream

void hs_record_rows_free(hs_record_rows *rows) {
	free(rows->values);
	free(rows->lines);
	rows->values = NULL;
	rows->lines = NULL;
	rows->count = 0;
}

HS_PRINTF(4, 5)
static bool row_error(hs_error *err, const char *path, long line, const char *fmt, ...) {
	va_list ap;
	va_start(ap, fmt);
	hs_vset_error(err, path, (unsigned long)line, fmt, ap);
	va_end(ap);
	return false;
}

// Parses one line's `columns` comma-separated numbers into v.
static bool read_row(const char *line, const char *path, long number, const char *shown, int columns, double *v,
                     hs_error *err) {
	const char *cursor = line;
	for (int k = 0; k < columns; ++k) {
		size_t n = strcspn(cursor, ",");
		hs_number_kind kind = hs_parse_number(cursor, n, &v[k]);
		if (kind == HS_NUMBER_NOT_FINITE)
			return row_error(err, path, number, "column %d must be finite, got %.*s", k + 1, n > 40 ? 40 : (int)n,
			                 cursor);
		if (kind != HS_NUMBER_OK)
			return row_error(err, path, number, "expected %d numbers (%s), column %d is %s", columns, shown, k + 1,
			                 n == 0 ? "empty or missing" : "not a number");
		if ((k < columns - 1 && cursor[n] != ',') || (k == columns - 1 && cursor[n] != '\0'))
			return row_error(err, path, number, "expected %d numbers (%s), got %s", columns, shown,
			                 k < columns - 1 ? "fewer" : "more");
		cursor += n + (cursor[n] == ',');
	}
	return true;
}

// What every recorded row must satisfy: time increasing, and per the layout (record.h) positions
// bounded and quaternions of unit norm.
static bool check_row(const hs_record_rows *rows, int columns, const char *layout, const double *v, const char *path,
                      long number, hs_error *err) {
	if (rows->count > 0 && !(v[0] > rows->values[(rows->count - 1) * columns]))
		return row_error(err, path, number, "time %.17g does not increase (previous sample at %.17g)", v[0],
		                 rows->values[(rows->count - 1) * columns]);
	for (int k = 1; k < columns; ++k) {
		char kind = layout ? layout[k] : (k < 4 ? 'p' : k == 4 ? 'q' : 'n');
		if (kind == 'p' && !(fabs(v[k]) <= MAX_RECORD_POSITION))
			return row_error(err, path, number, "column %d (position) must be within [-1000, 1000] m, got %.17g", k + 1,
			                 v[k]);
		if (kind == 'q') {
			double norm;
			hs_quat q;
			if (!hs_unit_quat(v + k, &norm, &q))
				return layout ? row_error(err, path, number,
				                          "orientation in columns %d-%d is not a unit quaternion (norm %.6g)", k + 1,
				                          k + 4, norm)
				              : row_error(err, path, number, "orientation is not a unit quaternion (norm %.6g)", norm);
			k += 3;
		}
	}
	return true;
}

// Appends a row; loading, not stepping: growing here is fine.
static bool append_row(hs_record_rows *rows, long *capacity, int columns, const double *v, long number) {
	if (rows->count == *capacity) {
		long grown = *capacity ? *capacity * 2 : 256;
		double *values = realloc(rows->values, (size_t)grown * (size_t)columns * sizeof *values);
		if (values)
			rows->values = values;
		long *lines = realloc(rows->lines, (size_t)grown * sizeof *lines);
		if (lines)
			rows->lines = lines;
		if (!values || !lines)
			return false;
		*capacity = grown;
	}
	memcpy(&rows->values[rows->count * columns], v, (size_t)columns * sizeof *v);
	rows->lines[rows->count++] = number;
	return true;
}

bool hs_record_reader_failure(hs_line_status status, const char *path, long line, const char *what, hs_error *err) {
	switch (status) {
	case HS_LINE_TOO_LONG:
		return row_error(err, path, line, "line longer than %zu MiB (the limit for %s)", HS_MAX_LINE_BYTES >> 20, what);
	case HS_LINE_TOO_BIG:
		return row_error(err, path, line, "file larger than %zu MiB (the limit for %s)", HS_MAX_INPUT_BYTES >> 20, what);
	case HS_LINE_NO_MEMORY:
		return row_error(err, path, line, "out of memory");
	default:
		return row_error(err, path, line, "cannot read %s: read error", what);
	}
}

bool hs_record_read(const char *path, const char *what, const char *header, const char *shown, int columns,
                    long max_rows, hs_record_rows *rows, hs_error *err) {
	return hs_record_read_layout(path, what, header, shown, columns, NULL, max_rows, rows, err);
}

bool hs_record_read_layout(const char *path, const char *what, const char *header, const char *shown, int columns,
                           const char *layout, long max_rows, hs_record_rows *rows, hs_error *err) {
	memset(rows, 0, sizeof *rows);
	if (columns < 1 || columns > HS_RECORD_MAX_COLUMNS)
		return row_error(err, path, 1, "internal: %d columns", columns);
	FILE *in = hs_open_input(path);
	if (!in)
		return row_error(err, path, 1, "cannot read %s: %s", what, strerror(errno));
	hs_line_reader reader;
	hs_line_reader_open(&reader, in);
	long capacity = 0;
	bool ok = true;
	char *line;
	size_t len;
	double v[HS_RECORD_MAX_COLUMNS];
	hs_line_status status = HS_LINE_END;
	bool header_seen = false;
	while (ok && (status = hs_line_next(&reader, &line, &len)) == HS_LINE_OK) {
		long number = reader.number;
		if (memchr(line, '\0', len)) {
			ok = row_error(err, path, number, "not a text file (NUL byte)");
			break;
		}
		while (len > 0 && line[len - 1] == '\r')
			line[--len] = '\0';
		if (len == 0 || line[0] == '#') // blank lines and comments, before the header too
			continue;
		if (!header_seen) {
			header_seen = true;
			if (line[0] == '@')
				ok = row_error(err, path, number, "'@' directives are for joint recordings; the header must be %s",
				               shown);
			else if (strcmp(line, header) != 0)
				ok = row_error(err, path, number, "the header must be %s", shown);
			continue;
		}
		if (rows->count >= max_rows)
			ok = row_error(err, path, number, "more than %ld samples", max_rows);
		else if (read_row(line, path, number, shown, columns, v, err) &&
		         check_row(rows, columns, layout, v, path, number, err))
			ok = append_row(rows, &capacity, columns, v, number) || row_error(err, path, number, "out of memory");
		else
			ok = false;
	}
	if (ok && status != HS_LINE_END)
		ok = hs_record_reader_failure(status, path, reader.number + 1, what, err);
	if (ok && reader.number == 0)
		ok = row_error(err, path, 1, "empty %s: the header %s is missing", what, shown);
	else if (ok && !header_seen)
		ok = row_error(err, path, reader.number, "%s has only comments and blank lines: the header %s is missing", what,
		               shown);
	else if (ok && rows->count == 0)
		ok = row_error(err, path, reader.number, "%s has a header but no samples", what);
	hs_line_reader_close(&reader);
	if (!ok)
		hs_record_rows_free(rows);
	return ok;
}
