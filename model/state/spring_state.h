// spring_state.h — the spring system's part of the world's state walk (spring_state.c), called
// by the world's walk (state.c).
#ifndef HS_SPRING_STATE_H
#define HS_SPRING_STATE_H

#include "spring_world.h"
#include "state_walk.h"

// Every field of the spring system a later step reads, in a fixed order, each through one
// hs_state_* call (state_walk.h); caches are skipped and rebuilt on LOAD.
void hs_spring_state_io(hs_spring_system *sys, hs_state_io *io);

#endif
