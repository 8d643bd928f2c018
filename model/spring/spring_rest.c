// spring_rest.c — resting contact between the objects of the spring model ("Dynamics in
// Interaction on the Responsive Workbench" §4.5: "physical contact of objects is intuitively
// equivalent with geometric intersection"; here stacks stand and friction acts between objects).
//
// Readings fixed here (the paper leaves them open; docs/model.md §8 "Resting contact between objects"):
//  - The floor's reading (spring_contact.c) carried over to contacts between objects: with every
//    object held where it is, the contact forces are those the touching objects, the floor and
//    the walls must exert on each other — normal forces ≥ 0 that leave no touching pair
//    accelerating into each other; friction up to μ N against the relative acceleration while a
//    contact sticks, μ_sliding N against the sliding otherwise (never more than stops the sliding
//    within the frame) — found together by projected Gauss–Seidel, then applied through the frame
//    as constant forces (spring_solve.c). The objects' own steps find the floor's and walls'
//    share again.
//  - Two objects touch when their true shapes lie within floor_tolerance (the floor's tolerance).
//  - A pair apart by more (up to v_b dt / 2, v_b = HS_REST_BOUNCE_SPEED) whose free motion closes
//    the gap within the frame slower than v_b (a push, not an impact) joins the solve ahead of its
//    meeting: its normal force acts only as far as it must for the gap to close by the frame's
//    end, g + v_n dt + a_n dt² / 2 ≥ 0 (a speculative contact). Without it a ball sliding off one
//    support fell into a second one a few µm away through the rest of the frame, was stopped
//    inside it and separated off the first: at 12 frames/s a pile never settled.
//  - Touching objects still approaching at the frame start first exchange impulses, pair by pair
//    until none approaches: the pair's restitution, none below HS_REST_BOUNCE_SPEED (5 cm/s: a
//    resting push, which an object the floor's static friction holds takes without moving); the
//    floor and the walls absorb (§4.4).
//  - An object in contact that is slower than 1 µm/s, sticks at all its contacts, lies in no other
//    deeper than HS_REST_DRIFT beyond the touch gap (what a resting separation parts is the depth
//    beyond the gap: spring_collide.c) and on which the forces leave less than 1e-9 of its load
//    (the floor's tolerances) is held: it keeps its position to the bit, its velocity is zero, and
//    it is not stepped.
#include <string.h>

#include "spring_contact.h"
#include "spring_impulse.h"
#include "spring_params.h"
#include "spring_rest.h"
#include "spring_solve.h"
#include "spring_touch.h"

#define HS_REST_HOLD_TRAVEL 1e-9   // m: a pull on the spring that moves an object less is held
#define HS_REST_APPROACH 1e-9      // m/s: a pair approaching slower is not answered by an impulse
#define HS_REST_MAX_PASSES 64      // impulse passes over the touches
// m/s × dt: pairs apart by up to this join the solve ahead of their meeting. Two objects meeting
// from rest at less than the bounce speed (a resting push) close at most v_b dt / 2 in a frame.
#define HS_REST_AHEAD (0.5 * HS_REST_BOUNCE_SPEED)

// Gravity and the spring on object i, with every object held where it is: the spring as the frame
// begins (a pull growing through the frame then presses the object on into what it touches, and
// the resting contact holds it, instead of lagging behind the contact force and opening the
// contact every frame).
static hs_vec3 free_force(const hs_world *world, const hs_spring_system *sys, int i, double dt) {
	const hs_body *b = &world->state.bodies[i];
	hs_vec3 f = hs_scale(world->model.def.gravity, b->mass);
	if (i != sys->attached)
		return f;
	hs_spring_params sp = hs_spring_params_of(&sys->def, world->model.def.gravity, b->mass);
	return hs_add(f, hs_spring_force(&sp, sys->axis, b->pos, hs_v3(0.0, 0.0, 0.0), hs_spring_anchor_prev(sys),
	                                 hs_spring_anchor_velocity(sys, dt)));
}

