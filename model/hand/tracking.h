// tracking.h — hands the tracker loses and finds again (docs/model.md §3 "Tracking loss").
#ifndef HS_TRACKING_H
#define HS_TRACKING_H

#include "world_internal.h"

// Before a step's hand pass: counts the frames each hand has been lost, lets its grasps go in place
// once it was lost past tracking_hold_s, and places a hand found again without motion.
void hs_tracking_update(hs_world *world);

#endif
