// spring_solve.c — the forces of the resting contacts between the spring model's objects, the
// floor and the walls (spring_rest.c sets the problem up: which pairs touch, how each slides, the
// free forces; its header gives the reading).
//
//  - Projected Gauss–Seidel over the floor and walls of each object, then over the touches, until
//    no force changes by more than HS_REST_CONVERGED of the largest free force (or
//    HS_REST_MAX_SWEEPS sweeps).
//  - Sticking contacts are first solved in Coulomb's cone: each contact's normal force and
//    friction together, stepped as far as the contact's own residual asks and projected onto
//    |f| ≤ μ_static n (see onto_cone). Where the contacts can hold every object still, these
//    sweeps find forces that do; the older order — normal force first, friction then clipped to
//    μ n — did not converge in a statically indeterminate pile (1000 sweeps, forces creeping by
//    mN a sweep, balls stepping µm a frame for good). Where they cannot, the cone's answer lifts
//    contacts whose friction is at its limit, which Coulomb's law does not: that frame is solved
//    again in the older order.
//  - Warm start: each sticking touch that goes on from the last frame starts from the forces it
//    ended that frame with (sys->warm, part of the state, so a resumed run matches an unbroken
//    one), so a still pile's solve goes on where the last frame's stopped: over frames it
//    converges where one frame's 1000 sweeps did not (one frame of a dense drop's pile took the
//    cone 266,000 sweeps from zero).
#include <string.h>

#include "spring_contact.h"
#include "spring_solve.h"

#define HS_REST_CONVERGED 1e-13    // relative change of every force in a sweep that ends the solve
#define HS_REST_MAX_SWEEPS 1000    // Gauss–Seidel sweeps at most

// Friction f (N, across the normal) held within radius `limit`.
static hs_vec3 within_cone(hs_vec3 f, double limit) {
	double len = hs_length(f);
	return len > limit ? hs_scale(f, limit / len) : f;
}

// The point of the cone |f| ≤ μ n nearest to (n, f). Objects do not turn (§4.2), so a contact's
// block of the solve's matrix is 1 / m_c times the identity, and this projection of the
// contact's unconstrained step is its exact minimiser: the sweeps descend one convex quadratic.
static void onto_cone(double *n, hs_vec3 *f, double mu) {
	double t = hs_length(*f);
	if (t <= mu * *n)
		return;
	if (mu * t <= -*n) { // in the polar cone: the contact opens
		*n = 0.0;
		*f = hs_v3(0.0, 0.0, 0.0);
		return;
	}
	double nn = (*n + mu * t) / (1.0 + mu * mu);
	*f = hs_scale(*f, mu * nn / t);
	*n = nn;
}

// Contact forces (*normal, *friction) stepped to (n, f) and projected onto the cone |f| ≤ μ n:
// the new forces kept, their changes in *dn and *df; the larger change.
static double step_in_cone(double *normal, hs_vec3 *friction, double n, hs_vec3 f, double mu, double *dn,
                           hs_vec3 *df) {
	onto_cone(&n, &f, mu);
	*dn = n - *normal;
	*df = hs_sub(f, *friction);
	*normal = n;
	*friction = f;
	return fmax(fabs(*dn), hs_length(*df));
}

// The floor's normal force and friction on a resting object, stepped together and projected
// onto the cone; the larger change.
static double floor_in_cone(hs_spring_rest_body *r, double m, double mu) {
	double dn;
	hs_vec3 df;
	double change = step_in_cone(&r->floor_normal, &r->floor_friction, r->floor_normal - m * r->acc.z,
	                             hs_sub(r->floor_friction, hs_scale(hs_v3(r->acc.x, r->acc.y, 0.0), m)), mu, &dn, &df);
	r->acc = hs_mul_add(r->acc, 1.0 / m, hs_v3(df.x, df.y, dn));
	return change;
}

