// spring_body.h — one object of the spring model through part of a frame on its own.
#ifndef HS_SPRING_BODY_H
#define HS_SPRING_BODY_H

#include "spring_system.h"
#include "world_internal.h"

// Object i (`body`) through `dt` seconds of its own motion on the floor or in the air from where it
// is: the whole frame (the step), or the rest of a frame after a collision within it
// (spring_collide.c). Reads the world's gravity and floor tolerance; counts its work in *counters.
void hs_spring_advance(hs_spring_system *sys, int i, hs_body *body, const hs_world_def *def, double dt,
                       hs_world_counters *counters);

#endif
