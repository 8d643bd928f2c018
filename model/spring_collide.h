// spring_collide.h — object–object collisions of the spring model (§4.5).
#ifndef HS_SPRING_COLLIDE_H
#define HS_SPRING_COLLIDE_H

#include "spring_geom.h"

// Every overlapping pair of the world's objects (array order, reaches in `geom`) exchanges an
// impulse of restitution e along the contact normal and is pushed apart; each object pushed gets
// separated[i] = 1 (the caller clears the flags).
void hs_spring_collide(hs_world *world, const hs_spring_geom *geom, double restitution, uint8_t *separated);

#endif
