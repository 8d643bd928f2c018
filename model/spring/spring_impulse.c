// spring_impulse.c — the impulse two objects of the spring model exchange along their contact
// normal (§4.5: momentum is conserved), with the pair's restitution; spring_rest.c's touches
// still approaching and spring_collide.c's meetings both answer with it.
#include "spring_impulse.h"

double hs_spring_pair_restitution(const hs_spring_def *def, const hs_body *a, const hs_body *b) {
	double ea = a->restitution, eb = b->restitution;
	ea = ea < 0.0 ? def->restitution : ea;
	eb = eb < 0.0 ? def->restitution : eb;
	return fmin(ea, eb);
}

bool hs_spring_pair_impulse(hs_world *world, const hs_spring_system *sys, int i, int j, hs_vec3 n, double e,
                            bool resting) {
	hs_body *a = &world->state.bodies[i], *b = &world->state.bodies[j];
	double vn = hs_dot(hs_sub(b->vel, a->vel), n);
	if (!(vn < 0.0))
		return false;
	double wa = 1.0 / a->mass, wb = 1.0 / b->mass;
	if (resting && hs_spring_floor_takes(world, sys, i, hs_scale(n, (1.0 + e) * vn / wb)))
		wa = 0.0; // the floor holds a: b stops against it
	else if (resting && hs_spring_floor_takes(world, sys, j, hs_scale(n, -(1.0 + e) * vn / wa)))
		wb = 0.0;
	double impulse = -(1.0 + e) * vn / (wa + wb);
	a->vel = hs_mul_add(a->vel, -impulse * wa, n);
	b->vel = hs_mul_add(b->vel, impulse * wb, n);
	return true;
}
