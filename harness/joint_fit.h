// joint_fit.h — the hand's size taken from a joint recording (scenarios/README.md, "Recorded
// joint positions", fit_hand).
#ifndef HS_HARNESS_JOINT_FIT_H
#define HS_HARNESS_JOINT_FIT_H

#include "joint_file.h"

// Sets def's 15 segment lengths to the median recorded lengths and scales its palm (the five
// bases) by the median ratio of the recorded distances between the bases to the definition's,
// over the tracked samples of the recording's first second (from its first tracked sample). A
// segment never recorded there keeps its length; a value within 1 µm (the palm: 1e-6 of its
// size) of the definition's keeps the definition's. A size beyond 3 times the definition's either
// way is an error at the window's first sample.
bool hs_joint_fit_size(const char *path, const hs_joint_file *file, hs_hand_def *def, hs_error *err);

#endif
