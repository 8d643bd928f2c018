// tracking.h — hands the tracker loses and finds again (docs/model.md §3 "Tracking loss").
#ifndef HS_TRACKING_H
#define HS_TRACKING_H

#include <stdbool.h>

#include "hand_internal.h"

// Before a step's hand pass, for one hand: counts the frames it has been lost and places it anew,
// without motion, when it is found again. True when its grasps must be let go in place
// (hs_grasp_let_go_in_place): it was lost past hold_frames (round(tracking_hold_s / dt)), or it
// came back further than a carrying hand moves in the time it was lost. Its placement does not
// read what a let-go writes, so the caller lets go after this.
bool hs_tracking_update(hs_hand *hand, int hold_frames, double dt);

#endif
