// hand_sweep.h — the hand's path through a step (docs/model.md §3 "Swept detection, rectification
// and contact hysteresis": check points and lines are tested along their path through the frame,
// not only where they end).
#ifndef HS_HAND_SWEEP_H
#define HS_HAND_SWEEP_H

#include "hand_internal.h"

// Fills the hand's path cache for the coming step from its two readings: path_steps S (1: the
// parts move along straight chords; > 1: the fingers or the wrist turn by more than
// HS_HAND_PATH_DEG in the frame, and the path runs through the kinematics of S - 1 readings
// interpolated between them), and the bounding sphere of every part over the whole path.
// `chords_only` (the paper's letter, hs_world_def.paper_contacts): S = 1 always.
void hs_hand_sweep(hs_hand *hand, bool chords_only);
// Fills the hand's finger spheres (hs_hand.cache.finger_center, finger_reach) for its points now, a frame
// ago and on the path of the last hs_hand_sweep, unless they are already made for them.
void hs_hand_finger_spheres(hs_hand *hand);

#endif
