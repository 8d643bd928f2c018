// fall_group.c — paper stacking (docs/model.md §6): [H] §4.3 says objects that interfere with each
// other and that no hand touches "are not affected by gravity and inertia". Read literally, a
// stack let go in mid-air hangs there for good; handspring reads it as holding for objects that
// something holds up from below (the floor, or a hand through the objects between): an object
// that nothing under it holds up falls, as one body with what rests on it, and lands as one.
#include "broadphase.h"
#include "fall_group.h"
#include "interfere.h"
#include "motion.h"
#include "stacking.h"

// The least height (m) of a step that holds an object up: objects side by side on one floor
// differ in their lowest points by rounding and by the tilt a push leaves (11 µm seen), far less.
#define HS_HELD_UP_STEP 1e-3

// j holds i up: they interfere and i's lowest point is above j's by HS_HELD_UP_STEP or more (i
// rests on j's upper part, or on a lower step of it: a cube on an L-block's foot; an object beside
// i on the same floor, touching its side, holds nothing up).
static bool supports(const hs_broadphase *bp, int j, int i) {
	if (!hs_objects_interfere(bp->model, bp->bodies, bp->cache->box_memo, i, j))
		return false;
	double low_i = hs_motion_pose_vertices(bp->model, bp->scratch, &bp->bodies[i]);
	return low_i >= hs_motion_pose_vertices(bp->model, bp->scratch, &bp->bodies[j]) + HS_HELD_UP_STEP;
}

static bool listed(const int *list, int n, int j) {
	for (int q = 0; q < n; ++q)
		if (list[q] == j)
			return true;
	return false;
}

// Breadth first from out[0] through `supports`, downward (what holds the members up) or upward
// (what they hold up); returns the count, or 0 when going down reaches something held up: a hand
// holds or carried it this frame, or it is on the floor.
static int walk(const hs_broadphase *bp, int *out, int cap, bool down) {
	int head = 0, n = 1;
	while (head < n) {
		int m = out[head++];
		const hs_body *b = &bp->bodies[m];
		if (down && (b->held || b->carried || b->floor_contacts > 0))
			return 0;
		int near = hs_grid_near(bp, b->pos, bp->model->shapes[b->shape].radius);
		for (int k = 0; k < near; ++k) {
			int j = bp->scratch->near[k];
			if (j == m || listed(out, n, j) || !(down ? supports(bp, j, m) : supports(bp, m, j)))
				continue;
			if (n == cap)
				return 0; // cannot happen: members are distinct objects
			out[n++] = j;
		}
	}
	return n;
}

int hs_fall_group(const hs_broadphase *bp, int object, int *out, int cap) {
	hs_body *bodies = bp->bodies;
	out[0] = object;
	if (walk(bp, out, cap, true) == 0)
		return 0; // held up
	out[0] = object; // nothing holds it up: it falls with what it holds up
	int n = walk(bp, out, cap, false);
	double dt = bp->model->def.dt, mass = 0.0;
	hs_vec3 momentum = hs_v3(0, 0, 0); // per frame: the group moves at its members' mean velocity
	for (int k = 0; k < n; ++k) {
		const hs_body *b = &bodies[out[k]];
		momentum = hs_add(momentum, hs_scale(hs_sub(b->pos, b->prev), b->mass));
		mass += b->mass;
	}
	hs_vec3 gm = hs_add(hs_scale(momentum, 1.0 / mass), hs_scale(bp->model->def.gravity, dt * dt));
	double low = INFINITY;
	for (int k = 0; k < n; ++k) { // eq. 3 for the group: no turn (§4.1: interfering, no inertia of rotation)
		hs_body *b = &bodies[out[k]];
		b->prev = b->pos;
		b->pos = hs_add(b->pos, gm);
		b->rot_prev = b->rot;
		b->spin = hs_quat_identity();
		b->asleep = 0;
		b->grounded = 0;
		double z = hs_motion_pose_vertices(bp->model, bp->scratch, b);
		low = z < low ? z : low;
	}
	bool landed = low <= bp->model->def.floor_tolerance;
	for (int k = 0; k < n; ++k) // §4.2 for the group: lifted as one
		if (low < 0.0)
			bodies[out[k]].pos.z -= low;
	for (int k = 0; k < n; ++k) { // out of what it fell into (Fig. 11), and it stops there (§4.1)
		hs_body *b = &bodies[out[k]];
		landed = hs_stack_rectify(bp, out[k]) || landed;
		hs_motion_keep_above_floor(bp->model, bp->scratch, b);
	}
	for (int k = 0; k < n; ++k) {
		hs_body *b = &bodies[out[k]];
		if (landed) {
			b->prev = b->pos;
			b->grounded = b->floor_contacts > 0;
		}
		hs_grid_update(bp->model, bodies, bp->cache, out[k]);
	}
	return n;
}
