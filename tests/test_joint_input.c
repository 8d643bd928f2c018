// test_joint_input.c — hands driven by recorded joint positions (scenarios/README.md, "Recorded
// joint positions"): the file format (comments, directives, frames, units, missing cells, the
// tracked and confidence columns), the untracked hold, the plausibility refusals and the hand's
// size fitted from the recording. Recordings are cut from the catalog's (hand/joints_*.csv,
// written by `handspring joints` from the glove model) and rewritten here, so every load can be
// compared with the original bit for bit.
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "test_util.h"
#include "scenario_internal.h"

#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char temp_dir[64];

static int make_temp_dir(void **state) {
	(void)state;
	strcpy(temp_dir, "/tmp/hs_joints_XXXXXX");
	return mkdtemp(temp_dir) ? 0 : -1;
}

static int remove_temp_dir(void **state) {
	(void)state;
	DIR *d = opendir(temp_dir);
	struct dirent *e;
	while (d && (e = readdir(d)) != NULL) {
		char sub[1024];
		snprintf(sub, sizeof sub, "%s/%s", temp_dir, e->d_name);
		if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
			remove(sub);
	}
	if (d)
		closedir(d);
	return remove(temp_dir) == 0 ? 0 : -1;
}

// Writes `text` to temp_dir/name; returns the path (static buffer).
static const char *write_file(const char *name, const char *text) {
	static char path[512];
	snprintf(path, sizeof path, "%s/%s", temp_dir, name);
	FILE *f = fopen(path, "w");
	assert_non_null(f);
	fputs(text, f);
	assert_int_equal(fclose(f), 0);
	return path;
}

// The first `rows` lines after the header of a catalog file, header included, as text.
static char *catalog_lines(const char *path, int rows) {
	FILE *f = fopen(path, "r");
	assert_non_null(f);
	size_t cap = 1 << 16, n = 0;
	char *text = malloc(cap), line[1 << 14];
	assert_non_null(text);
	int taken = -1;
	while (taken < rows && fgets(line, sizeof line, f)) {
		if (line[0] == '#' || line[0] == '@' || line[0] == '\n')
			continue;
		size_t len = strlen(line);
		if (n + len + 1 > cap) {
			cap *= 2;
			text = realloc(text, cap);
			assert_non_null(text);
		}
		memcpy(text + n, line, len + 1);
		n += len;
		taken++;
	}
	fclose(f);
	return text;
}

// A scenario of one hand whose record is `record` (a file name or a YAML mapping).
static hs_scenario *load_hand(const char *name, const char *record, const char *side, hs_error *err) {
	char text[2048];
	snprintf(text, sizeof text,
	         "description: joints\ndt: 1/60\nduration: 0.5\n"
	         "objects:\n  - { name: a, shape: cube, size: 0.05, position: [0, 0, 0.025] }\n"
	         "hands:\n  - name: right\n%s    record: %s\n",
	         side ? side : "", record);
	return hs_scenario_load(write_file(name, text), err);
}

static hs_scenario *must_load(const char *name, const char *record) {
	hs_error err;
	hs_scenario *s = load_hand(name, record, NULL, &err);
	if (!s)
		fail_msg("%s", err.message);
	return s;
}

// The two scripts have the same keys, bit for bit.
static void assert_same_keys(const hs_scenario *a, const hs_scenario *b) {
	const hs_hand_script *x = &a->hands.scripts[0], *y = &b->hands.scripts[0];
	assert_int_equal(x->key_count, y->key_count);
	for (int k = 0; k < x->key_count; ++k) {
		const hs_hand_key *p = &x->keys[k], *q = &y->keys[k];
		assert_true(p->tracked == q->tracked);
		assert_memory_equal(&p->t, &q->t, sizeof p->t);
		assert_memory_equal(&p->wrist, &q->wrist, sizeof p->wrist);
		assert_memory_equal(&p->rot, &q->rot, sizeof p->rot);
		assert_memory_equal(p->sensors, q->sensors, sizeof p->sensors);
	}
}

// A recording cut from a catalog file: `rows` samples of `cols` numbers.
typedef struct rec {
	int rows, cols;
	bool xr; // OpenXR (else MediaPipe)
	double *v;
} rec;

static rec rec_read(const char *path, int rows) {
	char *text = catalog_lines(path, rows);
	rec r = {0, 0, strstr(path, "openxr") != NULL, NULL};
	r.cols = r.xr ? 183 : 64;
	r.v = malloc((size_t)rows * (size_t)r.cols * sizeof *r.v);
	assert_non_null(r.v);
	char *line = strchr(text, '\n') + 1; // past the header
	for (; r.rows < rows && *line; ++r.rows) {
		char *end;
		for (int c = 0; c < r.cols; ++c, line = end + 1)
			r.v[r.rows * r.cols + c] = strtod(line, &end);
	}
	free(text);
	return r;
}

