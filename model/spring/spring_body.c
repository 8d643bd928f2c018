// spring_body.c — one object of the spring model through (part of) a frame on its own
// ("Dynamics in Interaction on the Responsive Workbench" §4.2–§4.5): on the floor with friction
// (spring_contact.c) or in the air under gravity and the spring (spring_integrate.c), then the
// walls. The frame's step runs it for every object; a collision within the frame runs it again
// for the rest of the frame (spring_collide.c).
#include <string.h>

#include "spring_body.h"
#include "spring_contact.h"

typedef struct frame_ctx {
	hs_body *body;
	hs_world_counters *counters;
	hs_spring_system *sys;
	double dt;
	double tol; // m: the world's floor tolerance
	hs_vec3 gravity;
} frame_ctx;

// Object i's spring parameters, from the cache while its mass is the one they were found for.
static hs_spring_params params_of(const frame_ctx *fx, int i) {
	hs_spring_system *sys = fx->sys;
	double mass = fx->body->mass;
	if (memcmp(&sys->params_mass[i], &mass, sizeof mass) != 0) {
		sys->params[i] = hs_spring_params_of(&sys->def, fx->gravity, mass);
		sys->params_mass[i] = mass;
	}
	return sys->params[i];
}

// What the floor sees of object i's frame.
static hs_spring_support support_of(const frame_ctx *fx, int i, const hs_spring_params *sp) {
	const hs_spring_system *sys = fx->sys;
	hs_spring_support su;
	su.integrator = sys->def.integrator;
	su.dt = fx->dt;
	su.tol = fx->tol;
	su.gravity = fx->gravity;
	su.def = &sys->def;
	su.sp = sp;
	su.g = &sys->geom[i];
	su.attached = i == sys->attached;
	su.axis = sys->axis;
	su.stylus_start = hs_spring_anchor_prev(sys); // the spring hangs from the anchor, not the pen tip
	su.stylus_end = hs_spring_anchor(sys);
	su.stylus_velocity = hs_spring_anchor_velocity(sys, fx->dt); // the anchor's, in fact
	su.load = sys->rest_index[i] >= 0 ? &sys->load[i] : NULL;
	return su;
}

// The walls (x: bit 0, y: bit 1) object i at p touches, at most floor_tolerance away.
static unsigned walls_touched(const hs_spring_walls *wl, const hs_spring_geom *g, hs_vec3 p, double tol) {
	unsigned w = hs_spring_walls_near(wl, g, p, tol);
	return (w & 3u ? 1u : 0u) | (w & 12u ? 2u : 0u);
}

// A frame in the air. An attached object that touches a wall at the frame start and that the
// free step would push on into it slides along it instead (the segment pinned to the wall:
// spring_integrate.c), so that it comes to rest where the spring's force along the wall vanishes,
// at any dt; an object that reaches a wall during the frame is stopped there by the projection.
static void fly_along_walls(const frame_ctx *fx, hs_spring_segment *sg, const hs_spring_params *sp, int i,
                            hs_vec3 *p, hs_vec3 *v) {
	hs_spring_system *sys = fx->sys;
	const hs_spring_geom *g = &sys->geom[i];
	unsigned touching = sg->spring ? walls_touched(&sys->def.walls, g, *p, fx->tol) : 0u;
	hs_spring_segment start = *sg;
	hs_vec3 axis0 = sys->axis, p1 = *p, v1 = *v;
	hs_spring_fly(sys->def.integrator, sg, sp, fx->dt, &sys->axis, &p1, &v1);
	hs_vec3 q = p1;
	hs_spring_wall_project(&sys->def.walls, g, &q, NULL);
	unsigned pinned = (q.x != p1.x ? 1u : 0u) | (q.y != p1.y ? 2u : 0u);
	if (!(pinned & touching)) {
		*p = p1;
		*v = v1;
		return;
	}
	*sg = start; // again, along the wall
	sys->axis = axis0;
	sg->pinned = pinned & touching;
	sg->pinned_at = *p;
	hs_spring_wall_project(&sys->def.walls, g, &sg->pinned_at, NULL);
	*p = sg->pinned_at;
	hs_spring_fly(sys->def.integrator, sg, sp, fx->dt, &sys->axis, p, v);
}

// One object through one frame: on the floor (friction) or in the air, then the walls.
static void step_body(const frame_ctx *fx, int i) {
	hs_spring_system *sys = fx->sys;
	hs_body *body = fx->body;
	const hs_spring_geom *g = &sys->geom[i];
	bool attached = i == sys->attached;
	hs_spring_params sp = params_of(fx, i);
	hs_vec3 p = body->pos, v = body->vel;

	hs_spring_segment sg;
	memset(&sg, 0, sizeof sg);
	sg.spring = attached;
	sg.s0 = hs_spring_anchor_prev(sys);
	sg.w = hs_spring_anchor_velocity(sys, fx->dt);
	if (attached) // linearise the spring about its state at the frame start
		hs_spring_linearise(&sg, &sp, p, &sys->axis);

	hs_spring_support su = support_of(fx, i, &sp);
	bool sliding = false;
	bool on_floor = hs_spring_floor_step(&su, &sg, &p, &v, &sliding);
	if (on_floor) {
		fx->counters->floor_checks++;
	} else { // in the air: gravity and the spring
		sg.accel = su.load ? hs_mul_add(fx->gravity, 1.0 / body->mass, *su.load) : fx->gravity;
		fly_along_walls(fx, &sg, &sp, i, &p, &v);
		on_floor = hs_spring_land(g, &p, &v);
	}
	hs_spring_wall_project(&sys->def.walls, g, &p, &v);
	body->pos = p;
	body->vel = v;
	sys->on_floor[i] = on_floor;
	sys->sliding[i] = sliding;
	fx->counters->object_steps++;
}

void hs_spring_advance(hs_spring_system *sys, int i, hs_body *body, const hs_world_def *def, double dt,
                       hs_world_counters *counters) {
	frame_ctx fx = {body, counters, sys, dt, def->floor_tolerance, def->gravity};
	step_body(&fx, i);
}
