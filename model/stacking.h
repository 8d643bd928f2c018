// stacking.h — objects against objects in both stacking modes (1999 paper §4.3, Fig. 11):
// interpenetration between objects is rectified as against the floor (§4.2), and a fall is
// tested along its path through the frame, not only at its end.
#ifndef HS_STACKING_H
#define HS_STACKING_H

#include <stdbool.h>

#include "world_internal.h"

// How far body a must rise (+z) for none of its vertices to lie inside b and none of b's inside
// a: exact for vertex-face interpenetration of convex parts.
double hs_stack_lift_out(const hs_world *world, const hs_body *a, const hs_body *b);
// §4.2 against objects (Fig. 11): lifts `object` along +z out of every object whose G is not above
// its own, so its lowest point rests on their surface. True when it was inside one.
bool hs_stack_rectify(hs_world *world, int object);
// The fall of `object` this frame, from `from` to its pose now, swept over the objects under it:
// at the first sub-pose that sinks into one, it is rectified onto it (above). True when it landed.
bool hs_stack_sweep(hs_world *world, int object, hs_vec3 from);

#endif
