// spring_impulse.h — the impulse between two objects of the spring model and the pair's restitution.
#ifndef HS_SPRING_IMPULSE_H
#define HS_SPRING_IMPULSE_H

#include "spring_system.h"
#include "world_internal.h"

#define HS_REST_STICK_SPEED 1e-6 // m/s: slower than this a contact sticks (spring_contact.c's)

// True when the floor's static friction takes the impulse `push` (N s) on object i within the
// frame: i lies on the floor and does not slide, the push goes along or into the floor, and its
// horizontal part is at most μ m g dt.
static inline bool hs_spring_floor_takes(const hs_world *world, const hs_spring_system *sys, int i, hs_vec3 push) {
	const hs_body *b = &world->state.bodies[i];
	double tol = world->model.def.floor_tolerance, grip = sys->def.friction_static * b->mass * hs_length(world->model.def.gravity);
	return b->pos.z + sys->geom[i].lo.z <= tol && hs_length(hs_v3(b->vel.x, b->vel.y, 0.0)) <= HS_REST_STICK_SPEED &&
	       push.z <= 0.0 && hs_length(hs_v3(push.x, push.y, 0.0)) <= grip * world->model.def.dt;
}

// The impulse of restitution e along n (unit, from i to j) when i and j approach (true then).
// For a resting contact (`resting`), an object lying on the floor whose static friction takes the
// impulse within the frame (μ m g dt) does not move: the other stops against it.
bool hs_spring_pair_impulse(hs_world *world, const hs_spring_system *sys, int i, int j, hs_vec3 n, double e,
                            bool resting);

// The restitution of a pair of objects: the smaller of their own (hs_object_def.restitution; the
// model's, def->restitution, where unset).
double hs_spring_pair_restitution(const hs_spring_def *def, const hs_body *a, const hs_body *b);

#endif
