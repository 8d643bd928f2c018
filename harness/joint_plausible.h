// joint_plausible.h — refusing a joint recording that cannot be where it says it is, after its
// frame, units and placement (scenarios/README.md, "Recorded joint positions").
#ifndef HS_HARNESS_JOINT_PLAUSIBLE_H
#define HS_HARNESS_JOINT_PLAUSIBLE_H

#include "hand_script.h"
#include "joint_file.h"

// m: how far under the floor (z = 0) a hand may reach before it is under it: a tracker's noise and
// a hand resting on the table's edge (also the start's warning, scenario_warn.c)
#define HS_HAND_FLOOR_SLACK 0.02

// The wrist (keys[k] for the tracked sample k, fitted with `def`, the definition before its size
// is fitted: a few millimetres do not decide where the hand is) under the floor (z < −0.02 m) in more than
// half the tracked samples: an error at the first such sample that names the frames that would
// put it above the floor; a tracked wrist more than 10 m from the origin: an error at it.
bool hs_joint_check_plausible(const char *path, const hs_joint_file *file, const hs_hand_def *def,
                              const hs_hand_key *keys, long tracked, hs_error *err);

#endif
