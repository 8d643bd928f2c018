// stacking.h — objects against objects in both stacking modes (1999 paper §4.3, Fig. 11):
// interpenetration between objects is rectified as against the floor (§4.2), and a fall is
// tested along its path through the frame, not only at its end.
#ifndef HS_STACKING_H
#define HS_STACKING_H

#include <stdbool.h>

#include "broadphase.h"
#include "world_internal.h"

// How far body a (of shape sa) must rise (+z) for none of its vertices to lie inside b (of shape
// sb) and none of b's inside a: exact for vertex-face interpenetration of convex parts.
double hs_stack_lift_out(const hs_shape *sa, const hs_body *a, const hs_shape *sb, const hs_body *b);
// §4.2 against objects (Fig. 11): lifts `object` along +z out of every object whose G is not above
// its own, so its lowest point rests on their surface. True when it was inside one.
bool hs_stack_rectify(const hs_broadphase *bp, int object);
// Paper mode, Fig. 11 ("an object piled on another, when the operator pushes an L-shaped block
// along the floor into a cube ... handled by the rectification process for the penetration of
// the cube into a floor"): `object`, which `mover` met this frame, rises along +z out of it when
// that lift is at most the height of its G above its lowest point (what it met lies below its G,
// as the L-block's foot under the cube). True when lifted; else it is left as it is. Reads the
// model's shapes; writes the object's body alone.
bool hs_stack_pile_onto(const hs_world_model *model, hs_body *bodies, int object, int mover);
// The fall of `object` this frame, from `from` to its pose now, swept over the objects under it:
// at the first sub-pose that sinks into one, it is rectified onto it (above). True when it landed.
bool hs_stack_sweep(const hs_broadphase *bp, int object, hs_vec3 from);

#endif