// Column c of a recording holds a position coordinate (not t, not an orientation).
static bool is_position(const rec *r, int c) { return c > 0 && (!r->xr || (c - 1) % 7 < 3); }

// The file's (x, y, z) of a scene point p in `frame`: the inverse of the library's mapping
// (scenarios/README.md: y_up (−z, −x, y), unity (z, −x, y), mediapipe (z, −x, −y)).
static hs_vec3 to_frame(hs_vec3 p, int frame) {
	switch (frame) {
	case 1:
		return hs_v3(-p.y, p.z, -p.x);
	case 2:
		return hs_v3(-p.y, p.z, p.x);
	case 3:
		return hs_v3(-p.y, -p.z, p.x);
	default:
		return p;
	}
}

// How rec_write writes a recording.
typedef struct rec_style {
	const char *head;  // lines before the header (directives, comments)
	int frame;         // 0 z_up, 1 y_up, 2 unity, 3 mediapipe
	double scale;      // 1 (m), 100 (cm), 1000 (mm)
	const char *extra; // after the header's coordinates, e.g. ",tracked,confidence"
	// the text of row k's cell c (NULL: the number as it is); and what follows row k's coordinates
	const char *(*cell)(int k, int c);
	const char *(*tail)(int k);
	const char *between; // a line written between the rows (e.g. a comment)
} rec_style;

static void rec_write(const char *name, const rec *r, const rec_style *st) {
	char path[512];
	snprintf(path, sizeof path, "%s/%s", temp_dir, name);
	FILE *f = fopen(path, "w");
	assert_non_null(f);
	char header[4096];
	size_t n = (size_t)snprintf(header, sizeof header, "t");
	for (int j = 0; j < (r->xr ? 26 : 21); ++j)
		n += r->xr ? (size_t)snprintf(header + n, sizeof header - n, ",px%d,py%d,pz%d,qw%d,qx%d,qy%d,qz%d", j, j, j, j,
		                              j, j, j)
		           : (size_t)snprintf(header + n, sizeof header - n, ",x%d,y%d,z%d", j, j, j);
	fprintf(f, "%s%s%s\n", st->head ? st->head : "", header, st->extra ? st->extra : "");
	double scale = st->scale > 0.0 ? st->scale : 1.0;
	for (int k = 0; k < r->rows; ++k) {
		const double *v = &r->v[k * r->cols];
		for (int c = 0; c < r->cols; ++c) {
			double x = v[c];
			if (is_position(r, c)) { // the first coordinate of a point: all three at once
				int first = c - (r->xr ? (c - 1) % 7 : (c - 1) % 3);
				hs_vec3 p = to_frame(hs_v3(v[first], v[first + 1], v[first + 2]), st->frame);
				x = (c == first ? p.x : c == first + 1 ? p.y : p.z) * scale;
			}
			const char *text = st->cell ? st->cell(k, c) : NULL;
			if (text)
				fprintf(f, "%s%s", c ? "," : "", text);
			else
				fprintf(f, "%s%.17g", c ? "," : "", x);
		}
		fprintf(f, "%s\n%s", st->tail ? st->tail(k) : "", st->between ? st->between : "");
	}
	assert_int_equal(fclose(f), 0);
}

// Loads a scenario whose hand records `record`, or fails with the message.
static hs_scenario *load_record(const char *name, const char *record) { return must_load(name, record); }

// Loading fails with a message that ends with `suffix` (after the file's path).
static void load_fails(const char *name, const char *record, const char *side, const char *suffix) {
	hs_error err;
	hs_scenario *s = load_hand(name, record, side, &err);
	if (s)
		fail_msg("%s loaded; expected ...%s", name, suffix);
	size_t m = strlen(err.message), k = strlen(suffix);
	if (m < k || strcmp(err.message + m - k, suffix) != 0)
		fail_msg("%s: got '%s', expected ...'%s'", name, err.message, suffix);
}

// A comment or blank line before the header: the file is still read as what its header says
// (a glove + tracker file, a MediaPipe recording), with the same keys.
static void test_comments_before_header(void **state) {
	(void)state;
	char *plain = catalog_lines("scenarios/hand/joints_mediapipe.csv", 12);
	size_t n = strlen(plain);
	char *commented = malloc(n + 64);
	assert_non_null(commented);
	snprintf(commented, n + 64, "# twelve samples\n\n%s", plain);
	write_file("plain.csv", plain);
	write_file("commented.csv", commented);
	hs_scenario *a = must_load("plain.yaml", "plain.csv"), *b = must_load("commented.yaml", "commented.csv");
	assert_same_keys(a, b);
	hs_scenario_destroy(a);
	hs_scenario_destroy(b);
	write_file("glove.csv", "# a glove\n\nt,x,y,z,qw,qx,qy,qz,s0,s1,s2,s3,s4,s5,s6,s7,s8,s9,s10,s11,s12,s13,s14,s15,s16,s17\n"
	                        "0,0,0,0.3,1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,128,128\n");
	hs_scenario *g = must_load("glove.yaml", "glove.csv");
	assert_int_equal(g->hands.scripts[0].key_count, 1);
	hs_scenario_destroy(g);
	free(plain);
	free(commented);
}

