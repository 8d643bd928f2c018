// test_bad_input.c — bad scenario input ends with one clear message (file:line: what), exit
// status 2, no crash, no leak. Every tests/bad/*.yaml starts with "# expect: <exact stderr line>";
// the tool ($HS_TOOL, default build/handspring) and hs_scenario_load must both give that line.
// A file that starts with "# warning: <line>" loads with that one warning: `run` prints it and runs
// on, `run --strict` prints it and exits 2 without running; the catalog loads without any.
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <signal.h>
#include <cmocka.h>

#include "test_util.h"

#include <dirent.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define BAD_DIR "tests/bad"
#define EXPECT_PREFIX "# expect: "
#define WARNING_PREFIX "# warning: "

static const char *tool_path(void) {
	const char *t = getenv("HS_TOOL");
	return t && *t ? t : "build/handspring";
}

static char *read_fd(int fd) {
	size_t cap = 256, n = 0;
	char *buf = malloc(cap);
	assert_non_null(buf);
	lseek(fd, 0, SEEK_SET);
	for (;;) {
		if (n + 1 >= cap) {
			cap *= 2;
			buf = realloc(buf, cap);
			assert_non_null(buf);
		}
		ssize_t got = read(fd, buf + n, cap - n - 1);
		if (got <= 0)
			break;
		n += (size_t)got;
	}
	buf[n] = '\0';
	return buf;
}

typedef struct tool_result {
	int status; // exit status, or -1 when the tool did not exit normally
	char *out, *err;
} tool_result;

// Runs the tool with `args` (NULL-terminated, without argv[0]); stdout and stderr go to temp files.
static tool_result run_tool(const char *const *args) {
	char out_name[] = "/tmp/hs_bad_out_XXXXXX", err_name[] = "/tmp/hs_bad_err_XXXXXX";
	int out = mkstemp(out_name), err = mkstemp(err_name);
	assert_true(out >= 0 && err >= 0);
	unlink(out_name);
	unlink(err_name);
	const char *argv[16];
	int argc = 0;
	argv[argc++] = tool_path();
	for (int i = 0; args[i] && argc < 15; ++i)
		argv[argc++] = args[i];
	argv[argc] = NULL;
	fflush(stdout);
	fflush(stderr);
	pid_t pid = fork();
	assert_true(pid >= 0);
	if (pid == 0) {
		dup2(out, 1);
		dup2(err, 2);
		execv(argv[0], (char *const *)argv);
		_exit(127);
	}
	int wstatus = 0;
	assert_int_equal(waitpid(pid, &wstatus, 0), pid);
	tool_result r = {WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1, read_fd(out), read_fd(err)};
	close(out);
	close(err);
	if (r.status == 127)
		print_error("could not run %s (set HS_TOOL to the built tool)\n", argv[0]);
	return r;
}

static void free_result(tool_result *r) {
	free(r->out);
	free(r->err);
}

// The tool and the library both report `expected` for `path`.
static void expect_bad(const char *path, const char *expected) {
	const char *args[] = {"run", path, NULL};
	tool_result r = run_tool(args);
	char *want = malloc(strlen(expected) + 2);
	assert_non_null(want);
	strcpy(want, expected);
	strcat(want, "\n");
	if (strcmp(r.err, want) != 0)
		print_error("%s:\n  stderr:   %s  expected: %s", path, r.err, want);
	assert_string_equal(r.err, want);
	assert_string_equal(r.out, ""); // nothing half-run on stdout
	assert_int_equal(r.status, 2);
	free(want);
	free_result(&r);

	hs_error err;
	memset(&err, 'x', sizeof err);
	hs_scenario *s = hs_scenario_load(path, &err);
	assert_null(s);
	assert_string_equal(err.message, expected);
}

