// fuzz_record.c — libFuzzer target for the recorded-input readers: the glove + tracker file
// (hs_record_load, internal.h) and, through a fixed scenario whose `stylus: { record: ... }` names
// the input, the recorded stylus file of the spring model (its reader is private to scenario.c).
// The readers take a path, so each input is written to a file in a private temp folder. Every
// input must end either in samples that are finite, unit-quaternion and increasing in time (a
// scenario that steps with finite states), or in exactly one "PATH:LINE: what" message; never a
// crash, a leak or undefined behaviour.
#include <stdint.h>

#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

// The input as a recorded stylus file of a spring scenario.
static void stylus_record(const uint8_t *data, size_t size) {
	static const char scenario[] = "description: a fuzzed recorded stylus file\n"
	                               "dt: 1/60\n"
	                               "duration: 0.5\n"
	                               "objects:\n"
	                               "  - { name: ball, shape: sphere, size: 0.05, position: [0, 0, 0.05] }\n"
	                               "  - { name: box, shape: box, size: [0.1, 0.1, 0.1], position: [0.3, 0, 0.05] }\n"
	                               "stylus:\n"
	                               "  record: stylus.csv\n";
	char yaml[256], csv[256];
	snprintf(yaml, sizeof yaml, "%s/stylus_scenario.yaml", fuzz_dir);
	snprintf(csv, sizeof csv, "%s/stylus.csv", fuzz_dir);
	fuzz_write(yaml, (const uint8_t *)scenario, sizeof scenario - 1);
	fuzz_write(csv, data, size);
	hs_error err;
	memset(&err, 'x', sizeof err);
	hs_scenario *s = hs_scenario_load(yaml, &err);
	if (!s) {
		fuzz_check_message(err.message);
		return;
	}
	hs_world *world = hs_scenario_world(s);
	for (int f = 0; f < 30 && hs_scenario_step(s); ++f)
		for (int i = 0; i < hs_world_object_count(world); ++i) {
			hs_object_state st;
			FUZZ_REQUIRE(hs_world_object_state(world, hs_world_object_at(world, i), &st) == HS_OK);
			FUZZ_REQUIRE(hs_vec3_is_finite(st.position) && hs_quat_is_finite(st.orientation) &&
			             hs_vec3_is_finite(st.velocity));
		}
	hs_scenario_destroy(s);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
	fuzz_make_dir();
	stylus_record(data, size);
	char path[256];
	snprintf(path, sizeof path, "%s/record.csv", fuzz_dir);
	fuzz_write(path, data, size);
	hs_hand_script script;
	hs_error err;
	memset(&err, 'x', sizeof err);
	if (!hs_record_load(path, &script, &err)) {
		fuzz_check_message(err.message);
		FUZZ_REQUIRE(strncmp(err.message, path, strlen(path)) == 0);
		FUZZ_REQUIRE(script.keys == NULL && script.key_count == 0);
		return 0;
	}
	FUZZ_REQUIRE(script.key_count >= 1 && script.keys != NULL);
	for (int i = 0; i < script.key_count; ++i) {
		const hs_hand_key *k = &script.keys[i];
		FUZZ_REQUIRE(isfinite(k->t) && hs_vec3_is_finite(k->wrist) && hs_quat_is_finite(k->rot));
		FUZZ_REQUIRE(fabs(hs_quat_dot(k->rot, k->rot) - 1.0) < 1e-9);
		FUZZ_REQUIRE(i == 0 || k->t > script.keys[i - 1].t);
		for (int s = 0; s < HS_GLOVE_SENSORS; ++s)
			FUZZ_REQUIRE(k->sensors[s] >= 0.0 && k->sensors[s] <= 255.0);
	}
	// sampling between and beyond the keys stays finite and unit
	double t0 = script.keys[0].t, t1 = script.keys[script.key_count - 1].t;
	for (int i = -1; i <= 9; ++i) {
		double t = t0 + (t1 - t0) * (double)i / 8.0;
		if (!isfinite(t))
			continue;
		hs_vec3 wrist;
		hs_quat rot;
		uint8_t sensors[HS_GLOVE_SENSORS];
		hs_hand_script_sample(&script, t, &wrist, &rot, sensors);
		FUZZ_REQUIRE(hs_quat_is_finite(rot) && fabs(hs_quat_dot(rot, rot) - 1.0) < 1e-9);
	}
	free(script.keys);
	return 0;
}