// The untracked hold: between a tracked key and the next tracked one with untracked keys in the
// gap, the script holds the last tracked pose and sensors and says untracked; it does not
// interpolate toward the next tracked key. Tracked to tracked is linear as always.
static void test_untracked_hold(void **state) {
	(void)state;
	hs_hand_key keys[4];
	memset(keys, 0, sizeof keys);
	for (int k = 0; k < 4; ++k) {
		keys[k].t = k;
		keys[k].rot = hs_quat_identity();
		keys[k].tracked = k != 2;
	}
	keys[0].wrist = hs_v3(0, 0, 0.3);
	keys[1].wrist = hs_v3(0.1, 0, 0.3);
	keys[2].wrist = keys[1].wrist; // untracked: holds key 1's pose, as the loader writes it
	keys[3].wrist = hs_v3(0.5, 0, 0.3);
	keys[1].sensors[4] = keys[2].sensors[4] = 40;
	keys[3].sensors[4] = 120;
	hs_hand_script script = {4, keys};
	hs_vec3 w;
	hs_quat q;
	uint8_t s[HS_GLOVE_SENSORS];
	assert_true(hs_hand_script_sample(&script, -1.0, &w, &q, s)); // before the first key: it holds
	assert_true(hs_hand_script_sample(&script, 0.5, &w, &q, s));
	assert_near(w.x, 0.05, 1e-15);
	assert_int_equal(s[4], 20);
	assert_true(hs_hand_script_sample(&script, 1.0, &w, &q, s)); // at the tracked key itself
	assert_true(w.x == 0.1 && s[4] == 40);
	for (double t = 1.25; t < 3.0; t += 0.25) { // after key 1, in the gap: held, untracked
		assert_false(hs_hand_script_sample(&script, t, &w, &q, s));
		assert_true(w.x == 0.1 && w.z == 0.3 && s[4] == 40);
		assert_true(q.w == 1.0 && q.x == 0.0);
	}
	assert_true(hs_hand_script_sample(&script, 3.0, &w, &q, s)); // the next tracked key: no blend into it
	assert_true(w.x == 0.5 && s[4] == 120);
	assert_true(hs_hand_script_sample(&script, 9.0, &w, &q, s));
	keys[3].tracked = false; // a recording that ends untracked stays untracked
	assert_false(hs_hand_script_sample(&script, 9.0, &w, &q, s));
	keys[0].tracked = false; // and one that starts untracked is untracked before its first key
	assert_false(hs_hand_script_sample(&script, -1.0, &w, &q, s));
}

// The keys of two loads agree within `tol` (m, and per quaternion component up to its sign);
// times, tracking and sensors exactly.
static void assert_keys_near(const hs_scenario *a, const hs_scenario *b, double tol) {
	const hs_hand_script *x = &a->hands.scripts[0], *y = &b->hands.scripts[0];
	assert_int_equal(x->key_count, y->key_count);
	for (int k = 0; k < x->key_count; ++k) {
		const hs_hand_key *p = &x->keys[k], *q = &y->keys[k];
		assert_true(p->t == q->t && p->tracked == q->tracked);
		assert_vec3_near(p->wrist, q->wrist, tol);
		double sign = hs_quat_dot(p->rot, q->rot) < 0.0 ? -1.0 : 1.0;
		assert_near(p->rot.w, sign * q->rot.w, tol);
		assert_near(p->rot.x, sign * q->rot.x, tol);
		assert_near(p->rot.y, sign * q->rot.y, tol);
		assert_near(p->rot.z, sign * q->rot.z, tol);
		assert_memory_equal(p->sensors, q->sensors, sizeof p->sensors);
	}
}

static const char *const frame_names[4] = {"z_up", "y_up", "unity", "mediapipe"};

