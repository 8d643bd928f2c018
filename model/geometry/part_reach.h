// part_reach.h — how far a convex part reaches once grown: its faces moved out by g (the hand
// check's release margin, contact.c) put a box's corner g·√3 further out, a sharper corner
// further still. The hand's bounding-volume culls grow each part's sphere by that much.
#ifndef HS_PART_REACH_H
#define HS_PART_REACH_H

#include "handspring.h"

// K such that the part with every face moved out by any g ≥ 0 lies within part->radius + g·K of
// part->center (and any vertex-centred bound grows by g·K). At least 1; √3 for a box.
double hs_part_grow_reach(const hs_shape *shape, const hs_part *part);

#endif
