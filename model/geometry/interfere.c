// interfere.c — interference between objects as they stand (1999 paper §4.3): the tests the
// stacking stages ask (fall_group.c, support.c, the hand step's paper mode).
#include "broadphase.h"
#include "interfere.h"

bool hs_objects_interfere(hs_world *world, int i, int j) { return i != j && bodies_overlap(world, i, j); }

bool hs_object_interferes(hs_world *world, int object) {
	const hs_body *body = &world->state.bodies[object];
	int n = hs_grid_near(world, body->pos, world->model.shapes[body->shape].radius);
	for (int k = 0; k < n; ++k)
		if (world->scratch.near[k] != object && bodies_overlap(world, object, world->scratch.near[k]))
			return true;
	return false;
}
