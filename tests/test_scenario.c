// test_scenario.c — scenario loading (dt fractions, defaults, orientation), every expectation
// predicate passing and failing on small scenarios written to /tmp, trajectories, their
// comparison, and the catalog.
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "hs_bench.h"
#include "test_util.h"
#include "noise.h"

#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char temp_dir[64];

static int make_temp_dir(void **state) {
	(void)state;
	strcpy(temp_dir, "/tmp/hs_scenario_XXXXXX");
	return mkdtemp(temp_dir) ? 0 : -1;
}

static int remove_tree(const char *path) {
	struct stat st;
	if (lstat(path, &st) != 0)
		return 0;
	if (S_ISDIR(st.st_mode)) {
		DIR *d = opendir(path);
		struct dirent *e;
		while (d && (e = readdir(d)) != NULL) {
			if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
				continue;
			char sub[1024];
			snprintf(sub, sizeof sub, "%s/%s", path, e->d_name);
			remove_tree(sub);
		}
		if (d)
			closedir(d);
	}
	return remove(path);
}

static int remove_temp_dir(void **state) {
	(void)state;
	return remove_tree(temp_dir) == 0 ? 0 : -1;
}

// Writes `text` to temp_dir/name (subfolders created); returns the path (static buffer).
static const char *write_file(const char *name, const char *text) {
	static char path[512];
	snprintf(path, sizeof path, "%s/%s", temp_dir, name);
	for (char *p = path + strlen(temp_dir) + 1; *p; ++p)
		if (*p == '/') {
			*p = '\0';
			mkdir(path, 0777);
			*p = '/';
		}
	FILE *f = fopen(path, "w");
	assert_non_null(f);
	fputs(text, f);
	assert_int_equal(fclose(f), 0);
	return path;
}

static hs_scenario *load_text(const char *name, const char *text) {
	hs_error err;
	hs_scenario *s = hs_scenario_load(write_file(name, text), &err);
	if (!s)
		fail_msg("%s", err.message);
	return s;
}

static void load_error(const char *name, const char *text, const char *expected_suffix) {
	hs_error err;
	const char *path = write_file(name, text);
	hs_scenario *s = hs_scenario_load(path, &err);
	assert_null(s);
	char want[1024];
	snprintf(want, sizeof want, "%s:%s", path, expected_suffix);
	assert_string_equal(err.message, want);
}

static void run_all(hs_scenario *s) {
	while (hs_scenario_step(s)) {
	}
}

// ---------------------------------------------------------------------------------------------
// loading

#define ONE_CUBE "objects:\n  - { name: a, shape: cube, size: 0.1, position: [0, 0, 1] }\n"

static void test_dt_fraction(void **state) {
	(void)state;
	static const struct {
		const char *dt;
		double value;
		const char *duration;
		long frames;
	} cases[] = {
	    {"1/60", 1.0 / 60.0, "1", 60},        {"0.01", 0.01, "0.5", 50},       {"\" 1 / 30 \"", 1.0 / 30.0, "0.1", 3},
	    {"1/12", 1.0 / 12.0, "1", 12},        {"1/2000", 1.0 / 2000.0, "0.01", 20}, {"0.0005", 0.0005, "0.001", 2},
	    {"1/16", 1.0 / 16.0, "0.09375", 2}, // exactly 1.5 frames rounds half away from zero (llround)
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
		char text[512];
		snprintf(text, sizeof text, "description: dt\ndt: %s\nduration: %s\n" ONE_CUBE, cases[i].dt, cases[i].duration);
		hs_scenario *s = load_text("dt.yaml", text);
		assert_true(hs_scenario_dt(s) == cases[i].value); // exact: a/b is one division
		assert_true(hs_world_dt(hs_scenario_world(s)) == cases[i].value);
		assert_int_equal(hs_scenario_frame_count(s), cases[i].frames);
		long steps = 0;
		while (hs_scenario_step(s))
			steps++;
		assert_int_equal(steps, cases[i].frames);
		assert_int_equal(hs_world_frame(hs_scenario_world(s)), cases[i].frames);
		assert_false(hs_scenario_step(s));
		hs_scenario_destroy(s);
	}
	load_error("dt.yaml", "description: dt\ndt: 1/0\nduration: 1\n" ONE_CUBE, "2: 'dt' divides by zero: 1/0");
	load_error("dt.yaml", "description: dt\ndt: 1/2001\nduration: 1\n" ONE_CUBE,
	           "2: 'dt' must be within [1/2000, 1/12] s, got 1/2001");
	load_error("dt.yaml", "description: dt\ndt: 1/nan\nduration: 1\n" ONE_CUBE, "2: 'dt' must be finite, got 1/nan");
	load_error("dt.yaml", "description: dt\ndt: 1/60/2\nduration: 1\n" ONE_CUBE,
	           "2: 'dt' must be a number, got '1/60/2'");
	load_error("dt.yaml", "description: dt\ndt: 1/60\nduration: 0.001\n" ONE_CUBE,
	           "3: 'duration' must be at least one frame (dt = 0.0166667 s), got 0.001");
}

static void test_defaults(void **state) {
	(void)state;
	hs_scenario *s = load_text("defaults.yaml", "# no name: the file's base name\n"
	                                            "description: the defaults\n"
	                                            "dt: 1/60\n"
	                                            "duration: 0.5\n" ONE_CUBE);
	assert_string_equal(hs_scenario_name(s), "defaults");
	assert_string_equal(hs_scenario_description(s), "the defaults");
	assert_int_equal(hs_scenario_object_count(s), 1);
	assert_string_equal(hs_scenario_object_name(s, 0), "a");
	assert_null(hs_scenario_object_name(s, 1));
	assert_null(hs_scenario_object_name(s, -1));
	assert_int_equal(hs_scenario_expectation_count(s), 0);
	hs_world *w = hs_scenario_world(s);
	hs_object_state st;
	assert_int_equal(hs_world_object_state(w, hs_world_object_at(w, 0), &st), HS_OK);
	assert_true(st.position.z == 1.0);
	assert_true(st.orientation.w == 1.0 && st.orientation.x == 0.0 && st.orientation.y == 0.0 && st.orientation.z == 0.0);
	run_all(s);
	assert_int_equal(hs_scenario_check(s, NULL), 0);
	assert_int_equal(hs_world_object_state(w, hs_world_object_at(w, 0), &st), HS_OK);
	assert_true(st.position.z < 1.0); // default gravity pulls down along -z
	assert_near(st.position.x, 0.0, 0.0);
	hs_scenario_destroy(s);

	// zero gravity: nothing moves
	s = load_text("still.yaml", "description: no gravity\ndt: 1/60\nduration: 0.5\ngravity: [0, 0, 0]\n" ONE_CUBE);
	w = hs_scenario_world(s);
	run_all(s);
	assert_int_equal(hs_world_object_state(w, hs_world_object_at(w, 0), &st), HS_OK);
	assert_true(st.position.z == 1.0);
	hs_scenario_destroy(s);
}

static void test_orientation_and_model(void **state) {
	(void)state;
	hs_scenario *s = load_text("pose.yaml", "name: pose\n"
	                                        "description: orientations\n"
	                                        "dt: 0.01\n"
	                                        "duration: 0.01\n"
	                                        "model: { grasp_threshold_deg: 60, stacking: support, floor_tolerance: 1e-5,"
	                                        " skip_work: false }\n"
	                                        "objects:\n"
	                                        "  - { name: r, shape: box, size: [0.1, 0.2, 0.3], position: [0, 0, 1],"
	                                        " rpy_deg: [10, 20, 30] }\n"
	                                        "  - { name: q, shape: pyramid, size: [0.1, 0.1], position: [1, 0, 1],"
	                                        " quat: [0.7071067811865476, 0, 0, 0.7071067811865476] }\n"
	                                        "  - { name: e, shape: ellipsoid, size: [0.1, 0.05, 0.05], position: [2, 0, 1],"
	                                        " velocity: [1, 0, 0], angular_velocity_deg: [0, 0, 90], density: 800 }\n"
	                                        "  - { name: s, shape: sphere, size: 0.05, position: [3, 0, 1] }\n"
	                                        "  - { name: l, shape: l_block, size: [0.1, 0.05, 0.1], thickness: 0.02,"
	                                        " position: [4, 0, 1] }\n");
	hs_world *w = hs_scenario_world(s);
	hs_object_state st;
	assert_int_equal(hs_world_object_state(w, hs_world_object_at(w, 0), &st), HS_OK);
	hs_quat want = hs_quat_from_rpy(10.0 * (HS_PI / 180.0), 20.0 * (HS_PI / 180.0), 30.0 * (HS_PI / 180.0));
	assert_near(st.orientation.w, want.w, 1e-15); // the documented formula (the world may renormalise)
	assert_near(st.orientation.x, want.x, 1e-15);
	assert_near(st.orientation.y, want.y, 1e-15);
	assert_near(st.orientation.z, want.z, 1e-15);
	assert_int_equal(hs_world_object_state(w, hs_world_object_at(w, 1), &st), HS_OK);
	assert_near(st.orientation.w, sqrt(0.5), 1e-15);
	assert_near(st.orientation.z, sqrt(0.5), 1e-15);
	assert_near(hs_quat_dot(st.orientation, st.orientation), 1.0, 1e-15);
	assert_int_equal(hs_world_object_count(w), 5);
	assert_int_equal(hs_world_shape(w, hs_world_shape_at(w, 3))->kind, HS_SHAPE_SPHERE);
	assert_int_equal(hs_world_shape(w, hs_world_shape_at(w, 4))->kind, HS_SHAPE_L_BLOCK);
	assert_false(hs_world_skip_work(w)); // model.skip_work reaches the world (hs_bench.h)
	hs_scenario_destroy(s);
}

static void test_polyhedron(void **state) {
	(void)state;
	hs_scenario *s = load_text("tet.yaml", "description: a tetrahedron\ndt: 1/60\nduration: 0.1\nobjects:\n"
	                                       "  - name: tet\n"
	                                       "    shape: polyhedron\n"
	                                       "    vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]\n"
	                                       "    faces: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]\n"
	                                       "    position: [0, 0, 2]\n");
	const hs_shape *shape = hs_world_shape(hs_scenario_world(s), hs_world_shape_at(hs_scenario_world(s), 0));
	assert_int_equal(shape->kind, HS_SHAPE_POLYHEDRON);
	assert_int_equal(shape->vertex_count, 4);
	assert_near(shape->volume, 1.0 / 6.0, 1e-12);
	hs_scenario_destroy(s);
}

// In-process messages beyond the tests/bad corpus.
static void test_load_errors(void **state) {
	(void)state;
	const char *head = "description: e\ndt: 1/60\nduration: 1\n";
	char text[1024];
	snprintf(text, sizeof text, "%sobjects:\n  - { name: a, shape: cube, size: 0.1 }\n", head);
	load_error("e.yaml", text, "5: object 'a' is missing 'position'");
	snprintf(text, sizeof text, "%sobjects:\n  - { shape: cube, size: 0.1, position: [0, 0, 1] }\n", head);
	load_error("e.yaml", text, "5: object 1 is missing 'name'");
	snprintf(text, sizeof text, "%sobjects:\n  - { name: a, shape: cube, size: 2000, position: [0, 0, 1] }\n", head);
	load_error("e.yaml", text, "5: 'size' must be within (0, 1000] m, got 2000");
	snprintf(text, sizeof text, "%sobjects:\n  - { name: a, shape: box, size: [0.1, 0, 0.1], position: [0, 0, 1] }\n", head);
	load_error("e.yaml", text, "5: 'size' must be within (0, 1000] m, got 0");
	snprintf(text, sizeof text, "%sobjects:\n  - { name: a, shape: cube, size: 0.1, position: [0, 0, 1], vertices: [] }\n",
	         head);
	load_error("e.yaml", text, "5: 'vertices' is only for shape polyhedron");
	snprintf(text, sizeof text, "%s" ONE_CUBE "expect:\n  - { object: a, at: end, near: [0, 0, 1], tolerance: 0 }\n", head);
	load_error("e.yaml", text, "7: 'tolerance' must be > 0, got 0");
	snprintf(text, sizeof text, "%s" ONE_CUBE "expect:\n  - { object: a, at: end }\n", head);
	load_error("e.yaml", text,
	           "7: expect clause needs a predicate: near, resting, floor_contacts, on_face, face_down, below, above, moved, turned_deg, "
	           "moved_at_most, turned_at_most_deg, speed_below, overlap_at_most, velocity, attached, candidate, extension_ratio, lands_at, still, "
	           "contact_sequence, never_contact, grasped, released, rest_length, stiffness, conserved, swing_below or energy_never_grows");
	snprintf(text, sizeof text, "%s" ONE_CUBE "expect:\n  - { object: a, still: true, at: end }\n", head);
	load_error("e.yaml", text, "7: 'at' is not used by 'still'");
	snprintf(text, sizeof text, "%s" ONE_CUBE "expect:\n  - { object: a, still: true, from: 2 }\n", head);
	load_error("e.yaml", text, "7: 'from' must be a time within [0, 1] s, got 2");
	snprintf(text, sizeof text, "%s" ONE_CUBE "expect:\n  - { object: a, contact_sequence: [0, 4] }\n", head);
	load_error("e.yaml", text, "7: 'contact_sequence' must be within [0, 3], got 4");
	snprintf(text, sizeof text, "%s" ONE_CUBE "expect:\n  - { object: a, at: end, floor_contacts: 2.5 }\n", head);
	load_error("e.yaml", text, "7: 'floor_contacts' must be an integer, got '2.5'");
	snprintf(text, sizeof text, "%s" ONE_CUBE "stylus: {}\n", head);
	load_error("e.yaml", text, "6: 'stylus' needs 'keys' or 'record'");
	snprintf(text, sizeof text, "%s" ONE_CUBE "expect: { object: a }\n", head);
	load_error("e.yaml", text, "6: 'expect' must be a list of clauses, got a mapping");
	load_error("e.yaml", "description: e\ndt:\nduration: 1\n" ONE_CUBE, "2: 'dt' must be a number, got nothing");
	load_error("e.yaml", "# only a comment\n", "1: empty file: a scenario needs description, dt, duration and objects");
}

