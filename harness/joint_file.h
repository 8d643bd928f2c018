// joint_file.h — the joint recording file, version 2 (scenarios/README.md, "Recorded joint
// positions"): comments and blank lines anywhere, directives before the header, a MediaPipe or
// OpenXR header with the optional columns tracked and confidence, and samples whose cells may be
// missing (empty, nan).
#ifndef HS_HARNESS_JOINT_FILE_H
#define HS_HARNESS_JOINT_FILE_H

#include <stdint.h>

#include "error.h"
#include "joint_options.h"

// One sample as recorded; `tracked` is decided by the loader (joint_input.c).
typedef struct hs_joint_sample {
	double t;                       // s
	long line;                      // its line in the file
	uint32_t present;               // bit i: check point i is recorded (all three coordinates)
	int8_t tracked_cell;            // the `tracked` column: 1, 0, or -1 when missing or absent
	bool tracked;                   // the loader's verdict
	double confidence;              // the `confidence` column; NaN when missing or absent
	hs_vec3 points[HS_HAND_POINTS]; // the check points in the file's frame and units
} hs_joint_sample;

typedef struct hs_joint_file {
	hs_joint_format format;
	hs_joint_said frame, units, hand; // the directives (hand: 0 right, 1 left); value -1: absent
	unsigned long header_line;
	hs_joint_place place;             // the directives and the scenario's options, resolved
	bool frame_assumed, units_assumed;
	long count;
	hs_joint_sample *samples;
} hs_joint_file;

// The header of a format without the optional columns.
void hs_joint_header(hs_joint_format format, char *out, size_t size);
// Reads the file: directives, header (resolved against `options` and the hand's side `left`:
// a directive the scenario contradicts is an error), then every sample (time increasing,
// positions within ±1000 m, OpenXR orientations of unit norm, tracked 0 or 1, confidence within
// [0, 1]). False with "PATH:LINE: what is wrong".
bool hs_joint_file_read(const char *path, const hs_joint_options *options, bool left, hs_joint_file *file,
                        hs_error *err);
void hs_joint_file_free(hs_joint_file *file);

// True when a recorded file is a joint recording: the first line that is not blank or a comment
// is a directive (@...) or a MediaPipe or OpenXR header. False for anything else (a glove file, or
// a file that cannot be read: the glove reader says why).
bool hs_joint_file_is_joints(const char *path);

#endif
