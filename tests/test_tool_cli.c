// test_tool_cli.c — the harness for any folder (docs/tool.md): `handspring golden DIR` and
// `handspring check DIR` on a temporary folder, and what `run` writes with --objects, --every,
// --from, --to and --out -.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>

typedef struct result {
	int status;
	char *out, *err;
} result;

static char *slurp(FILE *f) {
	fseek(f, 0, SEEK_END);
	long n = ftell(f);
	rewind(f);
	char *s = malloc((size_t)n + 1);
	assert_non_null(s);
	assert_int_equal(fread(s, 1, (size_t)n, f), (size_t)n);
	s[n] = 0;
	return s;
}

// `handspring ARGS...` with stdout and stderr captured.
static result tool(const char *const *args) {
	const char *t = getenv("HS_TOOL");
	const char *argv[24];
	int n = 0;
	argv[n++] = t && *t ? t : "build/handspring";
	for (int i = 0; args[i] && n < 23; ++i)
		argv[n++] = args[i];
	argv[n] = NULL;
	FILE *out = tmpfile(), *err = tmpfile();
	assert_true(out && err);
	fflush(stdout);
	fflush(stderr);
	pid_t pid = fork();
	assert_true(pid >= 0);
	if (pid == 0) {
		dup2(fileno(out), 1);
		dup2(fileno(err), 2);
		execv(argv[0], (char *const *)argv);
		_exit(127);
	}
	int status = 0;
	assert_int_equal(waitpid(pid, &status, 0), pid);
	result r = {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
	fclose(out);
	fclose(err);
	return r;
}

static void done(result *r) {
	free(r->out);
	free(r->err);
}

static void copy(const char *from, const char *to) {
	FILE *a = fopen(from, "rb"), *b = fopen(to, "wb");
	assert_true(a && b);
	char buf[4096];
	size_t n;
	while ((n = fread(buf, 1, sizeof buf, a)) > 0)
		assert_int_equal(fwrite(buf, 1, n, b), n);
	fclose(a);
	fclose(b);
}

// A user's folder: `golden` writes folder/golden/*.csv beside folder/scenarios, `check` passes;
// one number of a golden moved by 1e-4 m makes `check` exit 1 naming the frame, object and field;
// a scenario without a golden is named too.
static void test_golden_then_check(void **state) {
	(void)state;
	char dir[] = "/tmp/hs-cli-XXXXXX";
	assert_non_null(mkdtemp(dir));
	char scen[256], gold[256], path[300];
	snprintf(scen, sizeof scen, "%s/scenarios", dir);
	snprintf(gold, sizeof gold, "%s/golden", dir);
	assert_int_equal(mkdir(scen, 0755), 0);
	snprintf(path, sizeof path, "%s/drop_cube.yaml", scen);
	copy("scenarios/drop_cube.yaml", path);
	const char *golden_args[] = {"golden", scen, NULL};
	result r = tool(golden_args);
	assert_int_equal(r.status, 0);
	done(&r);
	const char *check_args[] = {"check", scen, NULL};
	r = tool(check_args);
	assert_int_equal(r.status, 0);
	assert_non_null(strstr(r.out, "drop_cube"));
	assert_non_null(strstr(r.out, "1 match, 0 differ"));
	done(&r);
	// move frame 1's z by 1e-4 m in the golden
	snprintf(path, sizeof path, "%s/drop_cube.csv", gold);
	FILE *f = fopen(path, "r+");
	assert_non_null(f);
	char *text = slurp(f);
	char *z = strstr(text, "\n1,0.016666666666666666,cube,0,0,1.0486374999999999,");
	assert_non_null(z);
	memcpy(strstr(z, "1.0486"), "1.0487", 6);
	rewind(f);
	fputs(text, f);
	fclose(f);
	free(text);
	r = tool(check_args);
	assert_int_equal(r.status, 1);
	assert_non_null(strstr(r.out, "drop_cube: frame 1, object cube, field z"));
	done(&r);
	snprintf(path, sizeof path, "%s/throw_block.yaml", scen);
	copy("scenarios/throw_block.yaml", path);
	r = tool(check_args);
	assert_int_equal(r.status, 1);
	assert_non_null(strstr(r.out, "throw_block.csv missing"));
	done(&r);
	char cmd[400];
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
	assert_int_equal(system(cmd), 0);
}

// --objects cube1,cube3 --every 30 --from 0.5 --to 2 on the seed scene (60 frames/s): frames 30,
// 60, 90, 120, two rows each; --out - writes them to stdout.
static void test_run_filters(void **state) {
	(void)state;
	const char *args[] = {"run", "scenarios/seed_scene.yaml", "--out", "-", "--objects", "cube1,cube3", "--every", "30",
	                      "--from", "0.5", "--to", "2", NULL};
	result r = tool(args);
	assert_int_equal(r.status, 0);
	int rows = 0;
	for (const char *p = r.out; (p = strchr(p, '\n')) && p[1]; ++p)
		rows++;
	assert_int_equal(rows, 8);
	assert_true(strncmp(r.out, "frame,t,object,", 15) == 0);
	assert_non_null(strstr(r.out, "\n30,0.5,cube1,"));
	assert_non_null(strstr(r.out, "\n120,2,cube3,"));
	assert_null(strstr(r.out, "cube2"));
	assert_null(strstr(r.out, "\n150,"));
	assert_non_null(strstr(r.err, "PASS")); // the summary on stderr
	done(&r);
	const char *bad[][8] = {{"run", "scenarios/seed_scene.yaml", "--objects", "nope", NULL},
	                        {"run", "scenarios/seed_scene.yaml", "--every", "0", NULL},
	                        {"run", "scenarios/seed_scene.yaml", "--from", "2", "--to", "1", NULL},
	                        {"run", "scenarios/seed_scene.yaml", "--from", "-1", NULL}};
	for (int k = 0; k < 4; ++k) {
		r = tool(bad[k]);
		assert_int_equal(r.status, 2);
		assert_true(strlen(r.err) > 0);
		done(&r);
	}
}

// An output that is not a regular file is written in place: `--out /dev/null` used to write
// /dev/null.tmp and rename it over /dev/null, which as root left a regular file there (and as
// any other user failed). /dev/null must still be a character device afterwards.
static void test_out_to_device(void **state) {
	(void)state;
	const char *args[] = {"run", "scenarios/seed_scene.yaml", "--out", "/dev/null", NULL};
	result r = tool(args);
	assert_int_equal(r.status, 0);
	done(&r);
	struct stat st;
	assert_int_equal(stat("/dev/null", &st), 0);
	assert_true(S_ISCHR(st.st_mode));
	assert_int_equal(stat("/dev/null.tmp", &st), -1);
	// a symbolic link is written through, not replaced (/dev/stdout is one)
	char dir[] = "/tmp/hs_cli_link_XXXXXX";
	assert_non_null(mkdtemp(dir));
	char target[64], link[64];
	snprintf(target, sizeof target, "%s/target.csv", dir);
	snprintf(link, sizeof link, "%s/link.csv", dir);
	FILE *f = fopen(target, "w");
	assert_non_null(f);
	fclose(f);
	assert_int_equal(symlink("target.csv", link), 0);
	const char *through[] = {"run", "scenarios/seed_scene.yaml", "--out", link, NULL};
	r = tool(through);
	assert_int_equal(r.status, 0);
	done(&r);
	assert_int_equal(lstat(link, &st), 0);
	assert_true(S_ISLNK(st.st_mode));
	assert_int_equal(stat(target, &st), 0);
	assert_true(st.st_size > 1000);
	remove(link);
	remove(target);
	rmdir(dir);
}

// `handspring hand`: the open hand's index tip (check point 7) at (0.18, 0.025, 0) m in the wrist
// frame, 20 named rows after the header; an unknown posture exits 2.
static void test_hand_points(void **state) {
	(void)state;
	const char *args[] = {"hand", NULL};
	result r = tool(args);
	assert_int_equal(r.status, 0);
	assert_non_null(strstr(r.out, "\npoint,name,x,y,z\n"));
	assert_non_null(strstr(r.out, "\n7,index_tip,0.18,0.025,0\n"));
	assert_non_null(strstr(r.out, "\n19,little_tip,"));
	done(&r);
	const char *bad[] = {"hand", "--posture", "wave", NULL};
	r = tool(bad);
	assert_int_equal(r.status, 2);
	assert_non_null(strstr(r.err, "--posture must be"));
	done(&r);
}

// `handspring campaign`: --count and --header, a slice's rows are those lines of the whole run's
// trial CSV, and each bad use exits 2 with one message.
static void test_campaign_cli(void **state) {
	(void)state;
	const char *count[] = {"campaign", "tests/campaigns/tiny.yaml", "--count", NULL};
	result r = tool(count);
	assert_int_equal(r.status, 0);
	assert_string_equal(r.out, "40\n");
	done(&r);
	char path[] = "/tmp/hs_cli_trials_XXXXXX";
	int fd = mkstemp(path);
	assert_true(fd >= 0);
	close(fd);
	const char *whole[] = {"campaign", "tests/campaigns/tiny.yaml", "--out", path, NULL};
	result all = tool(whole);
	assert_int_equal(all.status, 0);
	FILE *f = fopen(path, "r");
	assert_non_null(f);
	free(all.out);
	all.out = slurp(f); // the trial CSV (stdout has the table)
	fclose(f);
	remove(path);
	const char *slice[] = {"campaign", "tests/campaigns/tiny.yaml", "--trials", "3:5", NULL};
	r = tool(slice);
	assert_int_equal(r.status, 0);
	char *row3 = strstr(all.out, "\n3,");
	assert_non_null(row3);
	assert_memory_equal(r.out, row3 + 1, strlen(r.out)); // rows 3 and 4, as in the whole run
	assert_ptr_equal(strstr(row3 + 1, "\n5,"), row3 + strlen(r.out));
	done(&r);
	done(&all);
	const char *const bad[][6] = {
	    {"campaign", "tests/campaigns/tiny.yaml", "--trials", "5:5", NULL},
	    {"campaign", "tests/campaigns/tiny.yaml", "--trials", "0:41", NULL},
	    {"campaign", "tests/campaigns/tiny.yaml", "--frobnicate", NULL},
	    {"campaign", "tests/campaigns/tiny.yaml", "--count", "--header", NULL},
	    {"campaign", NULL},
	};
	const char *said[] = {"'--trials' needs A:B with 0 <= A < B, got '5:5'",
	                      "tests/campaigns/tiny.yaml: --trials reaches 41, the campaign has 40 trials",
	                      "unknown option '--frobnicate'", "go alone", "missing the campaign FILE"};
	for (int k = 0; k < 5; ++k) {
		r = tool(bad[k]);
		assert_int_equal(r.status, 2);
		if (!strstr(r.err, said[k]))
			fail_msg("case %d: %s", k, r.err);
		done(&r);
	}
}

// --letter runs the file to a paper's letter: the paper/ catalog's letter file and its default twin
// with --letter hand1999 land the 12 frames/s throw where the letter's closed form puts it.
static void test_run_letter(void **state) {
	(void)state;
	const char *letter[] = {"run", "scenarios/paper/throw_12fps_default.yaml", "--letter", "hand1999", NULL};
	result r = tool(letter);
	assert_int_equal(r.status, 1); // the default file's landing clauses fail under the letter
	assert_non_null(strstr(r.out, "(at [0.7645, 0, 0.025])"));
	done(&r);
	const char *none[] = {"run", "scenarios/paper/throw_12fps_letter.yaml", "--letter", "none", NULL};
	r = tool(none);
	assert_int_equal(r.status, 1); // and the letter file's fail under the defaults
	assert_non_null(strstr(r.out, "(at [1.97377969"));
	done(&r);
	const char *const bad[][10] = {{"run", "scenarios/seed_scene.yaml", "--letter", "paper", NULL},
	                              {"run", "scenarios/seed_scene.yaml", "--letter", NULL},
	                              {"run", "scenarios/seed_scene.yaml", "--letter", "hand1999", "--save-at", "3", "--state-out",
	                               "/tmp/x.state", NULL}};
	const char *said[] = {"--letter needs none, hand1999 or workbench", "--letter needs none, hand1999 or workbench",
	                      "do not go with --save-at or --resume"};
	for (int k = 0; k < 3; ++k) {
		r = tool(bad[k]);
		assert_int_equal(r.status, 2);
		if (!strstr(r.err, said[k]))
			fail_msg("case %d: %s", k, r.err);
		done(&r);
	}
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_golden_then_check),
	    cmocka_unit_test(test_run_letter),
	    cmocka_unit_test(test_run_filters),
	    cmocka_unit_test(test_out_to_device),
	    cmocka_unit_test(test_hand_points),
	    cmocka_unit_test(test_campaign_cli),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
