// spring_world.h — the Responsive Workbench spring model (spring.c, tracker.c) as the world sees
// it: an opaque system, present only in worlds that called hs_world_enable_springs.
#ifndef HS_SPRING_WORLD_H
#define HS_SPRING_WORLD_H

#include "handspring.h"

typedef struct hs_spring_system hs_spring_system;

// One frame of the spring model for every object of the world (replaces the 1999 motion).
void hs_spring_step(hs_world *world);
void hs_spring_system_destroy(hs_spring_system *system);
// Its part of the world's state walk: spring_state.h.

#endif