// A recording written in z_up and converted by hand into each frame loads to the same keys bit
// for bit, the frame said by @frame or by the scenario; in cm or mm (a division that rounds)
// within 1e-12. A version 1 file (no directive) is z_up in m, with one warning line.
static void test_frames_and_units(void **state) {
	(void)state;
	for (int xr = 0; xr < 2; ++xr) {
		rec r = rec_read(xr ? "scenarios/hand/joints_openxr.csv" : "scenarios/hand/joints_mediapipe.csv", 24);
		rec_style plain = {0};
		rec_write("v1.csv", &r, &plain);
		hs_scenario *base = load_record("v1.yaml", "v1.csv");
		const char *warning = hs_scenario_warnings(base);
		assert_non_null(strstr(warning, "/v1.csv:1: warning: the recording says no frame (@frame, or frame: in the "
		                                "scenario's record): read as z_up (x forward, y left, z up), in m\n"));
		assert_string_equal(strchr(warning, '\n'), "\n"); // one line
		for (int f = 0; f < 4; ++f) {
			char head[64], record[128];
			snprintf(head, sizeof head, "# converted by hand\n@frame %s\n\n", frame_names[f]);
			rec_style framed = {.head = head, .frame = f}, bare = {.frame = f};
			rec_write("framed.csv", &r, &framed);
			rec_write("bare.csv", &r, &bare);
			snprintf(record, sizeof record, "{ file: bare.csv, frame: %s }", frame_names[f]);
			hs_scenario *a = load_record("framed.yaml", "framed.csv"), *b = load_record("bare.yaml", record);
			assert_same_keys(base, a);
			assert_same_keys(base, b);
			assert_string_equal(hs_scenario_warnings(a), "");
			assert_string_equal(hs_scenario_warnings(b), "");
			hs_scenario_destroy(a);
			hs_scenario_destroy(b);
		}
		rec_style mm = {.head = "@units mm\n@frame y_up\n", .frame = 1, .scale = 1000.0};
		rec_style cm = {.head = "@frame mediapipe\n", .frame = 3, .scale = 100.0};
		rec_write("mm.csv", &r, &mm);
		rec_write("cm.csv", &r, &cm);
		hs_scenario *a = load_record("mm.yaml", "mm.csv"), *b = load_record("cm.yaml", "{ file: cm.csv, units: cm }");
		assert_keys_near(base, a, 1e-12);
		assert_keys_near(base, b, 1e-12);
		hs_scenario_destroy(a);
		hs_scenario_destroy(b);
		hs_scenario_destroy(base);
		free(r.v);
	}
}

// origin and rpy_deg place the recording rigidly after the frame: every key's wrist is moved and
// turned, its sensors unchanged.
static void test_placement(void **state) {
	(void)state;
	rec r = rec_read("scenarios/hand/joints_mediapipe.csv", 16);
	rec_style plain = {.head = "@frame z_up\n"};
	rec_write("p.csv", &r, &plain);
	hs_scenario *base = load_record("p.yaml", "p.csv");
	hs_scenario *s = load_record("placed.yaml", "{ file: p.csv, origin: [0.5, -0.2, 0.1], rpy_deg: [0, 0, 90] }");
	const hs_hand_script *x = &base->hands.scripts[0], *y = &s->hands.scripts[0];
	hs_quat turn = hs_quat_from_rpy(0.0, 0.0, HS_PI / 2.0);
	for (int k = 0; k < x->key_count; ++k) {
		assert_vec3_near(y->keys[k].wrist, hs_add(hs_v3(0.5, -0.2, 0.1), hs_quat_rotate(turn, x->keys[k].wrist)), 1e-12);
		hs_quat q = hs_quat_mul(turn, x->keys[k].rot);
		assert_true(fabs(fabs(hs_quat_dot(q, y->keys[k].rot)) - 1.0) < 1e-12);
		assert_memory_equal(x->keys[k].sensors, y->keys[k].sensors, sizeof x->keys[k].sensors);
	}
	hs_scenario_destroy(base);
	hs_scenario_destroy(s);
	free(r.v);
}

static int cell_mode;
// Row 3 without its ring tip (landmark 16: empty, nan, NaN); row 5 without its index MCP
// (landmark 5, which the wrist fit needs); mode 1: row 2's index tip (landmark 8) has only x missing.
static const char *missing_cell(int k, int c) {
	static const char *const spellings[3] = {"", "nan", "NaN"};
	if (k == 3 && c >= 1 + 3 * 16 && c < 4 + 3 * 16)
		return spellings[c - (1 + 3 * 16)];
	if (k == 5 && c >= 1 + 3 * 5 && c < 4 + 3 * 5)
		return "-nan";
	if (cell_mode == 1 && k == 2 && c == 1 + 3 * 8)
		return "";
	return NULL;
}

// Missing cells: a joint left out is left out of that sample's fit; a sample without a joint the
// wrist fit needs is untracked and holds the sample before. Comments and blank lines may come
// between the rows. A joint with only some coordinates missing is an error.
static void test_missing_cells(void **state) {
	(void)state;
	rec r = rec_read("scenarios/hand/joints_mediapipe.csv", 12);
	rec_style plain = {.head = "@frame z_up\n"}, holes = {.head = "@frame z_up\n", .cell = missing_cell,
	                                                      .between = "# a comment between rows\n\n"};
	rec_write("full.csv", &r, &plain);
	rec_write("holes.csv", &r, &holes);
	hs_scenario *a = load_record("full.yaml", "full.csv"), *b = load_record("holes.yaml", "holes.csv");
	const hs_hand_key *x = a->hands.scripts[0].keys, *y = b->hands.scripts[0].keys;
	for (int k = 0; k < 12; ++k) {
		assert_true(y[k].tracked == (k != 5));
		if (k != 5) // the wrist fit does not read the ring tip
			assert_memory_equal(&x[k].wrist, &y[k].wrist, sizeof x[k].wrist);
	}
	assert_memory_equal(&y[5].wrist, &y[4].wrist, sizeof y[4].wrist); // held
	assert_memory_equal(y[5].sensors, y[4].sensors, sizeof y[4].sensors);
	assert_true(y[5].t == x[5].t);
	hs_scenario_destroy(a);
	hs_scenario_destroy(b);
	cell_mode = 1;
	rec_write("partial.csv", &r, &holes);
	cell_mode = 0;
	load_fails("partial.yaml", "partial.csv", NULL,
	           "/partial.csv:9: joint 8 (columns 26-28) has 1 of its 3 coordinates missing: give all or none");
	free(r.v);
}

