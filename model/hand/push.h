// push.h — a push at one point on an object lying on the floor (1999 paper eq. 1-2 under §4.2).
#ifndef HS_PUSH_H
#define HS_PUSH_H

#include <stdbool.h>

#include "motion.h"

// Coulomb friction of a fingertip on an object and of an object on the floor (the same μ for
// both, docs/model.md §4): a part drags the surface it touches sideways by at most μ times how far
// it went into it (contact_rules.c), and a push that presses an object on the floor at least as much
// as it drives it sideways leaves it where it is (push.c).
#define HS_PUSH_FRICTION 1.0

// Each push below takes free motion's parts (motion.h): the model (shapes, definition), the scratch
// (the posed vertices and floor points it reads the floor from) and, for a release that settles,
// the bodies and counters hs_motion_settle reads and counts in. It moves `body` alone.

// Eq. 1-2 for an object on the floor (two or more floor vertices, or grounded): moves the surface
// point c toward b without lifting the object off the floor or turning it into it (docs/model.md
// §4 "Pushing an object on the floor"). Returns false, leaving the body alone, when the object is
// not on the floor: the caller then applies eq. 1-2 as for a free object.
bool hs_push_on_floor(const hs_motion_pass *m, hs_body *body, hs_vec3 c, hs_vec3 b);
// §3.2 (3), push at several points: translates the object by d (the mean of the parts' pushes),
// along the floor only when it lies on the floor.
void hs_push_many(const hs_motion_pass *m, hs_body *body, hs_vec3 d);
// A push has ended: an object lying on the floor and stable there (G' inside its floor hull)
// stops where it is instead of flying on by eq. 3 (docs/model.md §4 "Release"). After a push at
// several points (`many`) an object on the floor and not stable tips there by §4.2's rules
// instead. False when it is not on the floor, or after a one-point push not stable: eq. 3 then
// carries it on.
bool hs_push_release_on_floor(const hs_motion_pass *m, hs_body *body, bool many);

#endif