// The tool warns with `expected` for `path` and runs on (with --strict: refuses, status 2); the
// library loads it with that one warning.
static void expect_warning(const char *path, const char *expected) {
	char want[1100];
	snprintf(want, sizeof want, "%s\n", expected);
	const char *strict[] = {"run", "--strict", path, NULL}, *plain[] = {"run", path, NULL};
	tool_result r = run_tool(strict);
	if (strcmp(r.err, want) != 0)
		print_error("%s --strict:\n  stderr:   %s  expected: %s", path, r.err, want);
	assert_string_equal(r.err, want);
	assert_string_equal(r.out, "");
	assert_int_equal(r.status, 2);
	free_result(&r);
	r = run_tool(plain);
	assert_string_equal(r.err, want);
	assert_non_null(strstr(r.out, "PASS\n")); // the run went on; its status is the expectations'
	assert_int_equal(r.status, 0);
	free_result(&r);
	hs_error err;
	hs_scenario *s = hs_scenario_load(path, &err);
	assert_non_null(s);
	assert_string_equal(hs_scenario_warnings(s), want);
	hs_scenario_destroy(s);
}

// ---------------------------------------------------------------------------------------------
// the corpus: one test per file

static void test_corpus_file(void **state) {
	const char *path = *state;
	FILE *f = fopen(path, "rb");
	assert_non_null(f);
	char line[1024] = "";
	char *got = fgets(line, sizeof line, f);
	fclose(f);
	assert_non_null(got);
	line[strcspn(line, "\r\n")] = '\0';
	if (strncmp(line, WARNING_PREFIX, strlen(WARNING_PREFIX)) == 0)
		expect_warning(path, line + strlen(WARNING_PREFIX));
	else if (strncmp(line, EXPECT_PREFIX, strlen(EXPECT_PREFIX)) != 0)
		fail_msg("%s: the first line must be '" EXPECT_PREFIX "<exact stderr line>' (or '" WARNING_PREFIX "...')", path);
	else
		expect_bad(path, line + strlen(EXPECT_PREFIX));
}

