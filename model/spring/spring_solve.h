// spring_solve.h — the resting contacts' forces (spring_solve.c), for spring_rest.c.
#ifndef HS_SPRING_SOLVE_H
#define HS_SPRING_SOLVE_H

#include "spring_system.h"
#include "world_internal.h"

// The forces of the touches sys->touch and of the floor and walls on the objects sys->active
// (sys->rest), as spring_rest.c's prepare left them set up (forces zero, each object's
// acceleration under its free force).
void hs_spring_solve(hs_world *world, hs_spring_system *sys, double dt);

// The touches' forces as the frame's solve leaves them, for the next frame's start (sys->warm).
void hs_spring_keep_forces(hs_spring_system *sys);

// Relative: what the forces may leave unbalanced on an object they hold (of its load).
#define HS_REST_TOLERANCE 1e-9

#endif