static int tail_mode;
// ",tracked,confidence" (mode 0), ",confidence,tracked" (1) or ",tracked" (2) cells of row k.
static const char *tracking_tail(int k) {
	static char text[32];
	const char *tracked = k == 4 ? "0" : k == 8 ? "" : k == 9 ? "nan" : "1";
	const char *confidence = k == 6 ? "0.3" : k == 9 ? "NaN" : k == 8 ? "" : "0.9";
	if (tail_mode == 0)
		snprintf(text, sizeof text, ",%s,%s", tracked, confidence);
	else if (tail_mode == 1)
		snprintf(text, sizeof text, ",%s,%s", confidence, tracked);
	else
		snprintf(text, sizeof text, ",%s", k == 6 ? "0" : tracked);
	return text;
}

// The tracked and confidence columns: tracked 0, or a confidence below min_confidence (0.5 unless
// the scenario says), make a sample untracked; empty or nan cells say nothing. The script holds
// the last tracked pose through the gap. OpenXR files take the same columns.
static void test_tracked_and_confidence(void **state) {
	(void)state;
	for (int mode = 0; mode < 3; ++mode) {
		tail_mode = mode;
		rec r = rec_read(mode == 2 ? "scenarios/hand/joints_openxr.csv" : "scenarios/hand/joints_mediapipe.csv", 12);
		rec_style st = {.head = "@frame z_up\n", .extra = mode == 0 ? ",tracked,confidence" : mode == 1 ? ",confidence,tracked" : ",tracked",
		                .tail = tracking_tail};
		rec_write("tc.csv", &r, &st);
		hs_scenario *s = load_record("tc.yaml", "tc.csv");
		const hs_hand_script *script = &s->hands.scripts[0];
		for (int k = 0; k < 12; ++k)
			assert_true(script->keys[k].tracked == (k != 4 && k != 6));
		assert_memory_equal(&script->keys[4].wrist, &script->keys[3].wrist, sizeof(hs_vec3));
		assert_memory_equal(&script->keys[6].wrist, &script->keys[5].wrist, sizeof(hs_vec3));
		hs_vec3 w;
		hs_quat q;
		uint8_t sensors[HS_GLOVE_SENSORS];
		double t = 0.5 * (script->keys[3].t + script->keys[4].t);
		assert_false(hs_hand_script_sample(script, t, &w, &q, sensors)); // toward an untracked sample: held
		assert_memory_equal(&w, &script->keys[3].wrist, sizeof w);
		assert_true(hs_hand_script_sample(script, 0.5 * (script->keys[2].t + script->keys[3].t), &w, &q, sensors));
		if (mode == 0) { // `handspring joints` writes the tracking back: a tracked column, 0 where it is not
			char path[512];
			snprintf(path, sizeof path, "%s/re.csv", temp_dir);
			FILE *out = fopen(path, "w");
			hs_error err;
			assert_true(hs_scenario_export_joints(s, 0, "mediapipe", 120.0, out, &err));
			assert_int_equal(fclose(out), 0);
			char *head = catalog_lines(path, 0);
			assert_non_null(strstr(head, ",z20,tracked\n"));
			free(head);
			hs_scenario *back = load_record("re.yaml", "re.csv");
			for (int k = 0; k < back->hands.scripts[0].key_count; ++k)
				assert_true(back->hands.scripts[0].keys[k].tracked == (k != 4 && k != 6));
			assert_string_equal(hs_scenario_warnings(back), ""); // it says its frame
			hs_scenario_destroy(back);
		}
		hs_scenario_destroy(s);
		if (mode == 0) { // a lower minimum keeps the sample of confidence 0.3
			s = load_record("tc_low.yaml", "{ file: tc.csv, min_confidence: 0.2 }");
			assert_true(s->hands.scripts[0].keys[6].tracked && !s->hands.scripts[0].keys[4].tracked);
			hs_scenario_destroy(s);
			s = load_record("tc_high.yaml", "{ file: tc.csv, min_confidence: 1 }"); // 0.9 is below: only the
			for (int k = 0; k < 12; ++k) // samples that say no confidence stay tracked
				assert_true(s->hands.scripts[0].keys[k].tracked == (k == 8 || k == 9));
			hs_scenario_destroy(s);
		}
		free(r.v);
	}
	tail_mode = 0;
}

