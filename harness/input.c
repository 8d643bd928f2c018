// input.c — hand input scripts (keyframes or a recorded glove+tracker file) sampled per frame.
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "harness_internal.h"

static const long MAX_RECORD_ROWS = 10000000L;

void hs_hand_script_sample(const hs_hand_script *script, double t, hs_vec3 *wrist, hs_quat *rot,
                           uint8_t sensors[HS_GLOVE_SENSORS]) {
	const hs_hand_key *keys = script->keys;
	int n = script->key_count;
	const hs_hand_key *a = &keys[0], *b = &keys[0];
	double u = 0.0;
	if (t >= keys[n - 1].t) {
		a = b = &keys[n - 1];
	} else if (t > keys[0].t) {
		int lo = 0, hi = n - 1; // keys[lo].t <= t < keys[hi].t
		while (hi - lo > 1) {
			int mid = (lo + hi) / 2;
			if (keys[mid].t <= t)
				lo = mid;
			else
				hi = mid;
		}
		a = &keys[lo];
		b = &keys[hi];
		u = (t - a->t) / (b->t - a->t);
	}
	*wrist = hs_lerp(a->wrist, b->wrist, u);
	*rot = u > 0.0 ? hs_quat_slerp(a->rot, b->rot, u) : a->rot;
	for (int i = 0; i < HS_GLOVE_SENSORS; ++i) {
		double v = a->sensors[i] + u * (b->sensors[i] - a->sensors[i]);
		long r = lround(v);
		sensors[i] = (uint8_t)(r < 0 ? 0 : (r > 255 ? 255 : r));
	}
}

const char *hs_shown_path(const char *path, char buf[HS_SHOWN_PATH + 4]) {
	size_t n = strlen(path);
	if (n <= HS_SHOWN_PATH)
		return path;
	memcpy(buf, "...", 3);
	memcpy(buf + 3, path + n - HS_SHOWN_PATH, HS_SHOWN_PATH + 1);
	return buf;
}

static const char *const RECORD_HEADER = "t,x,y,z,qw,qx,qy,qz,s0,s1,s2,s3,s4,s5,s6,s7,s8,s9,s10,s11,s12,s13,s14,s15,s16,s17";

HS_PRINTF(4, 5)
static bool record_error(hs_error *err, const char *path, long line, const char *fmt, ...) {
	char shown[HS_SHOWN_PATH + 4];
	int n = snprintf(err->message, sizeof err->message, "%s:%ld: ", hs_shown_path(path, shown), line);
	va_list ap;
	va_start(ap, fmt);
	if (n >= 0 && (size_t)n < sizeof err->message)
		vsnprintf(err->message + n, sizeof err->message - (size_t)n, fmt, ap);
	va_end(ap);
	return false;
}

void hs_record_rows_free(hs_record_rows *rows) {
	free(rows->values);
	free(rows->lines);
	rows->values = NULL;
	rows->lines = NULL;
	rows->count = 0;
}

// Parses one line's `columns` comma-separated numbers into v.
static bool read_row(const char *line, const char *path, long number, const char *shown, int columns, double *v,
                     hs_error *err) {
	const char *cursor = line;
	for (int k = 0; k < columns; ++k) {
		size_t n = strcspn(cursor, ",");
		hs_number_kind kind = hs_parse_number(cursor, n, &v[k]);
		if (kind == HS_NUMBER_NOT_FINITE)
			return record_error(err, path, number, "column %d must be finite, got %.*s", k + 1, n > 40 ? 40 : (int)n,
			                    cursor);
		if (kind != HS_NUMBER_OK)
			return record_error(err, path, number, "expected %d numbers (%s), column %d is %s", columns, shown, k + 1,
			                    n == 0 ? "empty or missing" : "not a number");
		if ((k < columns - 1 && cursor[n] != ',') || (k == columns - 1 && cursor[n] != '\0'))
			return record_error(err, path, number, "expected %d numbers (%s), got %s", columns, shown,
			                    k < columns - 1 ? "fewer" : "more");
		cursor += n + (cursor[n] == ',');
	}
	return true;
}

