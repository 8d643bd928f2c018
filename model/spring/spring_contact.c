// spring_contact.c — the floor and the walls of the spring model, from "Dynamics in Interaction on
// the Responsive Workbench" (§4.2 friction, §4.5 ground and walls, Fig. 4).
//
// Readings fixed here (the paper leaves them open; docs/model.md §8 "Ground and walls", "Friction"):
//  - Constraints after the unconstrained step (splitting): the normal force N and the friction
//    force are evaluated once per stretch of a frame with the object held where it is and the
//    stylus at the frame end (the force the ground must supply to keep it still), then enter the
//    step as constant forces; afterwards the floor and the walls are projections (the position
//    is clamped and the velocity into the constraint removed: ground and walls absorb the impact,
//    the paper's drop ends on the ground).
//  - An object on the floor does not slide while the horizontal force ≤ μ N (with a 1e-9 relative
//    tolerance, so exactly μ N holds on every compiler); a sliding object feels μ_sliding N against
//    its velocity and stops when the velocity along its initial direction crosses zero — the
//    crossing is found by bisection, the rest of the frame starts from there (stuck again, or
//    breaking away the other way).
//  - A critically damped pull against sliding friction need not cross zero: it creeps toward the
//    point where the spring force equals μ_sliding N and, with μ_sliding = μ, would never quite
//    stop. So an object slower than 1 µm/s whose excess force over μ N would stretch the spring by
//    less than 1 nm (k · 1e-9 m) counts as held — the same rule at rest, where it means a pull that
//    would move the object by less than a nanometre does not break it away.
//  - A wall takes the force and velocity components pushing into it (frictionless walls), so a
//    pulled object stays at the wall while the spring stretches (Fig. 4).
#include "spring_contact.h"

#define HS_FRICTION_TOLERANCE 1e-9 // relative: a force within this of μ N does not break away
#define HS_STICK_SPEED 1e-6        // m/s: slower than this an object may stick (creep has ended)
#define HS_STICK_TRAVEL 1e-9       // m: a pull that would move a held object less than this is held
#define HS_MAX_SEGMENTS 4          // stop / break-away stretches per object and frame
#define HS_STOP_BISECTIONS 60      // halvings of the stretch when locating a stop

void hs_spring_wall_block(const hs_spring_walls *wl, const hs_spring_geom *g, hs_vec3 p, double tol, hs_vec3 *vec) {
	if (!wl->enabled)
		return;
	if (p.x + g->lo.x <= wl->x_min + tol && vec->x < 0.0)
		vec->x = 0.0;
	if (p.x + g->hi.x >= wl->x_max - tol && vec->x > 0.0)
		vec->x = 0.0;
	if (p.y + g->lo.y <= wl->y_min + tol && vec->y < 0.0)
		vec->y = 0.0;
	if (p.y + g->hi.y >= wl->y_max - tol && vec->y > 0.0)
		vec->y = 0.0;
}

hs_vec3 hs_spring_wall_normal(int k) {
	static const hs_vec3 n[4] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
	return n[k];
}

unsigned hs_spring_walls_near(const hs_spring_walls *wl, const hs_spring_geom *g, hs_vec3 p, double tol) {
	if (!wl->enabled)
		return 0u;
	return (p.x + g->lo.x <= wl->x_min + tol ? 1u : 0u) | (p.x + g->hi.x >= wl->x_max - tol ? 2u : 0u) |
	       (p.y + g->lo.y <= wl->y_min + tol ? 4u : 0u) | (p.y + g->hi.y >= wl->y_max - tol ? 8u : 0u);
}

void hs_spring_wall_project(const hs_spring_walls *wl, const hs_spring_geom *g, hs_vec3 *p, hs_vec3 *vel) {
	if (!wl->enabled)
		return;
	if (p->x + g->lo.x < wl->x_min) {
		p->x = wl->x_min - g->lo.x;
		if (vel && vel->x < 0.0)
			vel->x = 0.0;
	}
	if (p->x + g->hi.x > wl->x_max) {
		p->x = wl->x_max - g->hi.x;
		if (vel && vel->x > 0.0)
			vel->x = 0.0;
	}
	if (p->y + g->lo.y < wl->y_min) {
		p->y = wl->y_min - g->lo.y;
		if (vel && vel->y < 0.0)
			vel->y = 0.0;
	}
	if (p->y + g->hi.y > wl->y_max) {
		p->y = wl->y_max - g->hi.y;
		if (vel && vel->y > 0.0)
			vel->y = 0.0;
	}
}

// The force on an object held still at p with the stylus at the frame end: gravity, spring, and
// the damper (which then sees the stylus velocity only).
static hs_vec3 hold_force(const hs_spring_support *su, hs_vec3 p) {
	hs_vec3 f = hs_scale(su->gravity, su->sp->mass);
	if (su->attached)
		f = hs_add(f, hs_spring_force(su->sp, su->axis, p, hs_v3(0.0, 0.0, 0.0), su->stylus_end, su->stylus_velocity));
	if (su->load)
		f = hs_add(f, *su->load);
	return f;
}

