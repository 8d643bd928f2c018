// spring_collide.h — object–object collisions of the spring model (§4.5).
#ifndef HS_SPRING_COLLIDE_H
#define HS_SPRING_COLLIDE_H

#include "spring_system.h"
#include "world_internal.h"

// Every overlapping pair of the world's objects (array order, shapes in sys->geom, found through
// the broad phase sys->grid) exchanges an impulse of restitution sys->def.restitution along the
// contact normal and is pushed apart; each object pushed gets sys->separated[i] = 1 (the caller
// clears the flags).
void hs_spring_collide(hs_world *world, hs_spring_system *sys);

#endif
