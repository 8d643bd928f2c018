// fall_group.h — paper stacking: objects that interfere with each other and that nothing holds up
// fall together (docs/model.md §6, the reading of the 1999 paper's §4.3).
#ifndef HS_FALL_GROUP_H
#define HS_FALL_GROUP_H

#include "broadphase.h"
#include "world_internal.h"

// When `object`, free and interfering with another, belongs to a group of interfering objects of
// which none is held or carried by a hand or touches the floor: moves the whole group by one frame
// of eq. 3 (their momentum-weighted velocity and this frame's gravity), lands it on the floor as
// one (§4.2, no rebound), writes its members to out[0..n) and returns n. Returns 0 and moves
// nothing when the group is held up. The members' wake-up is the caller's (hs_wake, after the
// loop over the awake list). `out` must not be the scratch's query answer (near, found).
int hs_fall_group(const hs_broadphase *bp, int object, int *out, int cap);

#endif