// Plausibility: a headset's y-up recording (the hand 1 m up, 0.4 m ahead) that says no frame is
// read as z-up and refused (its wrist under the floor), and the message names the frames that
// would be right; said, it loads. A wrist beyond 10 m is refused (the units of a file in mm said
// to be m). tests/bad has each message at a file's line (test_bad_input).
static void test_plausibility(void **state) {
	(void)state;
	rec r = rec_read("scenarios/hand/joints_mediapipe.csv", 8);
	for (int k = 0; k < r.rows; ++k)
		for (int c = 1; c < r.cols; c += 3) {
			r.v[k * r.cols + c] += 0.4;
			r.v[k * r.cols + c + 2] += 1.0;
		}
	rec_style unsaid = {.frame = 1}, said = {.head = "@frame y_up\n", .frame = 1};
	rec_write("unsaid.csv", &r, &unsaid);
	rec_write("said.csv", &r, &said);
	load_fails("unsaid.yaml", "unsaid.csv", NULL,
	           "/unsaid.csv:2: the wrist is under the floor (z < -0.02 m) in 8 of 8 tracked samples, here at z = -0.318 "
	           "m: the frame is probably wrong (z_up, assumed: the file says no @frame); y_up or unity would put it "
	           "above the floor");
	hs_scenario *s = load_record("said.yaml", "said.csv");
	assert_true(s->hands.scripts[0].keys[0].wrist.z > 1.0);
	hs_scenario_destroy(s);
	rec_style mm = {.head = "@frame y_up\n@units m\n", .frame = 1, .scale = 100.0}; // cm said m
	rec_write("mm.csv", &r, &mm);
	load_fails("mm.yaml", "mm.csv", NULL,
	           "/mm.csv:4: the wrist is 132.5 m from the origin (at most 10 m): are the units right (read as m: are "
	           "they cm or mm?), or the placement (origin)?");
	free(r.v);
}

// Writes hand 1 of hand/free_manipulation as a joint recording (what `handspring joints` writes),
// its definition's segments scaled by `fingers` and its palm (the bases) by `palm`; a left hand
// when `left`.
static void export_hand(const char *name, const char *format, double fingers, double palm, bool left) {
	hs_error err;
	hs_scenario *s = hs_scenario_load("scenarios/hand/free_manipulation.yaml", &err);
	assert_non_null(s);
	hs_hand_def *def = &s->hands.defs[0];
	def->left = left;
	for (int f = 0; f < 5; ++f) {
		for (int k = 0; k < 3; ++k)
			def->segment_length[f][k] *= fingers;
		def->base[f] = hs_scale(def->base[f], palm);
	}
	char path[512];
	snprintf(path, sizeof path, "%s/%s", temp_dir, name);
	FILE *out = fopen(path, "w");
	assert_non_null(out);
	assert_true(hs_scenario_export_joints(s, 0, format, 60.0, out, &err));
	assert_int_equal(fclose(out), 0);
	hs_scenario_destroy(s);
}

static void export_scaled(const char *name, const char *format, double fingers, double palm) {
	export_hand(name, format, fingers, palm, false);
}

// A left hand's recording (@hand left, written by `handspring joints`) drives a hand of side: left
// at the fit's usual RMS; a hand without a side is a right hand, and the recording is refused.
static void test_left_hand(void **state) {
	(void)state;
	export_hand("left.csv", "openxr", 1.0, 1.0, true);
	hs_error err;
	hs_scenario *s = load_hand("left.yaml", "left.csv", "    side: left\n", &err);
	if (!s)
		fail_msg("%s", err.message);
	double rms;
	assert_true(hs_scenario_hand_fit(s, 0, &rms, NULL, NULL));
	print_message("left hand: RMS %.3f mm\n", rms);
	assert_true(rms < 1.0 && s->hands.defs[0].left);
	hs_scenario_destroy(s);
	load_fails("right.yaml", "left.csv", NULL,
	           "/left.csv:4: @hand left, but the scenario's hand 'right' is a right hand (right by default): give it "
	           "side: left, or use a recording of its own hand");
}

