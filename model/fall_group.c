// fall_group.c — paper stacking (docs/model.md §6): [H] §4.3 says objects that interfere with each
// other and that no hand touches "are not affected by gravity and inertia". Read literally, a
// stack let go in mid-air hangs there for good; handspring reads it as holding for objects that
// something holds up (the floor, or a hand through the objects between): a group that nothing
// holds up falls as one body and lands as one.
#include "broadphase.h"
#include "fall_group.h"
#include "manipulate.h"
#include "motion.h"

// The interference group of `object` in out[0..n) (breadth first); 0 when a member is held up: held
// or carried by a hand this frame, or on the floor.
static int group_of(hs_world *world, int object, int *out, int cap) {
	int head = 0, n = 0;
	out[n++] = object;
	while (head < n) {
		int m = out[head++];
		const hs_body *b = &world->bodies[m];
		if (b->held || b->carried || b->floor_contacts > 0)
			return 0;
		int near = hs_grid_near(world, b->pos, world->shapes[b->shape].radius);
		for (int k = 0; k < near; ++k) {
			int j = world->near[k];
			bool member = false;
			for (int q = 0; q < n && !member; ++q)
				member = out[q] == j;
			if (member || !hs_objects_interfere(world, m, j))
				continue;
			if (n == cap)
				return 0; // cannot happen: members are distinct objects
			out[n++] = j;
		}
	}
	return n;
}

int hs_fall_group(hs_world *world, int object, int *out, int cap) {
	int n = group_of(world, object, out, cap);
	if (n == 0)
		return 0;
	double dt = world->def.dt, mass = 0.0;
	hs_vec3 momentum = hs_v3(0, 0, 0); // per frame: the group moves at its members' mean velocity
	for (int k = 0; k < n; ++k) {
		const hs_body *b = &world->bodies[out[k]];
		momentum = hs_add(momentum, hs_scale(hs_sub(b->pos, b->prev), b->mass));
		mass += b->mass;
	}
	hs_vec3 gm = hs_add(hs_scale(momentum, 1.0 / mass), hs_scale(world->def.gravity, dt * dt));
	double low = INFINITY;
	for (int k = 0; k < n; ++k) { // eq. 3 for the group: no turn (§4.1: interfering, no inertia of rotation)
		hs_body *b = &world->bodies[out[k]];
		b->prev = b->pos;
		b->pos = hs_add(b->pos, gm);
		b->rot_prev = b->rot;
		b->spin = hs_quat_identity();
		b->asleep = 0;
		b->grounded = 0;
		double z = hs_motion_pose_vertices(world, b);
		low = z < low ? z : low;
	}
	bool landed = low <= world->def.floor_tolerance;
	for (int k = 0; k < n; ++k) { // §4.2 for the group: lifted as one, and it stops (§4.1)
		hs_body *b = &world->bodies[out[k]];
		if (low < 0.0)
			b->pos.z -= low;
		hs_motion_keep_above_floor(world, b);
		if (landed) {
			b->prev = b->pos;
			b->grounded = b->floor_contacts > 0;
		}
		hs_grid_update(world, out[k]);
	}
	return n;
}