// ---------------------------------------------------------------------------------------------
// expectations: a dropped cube (lands near t = 0.30 s and rests flat) and a box already resting

static const char drop_scenario[] = "description: a dropped cube and a resting box\n"
                                    "dt: 1/60\n"
                                    "duration: 1.5\n"
                                    "objects:\n"
                                    "  - { name: block, shape: cube, size: 0.1, position: [0, 0, 0.5] }\n"
                                    "  - { name: base, shape: box, size: [0.2, 0.2, 0.1], position: [1, 0, 0.05] }\n"
                                    "  - { name: high, shape: cube, size: 0.1, position: [2, 0, 100] }\n"
                                    "expect:\n";

// Loads `base` with one more clause, runs it, returns the failures and the report (one PASS or
// FAIL line per check).
static int check_in(const char *base, const char *file, const char *clause, char *report, size_t report_size) {
	static char text[20000]; // a whole catalog file (test_contact_watch) and one more clause
	int n = snprintf(text, sizeof text, "%s  - %s\n", base, clause);
	assert_true(n > 0 && (size_t)n < sizeof text);
	hs_scenario *s = load_text(file, text);
	run_all(s);
	char *buf = NULL;
	size_t size = 0;
	FILE *r = open_memstream(&buf, &size);
	assert_non_null(r);
	int failed = hs_scenario_check(s, r);
	fclose(r);
	snprintf(report, report_size, "%s", buf);
	free(buf);
	int lines = hs_scenario_expectation_count(s);
	hs_scenario_destroy(s);
	int counted = 0;
	for (const char *p = report; *p; p = strchr(p, '\n') + 1) {
		assert_true(strncmp(p, "PASS  ", 6) == 0 || strncmp(p, "FAIL  ", 6) == 0);
		counted++;
	}
	assert_int_equal(counted, lines);
	return failed;
}

// A catalog file's text (one at a time: the buffer is reused).
static const char *catalog_text(const char *path) {
	static char text[16384];
	FILE *f = fopen(path, "r");
	assert_non_null(f);
	size_t n = fread(text, 1, sizeof text - 1, f);
	fclose(f);
	text[n] = '\0';
	return text;
}

static int check_clause(const char *clause, char *report, size_t report_size) {
	return check_in(drop_scenario, "drop.yaml", clause, report, report_size);
}

static void expect_pass(const char *clause, const char *measured) {
	char report[4096];
	int failed = check_clause(clause, report, sizeof report);
	if (failed != 0 || !strstr(report, measured))
		fail_msg("%s\nshould pass with '%s', got:\n%s", clause, measured, report);
}

static void expect_fail(const char *clause, const char *measured) {
	char report[4096];
	int failed = check_clause(clause, report, sizeof report);
	if (failed != 1 || strncmp(report, "FAIL", 4) != 0 || !strstr(report, measured))
		fail_msg("%s\nshould fail once with '%s', got:\n%s", clause, measured, report);
}

static void test_near(void **state) {
	(void)state;
	expect_pass("{ object: block, at: end, near: [0, 0, 0.05], tolerance: 1e-9 }", "distance 0 m");
	expect_fail("{ object: block, at: end, near: [0.1, 0, 0.05], tolerance: 0.05 }", "distance 0.1 m");
	// only the chosen axes count
	expect_pass("{ object: block, at: end, near: [0, 0, 7], tolerance: 1e-9, axes: xy }", "on xy");
	expect_pass("{ object: high, at: 0, near: [5, 0, 100], tolerance: 1e-9, axes: zy }", "distance 0 m");
	expect_fail("{ object: high, at: 0, near: [5, 0, 100], tolerance: 1, axes: x }", "distance 3 m");
}

static void test_resting_and_contacts(void **state) {
	(void)state;
	expect_pass("{ object: block, at: end, resting: true }", "resting true");
	expect_fail("{ object: block, at: end, resting: false }", "resting true");
	expect_pass("{ object: block, at: 0.1, resting: false }", "resting false");
	expect_pass("{ object: block, at: end, floor_contacts: 4 }", "floor_contacts 4");
	expect_fail("{ object: block, at: end, floor_contacts: 3 }", "floor_contacts 4");
	expect_pass("{ object: block, at: 0, floor_contacts: 0 }", "floor_contacts 0");
	expect_pass("{ object: base, at: end, on_face: true }", "floor_contacts 4");
	expect_fail("{ object: high, at: end, on_face: true }", "floor_contacts 0");
	expect_pass("{ object: high, at: end, on_face: false }", "floor_contacts 0");
}

static void test_below_above_and_at(void **state) {
	(void)state;
	expect_pass("{ object: block, at: 0.1, below: 0.5 }", "z ");
	expect_fail("{ object: block, at: 0, below: 0.5 }", "z 0.5 m"); // strictly below
	expect_pass("{ object: block, at: end, above: 0.04 }", "z 0.05 m");
	expect_fail("{ object: block, at: end, above: 0.06 }", "z 0.05 m");

	// `at: t` checks the state after frame llround(t / dt): find z at frames 5, 6, 7 and bracket frame 6
	char text[2048];
	snprintf(text, sizeof text, "%s  - { object: block, at: end, resting: true }\n", drop_scenario);
	hs_scenario *s = load_text("drop.yaml", text);
	hs_world *w = hs_scenario_world(s);
	double z[8];
	for (int f = 0; f < 8; ++f) {
		hs_object_state st;
		assert_int_equal(hs_world_object_state(w, hs_world_object_at(w, 0), &st), HS_OK);
		z[f] = st.position.z;
		assert_true(hs_scenario_step(s));
	}
	hs_scenario_destroy(s);
	assert_true(z[5] > z[6] && z[6] > z[7]);
	char clause[256];
	// t = 0.1 s → frame 6 (0.1 × 60 = 6); t = 0.09 s → frame 5 (5.4 rounds down); t = 0.11 s → frame 7 (6.6)
	snprintf(clause, sizeof clause, "{ object: block, at: 0.1, below: %.17g }", 0.5 * (z[5] + z[6]));
	expect_pass(clause, "at t = 0.1 s");
	snprintf(clause, sizeof clause, "{ object: block, at: 0.1, above: %.17g }", 0.5 * (z[6] + z[7]));
	expect_pass(clause, "at t = 0.1 s");
	snprintf(clause, sizeof clause, "{ object: block, at: 0.09, above: %.17g }", 0.5 * (z[5] + z[6]));
	expect_pass(clause, "at t = 0.0833333 s");
	snprintf(clause, sizeof clause, "{ object: block, at: 0.11, below: %.17g }", 0.5 * (z[6] + z[7]));
	expect_pass(clause, "at t = 0.116667 s");
}

static void test_lands_at(void **state) {
	(void)state;
	// free fall from 0.45 m (bottom face) takes sqrt(2 · 0.45 / 9.81) = 0.303 s
	expect_pass("{ object: block, lands_at: 0.3, tolerance: 0.05 }", "landed at t = ");
	expect_fail("{ object: block, lands_at: 1.0, tolerance: 0.05 }", "landed at t = ");
	expect_fail("{ object: high, lands_at: 1.0, tolerance: 0.5 }", "never landed");
	expect_fail("{ object: base, lands_at: 0, tolerance: 0.5 }", "never left the floor");
}

static void test_still(void **state) {
	(void)state;
	expect_pass("{ object: block, still: true, from: 1.2 }", "unchanged");
	expect_fail("{ object: block, still: true }", "moved at frame 1 ");
	expect_pass("{ object: block, still: false }", "moved at frame 1 ");
	expect_pass("{ object: base, still: true, from: 0.5 }", "unchanged");
	expect_fail("{ object: high, still: true, from: 0.5 }", "moved at frame 31 ");
	expect_pass("{ object: high, still: true, from: 1.5 }", "unchanged"); // no frame after the last one
}

static void test_contact_sequence(void **state) {
	(void)state;
	expect_pass("{ object: block, contact_sequence: [0] }", "[0]");
	expect_fail("{ object: block, contact_sequence: [0, 2, 0] }", "[0]");
	expect_fail("{ object: block, contact_sequence: [2] }", "[0]");
}

// overlap_at_most: the deepest point of the object inside another (or of another inside it).
static void test_overlap_at_most(void **state) {
	(void)state;
	expect_pass("{ object: block, at: end, overlap_at_most: 0 }", "inside no other object");
	static const char pair[] = "description: two cubes 0.5 mm into each other\n"
	                           "dt: 1/60\n"
	                           "duration: 0.1\n"
	                           "objects:\n"
	                           "  - { name: a, shape: cube, size: 0.1, position: [0, 0, 0.05] }\n"
	                           "  - { name: b, shape: cube, size: 0.1, position: [0.0995, 0, 0.05] }\n"
	                           "expect:\n";
	char report[4096];
	assert_int_equal(check_in(pair, "pair.yaml", "{ object: a, at: 0, overlap_at_most: 0.0001 }", report, sizeof report), 1);
	assert_non_null(strstr(report, "overlap at most 0.0001 m at t = 0 s: 0.0005 m into 'b'"));
	assert_int_equal(check_in(pair, "pair.yaml", "{ object: b, at: 0, overlap_at_most: 0.0006 }", report, sizeof report), 0);
}

// energy_never_grows (scenarios/README.md, Expectations): a falling and landing cube never has
// more energy per unit mass than it began with (eq. 3 loses ½ g² dt² a frame in flight); a hand
// that lifts a cube gives it energy, and the clause says when it was highest.
static void test_energy_never_grows(void **state) {
	(void)state;
	expect_pass("{ object: '*', energy_never_grows: true, tolerance: 1e-12 }", "energy per unit mass never above");
	expect_pass("{ object: [block, high], energy_never_grows: true, tolerance: 1e-12, from: 0.2 }", "at t = 0.2 s");
	const char *text = catalog_text("scenarios/hand/grasp_adjoining_faces.yaml");
	char report[4096];
	assert_int_equal(check_in(text, "grasp_adjoining_faces.yaml",
	                          "{ object: cube, energy_never_grows: true, tolerance: 0.01, from: 0.5 }", report,
	                          sizeof report),
	                 1);
	assert_non_null(strstr(report, "FAIL  line"));
	assert_non_null(strstr(report, "cube energy per unit mass never above its value at t = 0.5 s by more than 0.01 J/kg"));
	char bad[2048];
	snprintf(bad, sizeof bad, "%s  - { object: block, energy_never_grows: false, tolerance: 1 }\n", drop_scenario);
	load_error("energy.yaml", bad, "9: 'energy_never_grows' can only be true (leave it out otherwise)");
}

static void test_every_object(void **state) {
	(void)state;
	char report[4096];
	int failed = check_clause("{ object: '*', at: end, above: 0.04 }", report, sizeof report);
	assert_int_equal(failed, 0);
	assert_non_null(strstr(report, "line 9: block above"));
	assert_non_null(strstr(report, "line 9: base above"));
	assert_non_null(strstr(report, "line 9: high above"));
	failed = check_clause("{ object: '*', at: end, on_face: true }", report, sizeof report);
	assert_int_equal(failed, 1); // only `high`, still in the air
	assert_non_null(strstr(report, "FAIL  line 9: high on_face"));
}

static void test_check_before_the_end(void **state) {
	(void)state;
	char text[2048];
	snprintf(text, sizeof text, "%s  - { object: block, at: end, resting: true }\n  - { object: block, at: 0, below: 1 }\n",
	         drop_scenario);
	hs_scenario *s = load_text("drop.yaml", text);
	assert_true(hs_scenario_step(s));
	char *buf = NULL;
	size_t size = 0;
	FILE *r = open_memstream(&buf, &size);
	assert_int_equal(hs_scenario_check(s, r), 1);
	fclose(r);
	assert_non_null(strstr(buf, "not reached: the run stopped at frame 1 of 90"));
	assert_non_null(strstr(buf, "PASS  line 10: block below 1 m at t = 0 s"));
	free(buf);
	hs_scenario_destroy(s);
}

// ---------------------------------------------------------------------------------------------
// trajectories

static char *trajectory_of(const char *text, size_t *size) {
	hs_scenario *s = load_text("traj.yaml", text);
	char *buf = NULL;
	FILE *out = open_memstream(&buf, size);
	hs_trajectory_write_header(out);
	hs_trajectory_write_frame(out, s);
	while (hs_scenario_step(s))
		hs_trajectory_write_frame(out, s);
	fclose(out);
	hs_scenario_destroy(s);
	return buf;
}

