// support.h — the 'support' stacking mode (docs/model.md §6, instead of the 1999 paper's §4.3): objects
// rest on the faces of objects under them, rectified and judged for stability as on the floor.
#ifndef HS_SUPPORT_H
#define HS_SUPPORT_H

#include "broadphase.h"
#include "world_internal.h"

// After its free step: lifts a body out of the objects it sank into and settles it on them (a
// tipping turn counted in counters->object_steps).
void hs_support_step(const hs_broadphase *bp, hs_world_counters *counters, int object);
// Objects moved `object` (a hand, or its own fall) from `from` (its G when the frame began):
// objects resting on or against it wake up and look again; a hand carries what rests on top of it,
// and on that, along with its motion.
void hs_support_wake_neighbours(const hs_broadphase *bp, int object, hs_vec3 from);

#endif