// The time within [0, rest] at which the horizontal velocity along dir crosses zero (bisection).
static double stop_time(const hs_spring_support *su, const hs_spring_segment *sg, hs_vec3 p, hs_vec3 v, hs_vec3 dir,
                        double rest) {
	hs_vec3 p1, v1;
	double lo = 0.0, hi = rest;
	for (int k = 0; k < HS_STOP_BISECTIONS; ++k) {
		double mid = 0.5 * (lo + hi);
		hs_spring_integrate(su->integrator, sg, p, v, mid, &p1, &v1);
		if (hs_dot(hs_v3(v1.x, v1.y, 0.0), dir) > 0.0)
			lo = mid;
		else
			hi = mid;
	}
	return hi;
}

// One stretch on the floor from time t with the force f of the object held still: static friction
// holds it (§4.2), or it slides against μ_sliding N to the frame end, or it stops within the stretch.
// True only in the last case, with the time it took in *used: the frame goes on from there.
static bool floor_stretch(const hs_spring_support *su, hs_spring_segment *sg, hs_vec3 f, double t, hs_vec3 *p,
                          hs_vec3 *v, bool *sliding, double *used) {
	double mu_s = su->def->friction_static, mu_k = su->def->friction_sliding;
	double normal = f.z < 0.0 ? -f.z : 0.0;
	hs_vec3 fh = hs_v3(f.x, f.y, 0.0), vh = hs_v3(v->x, v->y, 0.0);
	hs_spring_wall_block(&su->def->walls, su->g, *p, su->tol, &fh);
	hs_spring_wall_block(&su->def->walls, su->g, *p, su->tol, &vh);
	double speed = hs_length(vh), push = hs_length(fh);
	double hold = mu_s * normal * (1.0 + HS_FRICTION_TOLERANCE) + (su->attached ? su->sp->k * HS_STICK_TRAVEL : 0.0);
	if (speed <= HS_STICK_SPEED && push <= hold) {
		*v = hs_v3(0.0, 0.0, 0.0); // static friction holds (§4.2)
		*sliding = false;
		return false;
	}
	hs_vec3 dir = speed > 0.0 ? hs_scale(vh, 1.0 / speed) : hs_scale(fh, 1.0 / push);
	hs_vec3 fc = hs_mul_add(hs_v3(0.0, 0.0, normal), -mu_k * normal, dir); // the floor's force
	if (su->load) // and the touching objects' (spring_rest.c)
		fc = hs_add(fc, *su->load);
	sg->accel = hs_add(su->gravity, hs_scale(fc, 1.0 / su->sp->mass));
	sg->s0 = hs_mul_add(su->stylus_start, t, su->stylus_velocity);
	double rest = su->dt - t;
	hs_vec3 p1, v1;
	hs_spring_integrate(su->integrator, sg, *p, *v, rest, &p1, &v1);
	*sliding = true;
	if (hs_dot(hs_v3(v1.x, v1.y, 0.0), dir) > 0.0) {
		*p = p1;
		*v = v1;
		return false;
	}
	// the velocity along dir crossed zero within the stretch: find where, stop there
	double hi = stop_time(su, sg, *p, *v, dir, rest);
	hs_spring_integrate(su->integrator, sg, *p, *v, hi, &p1, &v1);
	*p = hs_v3(p1.x, p1.y, -su->g->lo.z);
	*v = hs_v3(0.0, 0.0, 0.0);
	*sliding = false;
	*used = hi;
	return true;
}

bool hs_spring_floor_step(const hs_spring_support *su, hs_spring_segment *sg, hs_vec3 *p, hs_vec3 *v,
                          bool *sliding) {
	double floor_z = -su->g->lo.z; // height of G when the object lies on the floor
	*sliding = false;
	if (!(p->z <= floor_z + su->tol && v->z <= 0.0))
		return false;
	hs_vec3 f = hold_force(su, *p);
	if (!(f.z <= 0.0))
		return false; // lifted off: the ground supplies no force
	// pressed onto the floor: it supplies N = −f_z (§4.5)
	p->z = floor_z;
	v->z = 0.0;
	double t = 0.0;
	for (int seg = 0; seg < HS_MAX_SEGMENTS && t < su->dt; ++seg) {
		if (seg > 0)
			f = hold_force(su, *p);
		double used;
		if (!floor_stretch(su, sg, f, t, p, v, sliding, &used))
			break;
		t += used;
	}
	p->z = floor_z;
	v->z = 0.0;
	return true;
}

bool hs_spring_land(const hs_spring_geom *g, hs_vec3 *p, hs_vec3 *v) {
	double floor_z = -g->lo.z;
	if (!(p->z < floor_z))
		return false;
	p->z = floor_z; // landed: the ground absorbs the normal velocity (§4.4 drop)
	if (v->z < 0.0)
		v->z = 0.0;
	return true;
}
