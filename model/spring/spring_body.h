// spring_body.h — one object of the spring model through part of a frame on its own.
#ifndef HS_SPRING_BODY_H
#define HS_SPRING_BODY_H

#include "spring_system.h"

// Object i through `dt` seconds of its own motion on the floor or in the air from where it is:
// the whole frame (the step), or the rest of a frame after a collision within it (spring_collide.c).
void hs_spring_advance(hs_world *world, hs_spring_system *sys, int i, double dt);

#endif