// Object i lies on the floor and does not leave it.
static bool on_floor(const hs_world *world, const hs_spring_system *sys, int i) {
	const hs_body *b = &world->state.bodies[i];
	return b->pos.z <= -sys->geom[i].lo.z + world->model.def.floor_tolerance && b->vel.z <= 0.0;
}

// The pair's free relative acceleration along n (gravity and the spring; what the floor holds up
// does not fall).
static double free_approach(const hs_world *world, const hs_spring_system *sys, const hs_spring_touch *c, double dt) {
	hs_vec3 fa = hs_scale(free_force(world, sys, c->a, dt), 1.0 / world->state.bodies[c->a].mass);
	hs_vec3 fb = hs_scale(free_force(world, sys, c->b, dt), 1.0 / world->state.bodies[c->b].mass);
	if (fa.z < 0.0 && on_floor(world, sys, c->a))
		fa.z = 0.0;
	if (fb.z < 0.0 && on_floor(world, sys, c->b))
		fb.z = 0.0;
	return hs_dot(hs_sub(fb, fa), c->n);
}

// Touches ahead (apart by more than the touch gap) that join the solve: the pair's free motion
// closes the gap within the frame, slower than the bounce speed at the meeting (a resting push;
// a faster one is an impact, which spring_collide.c answers with the pair's restitution). The
// rest are dropped: those pairs are left to spring_collide.c as before.
static void keep_meeting_ahead(hs_world *world, hs_spring_system *sys, double dt) {
	int kept = 0;
	for (int t = 0; t < sys->touch_count; ++t) {
		hs_spring_touch *c = &sys->touch[t];
		if (c->ahead) {
			double gap = -c->depth, an = free_approach(world, sys, c, dt);
			double vn = hs_dot(hs_sub(world->state.bodies[c->b].vel, world->state.bodies[c->a].vel), c->n);
			// the least gap over the frame of the free motion gap + vn t + an t² / 2
			double t_min = an > 0.0 && vn < 0.0 ? fmin(dt, -vn / an) : dt;
			double least = vn * t_min + 0.5 * an * t_min * t_min < 0.0 ? gap + vn * t_min + 0.5 * an * t_min * t_min : gap;
			double meet = vn * vn + 2.0 * fmax(0.0, -an) * gap;
			if (least > 0.0 || meet > HS_REST_BOUNCE_SPEED * HS_REST_BOUNCE_SPEED)
				continue;
		}
		sys->touch[kept++] = *c;
	}
	sys->touch_count = kept;
}

// The objects in any touch, ascending, with their place in sys->active.
static void collect_active(hs_world *world, hs_spring_system *sys) {
	for (int k = 0; k < sys->active_count; ++k)
		sys->rest_index[sys->active[k]] = -1;
	sys->active_count = 0;
	for (int t = 0; t < sys->touch_count; ++t)
		sys->rest_index[sys->touch[t].a] = sys->rest_index[sys->touch[t].b] = 0;
	for (int i = 0; i < world->model.object_count; ++i)
		if (sys->rest_index[i] == 0) {
			sys->rest_index[i] = sys->active_count;
			sys->active[sys->active_count++] = i;
		}
}

// Impulses between touching objects still approaching, pair by pair: each a collision of two
// bodies of restitution e ≤ 1 (or an absorption by the floor or a wall), so no pass adds energy;
// a slow one (a contact that persists) is a resting push: against an object the floor's static
// friction holds, it stops.
static void approach_impulses(hs_world *world, hs_spring_system *sys) {
	double tol = world->model.def.floor_tolerance;
	for (int pass = 0; pass < HS_REST_MAX_PASSES; ++pass) {
		bool any = false;
		for (int k = 0; k < sys->active_count; ++k) {
			int i = sys->active[k];
			hs_body *b = &world->state.bodies[i];
			if (on_floor(world, sys, i) && b->vel.z < 0.0) {
				b->vel.z = 0.0; // the floor absorbs (§4.4 drop)
				any = true;
			}
			unsigned w = hs_spring_walls_near(&sys->def.walls, &sys->geom[i], b->pos, tol);
			for (int q = 0; q < 4; ++q) {
				hs_vec3 n = hs_spring_wall_normal(q);
				if ((w >> q & 1u) && hs_dot(b->vel, n) < 0.0) {
					b->vel = hs_mul_add(b->vel, -hs_dot(b->vel, n), n); // and so do the walls
					any = true;
				}
			}
		}
		for (int t = 0; t < sys->touch_count; ++t) {
			hs_spring_touch *c = &sys->touch[t];
			hs_body *a = &world->state.bodies[c->a], *b = &world->state.bodies[c->b];
			double vn = hs_dot(hs_sub(b->vel, a->vel), c->n);
			if (c->ahead || !(vn < -HS_REST_APPROACH))
				continue;
			bool impact = -vn > HS_REST_BOUNCE_SPEED;
			hs_spring_pair_impulse(world, sys, c->a, c->b, c->n, impact ? c->e : 0.0, !impact);
			any = true;
		}
		if (!any)
			return;
	}
}

