// spring_world.h — the Responsive Workbench spring model (spring.c, tracker.c) as the world sees
// it: an opaque system, present only in worlds that called hs_world_enable_springs.
#ifndef HS_SPRING_WORLD_H
#define HS_SPRING_WORLD_H

#include "handspring.h"

typedef struct hs_spring_system hs_spring_system;
typedef struct hs_state_io hs_state_io;

// One frame of the spring model for every object of the world (replaces the 1999 motion).
void hs_spring_step(hs_world *world);
void hs_spring_system_destroy(hs_spring_system *system);
// The spring system's part of the world walk (state.h): every field a later step reads, in a
// fixed order, each through one hs_state_* call; caches are skipped and rebuilt on LOAD.
void hs_spring_state_io(hs_spring_system *sys, hs_state_io *io);

#endif
