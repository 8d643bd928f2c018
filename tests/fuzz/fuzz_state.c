// fuzz_state.c — libFuzzer target for the state loader (hs_scenario_resume): the world's part and
// the harness's. The input's first byte picks one of two fixed scenarios (tests/fuzz/state/: a
// noisy spring run with every kind of capture, a noisy hand run); the rest is a state file whose
// last word is set to the checksum of the bytes before it, so the fuzzer reaches every field
// check, not only the checksum. Every input must be refused with one "state file: ..." line, the
// scenario then untouched (at frame 0), or resume with finite states; a resumed run must step to its
// end, and any non-finite value or numeric fault on the way must be reported as a failure. Run from the repository's top folder (make fuzz does).
#include <stdint.h>

#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static hs_scenario *scenarios[2];

static hs_scenario *fresh(int which) {
	static const char *const paths[2] = {"tests/fuzz/state/spring.yaml", "tests/fuzz/state/hand.yaml"};
	hs_error err;
	hs_scenario *s = hs_scenario_load(paths[which], &err);
	if (!s) {
		fprintf(stderr, "fuzz_state: %s (run from the repository's top folder)\n", err.message);
		abort();
	}
	return s;
}

// Whether every object's state is finite. Right after a resume it must be (the harness checks
// what the loaded world reports); while stepping, the world checks each number of its block, not
// what they give together, so a crafted block of in-range numbers may step into non-finite values:
// those must then be reported as a failure (hs_scenario_check's numeric fault line).
static bool all_finite(hs_scenario *s) {
	hs_world *world = hs_scenario_world(s);
	bool finite = true;
	for (int i = 0; i < hs_world_object_count(world); ++i) {
		hs_object_state st;
		FUZZ_REQUIRE(hs_world_object_state(world, hs_world_object_at(world, i), &st) == HS_OK);
		finite = finite && hs_vec3_is_finite(st.position) && hs_quat_is_finite(st.orientation) &&
		         hs_vec3_is_finite(st.velocity);
	}
	return finite;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
	if (size < 1)
		return 0;
	int which = data[0] & 1;
	size_t n = size - 1;
	uint8_t *state = malloc(n ? n : 1);
	FUZZ_REQUIRE(state != NULL);
	memcpy(state, data + 1, n);
	if (n >= 8) {
		uint64_t h = 14695981039346656037ull; // FNV-1a, as harness/state_io.c
		for (size_t i = 0; i + 8 < n; ++i)
			h = (h ^ state[i]) * 1099511628211ull;
		for (int i = 0; i < 8; ++i)
			state[n - 8 + (size_t)i] = (uint8_t)(h >> (8 * i));
	}
	if (!scenarios[which])
		scenarios[which] = fresh(which); // kept: a refused state leaves it untouched
	hs_scenario *s = scenarios[which];
	FILE *f = n ? fmemopen(state, n, "rb") : tmpfile();
	FUZZ_REQUIRE(f != NULL);
	hs_error err;
	memset(&err, 'x', sizeof err);
	hs_status status = hs_scenario_resume(s, f, &err);
	fclose(f);
	free(state);
	if (status != HS_OK) {
		FUZZ_REQUIRE(strncmp(err.message, "state file: ", 12) == 0 && strchr(err.message, '\n') == NULL);
		FUZZ_REQUIRE(hs_world_frame(hs_scenario_world(s)) == 0);
		return 0;
	}
	scenarios[which] = NULL; // resumed: run it to its end, then load a fresh one next time
	FUZZ_REQUIRE(all_finite(s));
	bool finite = true;
	while (hs_scenario_step(s))
		finite = all_finite(s) && finite;
	FILE *null = fopen("/dev/null", "w");
	FUZZ_REQUIRE(null != NULL);
	int failed = hs_scenario_check(s, null);
	FUZZ_REQUIRE(failed > 0 || (finite && hs_world_get_counters(hs_scenario_world(s)).numeric_faults == 0));
	fclose(null);
	hs_scenario_destroy(s);
	return 0;
}