static void test_trajectory_rows(void **state) {
	(void)state;
	size_t size;
	char *csv = trajectory_of("description: t\ndt: 1/12\nduration: 0.1667\nobjects:\n"
	                          "  - { name: a, shape: cube, size: 0.1, position: [0, 0, 1] }\n"
	                          "  - { name: b, shape: cube, size: 0.1, position: [1, 0, 0.05] }\n",
	                          &size);
	const char *header = "frame,t,object,x,y,z,qw,qx,qy,qz,contact,floor,resting,hash\n";
	assert_memory_equal(csv, header, strlen(header));
	int rows = 0;
	for (const char *p = csv; (p = strchr(p, '\n')) && p[1]; ++p)
		rows++;
	assert_int_equal(rows, 2 * 3); // 2 objects × frames 0, 1, 2
	const char *first = csv + strlen(header);
	assert_memory_equal(first, "0,0,a,0,0,1,1,0,0,0,0,0,0,", 26);
	const char *hash = first + 26; // 16 lowercase hex digits
	for (int i = 0; i < 16; ++i)
		assert_true((hash[i] >= '0' && hash[i] <= '9') || (hash[i] >= 'a' && hash[i] <= 'f'));
	assert_int_equal(hash[16], '\n');
	assert_non_null(strstr(csv, "\n0,0,b,1,0,0.050000000000000003,1,0,0,0,0,4,"));
	assert_non_null(strstr(csv, "\n2,0.16666666666666666,b,")); // t = frame × dt, 17 digits
	free(csv);
}

// What the hands do (handspring run --hands-out): hand/push_press_down holds its index tip (check
// point 7) 1 mm into the top face of a box (z = 0.1): the point row gives the tip where the glove
// puts it (z 0.099) and rectified onto the face (w 0.1, §3.2), touching; the thumb's base (0) is
// in no object and rectified to itself; the tip's contact row names the box, the point C on its
// top face, the face normal +z and the box's contact state 1 (push at one point, Fig. 12).
static char *trace_frame(hs_scenario *s) {
	char *text = NULL;
	size_t size = 0;
	FILE *out = open_memstream(&text, &size);
	assert_non_null(out);
	hs_hand_trace_write_header(out);
	hs_hand_trace_write_frame(out, s);
	fclose(out);
	const char *header = "frame,t,kind,hand,index,x,y,z,u,v,w,flag,object,value\n";
	assert_memory_equal(text, header, strlen(header));
	return text;
}

static int count_kind(const char *text, const char *kind) {
	int n = 0;
	char key[32];
	snprintf(key, sizeof key, ",%s,", kind);
	for (const char *p = text; (p = strstr(p, key)); ++p)
		n++;
	return n;
}

static void test_hand_trace_rows(void **state) {
	(void)state;
	hs_error err;
	hs_scenario *s = hs_scenario_load("scenarios/hand/push_press_down.yaml", &err);
	assert_non_null(s);
	for (int f = 0; f < 30; ++f)
		assert_true(hs_scenario_step(s));
	char *text = trace_frame(s);
	assert_int_equal(count_kind(text, "point"), HS_HAND_POINTS);
	assert_int_equal(count_kind(text, "stylus"), 0); // a hand world
	const char *tip = strstr(text, "\n30,0.5,point,0,7,");
	assert_non_null(tip);
	double x, y, z, rx, ry, rz;
	int touching;
	assert_int_equal(sscanf(tip + 1, "30,0.5,point,0,7,%lf,%lf,%lf,%lf,%lf,%lf,%d", &x, &y, &z, &rx, &ry, &rz, &touching),
	                 7);
	assert_near(z, 0.099, 1e-12);
	assert_near(rz, 0.1, 1e-12);
	assert_near(rx, x, 1e-12);
	assert_near(ry, y, 1e-12);
	assert_int_equal(touching, 1);
	const char *base = strstr(text, "\n30,0.5,point,0,0,");
	assert_non_null(base);
	assert_int_equal(
	    sscanf(base + 1, "30,0.5,point,0,0,%lf,%lf,%lf,%lf,%lf,%lf,%d", &x, &y, &z, &rx, &ry, &rz, &touching), 7);
	assert_true(x == rx && y == ry && z == rz && touching == 0);
	const char *contact = strstr(text, "\n30,0.5,contact,0,7,");
	assert_non_null(contact);
	double nx, ny, nz;
	int edge, contact_state;
	char object[16];
	assert_int_equal(sscanf(contact + 1, "30,0.5,contact,0,7,%lf,%lf,%lf,%lf,%lf,%lf,%d,%15[^,],%d", &x, &y, &z, &nx,
	                        &ny, &nz, &edge, object, &contact_state),
	                 9);
	assert_near(z, 0.1, 1e-12);
	assert_true(nx == 0.0 && ny == 0.0 && nz == 1.0 && edge == 0);
	assert_string_equal(object, "box");
	assert_int_equal(contact_state, HS_CONTACT_PUSH_ONE);
	free(text);
	hs_scenario_destroy(s);
}

// In a spring world: spring/select_slow selects its target while the hand approaches (a candidate
// row at its G) and, once attached, the spring row runs from the anchor to the object's G with the
// extension hs_world_spring_state gives; the stylus row carries the button and the attached name.
static void test_hand_trace_spring(void **state) {
	(void)state;
	hs_error err;
	hs_scenario *s = hs_scenario_load("scenarios/spring/select_slow.yaml", &err);
	assert_non_null(s);
	hs_world *w = hs_scenario_world(s);
	bool saw_candidate = false, saw_spring = false;
	while (hs_scenario_step(s) && !(saw_candidate && saw_spring)) {
		char *text = trace_frame(s);
		assert_int_equal(count_kind(text, "stylus"), 1);
		hs_spring_state ss;
		assert_int_equal(hs_world_spring_state(w, &ss), HS_OK);
		assert_int_equal(count_kind(text, "candidate"), ss.candidate.index1 ? 1 : 0);
		assert_int_equal(count_kind(text, "spring"), ss.attached.index1 ? 1 : 0);
		const char *row = strstr(text, ",spring,");
		if (row) {
			double ax, ay, az, gx, gy, gz, ext;
			int flag;
			char object[16];
			assert_int_equal(sscanf(row, ",spring,,0,%lf,%lf,%lf,%lf,%lf,%lf,%d,%15[^,],%lf", &ax, &ay, &az, &gx, &gy,
			                        &gz, &flag, object, &ext),
			                 9);
			assert_true(ax == ss.anchor.x && ay == ss.anchor.y && az == ss.anchor.z);
			assert_true(ext == ss.extension);
			assert_string_equal(object, "target");
			assert_non_null(strstr(text, ",stylus,,0,"));
			saw_spring = true;
		}
		saw_candidate = saw_candidate || strstr(text, ",candidate,,0,") != NULL;
		free(text);
	}
	assert_true(saw_candidate && saw_spring);
	hs_scenario_destroy(s);
}

// A hand key may place a finger part instead of the wrist (scenarios/README.md "Hands"):
// `index_tip` puts the index fingertip (check point 7) on the point given, with the key's own
// posture and the wrist turned; `thumb_base` the thumb's CMC (point 0). Two placements in one key
// are refused.
static void test_key_places_finger_part(void **state) {
	(void)state;
	hs_scenario *s = load_text("finger_part0.yaml",
	              "description: index tip placed\ndt: 1/60\nduration: 0.1\n" ONE_CUBE
	              "hands:\n  - name: h\n    keys:\n"
	              "      - { t: 0, index_tip: [0.3, 0.2, 0.5], rpy_deg: [0, 0, 90], posture: { fist: 0.3 } }\n"
	              "      - { t: 0.05, index_tip: [0.3, 0.2, 0.5] }\n"
	              "      - { t: 0.1, thumb_base: [0.1, 0.1, 0.6] }\n");
	while (hs_scenario_step(s) && hs_world_frame(hs_scenario_world(s)) < 3) { // t = 0.05 s: the second key
	}
	hs_world *w = hs_scenario_world(s);
	hs_vec3 p[HS_HAND_POINTS];
	assert_int_equal(hs_world_hand_points(w, hs_world_hand_at(w, 0), p), HS_OK);
	assert_near(p[7].x, 0.3, 1e-12);
	assert_near(p[7].y, 0.2, 1e-12);
	assert_near(p[7].z, 0.5, 1e-12);
	run_all(s);
	assert_int_equal(hs_world_hand_points(w, hs_world_hand_at(w, 0), p), HS_OK);
	assert_near(p[0].x, 0.1, 1e-12);
	assert_near(p[0].y, 0.1, 1e-12);
	assert_near(p[0].z, 0.6, 1e-12);
	hs_scenario_destroy(s);
	load_error("two_places.yaml",
	           "description: two\ndt: 1/60\nduration: 0.1\n" ONE_CUBE
	           "hands:\n  - name: h\n    keys:\n      - { t: 0, wrist: [0, 0, 0.5], index_tip: [0.3, 0.2, 0.5] }\n",
	           "9: a hand key places the hand once: give one of 'wrist', 'grip' or a finger part");
}

// Joint input: hand/free_manipulation's motion recorded as MediaPipe landmarks
// and as OpenXR joints (scripts/joint_recordings.sh) drives the same run as the glove keys: the
// same contact state of the cube in every frame, its pose within 1e-9 m (measured: 1.2e-16 m; the
// wrist fit rounds). The fitted sensors are whole units near the glove's own, not always them
// (the fit's RMS is 0.2 mm: scenarios/README.md, "Recorded joint positions").
static void test_joint_input_matches_glove(void **state) {
	(void)state;
	const char *paths[2] = {"scenarios/hand/joints_mediapipe.yaml", "scenarios/hand/joints_openxr.yaml"};
	for (int k = 0; k < 2; ++k) {
		hs_error err;
		hs_scenario *glove = hs_scenario_load("scenarios/hand/free_manipulation.yaml", &err);
		hs_scenario *joints = hs_scenario_load(paths[k], &err);
		assert_non_null(glove);
		if (!joints)
			fail_msg("%s", err.message);
		hs_world *wg = hs_scenario_world(glove), *wj = hs_scenario_world(joints);
		double worst = 0.0;
		long frames = 0, grasped = 0;
		for (;;) {
			bool a = hs_scenario_step(glove), b = hs_scenario_step(joints);
			assert_int_equal(a, b);
			if (!a)
				break;
			hs_object_state sg, sj;
			hs_world_object_state(wg, hs_world_object_at(wg, 0), &sg);
			hs_world_object_state(wj, hs_world_object_at(wj, 0), &sj);
			assert_int_equal(sg.contact, sj.contact);
			grasped += sg.contact == HS_CONTACT_GRASP;
			worst = fmax(worst, hs_distance(sg.position, sj.position));
			frames++;
		}
		print_message("%s: %ld frames, %ld grasped, largest difference %.3g m\n", paths[k], frames, grasped, worst);
		assert_true(worst <= 1e-9);
		assert_true(grasped > 60); // the grasp is really there
		assert_int_equal(hs_scenario_check(joints, NULL), 0);
		hs_scenario_destroy(glove);
		hs_scenario_destroy(joints);
	}
}

// Bad joint files get the file's line: a short row, a joint position beyond 1000 m, an OpenXR
// orientation that is not a unit quaternion, time going back.
static void test_joint_input_errors(void **state) {
	(void)state;
	char header[2048] = "t";
	for (int i = 0; i < 21; ++i) {
		char c[64];
		snprintf(c, sizeof c, ",x%d,y%d,z%d", i, i, i);
		strcat(header, c);
	}
	char row[4096] = "0";
	for (int i = 0; i < 63; ++i)
		strcat(row, ",0.1");
	const char *hand = "description: joints\ndt: 1/60\nduration: 0.1\n" ONE_CUBE
	                   "hands:\n  - { name: h, record: j.csv }\n";
	static char text[32768];
	snprintf(text, sizeof text, "%s\n%s\n0.1,1,2\n", header, row);
	write_file("j.csv", text);
	hs_error err;
	assert_null(hs_scenario_load(write_file("joints_short.yaml", hand), &err));
	assert_non_null(strstr(err.message, "j.csv:3: expected 64 numbers"));
	snprintf(text, sizeof text, "%s\n%s\n%s\n", header, row, row);
	write_file("j.csv", text);
	assert_null(hs_scenario_load(write_file("joints_back.yaml", hand), &err));
	assert_non_null(strstr(err.message, "j.csv:3: time 0 does not increase"));
	char far[4096];
	snprintf(far, sizeof far, "%s", row);
	memcpy(strstr(far, ",0.1"), ",9e3", 4);
	snprintf(text, sizeof text, "%s\n%s\n", header, far);
	write_file("j.csv", text);
	assert_null(hs_scenario_load(write_file("joints_far.yaml", hand), &err));
	assert_non_null(strstr(err.message, "j.csv:2: column 2 (position) must be within [-1000, 1000] m"));
	char xr[8192] = "t";
	for (int j = 0; j < 26; ++j) {
		char c[128];
		snprintf(c, sizeof c, ",px%d,py%d,pz%d,qw%d,qx%d,qy%d,qz%d", j, j, j, j, j, j, j);
		strcat(xr, c);
	}
	char xrow[8192] = "0";
	for (int j = 0; j < 26; ++j)
		strcat(xrow, j == 3 ? ",0.1,0.1,0.1,2,0,0,0" : ",0.1,0.1,0.1,1,0,0,0");
	snprintf(text, sizeof text, "%s\n%s\n", xr, xrow);
	write_file("j.csv", text);
	assert_null(hs_scenario_load(write_file("joints_quat.yaml", hand), &err));
	assert_non_null(strstr(err.message, "j.csv:2: orientation in columns 26-29 is not a unit quaternion"));
}

