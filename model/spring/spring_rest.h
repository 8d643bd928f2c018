// spring_rest.h — resting contact between the spring model's objects: the forces touching objects,
// the floor and the walls exert on each other, found at the frame start (so stacks stand and
// static friction holds through contacts).
#ifndef HS_SPRING_REST_H
#define HS_SPRING_REST_H

#include "spring_system.h"
#include "world_internal.h"

// For the frame about to run: the touches (sys->touch), their impulses (touching objects still
// approaching), the force each object gets from the objects it touches (sys->load) and the
// objects those forces hold still (sys->held: they keep position and get zero velocity).
void hs_spring_rest(hs_world *world, hs_spring_system *sys);

// m/s: an impact slower than this does not bounce and is a resting contact's push (no restitution;
// the floor's static friction may hold the object pushed). Measured: under the tracker's noise
// (§5.1) an object pressed by the spring against another chatters at 0.5 to 20 mm/s.
#define HS_REST_BOUNCE_SPEED 0.05

// m: the drift of a contact at rest. A resting pair's separation by at most this goes only as far
// as the pair's kinetic energy pays (spring_collide.c); an object that deep in another at rest
// is held there all the same (it would step and fall back into the same place every frame).
#define HS_REST_DRIFT 1e-4

#endif
