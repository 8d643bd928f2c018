// joint_input.h — hands driven by recorded joint positions (MediaPipe Hands, OpenXR hand
// tracking), turned into the glove model's input at load (joint_input.c).
#ifndef HS_HARNESS_JOINT_INPUT_H
#define HS_HARNESS_JOINT_INPUT_H

#include "hand_script.h"

typedef enum hs_joint_format { HS_JOINTS_NONE = 0, HS_JOINTS_MEDIAPIPE, HS_JOINTS_OPENXR } hs_joint_format;

// The format a recorded file's header line names (HS_JOINTS_NONE: a glove + tracker file).
hs_joint_format hs_joint_format_of(const char *first_line);
// Reads a joint recording into keys (wrist pose and sensor values per sample) for a hand of
// definition `def`. Errors are "PATH:LINE: what is wrong".
bool hs_joint_record_load(const char *path, hs_joint_format format, const hs_hand_def *def, hs_hand_script *script,
                          hs_error *err);

// Writes a recording's header and one sample: the hand of definition `def` at the wrist pose with
// the glove reading `sensors` (the glove model's kinematics), as MediaPipe landmarks or OpenXR
// joints (joint orientations: −Z along the bone, +Y toward the back of the hand).
void hs_joint_write_header(FILE *out, hs_joint_format format);
void hs_joint_write_row(FILE *out, hs_joint_format format, double t, const hs_hand_def *def, hs_vec3 wrist,
                        hs_quat rot, const uint8_t sensors[HS_GLOVE_SENSORS]);

#endif
