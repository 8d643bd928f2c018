// spring_solve.c — the forces of the resting contacts between the spring model's objects, the
// floor and the walls (spring_rest.c sets the problem up: which pairs touch, how each slides, the
// free forces; its header gives the reading): projected Gauss–Seidel over the floor and walls of
// each object, then over the touches, until no force changes by more than HS_REST_CONVERGED of
// the largest free force (or HS_REST_MAX_SWEEPS sweeps).
#include "spring_contact.h"
#include "spring_solve.h"

#define HS_REST_CONVERGED 1e-13    // relative change of every force in a sweep that ends the solve
#define HS_REST_MAX_SWEEPS 1000    // Gauss–Seidel sweeps at most

// Friction f (N, across the normal) held within radius `limit`.
static hs_vec3 within_cone(hs_vec3 f, double limit) {
	double len = hs_length(f);
	return len > limit ? hs_scale(f, limit / len) : f;
}

// One Gauss–Seidel sweep over the floor and walls of each active object; the largest change.
static double sweep_bodies(hs_world *world, hs_spring_system *sys, double dt) {
	const hs_spring_def *d = &sys->def;
	double change = 0.0;
	for (int k = 0; k < sys->active_count; ++k) {
		hs_spring_rest_body *r = &sys->rest[k];
		const hs_body *b = &world->bodies[sys->active[k]];
		double m = b->mass;
		if (r->floor) {
			double n = fmax(0.0, r->floor_normal - m * r->acc.z);
			r->acc.z += (n - r->floor_normal) / m;
			change = fmax(change, fabs(n - r->floor_normal));
			r->floor_normal = n;
			hs_vec3 f;
			if (r->sliding) { // against the sliding, no more than stops it this frame
				hs_vec3 vh = hs_v3(b->vel.x, b->vel.y, 0.0);
				double speed = hs_length(vh);
				f = hs_scale(vh, -fmin(d->friction_sliding * n, m * speed / dt) / speed);
			} else {
				f = within_cone(hs_sub(r->floor_friction, hs_scale(hs_v3(r->acc.x, r->acc.y, 0.0), m)),
				                d->friction_static * n);
			}
			hs_vec3 df = hs_sub(f, r->floor_friction);
			r->acc = hs_mul_add(r->acc, 1.0 / m, df);
			change = fmax(change, hs_length(df));
			r->floor_friction = f;
		}
		for (int q = 0; q < 4; ++q) {
			if (!((unsigned)r->walls >> q & 1u))
				continue;
			hs_vec3 wn = hs_spring_wall_normal(q);
			double n = fmax(0.0, r->wall[q] - m * hs_dot(r->acc, wn));
			r->acc = hs_mul_add(r->acc, (n - r->wall[q]) / m, wn);
			change = fmax(change, fabs(n - r->wall[q]));
			r->wall[q] = n;
		}
	}
	return change;
}

// One Gauss–Seidel sweep over the touches; the largest change.
static double sweep_touches(hs_world *world, hs_spring_system *sys, double dt) {
	const hs_spring_def *d = &sys->def;
	double change = 0.0;
	for (int t = 0; t < sys->touch_count; ++t) {
		hs_spring_touch *c = &sys->touch[t];
		if (c->open)
			continue;
		hs_spring_rest_body *ra = &sys->rest[sys->rest_index[c->a]], *rb = &sys->rest[sys->rest_index[c->b]];
		double wa = 1.0 / world->bodies[c->a].mass, wb = 1.0 / world->bodies[c->b].mass;
		double n = fmax(0.0, c->normal - c->mass * (hs_dot(hs_sub(rb->acc, ra->acc), c->n) + c->bias));
		double dn = n - c->normal;
		ra->acc = hs_mul_add(ra->acc, -dn * wa, c->n);
		rb->acc = hs_mul_add(rb->acc, dn * wb, c->n);
		change = fmax(change, fabs(dn));
		c->normal = n;
		hs_vec3 f;
		if (hs_length_sq(c->slide) > 0.0) {
			// sliding: against it, no more than stops it this frame with every other force acting
			// (one contact's own stop let three boxes sliding on a fourth throw it back each frame)
			hs_vec3 v = hs_sub(world->bodies[c->b].vel, world->bodies[c->a].vel);
			double held = -hs_dot(c->friction, c->slide);
			double stop = held + c->mass * (hs_dot(hs_sub(rb->acc, ra->acc), c->slide) + hs_dot(v, c->slide) / dt);
			f = hs_scale(c->slide, -fmin(d->friction_sliding * n, fmax(0.0, stop)));
		} else {
			hs_vec3 ar = hs_sub(rb->acc, ra->acc);
			hs_vec3 at = hs_mul_add(ar, -hs_dot(ar, c->n), c->n);
			f = within_cone(hs_mul_add(c->friction, -c->mass, at), d->friction_static * n);
		}
		hs_vec3 df = hs_sub(f, c->friction);
		ra->acc = hs_mul_add(ra->acc, -wa, df);
		rb->acc = hs_mul_add(rb->acc, wb, df);
		change = fmax(change, hs_length(df));
		c->friction = f;
	}
	return change;
}

void hs_spring_solve(hs_world *world, hs_spring_system *sys, double dt) {
	double scale = 0.0;
	for (int k = 0; k < sys->active_count; ++k)
		scale = fmax(scale, hs_length(sys->rest[k].force));
	for (int sweep = 0; sweep < HS_REST_MAX_SWEEPS; ++sweep) {
		double change = sweep_bodies(world, sys, dt); // (two statements: the order is the result's)
		change = fmax(change, sweep_touches(world, sys, dt));
		if (!(change > HS_REST_CONVERGED * scale))
			return;
	}
}
