// input.c — hand input scripts (keyframes or a recorded glove+tracker file) sampled per frame.
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "internal.h"

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

static bool record_error(hs_error *err, const char *path, long line, const char *what) {
	char shown[HS_SHOWN_PATH + 4];
	snprintf(err->message, sizeof err->message, "%s:%ld: %s", hs_shown_path(path, shown), line, what);
	return false;
}

static const char *const RECORD_HEADER = "t,x,y,z,qw,qx,qy,qz,s0,s1,s2,s3,s4,s5,s6,s7,s8,s9,s10,s11,s12,s13,s14,s15,s16,s17";

// One CSV field as a finite number; `end` is where it stopped.
static bool read_field(const char **cursor, double *out) {
	const char *s = *cursor;
	if (*s == ',' || *s == '\0' || *s == ' ' || *s == '\t')
		return false;
	char *end = NULL;
	errno = 0;
	double v = strtod(s, &end);
	if (end == s || errno == ERANGE || !isfinite(v))
		return false;
	if (*end != ',' && *end != '\0')
		return false;
	*out = v;
	*cursor = *end == ',' ? end + 1 : end;
	return true;
}

bool hs_record_load(const char *path, const char *shown_path, hs_hand_script *script, hs_error *err) {
	script->key_count = 0;
	script->keys = NULL;
	FILE *in = fopen(path, "rb");
	struct stat st;
	if (in && fstat(fileno(in), &st) == 0 && S_ISDIR(st.st_mode)) { // fopen accepts a directory
		fclose(in);
		in = NULL;
		errno = EISDIR;
	}
	if (!in) {
		char what[256];
		snprintf(what, sizeof what, "cannot read recorded input: %s", strerror(errno));
		return record_error(err, shown_path, 1, what);
	}
	char *line = NULL;
	size_t cap = 0;
	long number = 0, capacity = 0;
	bool ok = true;
	ssize_t len;
	while (ok && (len = getline(&line, &cap, in)) >= 0) {
		++number;
		if ((size_t)len != strlen(line)) {
			ok = record_error(err, shown_path, number, "not a text file (NUL byte)");
			break;
		}
		while (len > 0 && (line[len - 1] == '\n' || line[len - 1] == '\r'))
			line[--len] = '\0';
		if (number == 1) {
			if (strcmp(line, RECORD_HEADER) != 0)
				ok = record_error(err, shown_path, 1, "the header must be t,x,y,z,qw,qx,qy,qz,s0,...,s17");
			continue;
		}
		if (len == 0 || line[0] == '#')
			continue;
		if (script->key_count >= MAX_RECORD_ROWS) {
			ok = record_error(err, shown_path, number, "more than 10000000 samples");
			break;
		}
		double v[8 + HS_GLOVE_SENSORS];
		const char *cursor = line;
		int k = 0;
		for (; k < 8 + HS_GLOVE_SENSORS; ++k) {
			if (!read_field(&cursor, &v[k]))
				break;
			if (k < 8 + HS_GLOVE_SENSORS - 1 && cursor[-1] != ',')
				break;
		}
		char what[160];
		if (k < 8 + HS_GLOVE_SENSORS || *cursor != '\0') {
			snprintf(what, sizeof what, "expected 26 finite numbers (t,x,y,z,qw,qx,qy,qz,s0..s17), column %d is not", k + 1);
			ok = record_error(err, shown_path, number, what);
			break;
		}
		if (script->key_count > 0 && !(v[0] > script->keys[script->key_count - 1].t)) {
			snprintf(what, sizeof what, "time %.17g does not increase (previous sample at %.17g)", v[0],
			         script->keys[script->key_count - 1].t);
			ok = record_error(err, shown_path, number, what);
			break;
		}
		for (int c = 1; c <= 3 && ok; ++c)
			if (!(fabs(v[c]) <= 1000.0)) { // what the scenario accepts for a wrist (HS_MAX_COORDINATE is the API's)
				snprintf(what, sizeof what, "column %d (position) must be within [-1000, 1000] m, got %.17g", c + 1, v[c]);
				ok = record_error(err, shown_path, number, what);
			}
		if (!ok)
			break;
		hs_quat q = hs_q(v[4], v[5], v[6], v[7]);
		double norm = sqrt(hs_quat_dot(q, q));
		if (fabs(norm - 1.0) > 1e-3) {
			snprintf(what, sizeof what, "orientation is not a unit quaternion (norm %.6g)", norm);
			ok = record_error(err, shown_path, number, what);
			break;
		}
		for (int i = 0; i < HS_GLOVE_SENSORS && ok; ++i)
			if (v[8 + i] < 0 || v[8 + i] > 255 || v[8 + i] != floor(v[8 + i])) {
				snprintf(what, sizeof what, "sensor s%d must be an integer from 0 to 255, got %.17g", i, v[8 + i]);
				ok = record_error(err, shown_path, number, what);
			}
		if (!ok)
			break;
		if (script->key_count == capacity) { // loading, not stepping: growing here is fine
			long grown = capacity ? capacity * 2 : 256;
			hs_hand_key *keys = realloc(script->keys, (size_t)grown * sizeof *keys);
			if (!keys) {
				ok = record_error(err, shown_path, number, "out of memory");
				break;
			}
			script->keys = keys;
			capacity = grown;
		}
		hs_hand_key *key = &script->keys[script->key_count++];
		key->t = v[0];
		key->wrist = hs_v3(v[1], v[2], v[3]);
		key->rot = hs_quat_normalize(q);
		for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
			key->sensors[i] = v[8 + i];
	}
	if (ok && ferror(in))
		ok = record_error(err, shown_path, number > 0 ? number : 1, "cannot read recorded input: read error");
	if (ok && number == 0)
		ok = record_error(err, shown_path, 1, "empty recorded input: the header t,x,y,z,qw,qx,qy,qz,s0,...,s17 is missing");
	else if (ok && script->key_count == 0)
		ok = record_error(err, shown_path, number, "recorded input has a header but no samples");
	free(line);
	fclose(in);
	if (!ok) {
		free(script->keys);
		script->keys = NULL;
		script->key_count = 0;
	}
	return ok;
}