bool hs_record_read(const char *path, const char *what, const char *header, const char *shown, int columns,
                    long max_rows, hs_record_rows *rows, hs_error *err) {
	memset(rows, 0, sizeof *rows);
	FILE *in = fopen(path, "rb");
	struct stat st;
	if (in && fstat(fileno(in), &st) == 0 && S_ISDIR(st.st_mode)) { // fopen accepts a directory
		fclose(in);
		in = NULL;
		errno = EISDIR;
	}
	if (!in)
		return record_error(err, path, 1, "cannot read %s: %s", what, strerror(errno));
	char *line = NULL;
	size_t cap = 0;
	long number = 0, capacity = 0;
	bool ok = true;
	ssize_t len;
	double v[64];
	while (ok && (len = getline(&line, &cap, in)) >= 0) {
		++number;
		if ((size_t)len != strlen(line)) {
			ok = record_error(err, path, number, "not a text file (NUL byte)");
			break;
		}
		while (len > 0 && (line[len - 1] == '\n' || line[len - 1] == '\r'))
			line[--len] = '\0';
		if (number == 1) {
			if (strcmp(line, header) != 0)
				ok = record_error(err, path, 1, "the header must be %s", shown);
			continue;
		}
		if (len == 0 || line[0] == '#')
			continue;
		if (rows->count >= max_rows) {
			ok = record_error(err, path, number, "more than %ld samples", max_rows);
			break;
		}
		if (!read_row(line, path, number, shown, columns, v, err)) {
			ok = false;
			break;
		}
		if (rows->count > 0 && !(v[0] > rows->values[(rows->count - 1) * columns])) {
			ok = record_error(err, path, number, "time %.17g does not increase (previous sample at %.17g)", v[0],
			                  rows->values[(rows->count - 1) * columns]);
			break;
		}
		for (int k = 1; ok && k < 4; ++k) // a hand within reach of the table: no overflow downstream
			if (!(fabs(v[k]) <= 1000.0))
				ok = record_error(err, path, number, "column %d (position) must be within [-1000, 1000] m, got %.17g",
				                  k + 1, v[k]);
		double norm = sqrt(v[4] * v[4] + v[5] * v[5] + v[6] * v[6] + v[7] * v[7]);
		if (ok && !(fabs(norm - 1.0) <= 1e-3))
			ok = record_error(err, path, number, "orientation is not a unit quaternion (norm %.6g)", norm);
		if (!ok)
			break;
		if (rows->count == capacity) { // loading, not stepping: growing here is fine
			long grown = capacity ? capacity * 2 : 256;
			double *values = realloc(rows->values, (size_t)grown * (size_t)columns * sizeof *values);
			if (values)
				rows->values = values;
			long *lines = realloc(rows->lines, (size_t)grown * sizeof *lines);
			if (lines)
				rows->lines = lines;
			if (!values || !lines) {
				ok = record_error(err, path, number, "out of memory");
				break;
			}
			capacity = grown;
		}
		memcpy(&rows->values[rows->count * columns], v, (size_t)columns * sizeof *v);
		rows->lines[rows->count++] = number;
	}
	if (ok && ferror(in))
		ok = record_error(err, path, number > 0 ? number : 1, "cannot read %s: read error", what);
	if (ok && number == 0)
		ok = record_error(err, path, 1, "empty %s: the header %s is missing", what, shown);
	else if (ok && rows->count == 0)
		ok = record_error(err, path, number, "%s has a header but no samples", what);
	free(line);
	fclose(in);
	if (!ok)
		hs_record_rows_free(rows);
	return ok;
}

bool hs_record_load(const char *path, hs_hand_script *script, hs_error *err) {
	script->key_count = 0;
	script->keys = NULL;
	hs_record_rows rows;
	if (!hs_record_read(path, "recorded input", RECORD_HEADER, "t,x,y,z,qw,qx,qy,qz,s0,...,s17", 8 + HS_GLOVE_SENSORS,
	                    MAX_RECORD_ROWS, &rows, err))
		return false;
	script->keys = calloc((size_t)rows.count, sizeof *script->keys);
	bool ok = script->keys != NULL || record_error(err, path, 1, "out of memory");
	for (long r = 0; ok && r < rows.count; ++r) {
		const double *v = &rows.values[r * (8 + HS_GLOVE_SENSORS)];
		for (int i = 0; i < HS_GLOVE_SENSORS && ok; ++i)
			if (v[8 + i] < 0 || v[8 + i] > 255 || v[8 + i] != floor(v[8 + i]))
				ok = record_error(err, path, rows.lines[r], "sensor s%d must be an integer from 0 to 255, got %.17g", i,
				                  v[8 + i]);
		if (!ok)
			break;
		hs_hand_key *key = &script->keys[script->key_count++];
		key->t = v[0];
		key->wrist = hs_v3(v[1], v[2], v[3]);
		key->rot = hs_quat_normalize(hs_q(v[4], v[5], v[6], v[7]));
		for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
			key->sensors[i] = v[8 + i];
	}
	hs_record_rows_free(&rows);
	if (!ok) {
		free(script->keys);
		script->keys = NULL;
		script->key_count = 0;
	}
	return ok;
}
