// joint_export.c — a scenario's hand written as a joint recording (`handspring joints`; the
// format: scenarios/README.md, "Recorded joint positions"): the glove model's kinematics of the
// hand's input, as MediaPipe landmarks or OpenXR joints. The catalog's hand/joints_mediapipe and
// hand/joints_openxr come from it (scripts/joint_recordings.sh).
#include <string.h>

#include "joint_file.h"
#include "joint_pose.h"
#include "scenario_internal.h"

// The OpenXR orientation of a joint whose bone runs along `forward` (unit) with the back of the hand
// toward `up`: −Z along the bone, +Y toward the back of the hand (XR_EXT_hand_tracking).
static hs_quat openxr_frame(hs_vec3 forward, hs_vec3 up) {
	hs_vec3 z = hs_neg(forward);
	hs_vec3 y = hs_sub(up, hs_scale(z, hs_dot(up, z)));
	y = hs_length_sq(y) > 0.0 ? hs_normalize(y) : hs_normalize(hs_cross(z, hs_v3(1, 0, 0)));
	hs_vec3 x = hs_cross(y, z);
	double m[3][3] = {{x.x, y.x, z.x}, {x.y, y.y, z.y}, {x.z, y.z, z.z}};
	return hs_joint_quat_of(m);
}

static void openxr_joint(FILE *out, hs_vec3 p, hs_quat q) {
	fprintf(out, ",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", p.x, p.y, p.z, q.w, q.x, q.y, q.z);
}

// What a recording of hand h says of itself (scenarios/README.md, "Recorded joint positions"): where
// it comes from, its frame and units (the library's), which hand; then the header, with the
// tracked column when the hand's script has untracked keys.
static void write_head(FILE *out, const hs_scenario *scenario, int h, hs_joint_format format, bool tracked) {
	const hs_hands *hands = &scenario->hands;
	char header[4096];
	hs_joint_header(format, header, sizeof header);
	fprintf(out, "@source handspring joints: scenario %s, hand '%s'\n@frame z_up\n@units m\n@hand %s\n%s%s\n",
	        hs_scenario_name(scenario), hands->names[h], hands->defs[h].left ? "left" : "right", header,
	        tracked ? ",tracked" : "");
}

// One sample: the hand of definition `def` at the wrist pose with the glove reading `sensors`.
// `tail` ends the line (the tracked cell, or nothing).
static void write_row(FILE *out, hs_joint_format format, double t, const hs_hand_def *def, hs_vec3 wrist, hs_quat rot,
                      const uint8_t sensors[HS_GLOVE_SENSORS], const char *tail) {
	hs_vec3 p[HS_HAND_POINTS], lines[HS_HAND_LINES][2];
	hs_hand_kinematics(def, wrist, rot, sensors, p, lines);
	fprintf(out, "%.17g", t);
	if (format == HS_JOINTS_MEDIAPIPE) {
		fprintf(out, ",%.17g,%.17g,%.17g", wrist.x, wrist.y, wrist.z); // landmark 0: the wrist
		for (int i = 0; i < HS_HAND_POINTS; ++i)
			fprintf(out, ",%.17g,%.17g,%.17g", p[i].x, p[i].y, p[i].z);
		fprintf(out, "%s\n", tail);
		return;
	}
	hs_vec3 up = hs_quat_rotate(rot, hs_v3(0, 0, 1)), along = hs_quat_rotate(rot, hs_v3(1, 0, 0));
	openxr_joint(out, hs_scale(hs_add(wrist, p[8]), 0.5), openxr_frame(along, up)); // 0 palm
	openxr_joint(out, wrist, openxr_frame(along, up));                               // 1 wrist
	for (int f = 0; f < 5; ++f) {
		if (f > 0) { // a finger's metacarpal joint: on the way from the wrist to its base
			hs_vec3 m = hs_add(wrist, hs_scale(hs_sub(p[f * 4], wrist), 0.3));
			openxr_joint(out, m, openxr_frame(hs_normalize(hs_sub(p[f * 4], m)), up));
		}
		for (int j = 0; j < 4; ++j) {
			hs_vec3 a = p[f * 4 + j], b = j < 3 ? p[f * 4 + j + 1] : p[f * 4 + j];
			hs_vec3 dir = j < 3 ? hs_sub(b, a) : hs_sub(p[f * 4 + 3], p[f * 4 + 2]);
			openxr_joint(out, a, openxr_frame(hs_normalize(dir), up));
		}
	}
	fprintf(out, "%s\n", tail);
}

bool hs_scenario_export_joints(hs_scenario *scenario, int hand, const char *format, double rate, FILE *out,
                               hs_error *err) {
	hs_joint_format f = strcmp(format, "mediapipe") == 0 ? HS_JOINTS_MEDIAPIPE
	                    : strcmp(format, "openxr") == 0  ? HS_JOINTS_OPENXR
	                                                     : HS_JOINTS_NONE;
	const hs_hands *hands = &scenario->hands;
	if (f == HS_JOINTS_NONE)
		return hs_set_error(err, hs_scenario_name(scenario), 0, "unknown joint format '%s' (mediapipe or openxr)", format);
	if (hand < 0 || hand >= hands->count)
		return hs_set_error(err, hs_scenario_name(scenario), 0, "the scenario has %d hand(s), no hand %d", hands->count, hand + 1);
	if (!(rate >= 1.0 && rate <= 10000.0))
		return hs_set_error(err, hs_scenario_name(scenario), 0, "the rate must be within [1, 10000] Hz, got %g", rate);
	const hs_hand_script *script = &hands->scripts[hand];
	bool untracked = false;
	for (int k = 0; k < script->key_count; ++k)
		untracked = untracked || !script->keys[k].tracked;
	write_head(out, scenario, hand, f, untracked);
	double dt = 1.0 / rate, duration = (double)hs_scenario_frame_count(scenario) * hs_scenario_dt(scenario);
	for (long k = 0; (double)k * dt <= duration + 1e-9; ++k) { // the script's input, as the world gets it
		hs_vec3 wrist;
		hs_quat rot;
		uint8_t sensors[HS_GLOVE_SENSORS];
		bool tracked = hs_hand_script_sample(script, (double)k * dt, &wrist, &rot, sensors);
		write_row(out, f, (double)k * dt, &hands->defs[hand], wrist, rot, sensors,
		          !untracked ? "" : tracked ? ",1" : ",0");
	}
	return true;
}