// fit_hand: a recording of a hand 0.8 and 1.2 times the definition's (and one with longer fingers
// on a smaller palm) gives the world's hand its segment lengths within 1 % and a fit of RMS under
// 1 mm; fit_hand: false keeps the definition (and the RMS says how far it is from the recording).
static void test_fit_hand(void **state) {
	(void)state;
	const double sizes[4][2] = {{0.8, 0.8}, {1.2, 1.2}, {1.15, 0.9}, {0.8, 0.8}};
	const hs_hand_def given = hs_default_hand_def();
	for (int c = 0; c < 4; ++c) {
		const char *format = c == 1 ? "openxr" : "mediapipe";
		export_scaled("scaled.csv", format, sizes[c][0], sizes[c][1]);
		hs_scenario *s = load_record("scaled.yaml", c == 3 ? "{ file: scaled.csv, fit_hand: false }" : "scaled.csv");
		double rms;
		long samples;
		const char *record;
		assert_true(hs_scenario_hand_fit(s, 0, &rms, &samples, &record));
		assert_string_equal(record, c == 3 ? "scaled.csv" : "scaled.csv");
		const hs_hand_def *def = &s->hands.defs[0];
		double worst = 0.0;
		for (int f = 0; f < 5; ++f)
			for (int k = 0; k < 3; ++k)
				worst = fmax(worst, fabs(def->segment_length[f][k] / (given.segment_length[f][k] * sizes[c][0]) - 1.0));
		print_message("%s hand x%.2f (palm x%.2f)%s: segments within %.2g %%, palm x%.6f, RMS %.3f mm over %ld samples\n",
		              format, sizes[c][0], sizes[c][1], c == 3 ? ", fit_hand: false" : "", 100.0 * worst,
		              def->base[1].x / given.base[1].x, rms, samples);
		if (c == 3) { // the definition as it is
			assert_memory_equal(def, &given, sizeof given);
			assert_true(rms > 5.0);
			hs_scenario_destroy(s);
			continue;
		}
		assert_true(worst < 0.01);
		assert_near(def->base[1].x / given.base[1].x, sizes[c][1], 0.01 * sizes[c][1]);
		assert_true(rms < 1.0);
		assert_true(samples == 181); // free_manipulation's 3 s at 60 Hz, both ends
		hs_scenario_step(s); // the world's hand is the fitted one: its segments have the fitted lengths
		hs_world *w = hs_scenario_world(s);
		hs_vec3 p[HS_HAND_POINTS];
		assert_int_equal(hs_world_hand_points(w, hs_world_hand_at(w, 0), p), HS_OK);
		for (int f = 0; f < 5; ++f)
			for (int k = 0; k < 3; ++k)
				assert_near(hs_distance(p[4 * f + k], p[4 * f + k + 1]), def->segment_length[f][k], 1e-12);
		hs_scenario_destroy(s);
	}
	export_scaled("palm.csv", "mediapipe", 1.0, 4.0); // fingers as they are on a palm 4 times too large
	load_fails("palm.yaml", "palm.csv", NULL,
	           "/palm.csv:6: fit_hand: the recorded palm is 4 times the hand definition's (the median of 305 distances "
	           "between the knuckles in the first second): more than 3 times either way; are the units right (m)?");
	hs_scenario_destroy(load_record("palm_kept.yaml", "{ file: palm.csv, fit_hand: false }"));
	// the catalog's recordings come from the default hand: the fit keeps it bit for bit (its medians
	// are within 1.4e-17 m of the definition's), so their runs and goldens are unchanged
	for (int xr = 0; xr < 2; ++xr) {
		hs_error err;
		hs_scenario *s = hs_scenario_load(xr ? "scenarios/hand/joints_openxr.yaml" : "scenarios/hand/joints_mediapipe.yaml", &err);
		assert_non_null(s);
		assert_memory_equal(&s->hands.defs[0], &given, sizeof given);
		hs_scenario_destroy(s);
	}
}

// drive: joints (scenarios/README.md, "Driven by the joints"): the hand's check points are the
// recorded landmarks 1-20 at every frame that falls on a sample (the recording's frame, placed as
// the scenario says), where the glove hand fitted to the same file is only near them; the
// definition is joint-driven and the fit reports 0 mm.
static void test_drive_joints(void **state) {
	(void)state;
	rec r = rec_read("scenarios/hand/joints_mediapipe.csv", 40);
	rec_style st = {.scale = 1.0};
	rec_write("driven.csv", &r, &st);
	hs_scenario *s = load_record("driven.yaml", "{ file: driven.csv, origin: [0.01, -0.02, 0.03], drive: joints }");
	hs_scenario *g = load_record("fitted.yaml", "{ file: driven.csv, origin: [0.01, -0.02, 0.03] }");
	assert_true(s->hands.defs[0].joint_driven);
	assert_false(g->hands.defs[0].joint_driven);
	double rms = -1.0;
	assert_true(hs_scenario_hand_fit(s, 0, &rms, NULL, NULL));
	assert_true(rms == 0.0);
	double glove_off = 0.0;
	for (int f = 1; f <= 12; ++f) { // frame f ends at t = f / 60 = sample 2 f (120 samples a second)
		assert_true(hs_scenario_step(s));
		assert_true(hs_scenario_step(g));
		hs_vec3 p[HS_HAND_POINTS], q[HS_HAND_POINTS];
		hs_world *w = hs_scenario_world(s), *wg = hs_scenario_world(g);
		assert_int_equal(hs_world_hand_points(w, hs_world_hand_at(w, 0), p), HS_OK);
		assert_int_equal(hs_world_hand_points(wg, hs_world_hand_at(wg, 0), q), HS_OK);
		const double *row = &r.v[2 * f * r.cols];
		for (int i = 0; i < HS_HAND_POINTS; ++i) {
			hs_vec3 want = hs_v3(row[1 + 3 * (i + 1)] + 0.01, row[2 + 3 * (i + 1)] - 0.02, row[3 + 3 * (i + 1)] + 0.03);
			assert_true(hs_distance(p[i], want) < 1e-12);
			double d = hs_distance(q[i], want);
			glove_off = d > glove_off ? d : glove_off;
		}
	}
	assert_true(glove_off > 1e-6); // the fitted glove is near the recorded points, not on them
	hs_scenario_destroy(s);
	hs_scenario_destroy(g);
	free(r.v);
	load_fails("bad_drive.yaml", "{ file: driven.csv, drive: bones }", NULL,
	           "/bad_drive.yaml:8: 'drive' must be glove or joints, got 'bones'");
}

