// joint_pose.h — one sample of recorded joint positions as the glove model's input (scenarios/
// README.md, "Recorded joint positions"): the wrist pose from three rigid points, the sensors by a
// least-squares search over whole units.
#ifndef HS_HARNESS_JOINT_POSE_H
#define HS_HARNESS_JOINT_POSE_H

#include <stdbool.h>
#include <stdint.h>

#include "handspring.h"

// The check points the wrist fit needs, which no sensor moves with the wrist sensors neutral:
// the thumb CMC and the index and middle MCPs.
#define HS_JOINT_RIGID_MASK ((1u << 0) | (1u << 4) | (1u << 8))

// The rigid motion carrying the definition's thumb CMC and index and middle MCPs (open hand,
// wrist frame) onto the recorded ones (`world`): false when those three are in one line.
bool hs_joint_fit_wrist(const hs_hand_def *def, const hs_vec3 world[HS_HAND_POINTS], hs_quat *rot, hs_vec3 *pos);
// The sensors whose kinematics reach the recorded check points `local` (wrist frame; only those
// of bit i in `present`) best, wrist pitch and yaw kept: from `s` by full scans of each sensor
// (`first`: the first sample) or by a pattern search (later samples, from the one before).
void hs_joint_fit_sensors(const hs_hand_def *def, uint32_t present, const hs_vec3 local[HS_HAND_POINTS], bool first,
                          uint8_t s[HS_GLOVE_SENSORS]);
// The unit quaternion of a rotation matrix.
hs_quat hs_joint_quat_of(double m[3][3]);

#endif
