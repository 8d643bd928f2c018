// collide.h — interference of posed shapes within a gap (collide.c), for the spring model's
// resting contacts: shapes that do not overlap but lie within `gap` of each other still touch.
#ifndef HS_COLLIDE_H
#define HS_COLLIDE_H

#include "handspring.h"

// hs_shapes_penetration with both shapes grown by gap / 2 (gap ≥ 0): true when they lie within
// gap of each other; *depth is the penetration less gap, so in [−gap, 0) for shapes apart but
// within the gap. With gap = 0 the bits of hs_shapes_penetration.
bool hs_shapes_within(const hs_shape *a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b, hs_vec3 pos_b,
                      hs_quat rot_b, double gap, double *depth, hs_vec3 *direction);

#endif
