// manipulate.h — object motion by the hand (1999 paper eq. 1-2, grasp, push; §3.2); interference
// among objects (§4.3) is interfere.h's.
#ifndef HS_MANIPULATE_H
#define HS_MANIPULATE_H

#include <stdbool.h>

#include "world_internal.h"

// Eq. 1-2: moves the surface point c of the body toward b (translation T ∥ CG, rotation about G).
void hs_push_at_one_point(hs_body *body, hs_vec3 c, hs_vec3 b);
// One frame of the hands: detect, classify, move touched objects, release the untouched. The
// stage the pipeline calls: takes the world and makes its steps' contexts once (the broad phase's,
// the contact tests', free motion's; docs/architecture.md lists what each step takes).
void hs_manipulate(hs_world *world);

#endif