// A touching pair moving apart too slowly to get clear within the frame of what pulls it back
// together (its free relative acceleration along n, a_n < 0: gravity pressing an object on the one
// below): v_n < −a_n dt / 2. Such a contact is a resting one: its separating speed is removed
// (both objects' velocities along n made equal, momentum kept, energy lost), so that the
// contact's force holds it instead of the object falling a whole frame back into the other.
static bool closes(hs_world *world, hs_spring_system *sys, const hs_spring_touch *c, double dt) {
	hs_body *a = &world->state.bodies[c->a], *b = &world->state.bodies[c->b];
	double an = free_approach(world, sys, c, dt), vn = hs_dot(hs_sub(b->vel, a->vel), c->n);
	if (!(an < 0.0 && vn < -0.5 * an * dt))
		return false;
	double wa = 1.0 / a->mass, wb = 1.0 / b->mass; // an object the floor holds does not move (hs_spring_floor_takes)
	if (hs_spring_floor_takes(world, sys, c->a, hs_scale(c->n, -vn / wb)))
		wa = 0.0;
	else if (hs_spring_floor_takes(world, sys, c->b, hs_scale(c->n, vn / wa)))
		wb = 0.0;
	double j = vn / (wa + wb);
	a->vel = hs_mul_add(a->vel, j * wa, c->n);
	b->vel = hs_mul_add(b->vel, -j * wb, c->n);
	return true;
}

// What each touch and each active object brings to the solve: sliding, the forces of
// gravity and the spring with every object held where it is.
static void prepare(hs_world *world, hs_spring_system *sys, double dt) {
	double tol = world->model.def.floor_tolerance;
	for (int k = 0; k < sys->active_count; ++k) {
		int i = sys->active[k];
		const hs_body *b = &world->state.bodies[i];
		hs_spring_rest_body *r = &sys->rest[k];
		memset(r, 0, sizeof *r);
		r->force = free_force(world, sys, i, dt);
		r->acc = hs_scale(r->force, 1.0 / b->mass);
		r->floor = on_floor(world, sys, i);
		r->sliding = r->floor && hs_length(hs_v3(b->vel.x, b->vel.y, 0.0)) > HS_REST_STICK_SPEED;
		unsigned w = hs_spring_walls_near(&sys->def.walls, &sys->geom[i], b->pos, tol);
		for (int q = 0; q < 4; ++q) // a wall it leaves pushes no more
			if (hs_dot(b->vel, hs_spring_wall_normal(q)) > HS_REST_APPROACH)
				w &= ~(1u << q);
		r->walls = (uint8_t)w;
	}
	for (int t = 0; t < sys->touch_count; ++t) {
		hs_spring_touch *c = &sys->touch[t];
		const hs_body *a = &world->state.bodies[c->a], *b = &world->state.bodies[c->b];
		hs_vec3 v = hs_sub(b->vel, a->vel);
		double vn = hs_dot(v, c->n);
		if (c->ahead) { // its force may only close the gap by the frame's end (keep_meeting_ahead)
			c->open = false;
			c->bias = 2.0 * (-c->depth + vn * dt) / (dt * dt);
		} else {
			c->open = vn > HS_REST_APPROACH && !closes(world, sys, c, dt);
			c->bias = 0.0;
		}
		hs_vec3 vt = hs_mul_add(v, -hs_dot(v, c->n), c->n);
		double s = hs_length(vt);
		c->slide = s > HS_REST_STICK_SPEED ? hs_scale(vt, 1.0 / s) : hs_v3(0.0, 0.0, 0.0);
		c->normal = 0.0;
		c->friction = hs_v3(0.0, 0.0, 0.0);
	}
	// closes() may have stopped an object it found sliding (a box bouncing slowly off a block the
	// floor holds ends at exactly 0): what no longer moves does not slide, and the floor's sliding
	// friction, which acts against the direction of the sliding, must never divide by zero speed
	for (int k = 0; k < sys->active_count; ++k) {
		const hs_body *b = &world->state.bodies[sys->active[k]];
		sys->rest[k].sliding = sys->rest[k].sliding && hs_length(hs_v3(b->vel.x, b->vel.y, 0.0)) > HS_REST_STICK_SPEED;
	}
}