static bool compare_texts(const char *golden, const char *now, double tolerance, char *why, size_t n) {
	FILE *g = fmemopen((void *)golden, strlen(golden), "r"), *a = fmemopen((void *)now, strlen(now), "r");
	assert_non_null(g);
	assert_non_null(a);
	bool same = hs_trajectory_compare(g, a, tolerance, "case", why, n);
	fclose(g);
	fclose(a);
	return same;
}

#define H "frame,t,object,x,y,z,qw,qx,qy,qz,contact,floor,resting,hash\n"
#define ROW(f, obj, z, contact, hash) #f ",0.5," obj ",0,0," z ",1,0,0,0," contact ",0,0," hash "\n"

static void test_compare(void **state) {
	(void)state;
	const char *golden = "# a comment\n# regenerate with make golden\n" H ROW(0, "a", "1", "0", "00000000000000aa")
	    ROW(0, "b", "0.5", "0", "00000000000000aa") ROW(1, "a", "0.9", "0", "00000000000000bb")
	        ROW(1, "b", "0.5", "2", "00000000000000bb") ROW(2, "a", "0.8", "0", "00000000000000cc")
	            ROW(2, "b", "0.5", "0", "00000000000000cc");
	char why[512];
	// itself, and itself without comments
	assert_true(compare_texts(golden, golden, 0.0, why, sizeof why));
	assert_string_equal(why, "");
	assert_true(compare_texts(golden, strstr(golden, H), 0.0, why, sizeof why));
	// within tolerance, with a different hash: not a failure
	const char *close = H ROW(0, "a", "1", "0", "00000000000000aa") ROW(0, "b", "0.5", "0", "00000000000000aa")
	    ROW(1, "a", "0.9", "0", "00000000000000bb") ROW(1, "b", "0.50000000000001", "2", "1234567890abcdef")
	        ROW(2, "a", "0.8", "0", "00000000000000cc") ROW(2, "b", "0.5", "0", "00000000000000cc");
	assert_true(compare_texts(golden, close, 1e-12, why, sizeof why));
	assert_false(compare_texts(golden, close, 1e-15, why, sizeof why));
	// beyond tolerance: frame, object, field, both values as written, the difference now - golden
	const char *far = H ROW(0, "a", "1", "0", "00000000000000aa") ROW(0, "b", "0.5", "0", "00000000000000aa")
	    ROW(1, "a", "0.9", "0", "00000000000000bb") ROW(1, "b", "0.5078125", "2", "00000000000000bb");
	assert_false(compare_texts(golden, far, 1e-3, why, sizeof why));
	assert_string_equal(why, "case: frame 1, object b, field z: golden 0.5, now 0.5078125 (difference 0.00781)");
	// a contact state must agree exactly
	const char *contact = H ROW(0, "a", "1", "0", "00000000000000aa") ROW(0, "b", "0.5", "0", "00000000000000aa")
	    ROW(1, "a", "0.9", "0", "00000000000000bb") ROW(1, "b", "0.5", "0", "00000000000000bb");
	assert_false(compare_texts(golden, contact, 1.0, why, sizeof why));
	assert_string_equal(why, "case: frame 1, object b, field contact: golden 2, now 0 (difference -2)");
	// fewer frames
	const char *shorter = H ROW(0, "a", "1", "0", "00000000000000aa") ROW(0, "b", "0.5", "0", "00000000000000aa")
	    ROW(1, "a", "0.9", "0", "00000000000000bb") ROW(1, "b", "0.5", "2", "00000000000000bb");
	assert_false(compare_texts(golden, shorter, 0.0, why, sizeof why));
	assert_string_equal(why, "case: golden has 3 frames, now 2");
	assert_false(compare_texts(shorter, golden, 0.0, why, sizeof why));
	assert_string_equal(why, "case: golden has 2 frames, now 3");
	// an object renamed
	const char *renamed = H ROW(0, "a", "1", "0", "00000000000000aa") ROW(0, "c", "0.5", "0", "00000000000000aa");
	assert_false(compare_texts(golden, renamed, 0.0, why, sizeof why));
	assert_string_equal(why, "case: frame 0, object b, field object: golden b, now c");
	// a wrong header, a short row, non-numbers
	assert_false(compare_texts(golden, "frame,t\n", 0.0, why, sizeof why));
	assert_string_equal(why, "case: now line 1: header is not '" "frame,t,object,x,y,z,qw,qx,qy,qz,contact,floor,resting,hash'");
	assert_false(compare_texts(golden, H "0,0,a\n", 0.0, why, sizeof why));
	assert_string_equal(why, "case: now line 2: expected 14 fields, got 3");
	assert_false(compare_texts(golden, H ROW(0, "a", "zz", "0", "00000000000000aa"), 0.0, why, sizeof why));
	assert_string_equal(why, "case: now line 2: field z is not a number: 'zz'");
	assert_false(compare_texts("", golden, 0.0, why, sizeof why));
	assert_string_equal(why, "case: golden file is empty (no header)");
	// NaN equals NaN (a frozen object's state is still reproducible); NaN against a number does not
	const char *nan_row = H ROW(0, "a", "nan", "0", "00000000000000aa");
	assert_true(compare_texts(nan_row, nan_row, 0.0, why, sizeof why));
	assert_false(compare_texts(nan_row, H ROW(0, "a", "1", "0", "00000000000000aa"), 1e9, why, sizeof why));
	assert_string_equal(why, "case: frame 0, object a, field z: golden nan, now 1 (difference nan)");
	// why may be NULL
	assert_false(hs_trajectory_compare(NULL, NULL, 0.0, NULL, NULL, 0));
}

// ---------------------------------------------------------------------------------------------
// catalog

static void test_catalog(void **state) {
	(void)state;
	const char *text = "description: c\ndt: 1/60\nduration: 0.1\n" ONE_CUBE;
	write_file("cat/zeta.yaml", text);
	write_file("cat/alpha.yaml", text);
	write_file("cat/hand/flick.yaml", text);
	write_file("cat/hand/deep/grasp.yaml", text);
	write_file("cat/notes.txt", "not a scenario");
	write_file("cat/.hidden.yaml", text);
	write_file("cat/README.md", "docs");
	char dir[256];
	snprintf(dir, sizeof dir, "%s/cat", temp_dir);
	hs_catalog c;
	hs_error err;
	assert_true(hs_catalog_load(dir, &c, &err));
	assert_int_equal(c.count, 4);
	assert_string_equal(c.names[0], "alpha");
	assert_string_equal(c.names[1], "hand/deep/grasp");
	assert_string_equal(c.names[2], "hand/flick");
	assert_string_equal(c.names[3], "zeta");
	char want[512];
	snprintf(want, sizeof want, "%s/hand/flick.yaml", dir);
	assert_string_equal(c.paths[2], want);
	// each catalog file loads, and a scenario's name is its base name
	hs_scenario *s = hs_scenario_load(c.paths[2], &err);
	assert_non_null(s);
	assert_string_equal(hs_scenario_name(s), "flick");
	hs_scenario_destroy(s);
	hs_catalog_free(&c);
	assert_int_equal(c.count, 0);
	assert_null(c.names);

	// a trailing slash gives the same paths without "//"
	snprintf(dir, sizeof dir, "%s/cat/", temp_dir);
	assert_true(hs_catalog_load(dir, &c, &err));
	assert_string_equal(c.paths[2], want);
	hs_catalog_free(&c);

	// empty and missing folders
	snprintf(dir, sizeof dir, "%s/cat_empty", temp_dir);
	mkdir(dir, 0777);
	assert_true(hs_catalog_load(dir, &c, &err));
	assert_int_equal(c.count, 0);
	hs_catalog_free(&c);
	snprintf(dir, sizeof dir, "%s/cat_missing", temp_dir);
	assert_false(hs_catalog_load(dir, &c, &err));
	snprintf(want, sizeof want, "%s: cannot read: No such file or directory", dir);
	assert_string_equal(err.message, want);
}

// ---------------------------------------------------------------------------------------------
// the stylus (spring model): keyframes, recorded files, model.spring, the spring predicates

static hs_spring_state spring_of(hs_scenario *s) {
	hs_spring_state ss;
	assert_int_equal(hs_world_spring_state(hs_scenario_world(s), &ss), HS_OK);
	return ss;
}

// Keys: positions linear between keys, what a key leaves out kept from the one before, the button
// a step at the key's time, orientation slerped; set for the end of each frame.
static void test_stylus_keys(void **state) {
	(void)state;
	hs_scenario *s = load_text("keys.yaml", "description: stylus keys\ndt: 1/60\nduration: 1.5\n" ONE_CUBE
	                                        "stylus:\n"
	                                        "  keys:\n"
	                                        "    - { t: 0.1, position: [0, 0, 0.6] }\n"
	                                        "    - { t: 0.5, position: [0.4, 0, 0.2], rpy_deg: [0, 0, 90] }\n"
	                                        "    - { t: 0.7, button: true }\n"
	                                        "    - { t: 1.0, position: [0.4, 0.3, 0.2], button: false }\n");
	hs_world *w = hs_scenario_world(s);
	assert_true(hs_world_springs_enabled(w));
	// frame 0: the first key holds before its time
	hs_spring_state ss = spring_of(s);
	assert_vec3_near(ss.stylus, hs_v3(0, 0, 0.6), 0.0);
	assert_false(ss.button);
	for (long f = 1; f <= 90; ++f) {
		assert_true(hs_scenario_step(s));
		double t = (double)f / 60.0;
		ss = spring_of(s);
		hs_vec3 want = t <= 0.1 ? hs_v3(0, 0, 0.6)
		               : t <= 0.5 ? hs_lerp(hs_v3(0, 0, 0.6), hs_v3(0.4, 0, 0.2), (t - 0.1) / 0.4)
		               : t <= 0.7 ? hs_v3(0.4, 0, 0.2)
		               : t <= 1.0 ? hs_lerp(hs_v3(0.4, 0, 0.2), hs_v3(0.4, 0.3, 0.2), (t - 0.7) / 0.3)
		                          : hs_v3(0.4, 0.3, 0.2);
		assert_vec3_near(ss.stylus, want, 1e-15);
		// the button goes down at the end of frame 42 (t = 0.7 s) and up at frame 60 (t = 1.0 s)
		assert_int_equal(ss.button, f >= 42 && f < 60);
		if (t >= 0.5) { // 90 deg about z from the key at 0.5 s on
			assert_near(ss.stylus_orientation.w, sqrt(0.5), 1e-12);
			assert_near(ss.stylus_orientation.z, sqrt(0.5), 1e-12);
		}
		if (f == 18) { // halfway between identity and 90 deg: 45 deg
			hs_quat q = ss.stylus_orientation;
			assert_near(q.w, cos(HS_PI / 8.0), 1e-12);
			assert_near(q.z, sin(HS_PI / 8.0), 1e-12);
		}
	}
	hs_scenario_destroy(s);
}

// A recorded file at 30 Hz, resampled to 60 fps; comment lines skipped; the last sample holds.
static void test_stylus_record(void **state) {
	(void)state;
	write_file("rec/track.csv", "t,x,y,z,qw,qx,qy,qz,button\n"
	                            "# 30 Hz\n"
	                            "0,0,0,0.5,1,0,0,0,0\n"
	                            "0.0333333333333333,0.01,0,0.5,1,0,0,0,0\n"
	                            "\n"
	                            "0.0666666666666667,0.02,0,0.5,1,0,0,0,1\n"
	                            "0.1,0.03,0,0.5,0.70710678,0,0,0.70710678,1\n");
	hs_scenario *s = load_text("rec/rec.yaml", "description: a record\ndt: 1/60\nduration: 0.13333333\n" ONE_CUBE
	                                           "stylus: { record: track.csv }\n");
	double want_x[] = {0.0, 0.005, 0.01, 0.015, 0.02, 0.025, 0.03, 0.03, 0.03};
	for (int f = 0; f < 9; ++f) {
		hs_spring_state ss = spring_of(s);
		assert_near(ss.stylus.x, want_x[f], 1e-12);
		assert_int_equal(ss.button, f >= 4); // the sample at 1/15 s presses
		assert_true(hs_scenario_step(s) == (f < 8));
	}
	hs_spring_state ss = spring_of(s);
	assert_near(ss.stylus_orientation.z, sqrt(0.5), 1e-12); // renormalised
	hs_scenario_destroy(s);
	// errors name the recorded file and its line
	hs_error err;
	write_file("rec/bad.csv", "t,x,y,z,qw,qx,qy,qz,button\n0,0,0,0.5,1,0,0,0,0\n0.1,0,0,0.5,1,0,0,0,0,7\n");
	const char *path = write_file("rec/bad.yaml", "description: a bad record\ndt: 1/60\nduration: 0.2\n" ONE_CUBE
	                                              "stylus: { record: bad.csv }\n");
	assert_null(hs_scenario_load(path, &err));
	char want[600];
	snprintf(want, sizeof want, "%s/rec/bad.csv:3: expected 9 numbers (t,x,y,z,qw,qx,qy,qz,button), got more", temp_dir);
	assert_string_equal(err.message, want);
	write_file("rec/hex.csv", "t,x,y,z,qw,qx,qy,qz,button\n0,0x1,0,0.5,1,0,0,0,0\n");
	path = write_file("rec/hex.yaml", "description: a bad record\ndt: 1/60\nduration: 0.2\n" ONE_CUBE
	                                  "stylus: { record: hex.csv }\n");
	assert_null(hs_scenario_load(path, &err));
	snprintf(want, sizeof want, "%s/rec/hex.csv:2: expected 9 numbers (t,x,y,z,qw,qx,qy,qz,button), column 2 is not a number",
	         temp_dir);
	assert_string_equal(err.message, want);
}