// One Gauss–Seidel sweep over the floor and walls of each active object (sticking floor contacts
// in the cone when `cone`); the largest change.
static double sweep_bodies(hs_world *world, hs_spring_system *sys, double dt, bool cone) {
	const hs_spring_def *d = &sys->def;
	double change = 0.0;
	for (int k = 0; k < sys->active_count; ++k) {
		hs_spring_rest_body *r = &sys->rest[k];
		const hs_body *b = &world->state.bodies[sys->active[k]];
		double m = b->mass;
		if (r->floor && cone && !r->sliding) {
			change = fmax(change, floor_in_cone(r, m, d->friction_static));
		} else if (r->floor) {
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

// A sticking touch's normal force and friction, stepped together and projected onto the cone;
// the larger change.
static double touch_in_cone(hs_spring_touch *c, hs_spring_rest_body *ra, hs_spring_rest_body *rb, double wa,
                            double wb, double mu) {
	hs_vec3 ar = hs_sub(rb->acc, ra->acc);
	double an = hs_dot(ar, c->n), dn;
	hs_vec3 df;
	double change = step_in_cone(&c->normal, &c->friction, c->normal - c->mass * (an + c->bias),
	                             hs_mul_add(c->friction, -c->mass, hs_mul_add(ar, -an, c->n)), mu, &dn, &df);
	hs_vec3 dl = hs_mul_add(df, dn, c->n);
	ra->acc = hs_mul_add(ra->acc, -wa, dl);
	rb->acc = hs_mul_add(rb->acc, wb, dl);
	return change;
}

// One Gauss–Seidel sweep over the touches (sticking ones in the cone when `cone`); the largest
// change.
static double sweep_touches(hs_world *world, hs_spring_system *sys, double dt, bool cone) {
	const hs_spring_def *d = &sys->def;
	double change = 0.0;
	for (int t = 0; t < sys->touch_count; ++t) {
		hs_spring_touch *c = &sys->touch[t];
		if (c->open)
			continue;
		hs_spring_rest_body *ra = &sys->rest[sys->rest_index[c->a]], *rb = &sys->rest[sys->rest_index[c->b]];
		double wa = 1.0 / world->state.bodies[c->a].mass, wb = 1.0 / world->state.bodies[c->b].mass;
		if (cone && !(hs_length_sq(c->slide) > 0.0)) {
			change = fmax(change, touch_in_cone(c, ra, rb, wa, wb, d->friction_static));
			continue;
		}
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
			hs_vec3 v = hs_sub(world->state.bodies[c->b].vel, world->state.bodies[c->a].vel);
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

// Sweeps until no force changes by more than HS_REST_CONVERGED of the largest free force.
static void solve(hs_world *world, hs_spring_system *sys, double dt, double scale, bool cone) {
	for (int sweep = 0; sweep < HS_REST_MAX_SWEEPS; ++sweep) {
		double change = sweep_bodies(world, sys, dt, cone); // (two statements: the order is the result's)
		change = fmax(change, sweep_touches(world, sys, dt, cone));
		if (!(change > HS_REST_CONVERGED * scale))
			return;
	}
}

// The cone's answer lifts a contact whose friction is at its limit (its normal acceleration
// apart is more than HS_REST_TOLERANCE of the largest free force, per unit of the pair's mass):
// there Coulomb's law would let the contact slide instead.
static bool cone_lifts(const hs_world *world, const hs_spring_system *sys, double scale) {
	// (friction at the limit to rounding)
	double mu = sys->def.friction_static * (1.0 - HS_REST_TOLERANCE), allowed = HS_REST_TOLERANCE * scale;
	for (int k = 0; k < sys->active_count; ++k) {
		const hs_spring_rest_body *r = &sys->rest[k];
		if (r->floor && !r->sliding && r->floor_normal > 0.0 && hs_length(r->floor_friction) >= mu * r->floor_normal &&
		    r->acc.z * world->state.bodies[sys->active[k]].mass > allowed)
			return true;
	}
	for (int t = 0; t < sys->touch_count; ++t) {
		const hs_spring_touch *c = &sys->touch[t];
		if (c->open || hs_length_sq(c->slide) > 0.0 || !(c->normal > 0.0) || hs_length(c->friction) < mu * c->normal)
			continue;
		const hs_spring_rest_body *ra = &sys->rest[sys->rest_index[c->a]], *rb = &sys->rest[sys->rest_index[c->b]];
		if ((hs_dot(hs_sub(rb->acc, ra->acc), c->n) + c->bias) * c->mass > allowed)
			return true;
	}
	return false;
}

// Every force of the solve back to none.
static void restart(hs_world *world, hs_spring_system *sys) {
	for (int k = 0; k < sys->active_count; ++k) {
		hs_spring_rest_body *r = &sys->rest[k];
		r->acc = hs_scale(r->force, 1.0 / world->state.bodies[sys->active[k]].mass);
		r->floor_normal = 0.0;
		r->floor_friction = hs_v3(0.0, 0.0, 0.0);
		memset(r->wall, 0, sizeof r->wall);
	}
	for (int t = 0; t < sys->touch_count; ++t) {
		sys->touch[t].normal = 0.0;
		sys->touch[t].friction = hs_v3(0.0, 0.0, 0.0);
	}
}

// Each sticking touch that goes on from the last frame starts from the forces it ended it with:
// its friction turned across the new normal, both put back in the cone.
static void warm_start(hs_world *world, hs_spring_system *sys) {
	double mu = sys->def.friction_static;
	int w = 0;
	for (int t = 0; t < sys->touch_count; ++t) {
		hs_spring_touch *c = &sys->touch[t];
		while (w < sys->warm_count && (sys->warm[w].a < c->a || (sys->warm[w].a == c->a && sys->warm[w].b < c->b)))
			++w; // (both lists ascend)
		if (w == sys->warm_count)
			return;
		const hs_spring_warm *last = &sys->warm[w];
		if (last->a != c->a || last->b != c->b || c->open || hs_length_sq(c->slide) > 0.0)
			continue;
		double n = last->normal;
		hs_vec3 f = hs_mul_add(last->friction, -hs_dot(last->friction, c->n), c->n);
		onto_cone(&n, &f, mu);
		c->normal = n;
		c->friction = f;
		hs_vec3 on_b = hs_mul_add(f, n, c->n);
		hs_spring_rest_body *ra = &sys->rest[sys->rest_index[c->a]], *rb = &sys->rest[sys->rest_index[c->b]];
		ra->acc = hs_mul_add(ra->acc, -1.0 / world->state.bodies[c->a].mass, on_b);
		rb->acc = hs_mul_add(rb->acc, 1.0 / world->state.bodies[c->b].mass, on_b);
	}
}

void hs_spring_keep_forces(hs_spring_system *sys) {
	int n = sys->touch_count;
	for (int t = 0; t < n; ++t) {
		const hs_spring_touch *c = &sys->touch[t];
		sys->warm[t] = (hs_spring_warm){c->a, c->b, c->normal, c->friction};
	}
	if (sys->warm_count > n) // (zero beyond the count: what a state's hash leaves out, spring_state.c)
		memset(&sys->warm[n], 0, (size_t)(sys->warm_count - n) * sizeof *sys->warm);
	sys->warm_count = n;
}

void hs_spring_solve(hs_world *world, hs_spring_system *sys, double dt) {
	double scale = 0.0;
	for (int k = 0; k < sys->active_count; ++k)
		scale = fmax(scale, hs_length(sys->rest[k].force));
	warm_start(world, sys);
	solve(world, sys, dt, scale, true);
	if (cone_lifts(world, sys, scale)) { // Coulomb's order instead (the file's header)
		restart(world, sys);
		solve(world, sys, dt, scale, false);
	}
	hs_spring_keep_forces(sys);
}
