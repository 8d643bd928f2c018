// fuzz_scenario.c — libFuzzer target for the scenario loader (hs_scenario_load) and, through a
// scenario's `record:`, the recorded-input reader. Every input must end either in a loaded
// scenario that steps with finite states, or in exactly one "PATH:LINE: what" message; never a
// crash, a leak (ASan's leak check), undefined behaviour (UBSan) or a hang.
//
// The input is written to a file named after its `name:` line (so catalog seeds stay valid)
// in a private folder that also holds a valid recorded glove file, r.csv, and copies of the
// recorded files (*.csv) of tests/bad, tests/fuzz/seeds and the catalog (the fuzzer runs from the
// top folder).
#include <dirent.h>
#include <stdint.h>

#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv);

enum { MAX_FRAMES_RUN = 120 };

static void copy_file(const char *from, const char *to) {
	FILE *in = fopen(from, "rb");
	if (!in)
		return;
	FILE *out = fopen(to, "wb");
	if (out) {
		char buf[4096];
		size_t n;
		while ((n = fread(buf, 1, sizeof buf, in)) > 0)
			if (fwrite(buf, 1, n, out) != n)
				break;
		fclose(out);
	}
	fclose(in);
}

int LLVMFuzzerInitialize(int *argc, char ***argv) {
	(void)argc;
	(void)argv;
	fuzz_make_dir();
	static const char glove[] = "t,x,y,z,qw,qx,qy,qz,s0,s1,s2,s3,s4,s5,s6,s7,s8,s9,s10,s11,s12,s13,s14,s15,s16,s17\n"
	                            "0.00,0,0,0.3,1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,128,128\n"
	                            "0.10,0.01,0,0.2,1,0,0,0,20,20,20,20,40,40,40,40,40,40,40,40,0,0,0,0,128,128\n"
	                            "0.20,0.02,0,0.1,0.7071067811865476,0,0.7071067811865476,0,60,60,60,60,90,90,90,"
	                            "90,90,90,90,90,0,0,0,0,128,128\n";
	char path[256];
	snprintf(path, sizeof path, "%s/r.csv", fuzz_dir);
	fuzz_write(path, (const uint8_t *)glove, sizeof glove - 1);
	// the recorded files the seeds name (glove and stylus), copied beside the input
	static const char *const dirs[] = {"tests/bad", "tests/fuzz/seeds", "scenarios", "scenarios/hand", "scenarios/spring"};
	for (size_t k = 0; k < sizeof dirs / sizeof dirs[0]; ++k) {
		DIR *d = opendir(dirs[k]);
		if (!d)
			continue;
		struct dirent *e;
		while ((e = readdir(d)) != NULL) {
			size_t n = strlen(e->d_name);
			if (n > 4 && n < 100 && strcmp(e->d_name + n - 4, ".csv") == 0) {
				char from[160], to[256];
				snprintf(from, sizeof from, "%s/%s", dirs[k], e->d_name);
				snprintf(to, sizeof to, "%s/%s", fuzz_dir, e->d_name);
				copy_file(from, to);
			}
		}
		closedir(d);
	}
	return 0;
}

// The file name the input asks for: the value of a `name: word` line, else "fuzz".
static void file_name(const uint8_t *data, size_t size, char *out, size_t out_size) {
	snprintf(out, out_size, "fuzz");
	for (size_t i = 0; i + 6 < size; ++i) {
		if ((i > 0 && data[i - 1] != '\n') || memcmp(data + i, "name: ", 6) != 0)
			continue;
		size_t j = i + 6, k = 0;
		char name[65];
		while (j < size && k < 64 &&
		       ((data[j] >= 'a' && data[j] <= 'z') || (data[j] >= 'A' && data[j] <= 'Z') ||
		        (data[j] >= '0' && data[j] <= '9') || data[j] == '_' || data[j] == '-'))
			name[k++] = (char)data[j++];
		name[k] = '\0';
		if (k > 0 && (j == size || data[j] == '\n' || data[j] == '\r' || data[j] == ' '))
			snprintf(out, out_size, "%s", name);
		return;
	}
}

static void require_finite_world(const hs_world *world) {
	int n = hs_world_object_count(world);
	for (int i = 0; i < n; ++i) {
		hs_object_state st;
		FUZZ_REQUIRE(hs_world_object_state(world, hs_world_object_at(world, i), &st) == HS_OK);
		FUZZ_REQUIRE(hs_vec3_is_finite(st.position) && hs_quat_is_finite(st.orientation));
		FUZZ_REQUIRE(hs_vec3_is_finite(st.velocity));
		FUZZ_REQUIRE(st.contact >= HS_CONTACT_NONE && st.contact <= HS_CONTACT_PUSH_MANY);
	}
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
	char name[80], path[256];
	file_name(data, size, name, sizeof name);
	snprintf(path, sizeof path, "%s/%s.yaml", fuzz_dir, name);
	fuzz_write(path, data, size);
	hs_error err;
	memset(&err, 'x', sizeof err);
	hs_scenario *s = hs_scenario_load(path, &err);
	if (!s) {
		fuzz_check_message(err.message);
		return 0;
	}
	hs_world *world = hs_scenario_world(s);
	FUZZ_REQUIRE(world != NULL);
	FUZZ_REQUIRE(hs_scenario_frame_count(s) >= 1);
	FUZZ_REQUIRE(hs_scenario_object_count(s) == hs_world_object_count(world));
	require_finite_world(world);
	FILE *sink = fopen("/dev/null", "w");
	FUZZ_REQUIRE(sink != NULL);
	hs_trajectory_write_header(sink);
	hs_trajectory_write_frame(sink, s);
	// a bounded prefix of the run: enough to land, tip, grasp and throw
	long budget = 200000 / (hs_scenario_object_count(s) + 1);
	if (budget > MAX_FRAMES_RUN)
		budget = MAX_FRAMES_RUN;
	for (long f = 0; f < budget && hs_scenario_step(s); ++f) {
		require_finite_world(world);
		hs_trajectory_write_frame(sink, s);
	}
	fclose(sink);
	FUZZ_REQUIRE(hs_scenario_check(s, NULL) >= 0);
	hs_scenario_destroy(s);
	return 0;
}