// Held still: slow, sticking at every contact, and the forces leave (almost) nothing.
static bool holds(const hs_world *world, const hs_spring_system *sys, int k) {
	int i = sys->active[k];
	const hs_body *b = &world->state.bodies[i];
	const hs_spring_rest_body *r = &sys->rest[k];
	if (hs_length(b->vel) > HS_REST_STICK_SPEED || r->sliding)
		return false;
	double left = hs_length(r->acc) * b->mass;
	double allowed = HS_REST_TOLERANCE * (hs_length(r->force) + r->floor_normal);
	if (i == sys->attached)
		allowed += hs_spring_params_of(&sys->def, world->model.def.gravity, b->mass).k * HS_REST_HOLD_TRAVEL;
	return left <= allowed;
}

void hs_spring_rest(hs_world *world, hs_spring_system *sys) {
	int n = world->model.object_count;
	double dt = world->model.def.dt;
	if (n > 0) { // (never negative; the test keeps gcc's size analysis quiet)
		memset(sys->load, 0, (size_t)n * sizeof *sys->load);
		memset(sys->held, 0, (size_t)n);
	}
	double tol = world->model.def.floor_tolerance;
	hs_spring_find_touches(world, sys, tol, fmax(tol, HS_REST_AHEAD * dt));
	keep_meeting_ahead(world, sys, dt);
	collect_active(world, sys);
	if (sys->touch_count == 0) {
		hs_spring_keep_forces(sys); // none: the next frame starts from none
		return;
	}
	for (int t = 0; t < sys->touch_count; ++t) {
		hs_spring_touch *c = &sys->touch[t];
		c->e = hs_spring_pair_restitution(&sys->def, &world->state.bodies[c->a], &world->state.bodies[c->b]);
		c->mass = 1.0 / (1.0 / world->state.bodies[c->a].mass + 1.0 / world->state.bodies[c->b].mass);
	}
	approach_impulses(world, sys);
	prepare(world, sys, dt);
	hs_spring_solve(world, sys, dt);
	for (int t = 0; t < sys->touch_count; ++t) {
		const hs_spring_touch *c = &sys->touch[t];
		hs_vec3 f = hs_mul_add(c->friction, c->normal, c->n); // on b
		sys->load[c->a] = hs_sub(sys->load[c->a], f);
		sys->load[c->b] = hs_add(sys->load[c->b], f);
	}
	for (int t = 0; t < sys->touch_count; ++t) { // sliding on another, or deeper than the gap and drift: not held
		const hs_spring_touch *c = &sys->touch[t];
		if (c->ahead && !(c->normal > 0.0))
			continue;
		if (hs_length_sq(c->slide) > 0.0 || c->depth - tol > HS_REST_DRIFT)
			sys->held[c->a] = sys->held[c->b] = 2;
	}
	for (int k = 0; k < sys->active_count; ++k) {
		int i = sys->active[k];
		sys->held[i] = sys->held[i] != 2 && holds(world, sys, k);
	}
}
