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

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_comments_before_header),
	    cmocka_unit_test(test_untracked_hold),
	};
	return cmocka_run_group_tests(tests, make_temp_dir, remove_temp_dir);
}