// model.spring reaches the world: friction 0 lets a pushed ball slide on, walls stop it, the noise
// seed makes the stylus readings the harness gives the world noisy (and reproducible).
static void test_spring_options(void **state) {
	(void)state;
	const char *text = "description: options\ndt: 1/60\nduration: 1\n"
	                   "model: { spring: { friction: 0, restitution: 0.5, integrator: rk4, walls: [-1, 0.3, -1, 1],"
	                   " noise_seed: 3 } }\n"
	                   "objects:\n"
	                   "  - { name: ball, shape: sphere, size: 0.05, position: [0, 0, 0.05], velocity: [1, 0, 0] }\n"
	                   "stylus: { keys: [{ t: 0, position: [0, 0.5, 0.5] }] }\n";
	hs_scenario *s = load_text("opts.yaml", text);
	hs_world *w = hs_scenario_world(s);
	for (int f = 0; f < 15; ++f)
		assert_true(hs_scenario_step(s));
	hs_object_state st;
	assert_int_equal(hs_world_object_state(w, hs_world_object_at(w, 0), &st), HS_OK);
	assert_near(st.position.x, 0.25, 1e-12); // no friction: 1 m/s for 0.25 s
	while (hs_scenario_step(s)) {
	}
	assert_int_equal(hs_world_object_state(w, hs_world_object_at(w, 0), &st), HS_OK);
	assert_near(st.position.x, 0.25, 1e-12); // the wall at 0.3 holds its surface
	hs_tracker_state tr;
	assert_int_equal(hs_world_tracker_state(w, &tr), HS_OK);
	assert_int_equal(tr.sample_count, 51); // 0, 0.02, ..., 1.0 s
	double noise = hs_distance(tr.newest.position, hs_v3(0, 0.5, 0.5));
	assert_true(noise > 0.0 && noise < 0.01);
	hs_scenario_destroy(s);
	s = load_text("opts.yaml", text); // the same seed, the same samples
	run_all(s);
	hs_tracker_state again;
	assert_int_equal(hs_world_tracker_state(hs_scenario_world(s), &again), HS_OK);
	assert_memory_equal(&again.newest.position, &tr.newest.position, sizeof tr.newest.position);
	hs_scenario_destroy(s);
	// friction defaults to 0.5 and sliding friction follows it; a ball pushed at 1 m/s stops after
	// v / (mu g) = 0.2039 s, 1 / (2 mu g) = 0.10194 m on
	s = load_text("mu.yaml", "description: mu\ndt: 1/60\nduration: 1\nobjects:\n"
	                         "  - { name: ball, shape: sphere, size: 0.05, position: [0, 0, 0.05], velocity: [1, 0, 0] }\n"
	                         "stylus: { keys: [{ t: 0, position: [0, 0.5, 0.5] }] }\n");
	run_all(s);
	w = hs_scenario_world(s);
	assert_int_equal(hs_world_object_state(w, hs_world_object_at(w, 0), &st), HS_OK);
	assert_near(st.position.x, 1.0 / (2.0 * 0.5 * 9.81), 1e-9);
	hs_scenario_destroy(s);
}

// A crate picked, lifted, thrown; a ball sliding against friction; two balls colliding.
static const char spring_scenario[] = "description: spring predicates\n"
                                      "dt: 1/60\n"
                                      "duration: 3\n"
                                      "objects:\n"
                                      "  - { name: crate, shape: cube, size: 0.1, density: 1000, position: [0, 0, 0.05] }\n"
                                      "  - { name: ball, shape: sphere, size: 0.05, position: [1, 1, 0.05], velocity: [1, 0, 0] }\n"
                                      "  - { name: idle, shape: sphere, size: 0.05, position: [-1, 1, 0.05] }\n"
                                      "stylus:\n"
                                      "  keys:\n"
                                      "    - { t: 0, position: [0, 0, 0.05] }\n"
                                      "    - { t: 0.2, button: true }\n"
                                      "    - { t: 1.0, position: [0, 0, 0.45] }\n"
                                      "    - { t: 2.0 }\n"
                                      "    - { t: 2.5, position: [0.5, 0, 0.45], button: false }\n"
                                      "expect:\n";

static int check_spring_clause(const char *clause, char *report, size_t report_size) {
	return check_in(spring_scenario, "spring.yaml", clause, report, report_size);
}

static void spring_pass(const char *clause, const char *measured) {
	char report[4096];
	int failed = check_spring_clause(clause, report, sizeof report);
	if (failed != 0 || !strstr(report, measured))
		fail_msg("%s\nshould pass with '%s', got:\n%s", clause, measured, report);
}

static void spring_fail(const char *clause, const char *measured) {
	char report[4096];
	int failed = check_spring_clause(clause, report, sizeof report);
	if (failed < 1 || strncmp(report, "FAIL", 4) != 0 || !strstr(report, measured))
		fail_msg("%s\nshould fail with '%s', got:\n%s", clause, measured, report);
}

static void test_attached_and_candidate(void **state) {
	(void)state;
	spring_pass("{ object: crate, at: 0.5, attached: true }", "on the spring (pick)");
	spring_pass("{ object: crate, at: 0.5, attached: pick }", "on the spring (pick)");
	spring_fail("{ object: crate, at: 0.5, attached: catch }", "on the spring (pick)");
	spring_fail("{ object: crate, at: 0.1, attached: true }", "not on the spring (it holds nothing)");
	spring_pass("{ object: ball, at: 0.5, attached: false }", "not on the spring (it holds 'crate')");
	spring_fail("{ object: crate, at: end, attached: true }", "not on the spring (it holds nothing)");
	spring_pass("{ object: crate, at: 0.1, candidate: true }", "the candidate is 'crate'"); // the stylus is inside it
	spring_fail("{ object: ball, at: 0.1, candidate: true }", "the candidate is 'crate'");
	spring_pass("{ object: crate, at: 0.5, candidate: false }", "no candidate"); // attached: no longer a candidate
}

static void test_extension_and_spring_constants(void **state) {
	(void)state;
	// 1 kg: x0 = 0.1 m, k = 490.5 N/m; hanging at rest: extension 0.2 x0
	spring_pass("{ object: crate, at: 2.0, extension_ratio: 0.2, tolerance: 1e-6 }", "(extension 0.02 m of x0 = 0.1 m)");
	spring_fail("{ object: crate, at: 2.0, extension_ratio: 0.3, tolerance: 0.01 }", "(extension 0.02 m of x0 = 0.1 m)");
	spring_fail("{ object: ball, at: 2.0, extension_ratio: 0.2, tolerance: 1 }", "not on the spring");
	spring_pass("{ object: crate, rest_length: 0.1, tolerance: 1e-12 }", "x0 = 0.1 m, k = 490.5 N/m (mass 1 kg)");
	spring_fail("{ object: crate, rest_length: 0.2, tolerance: 0.05 }", "x0 = 0.1 m");
	spring_pass("{ object: crate, stiffness: 490.5, tolerance: 1e-9 }", "k = 490.5 N/m");
	spring_fail("{ object: crate, stiffness: 400, tolerance: 1 }", "k = 490.5 N/m");
}

static void test_release_speed_velocity(void **state) {
	(void)state;
	// the hand moves at 1 m/s from 2.0 s and lets go at 2.5 s: a throw at the hand's velocity
	spring_pass("{ object: crate, released: throw }", "throw at t = 2.5 s (hand speed 1 m/s, leaving at [1, 0, 0] m/s)");
	spring_fail("{ object: crate, released: drop }", "throw at t = 2.5 s");
	spring_fail("{ object: ball, released: throw }", "never released");
	spring_pass("{ object: ball, released: none }", "never released");
	spring_pass("{ object: crate, at: 2.5, velocity: [1, 0, 0], tolerance: 1e-12 }", "velocity [1, 0, 0] m/s");
	spring_fail("{ object: crate, at: 2.5, velocity: [0, 0, 0], tolerance: 0.5 }", "(difference 1 m/s)");
	spring_pass("{ object: crate, at: 2.0, speed_below: 1e-4 }", "speed ");
	spring_fail("{ object: ball, at: 0, speed_below: 0.5 }", "speed 1 m/s");
	// the ball, on the floor at 1 m/s, stops after 1 / (mu g) = 0.2039 s (mu = 0.5)
	spring_pass("{ object: ball, at: 0.25, speed_below: 1e-12 }", "speed 0 m/s");
	// outside spring worlds the velocity is the frame's difference quotient
	expect_pass("{ object: block, at: 0.1, speed_below: 1.5 }", "speed 0.89925 m/s"); // g × 5.5 dt: frame 6's mean
	expect_fail("{ object: block, at: 0.1, velocity: [0, 0, 0], tolerance: 0.5 }", "velocity [0, 0, -0.89925");
}

static void test_conserved_and_swing(void **state) {
	(void)state;
	// nothing moves the idle ball
	spring_pass("{ object: idle, conserved: momentum, tolerance: 1e-15 }", "relative change 0");
	spring_pass("{ object: idle, conserved: energy, from: 0.5, to: 2.5, tolerance: 1e-15 }", "relative change 0");
	// friction takes the sliding ball's momentum and energy
	spring_fail("{ object: [ball], conserved: momentum, from: 0, to: 0.5, tolerance: 1e-3 }",
	            "p [0.261799388, 0, 0] -> [0, 0, 0] kg m/s, relative change 1");
	spring_fail("{ object: '*', conserved: energy, to: 0.5, tolerance: 1e-3 }", "relative change ");
	spring_pass("{ object: [idle, ball], conserved: energy, from: 1.0, to: 2.0, tolerance: 1e-15 }", "idle+ball conserved");
	// the group line names the objects, or "all objects"
	char report[4096];
	assert_int_equal(check_spring_clause("{ object: '*', conserved: momentum, from: 1.0, to: 2.0, tolerance: 1e-9 }", report,
	                                     sizeof report),
	                 1); // the crate rises from 1.0 s on its spring, slowing down
	assert_non_null(strstr(report, "FAIL  line 16: all objects conserved momentum from t = 1 s to t = 2 s"));
	// swing: the horizontal distance from the stylus to G, largest over the window
	spring_pass("{ object: crate, swing_below: 1e-9, from: 0.5, to: 2.0 }", "largest horizontal offset from the stylus 0 m");
	spring_fail("{ object: crate, swing_below: 0.01, from: 2.5, to: 2.7 }", "largest horizontal offset from the stylus");
	spring_fail("{ object: ball, swing_below: 1, from: 0, to: 1 }", "1.48804 m (at t = 0.216667 s)"); // where it stopped
}

static void test_spring_load_errors(void **state) {
	(void)state;
	const char *head = "description: e\ndt: 1/60\nduration: 1\n";
	char text[1024];
	snprintf(text, sizeof text, "%s" ONE_CUBE "expect:\n  - { object: a, conserved: momentum, tolerance: 1e-9 }\n", head);
	load_error("e.yaml", text, "7: 'conserved' needs a spring world: give the scenario a 'stylus'");
	snprintf(text, sizeof text,
	         "%s" ONE_CUBE "stylus: { keys: [{ t: 0, position: [0, 0, 1] }] }\n"
	         "expect:\n  - { object: a, conserved: heat, tolerance: 1e-9 }\n",
	         head);
	load_error("e.yaml", text, "8: 'conserved' must be momentum or energy, got 'heat'");
	snprintf(text, sizeof text,
	         "%s" ONE_CUBE "stylus: { keys: [{ t: 0, position: [0, 0, 1] }] }\n"
	         "expect:\n  - { object: a, at: end, swing_below: 0.1 }\n",
	         head);
	load_error("e.yaml", text, "8: 'at' is not used by 'swing_below'");
	snprintf(text, sizeof text,
	         "%s" ONE_CUBE "stylus: { keys: [{ t: 0, position: [0, 0, 1] }] }\n"
	         "expect:\n  - { object: a, at: end, resting: true, to: 0.5 }\n",
	         head);
	load_error("e.yaml", text, "8: 'to' is only for 'still', 'never_contact', 'grasped', 'conserved', 'swing_below' and 'energy_never_grows'");
	snprintf(text, sizeof text,
	         "%s" ONE_CUBE "stylus: { keys: [{ t: 0, position: [0, 0, 1] }] }\n"
	         "expect:\n  - { object: a, still: true, from: 0.5, to: 0.5 }\n",
	         head);
	load_error("e.yaml", text, "8: 'to' must come at least one frame after 'from' (frames 30 and 30 of dt = 0.0166667 s)");
	snprintf(text, sizeof text,
	         "%s" ONE_CUBE "stylus: { keys: [{ t: 0, position: [0, 0, 1] }] }\n"
	         "expect:\n  - { object: a, at: end, speed_below: 0 }\n",
	         head);
	load_error("e.yaml", text, "8: 'speed_below' must be > 0, got 0");
	snprintf(text, sizeof text, "%smodel: { spring: [] }\n" ONE_CUBE "stylus: { keys: [{ t: 0, position: [0, 0, 1] }] }\n",
	         head);
	load_error("e.yaml", text, "4: 'spring' must be a mapping, got a list");
	snprintf(text, sizeof text, "%s" ONE_CUBE "stylus: { keys: [{ t: 0, position: [0, 0, 1], quat: [2, 0, 0, 0] }] }\n", head);
	load_error("e.yaml", text, "6: 'quat' must have norm 1 (within 1e-06), got norm 2");
}

