// joint_input.h — hands driven by recorded joint positions (MediaPipe Hands, OpenXR hand
// tracking), turned into the glove model's input at load (joint_input.c; the file format:
// scenarios/README.md, "Recorded joint positions").
#ifndef HS_HARNESS_JOINT_INPUT_H
#define HS_HARNESS_JOINT_INPUT_H

#include "hand_script.h"
#include "joint_frame.h"

typedef enum hs_joint_format { HS_JOINTS_NONE = 0, HS_JOINTS_MEDIAPIPE, HS_JOINTS_OPENXR } hs_joint_format;

// A setting a scenario key or a file's directive says: its value (-1: not said) and its line.
typedef struct hs_joint_said {
	int value;
	unsigned long line;
} hs_joint_said;

// What the scenario says about a hand's joint recording: its `record:` mapping and the hand.
typedef struct hs_joint_options {
	const char *scenario;      // the scenario file, for messages
	const char *hand;          // the hand's name, for messages
	bool side_given;           // the hand's `side` is written (else it is right by default)
	hs_joint_said frame;       // hs_joint_frame
	hs_joint_said units;       // hs_joint_units
	bool placed;               // `origin` or `rpy_deg` given
	hs_vec3 origin;            // m
	hs_quat rot;
	double min_confidence;     // a sample of lower confidence is untracked (default 0.5)
	bool fit_hand;             // the hand's size from the recording (default true)
	bool drive_joints;         // the recorded joints are the hand's check points (`hand: joints`;
	                           // default false: the 18-sensor glove hand fitted to them)
} hs_joint_options;

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

// True when a recorded file is a joint recording: the first line that is not blank or a comment
// is a directive (@...) or a MediaPipe or OpenXR header. False for anything else (a glove file, or
// a file that cannot be read: the glove reader says why).
bool hs_joint_file_is_joints(const char *path);

// Reads a joint recording into keys (wrist pose and sensor values per sample, untracked samples
// holding the last tracked pose) for a hand of definition `def`, which takes the recording's size
// when options->fit_hand. With options->drive_joints the hand is joint-driven (def->joint_driven):
// each key also holds the recorded joints in the wrist frame (a joint not recorded in a sample: the
// fitted hand's), and the RMS reported is over the points the model uses (0 for the recorded ones).
// Errors are "PATH:LINE: what is wrong".
bool hs_joint_record_load(const char *path, const hs_joint_options *options, hs_hand_def *def,
                          hs_hand_script *script, hs_joint_report *report, hs_error *err);

#endif
