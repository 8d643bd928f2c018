// state.h — the name spring_step.c and spring_world.c still include for the state walk, whose
// header is state_walk.h (the word visitor, state_walk.c); state.c's own functions are the public
// hs_world_*_state and hs_world_hash (handspring.h). New code includes state_walk.h; this file goes
// once those two include it too.
#ifndef HS_STATE_H
#define HS_STATE_H

#include "state_walk.h"

#endif