// The harness's noise generator: Fastrak-like Gaussian stylus noise (0.762 mm and 0.15 deg RMS per
// axis), uniform glove and wrist noise within their amplitudes, and a state that saves and loads.
static void test_noise_draws(void **state) {
	(void)state;
	hs_noise *noise = hs_noise_create(7);
	assert_non_null(noise);
	enum { N = 20000 };
	double sp[3] = {0, 0, 0}, sr = 0.0;
	for (int i = 0; i < N; ++i) {
		hs_vec3 p = hs_v3(0, 0, 0);
		hs_quat q = hs_quat_identity();
		hs_noise_stylus(noise, &p, &q);
		sp[0] += p.x * p.x, sp[1] += p.y * p.y, sp[2] += p.z * p.z;
		double angle = hs_quat_angle(q);
		sr += angle * angle / 3.0; // three Gaussian components
	}
	for (int k = 0; k < 3; ++k)
		assert_near(sqrt(sp[k] / N), HS_STYLUS_NOISE_POSITION, 0.03 * HS_STYLUS_NOISE_POSITION);
	assert_near(sqrt(sr / N), HS_STYLUS_NOISE_ROTATION, 0.03 * HS_STYLUS_NOISE_ROTATION);
	hs_noise_options options = {.glove_units = 4, .wrist = 1.3e-3};
	int lowest = 0, highest = 0;
	for (int i = 0; i < 2000; ++i) {
		hs_vec3 w = hs_v3(0, 0, 0);
		hs_quat r = hs_quat_identity();
		uint8_t sensors[HS_GLOVE_SENSORS];
		memset(sensors, 100, sizeof sensors);
		sensors[0] = 2; // clamped at 0
		hs_noise_hand(noise, &options, &w, &r, sensors);
		assert_true(r.w == 1.0); // no wrist_rotation: no rotation drawn
		assert_true(fabs(w.x) <= 1.3e-3 && fabs(w.y) <= 1.3e-3 && fabs(w.z) <= 1.3e-3);
		assert_true(sensors[0] <= 6);
		for (int k = 1; k < HS_GLOVE_SENSORS; ++k) {
			assert_true(sensors[k] >= 96 && sensors[k] <= 104);
			lowest += sensors[k] == 96;
			highest += sensors[k] == 104;
		}
	}
	assert_true(lowest > 0 && highest > 0); // both ends are drawn
	// the state: saved, drawn from, loaded: the same draws again
	uint64_t saved[HS_NOISE_WORDS], bad[HS_NOISE_WORDS];
	assert_true(hs_noise_save(noise, saved));
	hs_vec3 a = hs_v3(0, 0, 0), b = hs_v3(0, 0, 0);
	hs_quat qa = hs_quat_identity(), qb = hs_quat_identity();
	hs_noise_stylus(noise, &a, &qa);
	// refused, the generator untouched: a word beyond 32 bits, a position beyond the words, all zero
	int field;
	memcpy(bad, saved, sizeof bad);
	bad[7] |= 1ull << 40;
	assert_false(hs_noise_load(noise, bad));
	assert_non_null(hs_noise_check(bad, &field));
	assert_int_equal(field, 7);
	memcpy(bad, saved, sizeof bad);
	bad[HS_NOISE_WORDS - 1] = (uint64_t)-100000000;
	assert_false(hs_noise_load(noise, bad));
	memset(bad, 0, sizeof bad);
	bad[0] = 0x7FFFFFFF; // only the top bit of the first word counts
	assert_false(hs_noise_load(noise, bad));
	assert_true(hs_noise_load(noise, saved));
	hs_noise_stylus(noise, &b, &qb);
	assert_memory_equal(&a, &b, sizeof a);
	assert_memory_equal(&qa, &qb, sizeof qa);
	hs_noise_destroy(noise);
}

// noise_seed: every stylus reading the world gets is the script's plus noise; the same seed gives
// the same run, another seed another.
static void test_stylus_noise(void **state) {
	(void)state;
	const char *text = "description: noisy stylus\ndt: 1/60\nduration: 2\n"
	                   "model: { spring: { noise_seed: 11 } }\n" ONE_CUBE
	                   "stylus: { keys: [{ t: 0, position: [0.2, 0.1, 0.5] }] }\n";
	hs_scenario *s = load_text("noisy.yaml", text);
	double sum2 = 0.0;
	long n = 0;
	while (hs_scenario_step(s)) {
		hs_spring_state ss = spring_of(s);
		hs_vec3 d = hs_sub(ss.stylus, hs_v3(0.2, 0.1, 0.5));
		assert_true(hs_length(d) > 0.0 && hs_length(d) < 0.01);
		sum2 += hs_dot(d, d) / 3.0;
		n++;
	}
	assert_near(sqrt(sum2 / (double)n), HS_STYLUS_NOISE_POSITION, 0.15 * HS_STYLUS_NOISE_POSITION);
	hs_vec3 last = spring_of(s).stylus;
	hs_scenario_destroy(s);
	s = load_text("noisy.yaml", text);
	run_all(s);
	hs_vec3 same = spring_of(s).stylus;
	assert_memory_equal(&same, &last, sizeof last);
	hs_scenario_destroy(s);
	char other[1024];
	snprintf(other, sizeof other, "%s", text);
	memcpy(strstr(other, "noise_seed: 11"), "noise_seed: 12", 14);
	s = load_text("noisy.yaml", other);
	run_all(s);
	hs_vec3 different = spring_of(s).stylus;
	assert_true(memcmp(&different, &last, sizeof last) != 0);
	hs_scenario_destroy(s);
}

#define ONE_HAND "hands:\n  - name: right\n    keys: [{ t: 0, wrist: [0.3, 0, 0.3], posture: open }]\n"

// The hand's check points after each step (hand 1).
static void hand_points(hs_scenario *s, hs_vec3 points[HS_HAND_POINTS]) {
	hs_world *w = hs_scenario_world(s);
	assert_int_equal(hs_world_hand_points(w, hs_world_hand_at(w, 0), points), HS_OK);
}

// model.input_noise: wrist noise moves the whole hand by at most wrist_mm per axis; glove noise
// bends the fingers; both reproducible from the seed.
static void test_input_noise(void **state) {
	(void)state;
	const char *head = "description: noisy hand\ndt: 1/60\nduration: 0.5\n";
	char clean_text[1024], wrist_text[1024], glove_text[1024];
	snprintf(clean_text, sizeof clean_text, "%s" ONE_CUBE ONE_HAND, head);
	snprintf(wrist_text, sizeof wrist_text, "%smodel: { input_noise: { wrist_mm: 1.3, seed: 7 } }\n" ONE_CUBE ONE_HAND,
	         head);
	snprintf(glove_text, sizeof glove_text, "%smodel: { input_noise: { glove_units: 4, seed: 7 } }\n" ONE_CUBE ONE_HAND,
	         head);
	hs_scenario *clean = load_text("clean.yaml", clean_text), *wrist = load_text("wrist.yaml", wrist_text);
	hs_scenario *glove = load_text("glove.yaml", glove_text), *again = load_text("glove.yaml", glove_text);
	int moved = 0, bent = 0;
	while (hs_scenario_step(clean)) {
		assert_true(hs_scenario_step(wrist) && hs_scenario_step(glove) && hs_scenario_step(again));
		hs_vec3 c[HS_HAND_POINTS], w[HS_HAND_POINTS], g[HS_HAND_POINTS], a[HS_HAND_POINTS];
		hand_points(clean, c), hand_points(wrist, w), hand_points(glove, g), hand_points(again, a);
		hs_vec3 shift = hs_sub(w[0], c[0]);
		assert_true(fabs(shift.x) <= 1.3e-3 + 1e-12 && fabs(shift.y) <= 1.3e-3 + 1e-12 && fabs(shift.z) <= 1.3e-3 + 1e-12);
		for (int i = 1; i < HS_HAND_POINTS; ++i) // a translation of the whole hand
			assert_vec3_near(hs_sub(w[i], c[i]), shift, 1e-12);
		moved += hs_length(shift) > 0.0;
		assert_memory_equal(g, a, sizeof g); // the same seed, the same glove
		bent += memcmp(g, c, sizeof g) != 0;
	}
	assert_int_equal(moved, 30);
	assert_true(bent > 25);
	hs_scenario_destroy(clean), hs_scenario_destroy(wrist), hs_scenario_destroy(glove), hs_scenario_destroy(again);
	char text[1024];
	snprintf(text, sizeof text, "%smodel: { input_noise: { glove_units: 4, seed: 7 } }\n" ONE_CUBE, head);
	load_error("e.yaml", text, "4: 'input_noise' needs 'hands': only hand worlds use it");
	snprintf(text, sizeof text, "%smodel: { input_noise: { glove_units: 4 } }\n" ONE_CUBE ONE_HAND, head);
	load_error("e.yaml", text, "4: 'input_noise' needs a 'seed' (an integer within [0, 4294967295])");
	snprintf(text, sizeof text, "%smodel: { input_noise: { glove_units: 256, seed: 1 } }\n" ONE_CUBE ONE_HAND, head);
	load_error("e.yaml", text, "4: 'glove_units' must be within [0, 255], got 256");
	snprintf(text, sizeof text, "%smodel: { input_noise: { wrist_mm: -1, seed: 1 } }\n" ONE_CUBE ONE_HAND, head);
	load_error("e.yaml", text, "4: 'wrist_mm' must be within [0, 1000] mm, got -1");
	snprintf(text, sizeof text, "%smodel: { input_noise: { seed: 4294967296 } }\n" ONE_CUBE ONE_HAND, head);
	load_error("e.yaml", text, "4: 'seed' must be within [0, 4294967295], got 4294967296");
}

// A run whose world caught a numeric fault fails: an explicit integrator (semi-implicit Euler,
// omega dt = 2.8 at 20 frames/s) blows up on a stiff spring; the world freezes the object and counts
// it, and hs_scenario_check adds a failing line.
// The scenario's frame times are a sub-range of the model's, written once each.
static void test_dt_ranges_nest(void **state) {
	(void)state;
	assert_true(HS_SCENARIO_MIN_DT >= HS_MIN_DT && HS_SCENARIO_MAX_DT <= HS_MAX_DT);
	assert_true(HS_SCENARIO_MIN_DT < HS_SCENARIO_MAX_DT);
}

static void test_numeric_fault_fails(void **state) {
	(void)state;
	hs_scenario *s = load_text("fault.yaml", "description: blows up\ndt: 1/20\nduration: 60\n"
	                                         "model: { spring: { integrator: semi_implicit_euler } }\n"
	                                         "objects:\n  - { name: speck, shape: sphere, size: 0.01, density: 1000,"
	                                         " position: [0, 0, 0.01] }\n"
	                                         "stylus:\n  keys:\n    - { t: 0, position: [0.003, 0, 0.01] }\n"
	                                         "    - { t: 0.1, button: true }\n    - { t: 0.5, position: [0, 0, 0.5] }\n"
	                                         "expect:\n  - { object: speck, at: 1, attached: pick }\n");
	run_all(s);
	assert_true(hs_world_get_counters(hs_scenario_world(s)).numeric_faults > 0);
	char report[2048] = "";
	FILE *f = fmemopen(report, sizeof report, "w");
	assert_non_null(f);
	int failed = hs_scenario_check(s, f);
	fclose(f);
	assert_int_equal(failed, 1);
	assert_int_equal(hs_scenario_expectation_count(s), 2);
	assert_non_null(strstr(report, "PASS  line 13: speck attached pick"));
	long frame = -1;
	hs_object_id first = {0, 0, 0};
	assert_int_equal(hs_world_first_fault(hs_scenario_world(s), &frame, &first), HS_OK);
	assert_true(frame > 0 && first.index1 == 1);
	char line[160];
	snprintf(line, sizeof line, "FAIL  numeric fault at frame %ld in object 'speck' (%ld in all): ", frame,
	         hs_world_get_counters(hs_scenario_world(s)).numeric_faults);
	if (!strstr(report, line))
		fail_msg("no line '%s' in:\n%s", line, report);
	hs_scenario_destroy(s);
}

