// joint_input.h — hands driven by recorded joint positions (MediaPipe Hands, OpenXR hand
// tracking), turned into the glove model's input at load (joint_input.c; the file format:
// scenarios/README.md, "Recorded joint positions").
#ifndef HS_HARNESS_JOINT_INPUT_H
#define HS_HARNESS_JOINT_INPUT_H

#include "hand_script.h"
#include "joint_file.h"
#include "joint_options.h"

// The options of a bare `record: FILE`.
hs_joint_options hs_joint_options_default(void);

// What a load found, for the scenario's report and hs_scenario_hand_fit.
typedef struct hs_joint_report {
	long samples;              // tracked samples
	double rms_mm;             // the fit's RMS distance over their recorded check points
	bool frame_assumed;        // neither the file nor the scenario said the frame: z_up
	bool units_assumed;        // nor the units: m
	unsigned long header_line; // the header's line in the file
} hs_joint_report;

// Reads a joint recording into keys (wrist pose and sensor values per sample, untracked samples
// holding the last tracked pose) for a hand of definition `def`, which takes the recording's size
// when options->fit_hand. With options->drive_joints the hand is joint-driven (def->joint_driven):
// each key also holds the recorded joints in the wrist frame (a joint not recorded in a sample: the
// fitted hand's), and the RMS reported is over the points the model uses (0 for the recorded ones).
// Errors are "PATH:LINE: what is wrong".
bool hs_joint_record_load(const char *path, const hs_joint_options *options, hs_hand_def *def,
                          hs_hand_script *script, hs_joint_report *report, hs_error *err);

#endif
