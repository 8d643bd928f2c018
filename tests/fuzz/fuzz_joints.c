// fuzz_joints.c — libFuzzer target for the joint-recording readers (MediaPipe Hands and OpenXR
// files, a hand's `record:`), driven through the public scenario loader only: a fixed scenario
// (tests/fuzz/joints/record.yaml, copied into a private folder) whose hand records `joints.csv`,
// the fuzzed input. Every input must end in a scenario that steps with finite states, or in
// exactly one "PATH:LINE: what" message; never a crash, a leak, undefined behaviour or a hang.
// Run from the repository's top folder (make fuzz does).
#include <stdint.h>

#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv);

static char scenario[256], recording[256];

int LLVMFuzzerInitialize(int *argc, char ***argv) {
	(void)argc;
	(void)argv;
	fuzz_make_dir();
	fuzz_copy_in("tests/fuzz/joints/record.yaml", "record.yaml");
	snprintf(scenario, sizeof scenario, "%s/record.yaml", fuzz_dir);
	snprintf(recording, sizeof recording, "%s/joints.csv", fuzz_dir);
	return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
	fuzz_write(recording, data, size);
	hs_error err;
	memset(&err, 'x', sizeof err);
	hs_scenario *s = hs_scenario_load(scenario, &err);
	if (!s) {
		fuzz_check_message(err.message);
		return 0;
	}
	hs_world *world = hs_scenario_world(s);
	while (hs_scenario_step(s))
		for (int i = 0; i < hs_world_object_count(world); ++i) {
			hs_object_state st;
			FUZZ_REQUIRE(hs_world_object_state(world, hs_world_object_at(world, i), &st) == HS_OK);
			FUZZ_REQUIRE(hs_vec3_is_finite(st.position) && hs_quat_is_finite(st.orientation) &&
			             hs_vec3_is_finite(st.velocity));
		}
	hs_scenario_destroy(s);
	return 0;
}