// Runs a loaded scenario to the end, rows of frames after `after` (-1: every frame, header first)
// into a string.
static char *run_rows(hs_scenario *s, bool header) {
	char *text = NULL;
	size_t size = 0;
	FILE *f = open_memstream(&text, &size);
	assert_non_null(f);
	if (header) {
		hs_trajectory_write_header(f);
		hs_trajectory_write_frame(f, s);
	}
	while (hs_scenario_step(s))
		hs_trajectory_write_frame(f, s);
	fclose(f);
	return text;
}

static char *report_of(const hs_scenario *s) {
	char *text = NULL;
	size_t size = 0;
	FILE *f = open_memstream(&text, &size);
	assert_non_null(f);
	hs_scenario_check(s, f);
	fclose(f);
	return text;
}

// The rows of `trajectory` (header first) whose frame is after `frame`.
static const char *rows_after(const char *trajectory, long frame) {
	const char *line = strchr(trajectory, '\n') + 1;
	while (*line && strtol(line, NULL, 10) <= frame)
		line = strchr(line, '\n') + 1;
	return line;
}

static const char resume_spring[] = "description: resume a noisy spring run\ndt: 1/60\nduration: 2\n"
                                    "model: { spring: { noise_seed: 5 } }\n"
                                    "objects:\n  - { name: ball, shape: sphere, size: 0.05, position: [0, 0, 0.05] }\n"
                                    "  - { name: other, shape: sphere, size: 0.05, position: [1, 0, 0.05] }\n"
                                    "stylus:\n  keys:\n    - { t: 0, position: [0, 0, 0.05] }\n"
                                    "    - { t: 0.3, button: true }\n    - { t: 1.0, position: [0, 0, 0.4] }\n"
                                    "    - { t: 1.5, position: [0.3, 0, 0.4], button: false }\n"
                                    "expect:\n  - { object: ball, at: 0.5, attached: pick }\n"
                                    "  - { object: ball, at: end, above: 0 }\n"
                                    "  - { object: '*', contact_sequence: [0, 2, 0] }\n"
                                    "  - { object: other, still: true }\n"
                                    "  - { object: ball, released: throw }\n"
                                    "  - { object: ball, lands_at: 1.8, tolerance: 1 }\n"
                                    "  - { object: [ball, other], conserved: momentum, from: 0.1, to: 1.9, tolerance: 1 }\n";

static const char resume_hand[] = "description: resume a noisy hand run\ndt: 1/60\nduration: 1\n"
                                  "model: { input_noise: { glove_units: 3, wrist_mm: 1, seed: 9 } }\n"
                                  "objects:\n  - { name: block, shape: cube, size: 0.05, position: [0, 0, 0.025] }\n"
                                  "hands:\n  - name: right\n    keys:\n"
                                  "      - { t: 0, grip: [0, 0, 0.12], rpy_deg: [0, 90, 0], posture: { grasp: 0.11 } }\n"
                                  "      - { t: 0.4, grip: [0, 0, 0.025] }\n      - { t: 0.5, posture: { grasp: 0.045 } }\n"
                                  "      - { t: 0.9, grip: [0, 0, 0.2] }\n"
                                  "expect:\n  - { object: block, at: end, above: 0.1 }\n"
                                  "  - { object: block, contact_sequence: [0, 2] }\n";

// hs_scenario_save at frame F, then hs_scenario_resume in a freshly loaded scenario: the rest of the
// trajectory is the full run's, byte for byte, and so is the report. Needs the model's state block
// (hs_world_save_state).
static void test_save_and_resume(void **state) {
	(void)state;
	const char *texts[] = {resume_spring, resume_hand};
	for (int t = 0; t < 2; ++t) {
		hs_scenario *full = load_text("resume.yaml", texts[t]);
		assert_true(hs_world_state_size(hs_scenario_world(full)) > 0);
		char *whole = run_rows(full, true), *whole_report = report_of(full);
		for (long at = 0; at <= 60; at += 30) {
			hs_scenario *first = load_text("resume.yaml", texts[t]);
			for (long f = 0; f < at; ++f)
				assert_true(hs_scenario_step(first));
			FILE *saved = tmpfile();
			assert_non_null(saved);
			hs_error err;
			if (hs_scenario_save(first, saved, &err) != HS_OK)
				fail_msg("%s", err.message);
			hs_scenario_destroy(first);
			rewind(saved);
			hs_scenario *second = load_text("resume.yaml", texts[t]);
			if (hs_scenario_resume(second, saved, &err) != HS_OK)
				fail_msg("%s", err.message);
			fclose(saved);
			char *rest = run_rows(second, false), *report = report_of(second);
			assert_string_equal(rest, rows_after(whole, at));
			assert_string_equal(report, whole_report);
			free(rest), free(report);
			hs_scenario_destroy(second);
		}
		free(whole), free(whole_report);
		hs_scenario_destroy(full);
	}
}

// A state file is checked before anything is restored: not a state file, another scenario's.
static void test_resume_refusals(void **state) {
	(void)state;
	hs_scenario *s = load_text("resume.yaml", resume_spring);
	FILE *f = tmpfile();
	assert_non_null(f);
	fputs("frame,t,object\n", f);
	rewind(f);
	hs_error err;
	assert_int_equal(hs_scenario_resume(s, f, &err), HS_ERR_STATE_MISMATCH);
	assert_string_equal(err.message, "state file: not a handspring state file");
	fclose(f);
	hs_scenario *other = load_text("other.yaml", resume_hand);
	f = tmpfile();
	assert_non_null(f);
	assert_int_equal(hs_scenario_save(other, f, &err), HS_OK);
	rewind(f);
	assert_int_equal(hs_scenario_resume(s, f, &err), HS_ERR_STATE_MISMATCH);
	assert_string_equal(err.message, "state file: saved from scenario 'other', not 'resume'");
	fclose(f);
	assert_true(hs_scenario_step(s)); // the scenario is unchanged and runs
	hs_scenario_destroy(other);
	hs_scenario_destroy(s);
}

// Objects that overlap at load are refused, naming two of them (harness/overlap.c): 10,000 cubes at
// one point answer at once; touching objects (a stack, a row side by side, a tilted cube on its
// edge against another) and an overlap within the 1 mm tolerance load.
static void test_overlap(void **state) {
	(void)state;
	const char *head = "description: objects at load\ndt: 1/60\nduration: 0.1\nobjects:\n";
	char *text = NULL;
	size_t size = 0;
	FILE *f = open_memstream(&text, &size);
	assert_non_null(f);
	fputs(head, f);
	for (int i = 0; i < 10000; ++i)
		fprintf(f, "  - { name: c%d, shape: cube, size: 0.05, position: [0, 0, 0.025] }\n", i);
	fclose(f);
	load_error("crowd.yaml", text, "6: objects 'c0' (line 5) and 'c1' overlap: a point of one lies 25 mm inside the other "
	                               "(objects may touch, not overlap by more than 1 mm)");
	free(text);
	char touching[2048];
	snprintf(touching, sizeof touching,
	         "%s  - { name: a, shape: cube, size: 0.05, position: [0, 0, 0.025] }\n"
	         "  - { name: b, shape: cube, size: 0.05, position: [0, 0, 0.075] }\n"
	         "  - { name: c, shape: cube, size: 0.05, position: [0.05, 0, 0.025] }\n"
	         "  - { name: d, shape: cube, size: 0.05, position: [0.1, 0, 0.0255] }\n"
	         "  - { name: e, shape: cube, size: 0.05, position: [0.1, 0, 0.0755], rpy_deg: [0, 0, 45] }\n"
	         "  - { name: f, shape: box, size: [0.1, 0.02, 0.02], position: [0.3, 0, 0.01] }\n"
	         "  - { name: g, shape: box, size: [0.02, 0.1, 0.02], position: [0.3, 0, 0.0295] }\n",
	         head);
	hs_scenario_destroy(load_text("touching.yaml", touching));
}

// still with `to`: the pose may change after the window
static void test_still_window(void **state) {
	(void)state;
	expect_pass("{ object: base, still: true, from: 0.5, to: 1.0 }", "still true from t = 0.5 s to t = 1 s: unchanged");
	expect_fail("{ object: high, still: true, from: 0.5, to: 0.6 }", "moved at frame 31 ");
	// the crate waits for the spring until 0.2 s, then rises: still before, not after
	spring_pass("{ object: crate, still: true, from: 0, to: 0.2 }", "unchanged");
	spring_fail("{ object: crate, still: true, from: 0, to: 0.5 }", "moved at frame ");
}

// ---------------------------------------------------------------------------------------------
// Real input: upper bounds, contact watches, load options and the robust sweep
// (scenarios/README.md "Expectations", "Robustness")

// a cube dropped tilted 30 deg about x: it lands on an edge and falls onto a face
static const char tilt_scenario[] = "description: a tilted cube dropped\n"
                                    "dt: 1/60\n"
                                    "duration: 1.5\n"
                                    "objects:\n"
                                    "  - { name: tilt, shape: cube, size: 0.1, position: [0, 0, 0.5], rpy_deg: [30, 0, 0] }\n"
                                    "expect:\n";

static void test_upper_bounds(void **state) {
	(void)state;
	expect_pass("{ object: block, at: end, moved_at_most: 0.5 }", "block moved at most 0.5 m at end (t = 1.5 s): moved 0.45 m");
	expect_fail("{ object: block, at: end, moved_at_most: 0.1 }", "block moved at most 0.1 m at end (t = 1.5 s): moved 0.45 m");
	expect_pass("{ object: block, at: end, turned_at_most_deg: 0 }", "block turned at most 0 deg at end (t = 1.5 s): turned 0 deg");
	expect_pass("{ object: block, at: end, moved: 0.4 }", "moved at least 0.4 m"); // the lower bound unchanged
	char report[4096];
	assert_int_equal(check_in(tilt_scenario, "tilt.yaml", "{ object: tilt, at: end, turned_at_most_deg: 1 }", report,
	                          sizeof report),
	                 1);
	assert_string_equal(report, "FAIL  line 7: tilt turned at most 1 deg at end (t = 1.5 s): turned 30 deg\n");
	assert_int_equal(check_in(tilt_scenario, "tilt.yaml", "{ object: tilt, at: end, turned_at_most_deg: 31 }", report,
	                          sizeof report),
	                 0);
}

// face_down: which face an object rests on (a face's outward normal in its own frame, any length)
static void test_face_down(void **state) {
	(void)state;
	char report[4096];
	// the tilted cube ends flat on the face that was its bottom
	assert_int_equal(check_in(tilt_scenario, "tilt.yaml", "{ object: tilt, at: end, face_down: [0, 0, -2] }", report,
	                          sizeof report),
	                 0);
	assert_int_equal(check_in(tilt_scenario, "tilt.yaml", "{ object: tilt, at: end, face_down: [0, 1, 0] }", report,
	                          sizeof report),
	                 1);
	assert_string_equal(report, "FAIL  line 7: tilt face_down [0, 1, 0] at end (t = 1.5 s): that normal 90 deg from "
	                            "straight down, floor_contacts 4\n");
	// in the air, turned 30 deg: neither on a face nor with that normal down
	assert_int_equal(check_in(tilt_scenario, "tilt.yaml", "{ object: tilt, at: 0, face_down: [0, 0, -1] }", report,
	                          sizeof report),
	                 1);
	assert_string_equal(report, "FAIL  line 7: tilt face_down [0, 0, -1] at t = 0 s: that normal 30 deg from "
	                            "straight down, floor_contacts 0\n");
}

// Paper mode (§4.3) carries what interferes with a held object by its rigid motion, turn included:
// hand/stack_lift_pair_paper's hand turns 10 deg about the vertical while it holds the bar up. The
// cube on the bar, its G at (0, -0.06, 0.045) from the bar's, must end at the bar's G plus that
// offset turned by 10 deg about z, (0.06 sin 10, -0.06 cos 10, 0.045), and turned 10 deg itself: it
// stays where it sat on the bar. (Translated by the bar's displacement only, it would be 1 cm off
// and unturned.) The bar's end is where the hand's grip took it (pinned as measured).
static const char carry_turn_scenario[] =
    "description: a held bar turns and carries the cube on it\n"
    "dt: 1/60\n"
    "duration: 1.6\n"
    "model: { stacking: paper }\n"
    "objects:\n"
    "  - { name: lower, shape: box, size: [0.05, 0.2, 0.05], position: [0, 0, 0.025] }\n"
    "  - { name: upper, shape: cube, size: 0.04, position: [0, -0.06, 0.07] }\n"
    "hands:\n"
    "  - name: right\n"
    "    keys:\n"
    "      - { t: 0.0, grip: [0.004, 0.06, 0.208], rpy_deg: [0, 0, 0], posture: { grasp: 0.12 } }\n"
    "      - { t: 0.5, grip: [0.004, 0.06, 0.058] }\n"
    "      - { t: 0.6 }\n"
    "      - { t: 0.605, grip: [0, 0.06, 0.043], posture: { grasp: 0.035 } }\n"
    "      - { t: 0.7 }\n"
    "      - { t: 1.2, grip: [0, 0.06, 0.143] }\n"
    "      - { t: 1.4, rpy_deg: [0, 0, 10] }\n"
    "expect:\n"
    "  - { object: lower, at: end, near: [0.006242324910926, 0.018630177935619, 0.125], tolerance: 1e-9 }\n";

