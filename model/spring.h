// spring.h — what the world calls of the spring model (the Responsive Workbench paper): the
// per-frame step, the end of the system, and its state walk.
#ifndef HS_SPRING_H
#define HS_SPRING_H

#include "internal.h"
#include "state.h"

// One frame of the spring model for every object of the world (replaces the 1999 motion).
void hs_spring_step(hs_world *world);
void hs_spring_system_destroy(hs_spring_system *system);
// Visits every field of the spring system and its tracker that a later step reads (not the
// definition, not what lives in hs_body, not caches the step recomputes). LOAD checks what it
// read and sets io->invalid and io->why on a bad value (the system must then not be stepped).
void hs_spring_state_io(hs_spring_system *sys, hs_state_io *io);

#endif
