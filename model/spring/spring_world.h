// spring_world.h — the Responsive Workbench spring model as the world sees it: an opaque system,
// present only in spring worlds (hs_world_def.kind), made and freed with the world.
#ifndef HS_SPRING_WORLD_H
#define HS_SPRING_WORLD_H

#include "handspring.h"

typedef struct hs_spring_system hs_spring_system;

// Made and freed by spring_system.c; its part of the world's state walk: spring_state.h.

#endif
