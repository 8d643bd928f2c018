// contact_pass.h — the parts of a world the hand-object contact tests take (contact.h, the 1999
// paper §3.2): their context, of its own so that the private contact headers (contact_rules.h,
// contact_swept.h, contact_cull.h) take it without including contact.h, which includes them.
#ifndef HS_CONTACT_PASS_H
#define HS_CONTACT_PASS_H

#include "world_internal.h"

// The parts of a world the contact tests read and write: the model (shapes, their part caches and
// face trees and edges, the definition, the hand count), the bodies (read: the object's pose now
// and a frame ago), the hands (their check points and lines; detection writes each hand's pass
// scratch and readies its segments), the scratch (a swept line's picks against a many-faced part,
// contact_swept.c), the output (the frame's contacts, appended) and the counters (hand tests,
// dropped contacts); `frame` the state's frame number (an object came onto a part only after the
// first frame). Made once per hand pass (hs_contact_pass_of); the grasp (grasp.h) and the hand
// pass (manipulate.c) hand it down.
typedef struct hs_contact_pass {
	const hs_world_model *model;
	const hs_body *bodies;
	hs_hand *hands;
	hs_world_scratch *scratch;
	hs_world_output *out;
	hs_world_counters *counters;
	long frame;
} hs_contact_pass;

// A world's contact parts.
static inline hs_contact_pass hs_contact_pass_of(hs_world *world) {
	return (hs_contact_pass){&world->model, world->state.bodies, world->state.hands, &world->scratch,
	                         &world->out,   &world->counters,    world->state.frame};
}

#endif