// The text of the first ``` block of `kind` after `marker` in a file (malloc'd).
static char *doc_block(const char *path, const char *marker, const char *kind) {
	FILE *f = fopen(path, "r");
	assert_non_null(f);
	static char doc[1 << 20];
	size_t n = fread(doc, 1, sizeof doc - 1, f);
	fclose(f);
	doc[n] = '\0';
	char open[32];
	snprintf(open, sizeof open, "```%s\n", kind);
	const char *at = strstr(doc, marker);
	assert_non_null(at);
	const char *start = strstr(at, open);
	assert_non_null(start);
	start += strlen(open);
	const char *end = strstr(start, "```");
	assert_non_null(end);
	char *text = strndup(start, (size_t)(end - start));
	assert_non_null(text);
	return text;
}

// The worked example of scenarios/README.md loads as the page says: five samples, the one at
// 0.311 s untracked; the hand holds the pose of 0.2 s, untracked, from the first frame after it
// until the sample at 0.4 s; placed where the catalog's cube is.
static void test_readme_example(void **state) {
	(void)state;
	char *csv = doc_block("scenarios/README.md", "**A worked example**", "csv");
	char *yaml = doc_block("scenarios/README.md", "**A worked example**", "yaml");
	write_file("quest_take3.csv", csv);
	const char *record = strstr(yaml, "record: ");
	assert_non_null(record);
	char line[256];
	snprintf(line, sizeof line, "%.*s", (int)strcspn(record + 8, "\n"), record + 8);
	hs_scenario *s = load_record("quest.yaml", line);
	assert_string_equal(hs_scenario_warnings(s), "");
	const hs_hand_script *script = &s->hands.scripts[0];
	assert_int_equal(script->key_count, 5);
	for (int k = 0; k < 5; ++k)
		assert_true(script->keys[k].tracked == (k != 3));
	double rms;
	long samples;
	assert_true(hs_scenario_hand_fit(s, 0, &rms, &samples, NULL));
	print_message("README example: %ld tracked samples, RMS %.3f mm, wrist at %.4f %.4f %.4f\n", samples, rms,
	              script->keys[0].wrist.x, script->keys[0].wrist.y, script->keys[0].wrist.z);
	assert_int_equal(samples, 4);
	assert_true(rms < 1.0);
	rec r = rec_read("scenarios/hand/joints_mediapipe.csv", 1); // the catalog's first sample, where the take is put
	assert_near(hs_distance(script->keys[0].wrist, hs_v3(r.v[1], r.v[2], r.v[3])), 0.0, 1e-3);
	free(r.v);
	for (long frame = 1; frame <= 30; ++frame) { // the frames of 1/60 s the page describes
		double t = (double)frame * hs_scenario_dt(s); // as the scenario samples its hands
		hs_vec3 w;
		hs_quat q;
		uint8_t sensors[HS_GLOVE_SENSORS];
		bool tracked = hs_hand_script_sample(script, t, &w, &q, sensors);
		assert_true(tracked == (frame <= 12 || frame >= 24));
		if (!tracked)
			assert_memory_equal(&w, &script->keys[2].wrist, sizeof w);
	}
	hs_scenario_destroy(s);
	free(csv);
	free(yaml);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_comments_before_header),
	    cmocka_unit_test(test_untracked_hold),
	    cmocka_unit_test(test_frames_and_units),
	    cmocka_unit_test(test_placement),
	    cmocka_unit_test(test_missing_cells),
	    cmocka_unit_test(test_tracked_and_confidence),
	    cmocka_unit_test(test_plausibility),
	    cmocka_unit_test(test_fit_hand),
	    cmocka_unit_test(test_drive_joints),
	    cmocka_unit_test(test_left_hand),
	    cmocka_unit_test(test_readme_example),
	};
	return cmocka_run_group_tests(tests, make_temp_dir, remove_temp_dir);
}