static int compare_strings(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

// ---------------------------------------------------------------------------------------------
// files that cannot be committed, or depend on the machine

static char *temp_path(const char *name) {
	char *p = malloc(256);
	assert_non_null(p);
	snprintf(p, 256, "/tmp/hs_bad_%ld_%s", (long)getpid(), name);
	return p;
}

static void write_bytes(const char *path, const void *data, size_t n) {
	FILE *f = fopen(path, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(data, 1, n, f), n);
	assert_int_equal(fclose(f), 0);
}

static void test_directory(void **state) {
	(void)state;
	expect_bad(BAD_DIR, BAD_DIR ":1: cannot read: Is a directory");
}

static void test_missing_file(void **state) {
	(void)state;
	char *path = temp_path("missing.yaml");
	char want[512];
	snprintf(want, sizeof want, "%s:1: cannot read: No such file or directory", path);
	expect_bad(path, want);
	free(path);
}

static void test_binary_file(void **state) {
	(void)state;
	static const unsigned char elf[] = {0x7f, 'E', 'L', 'F', 2, 1, 1, 0, 0, 0, '\n', 0xff, 0xfe, 0x00, 0x12};
	char *path = temp_path("binary.yaml");
	write_bytes(path, elf, sizeof elf);
	char want[512];
	snprintf(want, sizeof want, "%s:1: not a text file (NUL byte at byte 7)", path);
	expect_bad(path, want);
	remove(path);
	free(path);
}

static void test_invalid_utf8(void **state) {
	(void)state;
	static const char text[] = "description: ok\ndt: 1/60 \xff\xfe\nduration: 1\n";
	char *path = temp_path("utf8.yaml");
	write_bytes(path, text, sizeof text - 1);
	char want[512];
	snprintf(want, sizeof want, "%s:2: not a text file: invalid leading UTF-8 octet (byte 25)", path);
	expect_bad(path, want);
	remove(path);
	free(path);
}

static const char valid_scenario[] = "# a valid scenario, cut and damaged below\n"
                                     "description: truncation and damage must never crash\n"
                                     "dt: 1/60\n"
                                     "duration: 0.1\n"
                                     "model: { stacking: support, floor_tolerance: 1e-6 }\n"
                                     "objects:\n"
                                     "  - name: a\n"
                                     "    shape: l_block\n"
                                     "    size: [0.1, 0.05, 0.1]\n"
                                     "    thickness: 0.02\n"
                                     "    position: [0, 0, 0.2]\n"
                                     "    rpy_deg: [0, 10, 0]\n"
                                     "  - { name: b, shape: polyhedron, vertices: [[0,0,0],[1,0,0],[0,1,0],[0,0,1]],\n"
                                     "      faces: [[0,2,1],[0,1,3],[0,3,2],[1,2,3]], position: [1, 0, 1] }\n"
                                     "expect:\n"
                                     "  - { object: '*', at: end, above: 0 }\n"
                                     "  - { object: a, lands_at: 0.05, tolerance: 1 }\n";

// A loaded scenario, or exactly one "PATH:LINE: ..." message.
static void expect_clean_outcome(const char *path) {
	hs_error err;
	hs_scenario *s = hs_scenario_load(path, &err);
	if (s) {
		while (hs_scenario_step(s)) {
		}
		hs_scenario_check(s, NULL);
		hs_scenario_destroy(s);
		return;
	}
	size_t n = strlen(path);
	assert_memory_equal(err.message, path, n);
	assert_int_equal(err.message[n], ':');
	const char *p = err.message + n + 1;
	assert_true(*p >= '1' && *p <= '9');
	while (*p >= '0' && *p <= '9')
		++p;
	assert_int_equal(p[0], ':');
	assert_int_equal(p[1], ' ');
	assert_true(strlen(p) > 3);
	assert_null(strchr(err.message, '\n'));
}

static void test_every_truncation(void **state) {
	(void)state;
	char *path = temp_path("cut.yaml");
	size_t n = sizeof valid_scenario - 1;
	write_bytes(path, valid_scenario, n);
	hs_error err;
	hs_scenario *s = hs_scenario_load(path, &err);
	if (!s)
		fail_msg("the uncut scenario must load: %s", err.message);
	hs_scenario_destroy(s);
	for (size_t cut = 0; cut < n; ++cut) {
		write_bytes(path, valid_scenario, cut);
		expect_clean_outcome(path);
	}
	remove(path);
	free(path);
}

static void test_damaged_bytes(void **state) {
	(void)state;
	static const char damage[] = {'[', ']', '{', ':', '-', '\t', '"', '*', '&', '!', '#', 'x', '9', '\n'};
	char *path = temp_path("damaged.yaml");
	size_t n = sizeof valid_scenario - 1;
	char *copy = malloc(n);
	assert_non_null(copy);
	for (size_t i = 0; i < n; i += 3) {
		for (size_t d = 0; d < sizeof damage; ++d) {
			memcpy(copy, valid_scenario, n);
			copy[i] = damage[d];
			write_bytes(path, copy, n);
			expect_clean_outcome(path);
		}
	}
	free(copy);
	remove(path);
	free(path);
}

// The process's CPU time: what the loader spends, not how busy the machine is.
static double seconds_now(void) {
	struct timespec ts;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

// hs_scenario_load fails with `expected` (after the path) within `limit` seconds of CPU time. The
// limits catch what these inputs once did (reading without end, a quadratic scan of over a minute)
// with a margin of 10 or more over a loaded machine's time.
static void expect_fast_failure(const char *path, const char *expected, double limit) {
	hs_error err;
	double t0 = seconds_now();
	hs_scenario *s = hs_scenario_load(path, &err);
	double took = seconds_now() - t0;
	assert_null(s);
	assert_string_equal(err.message, expected);
	print_message("%s: refused in %.4f s\n", path, took);
	assert_true(took < limit);
}

// 200,000 nested '[' (400 kB with the closing ones): libyaml's scanner is quadratic in flow depth
// (the loader took over a minute); the depth pass stops at the 9th level.
static void test_deep_flow_nesting(void **state) {
	(void)state;
	char *path = temp_path("deep.yaml");
	static const char head[] = "description: deep\ndt: 1/60\nduration: 1\nobjects: ";
	size_t depth = 200000, n = sizeof head - 1;
	char *text = malloc(n + 2 * depth + 1);
	assert_non_null(text);
	memcpy(text, head, n);
	memset(text + n, '[', depth);
	memset(text + n + depth, ']', depth);
	text[n + 2 * depth] = '\n';
	write_bytes(path, text, n + 2 * depth + 1);
	free(text);
	char want[512];
	snprintf(want, sizeof want, "%s:4: nested deeper than 8 levels", path);
	expect_fast_failure(path, want, 2.0);
	remove(path);
	free(path);
}

// A recorded file that is /dev/zero (no line breaks, no end) or a FIFO without a writer: an error
// at once, naming the limit, instead of reading forever or waiting for a writer.
static void test_endless_records(void **state) {
	(void)state;
	char *yaml = temp_path("zero.yaml"), want[512];
	static const char head[] = "description: endless\ndt: 1/60\nduration: 1\n"
	                           "objects:\n  - { name: a, shape: cube, size: 0.1, position: [0, 0, 0.05] }\n";
	char text[1024];
	snprintf(text, sizeof text, "%shands:\n  - { name: right, record: /dev/zero }\n", head);
	write_bytes(yaml, text, strlen(text));
	expect_fast_failure(yaml, "/dev/zero:1: line longer than 16 MiB (the limit for recorded input)", 5.0);
	snprintf(text, sizeof text, "%sstylus: { record: /dev/zero }\n", head);
	write_bytes(yaml, text, strlen(text));
	expect_fast_failure(yaml, "/dev/zero:1: line longer than 16 MiB (the limit for recorded stylus input)", 5.0);
	char *fifo = temp_path("fifo.csv");
	remove(fifo);
	assert_int_equal(mkfifo(fifo, 0600), 0);
	snprintf(text, sizeof text, "%sstylus: { record: %s }\n", head, fifo);
	write_bytes(yaml, text, strlen(text));
	snprintf(want, sizeof want,
	         "%s:1: empty recorded stylus input: the header t,x,y,z,qw,qx,qy,qz,button is missing", fifo);
	expect_fast_failure(yaml, want, 5.0);
	// a FIFO that never ends: the header, then comment lines without end: refused at 256 MiB. The
	// writer holds the FIFO open read-write (so it is connected before the loader opens it, and never
	// sees EPIPE): it is killed when the loader is done.
	int fd = open(fifo, O_RDWR);
	assert_true(fd >= 0);
	pid_t writer = fork();
	assert_true(writer >= 0);
	if (writer == 0) {
		static char line[1024];
		memset(line, '#', sizeof line - 1);
		line[sizeof line - 1] = '\n';
		static const char header[] = "t,x,y,z,qw,qx,qy,qz,button\n";
		if (write(fd, header, sizeof header - 1) < 0)
			_exit(1);
		while (write(fd, line, sizeof line) > 0) {
		}
		_exit(0);
	}
	close(fd);
	hs_error err;
	double t0 = seconds_now();
	hs_scenario *s = hs_scenario_load(yaml, &err);
	double took = seconds_now() - t0;
	kill(writer, SIGKILL); // first: a failed assertion below must not leave it writing forever
	int wstatus;
	assert_int_equal(waitpid(writer, &wstatus, 0), writer);
	assert_null(s);
	print_message("%s (a FIFO without end): refused in %.4f s\n", fifo, took);
	static const char tail[] = ": file larger than 256 MiB (the limit for recorded stylus input)";
	size_t n = strlen(fifo), m = strlen(err.message);
	assert_memory_equal(err.message, fifo, n); // the line depends on how the pipe delivers: not checked
	assert_true(m > sizeof tail && strcmp(err.message + m - (sizeof tail - 1), tail) == 0);
	assert_true(took < 5.0);
	// a scenario file that is a FIFO without a writer reads as empty
	snprintf(want, sizeof want, "%s:1: empty file: a scenario needs description, dt, duration and objects", fifo);
	expect_fast_failure(fifo, want, 5.0);
	remove(fifo);
	remove(yaml);
	free(fifo);
	free(yaml);
}

static char *read_text(const char *path) {
	FILE *f = fopen(path, "rb");
	assert_non_null(f);
	int fd = fileno(f);
	char *text = read_fd(fd);
	fclose(f);
	return text;
}

// handspring run --save-at F --state-out S, then --resume S --out REST: REST is the header and the
// full run's rows after frame F, byte for byte, and the report is the full run's.
static void test_tool_resume(void **state) {
	(void)state;
	const char *scenario = "scenarios/spring/select_among_three.yaml"; // seeded input noise
	char *full = temp_path("full.csv"), *st = temp_path("state.bin"), *rest = temp_path("rest.csv");
	const char *save[] = {"run", scenario, "--save-at", "100", "--state-out", st, NULL};
	tool_result r = run_tool(save);
	assert_true(r.status == 0 || r.status == 1); // the save run ran (expectations aside)
	free_result(&r);
	const char *whole[] = {"run", scenario, "--out", full, NULL}, *resume[] = {"run", scenario, "--resume", st, "--out", rest, NULL};
	tool_result a = run_tool(whole), b = run_tool(resume);
	assert_int_equal(a.status, b.status);
	char *fa = read_text(full), *fb = read_text(rest);
	const char *rows = strchr(fa, '\n') + 1, *header_end = rows;
	while (*rows && strtol(rows, NULL, 10) <= 100)
		rows = strchr(rows, '\n') + 1;
	size_t header = (size_t)(header_end - fa);
	assert_memory_equal(fb, fa, header);
	assert_string_equal(fb + header, rows);
	// the reports agree but for the lines that name the files
	char *pa = strstr(a.out, "frames:"), *pb = strstr(b.out, "frames:");
	assert_non_null(pa);
	assert_non_null(pb);
	*strstr(pa, "trajectory:") = '\0';
	*strstr(pb, "resumed from:") = '\0';
	assert_string_equal(pa, pb);
	free(fa), free(fb);
	free_result(&a), free_result(&b);
	remove(full), remove(st), remove(rest);
	free(full), free(st), free(rest);
}

// --out - writes the trajectory to stdout (the summary goes to stderr), not to a file named '-'.
static void test_out_stdout(void **state) {
	(void)state;
	const char *args[] = {"run", "scenarios/drop_cube.yaml", "--out", "-", NULL};
	tool_result r = run_tool(args);
	assert_int_equal(r.status, 0);
	assert_true(strncmp(r.out, "frame,t,object,", 15) == 0);
	assert_non_null(strstr(r.err, "trajectory: stdout\nPASS\n"));
	assert_int_equal(access("-", F_OK), -1);
	free_result(&r);
}

// Usage errors: a message and exit status 2; --help: exit status 0.
static void test_usage(void **state) {
	(void)state;
	static const char *const cases[][8] = {
	    {NULL},
	    {"frobnicate", NULL},
	    {"run", NULL},
	    {"run", "a.yaml", "b.yaml", NULL},
	    {"run", "--bogus", "a.yaml", NULL},
	    {"run", "a.yaml", "--out", NULL},
	    {"list", "--dir", NULL},
	    {"all", "extra", NULL},
	    {"run", "a.yaml", "--save-at", "3", NULL},
	    {"run", "a.yaml", "--save-at", "x", "--state-out", "s", NULL},
	    {"run", "a.yaml", "--dt", "1/7", NULL},
	    {"run", "a.yaml", "--dt", NULL},
	    {"run", "a.yaml", "--noise-seed", "-1", NULL},
	    {"run", "a.yaml", "--noise-seed", "4294967296", NULL},
	    {"run", "a.yaml", "--dt", "1/60", "--resume", "s", NULL},
	    {"sweep", NULL},
	    {"sweep", "a.yaml", "--bogus", NULL},
	    {"sweep", "a.yaml", "b.yaml", NULL},
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
		tool_result r = run_tool(cases[i]);
		assert_int_equal(r.status, 2);
		assert_true(strlen(r.err) > 0);
		assert_non_null(strstr(r.err, "usage: handspring"));
		free_result(&r);
	}
	static const char *const helps[][3] = {{"--help", NULL}, {"run", "--help", NULL}, {"list", "--help", NULL},
	                                       {"all", "--help", NULL}, {"sweep", "--help", NULL}};
	for (size_t i = 0; i < sizeof helps / sizeof helps[0]; ++i) {
		tool_result r = run_tool(helps[i]);
		assert_int_equal(r.status, 0);
		assert_non_null(strstr(r.out, "usage: handspring"));
		assert_string_equal(r.err, "");
		free_result(&r);
	}
}

// Touching is not overlapping: cubes side by side, stacked and on the floor, a box turned 45 degrees
// on its edge against them, a hand whose fingers rest on the floor, a sphere in a spring world: no
// warning. And every catalog scenario loads without one.
static void test_no_warnings(void **state) {
	(void)state;
	static const char text[] =
	    "description: touching, not overlapping\ndt: 1/60\nduration: 0.1\nobjects:\n"
	    "  - { name: a, shape: cube, size: 0.1, position: [0, 0, 0.05] }\n"
	    "  - { name: b, shape: cube, size: 0.1, position: [0.1, 0, 0.05] }\n"
	    "  - { name: c, shape: cube, size: 0.1, position: [0, 0, 0.15] }\n"
	    "  - { name: d, shape: box, size: [0.1, 0.1, 0.1], rpy_deg: [45, 0, 0], position: [0, 0.12071067811865475, "
	    "0.07071067811865475] }\n"
	    "hands:\n  - name: right\n    keys:\n      - { t: 0, wrist: [0.5, 0, 0.008] }\n";
	char *path = temp_path("touching.yaml");
	write_bytes(path, text, sizeof text - 1);
	hs_error err;
	hs_scenario *s = hs_scenario_load(path, &err);
	if (!s)
		fail_msg("%s", err.message);
	assert_string_equal(hs_scenario_warnings(s), "");
	hs_scenario_destroy(s);
	remove(path);
	free(path);
	hs_catalog catalog;
	assert_true(hs_catalog_load("scenarios", &catalog, &err));
	assert_true(catalog.count > 50);
	for (int i = 0; i < catalog.count; ++i) {
		s = hs_scenario_load(catalog.paths[i], &err);
		if (!s)
			fail_msg("%s", err.message);
		if (hs_scenario_warnings(s)[0])
			fail_msg("%s warns: %s", catalog.paths[i], hs_scenario_warnings(s));
		hs_scenario_destroy(s);
	}
	hs_catalog_free(&catalog);
}

// A catalog folder that does not exist is bad input for list and all.
static void test_missing_catalog(void **state) {
	(void)state;
	char *dir = temp_path("no_such_dir");
	const char *args[] = {"all", "--dir", dir, NULL};
	tool_result r = run_tool(args);
	char want[512];
	snprintf(want, sizeof want, "%s: cannot read: No such file or directory\n", dir);
	assert_string_equal(r.err, want);
	assert_int_equal(r.status, 2);
	free_result(&r);
	const char *list_args[] = {"list", "--dir", dir, NULL};
	r = run_tool(list_args);
	assert_string_equal(r.err, want);
	assert_int_equal(r.status, 2);
	free_result(&r);
	free(dir);
}

int main(void) {
	// one test per corpus file, in name order
	DIR *d = opendir(BAD_DIR);
	if (!d) {
		fprintf(stderr, "test_bad_input: cannot open " BAD_DIR " (run from the top folder)\n");
		return 1;
	}
	char **paths = NULL;
	size_t count = 0;
	struct dirent *e;
	while ((e = readdir(d)) != NULL) {
		size_t n = strlen(e->d_name);
		if (n <= 5 || strcmp(e->d_name + n - 5, ".yaml") != 0)
			continue;
		paths = realloc(paths, (count + 1) * sizeof *paths);
		paths[count] = malloc(strlen(BAD_DIR) + n + 2);
		sprintf(paths[count], "%s/%s", BAD_DIR, e->d_name);
		count++;
	}
	closedir(d);
	if (count < 14) {
		fprintf(stderr, "test_bad_input: " BAD_DIR " holds %zu files; the corpus needs at least 14\n", count);
		return 1;
	}
	qsort(paths, count, sizeof *paths, compare_strings);
	static const struct CMUnitTest fixed[] = {
	    cmocka_unit_test(test_directory),       cmocka_unit_test(test_missing_file),
	    cmocka_unit_test(test_binary_file),     cmocka_unit_test(test_invalid_utf8),
	    cmocka_unit_test(test_every_truncation), cmocka_unit_test(test_damaged_bytes),
	    cmocka_unit_test(test_usage),           cmocka_unit_test(test_missing_catalog),
	    cmocka_unit_test(test_deep_flow_nesting), cmocka_unit_test(test_endless_records),
	    cmocka_unit_test(test_tool_resume),     cmocka_unit_test(test_out_stdout),
	    cmocka_unit_test(test_no_warnings),
	};
	size_t nfixed = sizeof fixed / sizeof fixed[0];
	struct CMUnitTest *tests = calloc(count + nfixed, sizeof *tests);
	for (size_t i = 0; i < count; ++i) {
		tests[i].name = paths[i];
		tests[i].test_func = test_corpus_file;
		tests[i].initial_state = paths[i];
	}
	memcpy(tests + count, fixed, sizeof fixed);
	int failed = _cmocka_run_group_tests("bad_input", tests, count + nfixed, NULL, NULL);
	for (size_t i = 0; i < count; ++i)
		free(paths[i]);
	free(paths);
	free(tests);
	return failed;
}