static void test_paper_carry_turns(void **state) {
	(void)state;
	char report[4096];
	assert_int_equal(check_in(carry_turn_scenario, "carry.yaml",
	                          "{ object: upper, at: end, near: [0.016661215570942, -0.040458287245113, 0.17], tolerance: 1e-9 }",
	                          report, sizeof report),
	                 0);
	assert_int_equal(check_in(carry_turn_scenario, "carry.yaml", "{ object: upper, at: end, turned_deg: 9.999999 }", report,
	                          sizeof report),
	                 0);
	assert_int_equal(check_in(carry_turn_scenario, "carry.yaml", "{ object: upper, at: end, turned_at_most_deg: 10.000001 }",
	                          report, sizeof report),
	                 0);
}

static void test_contact_watch(void **state) {
	(void)state;
	expect_pass("{ object: block, never_contact: 2 }", "block never_contact 2 from t = 0 s to t = 1.5 s: never in state 2");
	expect_fail("{ object: block, never_contact: 0 }", "never_contact 0 from t = 0 s to t = 1.5 s: contact state 0 at frame 0 (t = 0 s)");
	expect_fail("{ object: block, never_contact: 0, from: 1, to: 1.2 }", "contact state 0 at frame 60 (t = 1 s)");
	expect_fail("{ object: block, grasped: true, from: 0.5, to: 1 }",
	            "block grasped (contact state 2) from t = 0.5 s to t = 1 s: contact state 0 at frame 30 (t = 0.5 s)");
	// a hand that holds a cube from t = 0.61 s to 1.9 s (the catalog scenario, with one more clause)
	const char *text = catalog_text("scenarios/hand/grasp_adjoining_faces.yaml");
	char report[4096];
	assert_int_equal(check_in(text, "grasp_adjoining_faces.yaml", "{ object: cube, grasped: true, from: 1, to: 1.5 }",
	                          report, sizeof report),
	                 0);
	assert_non_null(strstr(report, "cube grasped (contact state 2) from t = 1 s to t = 1.5 s: grasped on every frame"));
	assert_int_equal(check_in(text, "grasp_adjoining_faces.yaml", "{ object: cube, grasped: true, from: 0.5, to: 1.5 }",
	                          report, sizeof report),
	                 1);
	assert_non_null(strstr(report, "contact state 0 at frame 30 (t = 0.5 s)"));
	assert_int_equal(check_in(text, "grasp_adjoining_faces.yaml", "{ object: cube, never_contact: 3 }", report,
	                          sizeof report),
	                 0);
}

// contact_sequence's min_s: a state held for less is left out. In hand/push_off_centre the tip
// pushes for frames 23-30, reads 0 for frame 31 (resting on the face of a box that moved the frame
// before) and 1 again for frames 32-36, then draws back.
static void test_contact_sequence_min_s(void **state) {
	(void)state;
	const char *text = catalog_text("scenarios/hand/push_off_centre.yaml");
	static const struct {
		const char *clause, *measured;
	} cases[] = {
	    {"{ object: box, contact_sequence: [0, 1, 0, 1, 0] }", "contact_sequence [0, 1, 0, 1, 0]: [0, 1, 0, 1, 0]"},
	    {"{ object: box, contact_sequence: [0, 1, 0], min_s: 0.05 }", "(states held 3 frames or more): [0, 1, 0]"},
	    {"{ object: box, contact_sequence: [0, 1, 0], min_s: 0.1 }", "(states held 6 frames or more): [0, 1, 0]"},
	    {"{ object: box, contact_sequence: [0], min_s: 0.15 }", "(states held 9 frames or more): [0]"},
	};
	char report[8192];
	for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
		int failed = check_in(text, "push_off_centre.yaml", cases[k].clause, report, sizeof report);
		if (failed != 0 || !strstr(report, cases[k].measured))
			fail_msg("%s: expected '%s', got:\n%s", cases[k].clause, cases[k].measured, report);
	}
	assert_int_equal(check_in(text, "push_off_centre.yaml", "{ object: box, contact_sequence: [0, 1, 0] }", report,
	                          sizeof report),
	                 1);
	load_error("m.yaml", "name: m\ndescription: d\ndt: 1/60\nduration: 1\nobjects:\n  - { name: a, shape: cube, size: 0.1, position: [0, 0, 0.05] }\n"
	           "expect:\n  - { object: a, at: end, resting: true, min_s: 0.1 }\n",
	           "8: 'min_s' is only for 'contact_sequence'");
}

// hs_scenario_load_with: --dt replaces the file's, the frames follow; a noise seed changes the run.
static void test_load_options(void **state) {
	(void)state;
	char text[4096];
	snprintf(text, sizeof text, "%s  - { object: block, at: 1.0, below: 1 }\n", drop_scenario);
	const char *path = write_file("drop.yaml", text);
	hs_error err;
	hs_scenario_options o = {.dt = 1.0 / 30.0};
	hs_scenario *s = hs_scenario_load_with(path, &o, &err);
	assert_non_null(s);
	assert_true(hs_scenario_dt(s) == 1.0 / 30.0);
	assert_int_equal(hs_scenario_frame_count(s), 45);
	FILE *f = tmpfile();
	assert_non_null(f);
	assert_int_equal(hs_scenario_save(s, f, &err), HS_ERR_INVALID_ARGUMENT); // the file alone cannot name this run
	assert_string_equal(err.message, "state file: a run loaded with a dt or noise seed option cannot be saved");
	assert_int_equal(hs_scenario_resume(s, f, &err), HS_ERR_INVALID_ARGUMENT);
	fclose(f);
	hs_scenario_destroy(s);
	double dt = 0.0;
	assert_true(hs_scenario_parse_dt("1/12", &dt) && dt == 1.0 / 12.0);
	assert_true(hs_scenario_parse_dt("0.01", &dt) && dt == 0.01);
	assert_false(hs_scenario_parse_dt("1/7", &dt));
	assert_false(hs_scenario_parse_dt("1/0", &dt));
	assert_false(hs_scenario_parse_dt("x", &dt));
	// hand input: the same seed twice gives the same run, another seed or none another
	snprintf(text, sizeof text, "description: noisy hand\ndt: 1/60\nduration: 0.5\n" ONE_CUBE ONE_HAND);
	path = write_file("hand.yaml", text);
	uint64_t hash[4];
	for (int i = 0; i < 4; ++i) {
		hs_scenario_options n = {.noise = i > 0, .noise_seed = i == 3 ? 2u : 1u};
		s = hs_scenario_load_with(path, &n, &err);
		assert_non_null(s);
		run_all(s);
		hash[i] = hs_world_hash(hs_scenario_world(s));
		hs_scenario_destroy(s);
	}
	assert_true(hash[1] == hash[2]);
	assert_true(hash[0] != hash[1] && hash[1] != hash[3]);
	// the stylus: tracker noise on
	snprintf(text, sizeof text, "%s  - { object: crate, at: end, above: 0 }\n", spring_scenario);
	path = write_file("spring.yaml", text);
	for (int i = 0; i < 2; ++i) {
		hs_scenario_options n = {.noise = i > 0, .noise_seed = 5};
		s = hs_scenario_load_with(path, &n, &err);
		assert_non_null(s);
		run_all(s);
		hash[i] = hs_world_hash(hs_scenario_world(s));
		hs_scenario_destroy(s);
	}
	assert_true(hash[0] != hash[1]);
}

// The sweep's table: `robust` clauses in every cell, the others at the nominal run only.
static char *sweep_of(const char *clauses, int *status) {
	char text[4096];
	snprintf(text, sizeof text,
	         "description: a dropped cube\ndt: 1/60\nduration: 1.5\nrobust: { dt: [1/12, 1/60], seeds: 2 }\n"
	         "objects:\n  - { name: block, shape: cube, size: 0.1, position: [0, 0, 0.5] }\nexpect:\n%s",
	         clauses);
	const char *path = write_file("sweep.yaml", text);
	char *buf = NULL;
	size_t size = 0;
	FILE *out = open_memstream(&buf, &size);
	assert_non_null(out);
	hs_error err;
	*status = hs_scenario_sweep(path, out, &err);
	fclose(out);
	return buf;
}

static void test_sweep(void **state) {
	(void)state;
	int status;
	char *table = sweep_of("  - { object: block, at: end, near: [0, 0, 0.05], tolerance: 1e-9 }\n"
	                       "  - { object: block, at: end, resting: true, robust: true }\n"
	                       "  - { object: block, lands_at: 0.3, tolerance: 0.05, robust: true }\n",
	                       &status);
	assert_string_equal(table, "sweep sweep: 2 dt x 2 seeds, no hand or stylus input to add noise to\n"
	                           "dt              1      2\n"
	                           "1/12           ok     ok\n"
	                           "1/60           ok     ok\n"
	                           "nominal (the file's dt, every clause): ok\n"
	                           "sweep: 4 of 4 cells pass\n");
	assert_int_equal(status, 0);
	free(table);
	// landing within 0.02 s of 0.3 s: frame 19 of 1/60 (0.3167 s) is, frame 4 of 1/12 (0.3333 s) is not
	table = sweep_of("  - { object: block, at: end, resting: true, robust: true }\n"
	                 "  - { object: block, lands_at: 0.3, tolerance: 0.02, robust: true }\n",
	                 &status);
	assert_string_equal(table, "sweep sweep: 2 dt x 2 seeds, no hand or stylus input to add noise to\n"
	                           "dt              1      2\n"
	                           "1/12           L9     L9\n"
	                           "1/60           ok     ok\n"
	                           "nominal (the file's dt, every clause): ok\n"
	                           "sweep: 2 of 4 cells pass\n");
	assert_int_equal(status, 1);
	free(table);
	// a clause without `robust` that fails only in cells does not count there
	table = sweep_of("  - { object: block, lands_at: 0.3, tolerance: 0.02 }\n", &status);
	assert_non_null(strstr(table, "sweep: 4 of 4 cells pass\n"));
	assert_int_equal(status, 0);
	free(table);
	// no robust block: bad input
	const char *path = write_file("plain.yaml", "description: plain\ndt: 1/60\nduration: 0.1\n" ONE_CUBE);
	hs_error err;
	assert_int_equal(hs_scenario_sweep(path, stdout, &err), 2);
	char want[600];
	snprintf(want, sizeof want, "%s: no 'robust' block: nothing to sweep", path);
	assert_string_equal(err.message, want);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_dt_fraction),
	    cmocka_unit_test(test_defaults),
	    cmocka_unit_test(test_orientation_and_model),
	    cmocka_unit_test(test_polyhedron),
	    cmocka_unit_test(test_load_errors),
	    cmocka_unit_test(test_near),
	    cmocka_unit_test(test_resting_and_contacts),
	    cmocka_unit_test(test_below_above_and_at),
	    cmocka_unit_test(test_lands_at),
	    cmocka_unit_test(test_still),
	    cmocka_unit_test(test_contact_sequence),
	    cmocka_unit_test(test_overlap_at_most),
	    cmocka_unit_test(test_energy_never_grows),
	    cmocka_unit_test(test_contact_sequence_min_s),
	    cmocka_unit_test(test_every_object),
	    cmocka_unit_test(test_check_before_the_end),
	    cmocka_unit_test(test_trajectory_rows),
	    cmocka_unit_test(test_compare),
	    cmocka_unit_test(test_catalog),
	    cmocka_unit_test(test_stylus_keys),
	    cmocka_unit_test(test_stylus_record),
	    cmocka_unit_test(test_spring_options),
	    cmocka_unit_test(test_attached_and_candidate),
	    cmocka_unit_test(test_extension_and_spring_constants),
	    cmocka_unit_test(test_release_speed_velocity),
	    cmocka_unit_test(test_conserved_and_swing),
	    cmocka_unit_test(test_spring_load_errors),
	    cmocka_unit_test(test_still_window),
	    cmocka_unit_test(test_noise_draws),
	    cmocka_unit_test(test_stylus_noise),
	    cmocka_unit_test(test_input_noise),
	    cmocka_unit_test(test_numeric_fault_fails),
	    cmocka_unit_test(test_dt_ranges_nest),
	    cmocka_unit_test(test_save_and_resume),
	    cmocka_unit_test(test_resume_refusals),
	    cmocka_unit_test(test_overlap),
	    cmocka_unit_test(test_upper_bounds),
	    cmocka_unit_test(test_face_down),
	    cmocka_unit_test(test_paper_carry_turns),
	    cmocka_unit_test(test_contact_watch),
	    cmocka_unit_test(test_load_options),
	    cmocka_unit_test(test_sweep),
	    cmocka_unit_test(test_hand_trace_rows),
	    cmocka_unit_test(test_hand_trace_spring),
	    cmocka_unit_test_setup_teardown(test_key_places_finger_part, make_temp_dir, remove_temp_dir),
	    cmocka_unit_test(test_joint_input_matches_glove),
	    cmocka_unit_test_setup_teardown(test_joint_input_errors, make_temp_dir, remove_temp_dir),
	};
	return cmocka_run_group_tests_name("scenario", tests, make_temp_dir, remove_temp_dir);
}
