// joint_options.h — how a joint recording is to be read: its format, what the scenario and the file
// say of its frame and units, and the scenario's `record:` mapping (scenarios/README.md, "Recorded
// joint positions"). Read by joint_file.c, filled by hand_record.c, used by joint_input.c.
#ifndef HS_HARNESS_JOINT_OPTIONS_H
#define HS_HARNESS_JOINT_OPTIONS_H

#include <stdbool.h>

#include "handspring.h"
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

#endif
