// spring_collide.c — object–object collisions of "Dynamics in Interaction on the Responsive
// Workbench" (§4.5: "collisions ... momentum and energy are conserved").
//
// Readings fixed here (the paper leaves them open; docs/model.md §8 "Collisions"):
//  - After the step, pairs that met during the frame are answered in the order of time (the
//    earliest first, then the meetings of its two objects found again from their new paths): an
//    impulse along the contact normal, J = −(1 + e) v_n / (1/m_a + 1/m_b) with the pair's e (the
//    smaller of the two objects'; none below HS_REST_BOUNCE_SPEED), then the separation
//    (separate). Pairs still overlapping where the frame leaves them follow, in array order, in
//    passes until none moved (at most HS_SEPARATION_PASSES).
//  - "Physical contact of objects is intuitively equivalent with geometric intersection" (§4.5):
//    the true shapes meet. Spheres are exact (along the line of centres); a box is the box in its
//    own orientation: sphere–box along the nearest point, box–box along the separating-axis
//    test's axis of least overlap (15 axes); every other shape (pyramid, the L-block's parts,
//    ellipsoid, polyhedron) and any pair with one goes through libccd (hs_shapes_penetration:
//    MPR's depth and direction, deepest part pair). A box whose faces lie on its world-axis
//    bounding box uses the bounding-box formulas, the same bits as before turned boxes existed.
//    Objects do not turn (§4.2: no torque), so a collision changes velocities only.
//  - No tunnelling: a pair apart at the frame's end whose paths through the frame met (exactly for
//    two spheres, by sub-steps no longer than the sum of their inner radii otherwise) is put back
//    where they met and answered there (first_meeting).
//  - A pair touching at the frame's start is a resting contact (spring_rest.c: its forces acted
//    through the frame): no sweep and no bounce; an overlap up to twice the touch gap stays. Its
//    separation lifts it as far as its kinetic energy pays, and deeper than HS_REST_DRIFT as far
//    as that and the potential energy it released this frame pay, and at least back to half the
//    drift (so no overlap deeper than the drift stays; that last step is not paid for, and
//    test_spring_rest's closed box measures that its energy still never rises).
//  - Resting pairs on the floor left deeper than the drift by the end passes are projected out
//    together, along the floor (project_floor_layer): no energy either way.
#include <stdlib.h>
#include <string.h>

#include "spring_collide.h"
#include "spring_contact.h"
#include "spring_near.h"
#include "spring_impulse.h"
#include "spring_rest.h"
#include "spring_body.h"
#include "spring_touch.h"

// Object i lies where the frame began, without velocity along the floor.
static bool still(const hs_world *world, int i) {
	const hs_body *b = &world->state.bodies[i];
	hs_vec3 p = b->pos, s = world->scratch.spring.saved_pos[i];
	return p.x == s.x && p.y == s.y && b->vel.x == 0.0 && b->vel.y == 0.0;
}

// Object i lies on the floor (within the floor's tolerance).
static bool lies_on_floor(const hs_world *world, const hs_spring_system *sys, int i) {
	return world->state.bodies[i].pos.z + sys->geom[i].lo.z <= world->model.def.floor_tolerance;
}

// The direction d (unit) object i can be moved along to separate it: without the components
// into the floor or a wall it touches, and none at all, for a resting contact, when it lies on the
// floor and has not moved this frame (static friction holds it: the overlap is the other's doing).
static hs_vec3 free_part(const hs_world *world, const hs_spring_system *sys, int i, hs_vec3 d, bool holds) {
	const hs_spring_geom *g = &sys->geom[i];
	const hs_body *b = &world->state.bodies[i];
	hs_vec3 p = b->pos;
	double tol = world->model.def.floor_tolerance;
	const hs_spring_walls *wl = &sys->def.walls;
	bool on_floor = lies_on_floor(world, sys, i);
	if (holds && on_floor && d.z <= 0.0 && still(world, i))
		return hs_v3(0.0, 0.0, 0.0); // it has not moved this frame
	if (d.z < 0.0 && on_floor)
		d.z = 0.0;
	if (wl->enabled) {
		if ((d.x < 0.0 && p.x + g->lo.x <= wl->x_min + tol) || (d.x > 0.0 && p.x + g->hi.x >= wl->x_max - tol))
			d.x = 0.0;
		if ((d.y < 0.0 && p.y + g->lo.y <= wl->y_min + tol) || (d.y > 0.0 && p.y + g->hi.y >= wl->y_max - tol))
			d.y = 0.0;
	}
	return d;
}

// The separation of an overlapping pair by depth along n: each object moved along the part of
// ±n it is free to move along (free_part), mass-weighted (inverse-mass shares when both are
// free); velocities untouched, so momentum stays exact. A separation that lifts the pair costs
// potential energy: it is paid from the pair's kinetic energy (both velocities scaled down, to
// zero when it does not suffice). A resting pair's separation by at most HS_REST_DRIFT (the drift
// of a contact at rest) goes only as far as that pays; a deeper one as far as that and the potential
// energy the pair released since the frame began pay, and at least back to half the drift (objects
// do not pass through each other); an impact's all the way. test_spring_rest's seeded closed box
// measures that energy never rises: a pair within the drift at the frame's start that
// sank deeper used to be lifted all the way, by the drift it began with too, for nothing.
// The way off the walls both objects of a pair touch and that n runs along (half a unit per
// wall, into the room): zero when there is none.
static hs_vec3 off_shared_walls(const hs_world *world, const hs_spring_system *sys, int i, int j, hs_vec3 n) {
	const hs_spring_walls *wl = &sys->def.walls;
	double tol = world->model.def.floor_tolerance;
	unsigned both = hs_spring_walls_near(wl, &sys->geom[i], world->state.bodies[i].pos, tol) &
	                hs_spring_walls_near(wl, &sys->geom[j], world->state.bodies[j].pos, tol);
	hs_vec3 off = hs_v3(0.0, 0.0, 0.0);
	for (int q = 0; q < 4; ++q)
		if ((both >> q & 1u) && fabs(hs_dot(n, hs_spring_wall_normal(q))) < 1e-9)
			off = hs_mul_add(off, 0.5, hs_spring_wall_normal(q));
	return off;
}

#define HS_SEPARATE_REACH 2.0 // depths: the farthest a separation moves one object

static hs_vec3 within_reach(hs_vec3 d, double reach) {
	double len = hs_length(d);
	return len > reach ? hs_scale(d, reach / len) : d;
}
static void separate(hs_world *world, const hs_spring_system *sys, int i, int j, hs_vec3 n, double depth,
                     bool resting) {
	if (!(depth > 0.0))
		return;
	hs_body *a = &world->state.bodies[i], *b = &world->state.bodies[j];
	// a resting pair where one has not moved: the other's doing (both still: shared)
	bool hold_a = resting && !still(world, j), hold_b = resting && !still(world, i);
	hs_vec3 ua = free_part(world, sys, i, hs_neg(n), hold_a), ub = free_part(world, sys, j, n, hold_b);
	// a pair in a line along a wall both touch (a row of balls against it, more than fit): parted
	// along the line, the row's overlap only moves on to the next pair and back (a ball ended
	// inside another); b leaves the line, off the wall into the room
	if (hs_dot(ub, ub) > 0.0)
		ub = hs_add(ub, off_shared_walls(world, sys, i, j, n));
	if (sys->shock) { // shock propagation (end passes, bottom up): the lower one is not pushed down
		hs_vec3 *down = world->state.bodies[i].pos.z <= world->state.bodies[j].pos.z ? &ua : &ub;
		if (down->z < 0.0)
			down->z = 0.0;
	}
	double wa = 1.0 / a->mass, wb = 1.0 / b->mass;
	hs_vec3 da, db;
	if (hs_dot(ua, ua) == 1.0 && hs_dot(ub, ub) == 1.0 && hs_dot(ua, n) == -1.0) { // both free: along n
		double wsum = wa + wb;
		da = hs_scale(n, -depth * wa / wsum);
		db = hs_scale(n, depth * wb / wsum);
	} else {
		double ga = -hs_dot(ua, n), gb = hs_dot(ub, n), den = wa * ga * ga + wb * gb * gb;
		if (!(den > 0.0))
			return; // held on both sides
		double lam = depth / den;
		da = hs_scale(ua, lam * wa * ga);
		db = hs_scale(ub, lam * wb * gb);
		// a side free to move only nearly across n (an object wedged by the floor and walls) would
		// travel far for little separation (a ball in a corner was thrown 0.3 m across the box in
		// one frame): no side moves more than HS_SEPARATE_REACH depths; what is left stays a touch
		da = within_reach(da, HS_SEPARATE_REACH * depth);
		db = within_reach(db, HS_SEPARATE_REACH * depth);
	}
	hs_vec3 g = world->model.def.gravity;
	double lift = -a->mass * hs_dot(g, da) - b->mass * hs_dot(g, db); // J of potential energy
	if (lift > 0.0) {
		double kinetic = 0.5 * a->mass * hs_length_sq(a->vel) + 0.5 * b->mass * hs_length_sq(b->vel);
		double share = kinetic >= lift || !resting ? 1.0 : kinetic / lift;
		if (share < 1.0 && depth > HS_REST_DRIFT) {
			double sank = fmax(0.0, a->mass * hs_dot(g, hs_sub(a->pos, world->scratch.spring.saved_pos[i])) +
			                            b->mass * hs_dot(g, hs_sub(b->pos, world->scratch.spring.saved_pos[j])));
			share = fmax(fmin(1.0, (kinetic + sank) / lift), 1.0 - 0.5 * HS_REST_DRIFT / depth);
		}
		double keep = kinetic > lift ? sqrt(1.0 - lift / kinetic) : 0.0;
		a->vel = hs_scale(a->vel, keep);
		b->vel = hs_scale(b->vel, keep);
		da = hs_scale(da, share);
		db = hs_scale(db, share);
	}
	a->pos = hs_add(a->pos, da);
	b->pos = hs_add(b->pos, db);
}

// Object i at the fraction tau of the frame, for motion at constant acceleration through it (gravity,
// sliding friction): the position from its path's start and the frame end's velocity, p0 + h (s v0
// + s² (v1 - v0) / 2) with s the fraction of the path (h long) done, when its end is the frame's
// end (the step was such); else the straight path. A path starts at the frame start, or where the
// object was last answered this frame (the scratch's spring.path_*); before that the object is where the path starts.
static hs_vec3 path_at(const hs_world *world, int i, double tau) {
	const hs_body *b = &world->state.bodies[i];
	double t0 = world->scratch.spring.path_t0[i];
	hs_vec3 v0 = world->scratch.spring.path_vel[i], dv = hs_sub(b->vel, v0), p0 = world->scratch.spring.path_pos[i];
	if (!(tau > t0))
		return p0;
	double dt = (1.0 - t0) * world->model.def.dt, s = (tau - t0) / (1.0 - t0);
	hs_vec3 end = hs_add(p0, hs_scale(hs_mul_add(v0, 0.5, dv), dt));
	if (hs_length_sq(hs_sub(end, b->pos)) <= 1e-24)
		return hs_add(p0, hs_scale(hs_mul_add(hs_scale(v0, s), 0.5 * s * s, dv), dt));
	return hs_mul_add(p0, s, hs_sub(b->pos, p0));
}

// Object i put back to the fraction tau of the frame: on its path, the velocity between the path
// start's and the frame end's.
static void state_at(hs_world *world, int i, double tau) {
	hs_body *b = &world->state.bodies[i];
	hs_vec3 p = path_at(world, i, tau);
	double t0 = world->scratch.spring.path_t0[i], s = tau > t0 ? (tau - t0) / (1.0 - t0) : 0.0;
	b->vel = hs_mul_add(world->scratch.spring.path_vel[i], s, hs_sub(b->vel, world->scratch.spring.path_vel[i]));
	b->pos = p;
}

// No tunnelling (docs/model.md §8): two objects apart at the frame's start may meet on the way, whether or
// not they still overlap where the frame leaves them. The first fraction tau at which they meet, -1 when
// they do not: at sub-steps no longer than the sum of their inner radii (a sphere's radius, a box's
// smallest half extent) along their paths (path_at), so no pass through the other's inner ball is
// missed (a glancing overlap shallower than that may be), then by bisection to 1e-12 of the frame
// between the last sub-step apart and the first that meets.
#define HS_MAX_SWEEP_STEPS 4096
static bool meet_at(const hs_world *world, const hs_spring_system *sys, int i, int j, double t) {
	hs_vec3 n;
	double depth;
	return hs_spring_contact(world, &sys->geom[i], path_at(world, i, t), &sys->geom[j], path_at(world, j, t),
	                         &n, &depth);
}

// The pair's overlap at t on their paths (0: apart).
static double depth_at(const hs_world *world, const hs_spring_system *sys, int i, int j, double t) {
	hs_vec3 n;
	double depth;
	return hs_spring_contact(world, &sys->geom[i], path_at(world, i, t), &sys->geom[j], path_at(world, j, t),
	                         &n, &depth) ? depth : 0.0;
}

// Two spheres: the gap |G_b - G_a| - (r_a + r_b) along their paths, a smooth function of tau.
static double sphere_gap(const hs_world *world, const hs_spring_system *sys, int i, int j, double t) {
	return hs_length(hs_sub(path_at(world, j, t), path_at(world, i, t))) - sys->geom[i].radius -
	       sys->geom[j].radius;
}

// The gap's root in [lo, hi] (apart at lo, meeting at hi) by regula falsi with the Illinois rule,
// to 1e-12 of the frame or a gap within 1e-15 m: a few steps where bisection takes forty.
static double sphere_root(const hs_world *world, const hs_spring_system *sys, int i, int j, double lo, double hi) {
	double flo = sphere_gap(world, sys, i, j, lo), fhi = sphere_gap(world, sys, i, j, hi);
	int side = 0;
	for (int it = 0; it < 100 && hi - lo > 1e-12; ++it) {
		double t = flo - fhi > 0.0 ? lo + (hi - lo) * flo / (flo - fhi) : 0.5 * (lo + hi);
		if (!(t > lo && t < hi))
			t = 0.5 * (lo + hi);
		double f = sphere_gap(world, sys, i, j, t);
		if (f <= 0.0) { // meeting at t
			hi = t;
			fhi = f;
			if (side == -1)
				flo *= 0.5;
			side = -1;
			if (f > -1e-15)
				break;
		} else {
			lo = t;
			flo = f;
			if (side == 1)
				fhi *= 0.5;
			side = 1;
		}
	}
	return hi;
}

static double first_meeting(const hs_world *world, const hs_spring_system *sys, int i, int j, bool end_meets) {
	const hs_spring_geom *ga = &sys->geom[i], *gb = &sys->geom[j];
	double t0 = fmax(world->scratch.spring.path_t0[i], world->scratch.spring.path_t0[j]); // the later of their paths' starts
	hs_vec3 rel = hs_sub(hs_sub(world->state.bodies[j].pos, path_at(world, j, t0)),
	                     hs_sub(world->state.bodies[i].pos, path_at(world, i, t0)));
	double step = ga->inner + gb->inner, len = hs_length(rel);
	if (!(step > 0.0) || !(len > 0.0) || (!end_meets && !(len > step)))
		return -1.0; // no relative motion, or slower: a pass through the inner balls shows at an end
	bool spheres = ga->sphere && gb->sphere && ga->form != HS_FORM_BOX && gb->form != HS_FORM_BOX;
	if (spheres ? sphere_gap(world, sys, i, j, t0) <= 0.0 : meet_at(world, sys, i, j, t0))
		// met already at the start: a contact going on, not a first meeting; but a pair deeper than
		// the drift where a path restarted (an answer's separation pushed one into the other) is
		// answered there and then: left to the frame's end, a ball pushed into a third one mid-fall
		// reached the floor inside it, where the end passes' level normal never lifts it out (the
		// floor layer of a dense drop jammed, its balls pushed to and fro by 1 cm a frame)
		return t0 > 0.0 && depth_at(world, sys, i, j, t0) > HS_REST_DRIFT ? t0 : -1.0;
	double n = ceil(len / step), span = 1.0 - t0;
	int steps = n > HS_MAX_SWEEP_STEPS ? HS_MAX_SWEEP_STEPS : n < 1.0 ? 1 : (int)n;
	int k = 1;
	while (k < steps && !(spheres ? sphere_gap(world, sys, i, j, t0 + span * ((double)k / steps)) <= 0.0
	                              : meet_at(world, sys, i, j, t0 + span * ((double)k / steps))))
		++k;
	if (k == steps && !end_meets)
		return -1.0;
	double lo = t0 + span * ((double)(k - 1) / steps), hi = t0 + span * ((double)k / steps);
	if (spheres)
		return sphere_root(world, sys, i, j, lo, hi);
	while (hi - lo > 1e-12) {
		double mid = 0.5 * (lo + hi);
		if (meet_at(world, sys, i, j, mid))
			hi = mid;
		else
			lo = mid;
	}
	return hi;
}


// Two objects lying on the floor.
static bool both_on_floor(const hs_world *world, const hs_spring_system *sys, int i, int j) {
	return lies_on_floor(world, sys, i) && lies_on_floor(world, sys, j);
}

// Object i joins the floor layer's projection (once).
static void join_layer(hs_world_scratch *scratch, int i) {
	if (!scratch->spring.in_layer[i]) {
		scratch->spring.in_layer[i] = 1;
		scratch->spring.layer[scratch->spring.layer_count++] = i;
	}
}

// Objects i and j, a resting pair, lie on the floor and in each other deeper than the drift
// beyond the gap: they are for the floor layer's projection.
static void note_layer(const hs_spring_system *sys, hs_world *world, int i, int j, double depth) {
	if (depth > HS_REST_DRIFT && both_on_floor(world, sys, i, j)) {
		join_layer(&world->scratch, i);
		join_layer(&world->scratch, j);
	}
}

// Objects i and j answered at the fraction tau of the frame (tau < 0: where the frame leaves
// them): both put back to where they met, the impulse, the separation, then for each the rest of
// the frame from there on a new path (on the spring, or a push: the rest is lost). False when
// they were a resting pair still within the touch gap: nothing to answer.
static bool answer(hs_world *world, hs_spring_system *sys, int i, int j, double tau, bool resting) {
	hs_body *a = &world->state.bodies[i], *b = &world->state.bodies[j];
	const hs_spring_geom *ga = &sys->geom[i], *gb = &sys->geom[j];
	hs_vec3 n;
	double depth;
	if (tau >= 0.0 && tau < 1.0) {
		state_at(world, i, tau); // both back to where they met (the rest of the frame's
		state_at(world, j, tau); // motion is lost: a delay, no energy)
		if (!hs_spring_contact(world, ga, a->pos, gb, b->pos, &n, &depth)) { // just touching
			n = hs_normalize(hs_sub(b->pos, a->pos));
			depth = 0.0;
		}
	} else if (!hs_spring_contact(world, ga, a->pos, gb, b->pos, &n, &depth)) {
		return false;
	}
	if (resting) { // an overlap up to twice the touch gap stays (it is a touch: the next frame holds it)
		double gap = world->model.def.floor_tolerance;
		depth = depth > 2.0 * gap ? depth - gap : 0.0;
		note_layer(sys, world, i, j, depth);
		if (!(depth > 0.0) && !(hs_dot(hs_sub(b->vel, a->vel), n) < 0.0))
			return false; // at rest on each other, within the gap
	}
	// an impact slower than HS_REST_BOUNCE_SPEED is a resting push: no bounce (spring_rest.h)
	double bounce = sys->def.paper_collisions ? 0.0 : HS_REST_BOUNCE_SPEED; // the letter: every impact bounces
	bool push = resting || -hs_dot(hs_sub(b->vel, a->vel), n) <= bounce;
	hs_spring_pair_impulse(world, sys, i, j, n, push ? 0.0 : hs_spring_pair_restitution(&sys->def, &world->state.bodies[i], &world->state.bodies[j]), push);
	separate(world, sys, i, j, n, depth, push);
	// the rest of the frame, from where they met; a push (no bounce) stops there: moved on by the
	// frame start's load, an object that met a second support fell on into it and was separated
	// off the first by mm, so a pile never settled at 12-30 frames/s (it has no energy to add)
	if (tau > 0.0 && tau < 1.0) {
		int ends[2] = {i, j};
		for (int q = 0; q < 2; ++q) { // their paths start again here
			world->scratch.spring.path_pos[ends[q]] = world->state.bodies[ends[q]].pos;
			world->scratch.spring.path_vel[ends[q]] = world->state.bodies[ends[q]].vel;
			world->scratch.spring.path_t0[ends[q]] = tau;
			if (ends[q] != sys->attached && !push)
				hs_spring_advance(sys, ends[q], &world->state.bodies[ends[q]], &world->model.def, (1.0 - tau) * world->model.def.dt,
				                  &world->counters);
		}
	}
	sys->separated[i] = sys->separated[j] = 1;
	hs_spring_refile(world, sys, i);
	hs_spring_refile(world, sys, j);
	return true;
}

// Where the pair (i, j), i < j, first meets on the rest of its paths, -1 when it does not (or
// is a resting pair, or both are held).
static double meeting_of(hs_world *world, const hs_spring_system *sys, int i, int j) {
	if ((sys->held[i] && sys->held[j]) || hs_spring_touching(sys, i, j))
		return -1.0;
	const hs_spring_geom *ga = &sys->geom[i], *gb = &sys->geom[j];
	hs_vec3 pa = world->state.bodies[i].pos, pb = world->state.bodies[j].pos, n;
	double depth;
	bool end_meets = hs_spring_boxes_meet(ga, pa, gb, pb, hs_spring_margin(ga, pa) + hs_spring_margin(gb, pb)) &&
	                 hs_spring_contact(world, ga, pa, gb, pb, &n, &depth);
	double tau = first_meeting(world, sys, i, j, end_meets);
	return tau >= 0.0 && tau < 1.0 ? tau : -1.0;
}

// Events by tau (the meetings: their fraction of the frame; the end passes: the height of the pair's
// lower object), then the pair: a strict order, a pair being listed once at a time.
static int event_order(const void *x, const void *y) {
	const hs_spring_event *a = x, *b = y;
	if (a->tau != b->tau)
		return a->tau < b->tau ? -1 : 1;
	if (a->i != b->i)
		return a->i < b->i ? -1 : 1;
	return (a->j > b->j) - (a->j < b->j);
}

static bool before(const hs_spring_event *a, const hs_spring_event *b) { return event_order(a, b) < 0; }

static bool stale(const hs_spring_system *sys, const hs_spring_event *e) {
	return e->vi != sys->version[e->i] || e->vj != sys->version[e->j];
}

static void sift_up(hs_spring_event *h, int k) {
	for (int parent; k > 0 && before(&h[k], &h[parent = (k - 1) / 2]); k = parent) {
		hs_spring_event t = h[k];
		h[k] = h[parent];
		h[parent] = t;
	}
}

static void sift_down(hs_spring_event *h, int n, int k) {
	for (int child; (child = 2 * k + 1) < n; k = child) {
		if (child + 1 < n && before(&h[child + 1], &h[child]))
			++child;
		if (!before(&h[child], &h[k]))
			return;
		hs_spring_event t = h[k];
		h[k] = h[child];
		h[child] = t;
	}
}

// Makes room in a full heap by dropping its stale meetings; false when every one is live.
static bool compact(hs_spring_system *sys) {
	int kept = 0;
	for (int e = 0; e < sys->event_count; ++e)
		if (!stale(sys, &sys->events[e]))
			sys->events[kept++] = sys->events[e];
	if (kept == sys->event_count)
		return false;
	sys->event_count = kept;
	for (int k = kept / 2 - 1; k >= 0; --k)
		sift_down(sys->events, kept, k);
	return true;
}

// The meetings of object q with its neighbours r > after (and r != skip) onto the heap, counting
// those beyond the capacity of live meetings (answered at the frame's end instead).
static void list_meetings(hs_world *world, hs_spring_system *sys, int q, int after, int skip, double reach) {
	const int *near;
	int count = hs_spring_near(world, sys, q, reach, &near);
	for (int k = 0; k < count; ++k) {
		int r = near[k], i = q < r ? q : r, j = q < r ? r : q;
		if (r == q || r <= after || r == skip)
			continue;
		double tau = meeting_of(world, sys, i, j);
		if (tau < 0.0)
			continue;
		if (sys->event_count == sys->event_capacity && !compact(sys)) {
			world->counters.dropped_contacts++;
			continue;
		}
		sys->events[sys->event_count] = (hs_spring_event){i, j, tau, sys->version[i], sys->version[j]};
		sift_up(sys->events, sys->event_count++);
	}
}

// The earliest live meeting (ties: the lowest pair), taken off the heap; false when none. Meetings
// of an answered object went stale when it was (its version moved on) and are skipped here: the
// linear scan and removal this replaces made a frame of E meetings O(E²).
static bool earliest(hs_spring_system *sys, hs_spring_event *out) {
	while (sys->event_count > 0) {
		*out = sys->events[0];
		sys->events[0] = sys->events[--sys->event_count];
		sift_down(sys->events, sys->event_count, 0);
		if (!stale(sys, out))
			return true;
	}
	return false;
}

#define HS_SEPARATION_PASSES 8

// Object i held still by its contacts this frame and not moved since (by a separation).
static bool unmoved(const hs_world *world, const hs_spring_system *sys, int i) {
	return sys->held[i] && memcmp(&world->state.bodies[i].pos, &world->scratch.spring.saved_pos[i], sizeof(hs_vec3)) == 0;
}

// Sorts by event_order in place: the meetings' min-heap (sift_down) taken apart from the back
// leaves the events in falling order, then reversed. glibc's qsort allocates a buffer for arrays
// over 1 KiB, and the step must not (a dense drop's end passes sorted 63 such arrays in 10 s). The
// order is strict, so the result is qsort's.
static void sort_events(hs_spring_event *e, int n) {
	for (int k = n / 2 - 1; k >= 0; --k)
		sift_down(e, n, k);
	for (int end = n - 1; end > 0; --end) {
		hs_spring_event t = e[0];
		e[0] = e[end];
		e[end] = t;
		sift_down(e, end, 0);
	}
	for (int lo = 0, hi = n - 1; lo < hi; ++lo, --hi) {
		hs_spring_event t = e[lo];
		e[lo] = e[hi];
		e[hi] = t;
	}
}

static bool in_order(const hs_spring_event *e, int n) {
	for (int k = 1; k < n; ++k)
		if (event_order(&e[k - 1], &e[k]) > 0)
			return false;
	return true;
}

// One pass over the overlapping pairs where the frame leaves them, bottom up (shock propagation,
// Guendelman et al. 2003: a separation never pushes the lower object of a pair down, so a column
// of overlapping objects comes apart in one pass): the first pass over every pair, later ones over
// the pairs of objects the pass before moved (sys->moved bit 0; this pass's in bit 1). True when
// one was separated.
static bool end_pass(hs_world *world, hs_spring_system *sys, bool first) {
	const hs_spring_geom *geom = sys->geom;
	uint8_t *mv = sys->moved;
	sys->event_count = 0;
	for (int q = 0; q < world->model.object_count; ++q) {
		if (!first && !(mv[q] & 1u))
			continue;
		const int *near;
		int count = hs_spring_near(world, sys, q, 0.0, &near);
		for (int k = 0; k < count; ++k) {
			int r = near[k], i = q < r ? q : r, j = q < r ? r : q;
			if (r == q || (first && r < q) || (!first && r < q && (mv[r] & 1u)) || (unmoved(world, sys, i) && unmoved(world, sys, j)) ||
			    !hs_spring_boxes_meet(&geom[i], world->state.bodies[i].pos, &geom[j], world->state.bodies[j].pos,
			                hs_spring_margin(&geom[i], world->state.bodies[i].pos) + hs_spring_margin(&geom[j], world->state.bodies[j].pos)))
				continue; // (a pair of two movers is met from the lower index)
			if (sys->event_count == sys->event_capacity) {
				world->counters.dropped_contacts++;
				continue;
			}
			double low = fmin(world->state.bodies[i].pos.z, world->state.bodies[j].pos.z);
			sys->events[sys->event_count++] = (hs_spring_event){i, j, low, 0u, 0u};
		}
	}
	if (!in_order(sys->events, sys->event_count)) // (often already: objects on one floor, met in index order)
		sort_events(sys->events, sys->event_count);
	bool moved = false;
	sys->shock = true;
	for (int e = 0; e < sys->event_count; ++e) {
		int i = sys->events[e].i, j = sys->events[e].j;
		hs_vec3 pa = world->state.bodies[i].pos, pb = world->state.bodies[j].pos;
		if (!answer(world, sys, i, j, -1.0, hs_spring_touching(sys, i, j)))
			continue;
		if (memcmp(&pa, &world->state.bodies[i].pos, sizeof pa) != 0)
			mv[i] |= 2u;
		if (memcmp(&pb, &world->state.bodies[j].pos, sizeof pb) != 0)
			mv[j] |= 2u;
		moved = moved || (mv[i] & 2u) || (mv[j] & 2u);
	}
	sys->shock = false;
	sys->event_count = 0;
	for (int q = 0; q < world->model.object_count; ++q)
		mv[q] = (uint8_t)(mv[q] >> 1);
	return moved;
}

#define HS_LAYER_SWEEPS 64 // sweeps of the floor layer's projection at most

// The floor layer's overlaps deeper than the drift, which the end passes part one pair at a time
// and moving the object that moved only (the other one's static friction holds it), so that a
// layer near jamming never came apart (its overlaps of 0.1-2.5 mm moved around it by up to
// 0.2 mm a frame for good): projected out all together, from the objects the end passes noted,
// in sweeps over their pairs with objects on the floor, each parted along the floor by
// inverse-mass shares and kept within the walls; an object pushed joins the sweeps; until no pair
// is deeper than the drift. Along the floor this costs and adds no energy (velocities untouched).
static void project_floor_layer(hs_world *world, hs_spring_system *sys) {
	double gap = world->model.def.floor_tolerance;
	for (int sweep = 0; sweep < HS_LAYER_SWEEPS; ++sweep) {
		double worst = 0.0;
		for (int k = 0; k < world->scratch.spring.layer_count; ++k) { // (the list grows as the sweep pushes)
			int q = world->scratch.spring.layer[k];
			const int *near;
			int count = hs_spring_near(world, sys, q, 0.0, &near);
			for (int m = 0; m < count; ++m) {
				int r = near[m];
				if (r == q || !both_on_floor(world, sys, q, r) || (world->scratch.spring.in_layer[r] && r < q))
					continue; // (a pair of two in the layer is met from the lower index)
				hs_body *a = &world->state.bodies[q], *b = &world->state.bodies[r];
				hs_vec3 n;
				double depth;
				if (!hs_spring_contact(world, &sys->geom[q], a->pos, &sys->geom[r], b->pos, &n, &depth))
					continue;
				hs_vec3 h = hs_v3(n.x, n.y, 0.0);
				double len = hs_length(h);
				depth -= gap;
				if (!(depth > 0.5 * HS_REST_DRIFT) || !(len > 0.5))
					continue;
				worst = fmax(worst, depth);
				h = hs_scale(h, 1.0 / len);
				double wa = 1.0 / a->mass, wb = 1.0 / b->mass, push = depth / len / (wa + wb);
				a->pos = hs_mul_add(a->pos, -push * wa, h);
				b->pos = hs_mul_add(b->pos, push * wb, h);
				hs_spring_wall_project(&sys->def.walls, &sys->geom[q], &a->pos, NULL);
				hs_spring_wall_project(&sys->def.walls, &sys->geom[r], &b->pos, NULL);
				sys->separated[q] = sys->separated[r] = 1;
				hs_spring_refile(world, sys, q);
				hs_spring_refile(world, sys, r);
				join_layer(&world->scratch, r);
			}
		}
		if (!(worst > HS_REST_DRIFT))
			break;
	}
	for (int k = 0; k < world->scratch.spring.layer_count; ++k)
		world->scratch.spring.in_layer[world->scratch.spring.layer[k]] = 0;
	world->scratch.spring.layer_count = 0;
}

void hs_spring_collide(hs_world *world, hs_spring_system *sys) {
	const hs_spring_geom *geom = sys->geom;
	double reach = 0.0, inner = INFINITY;
	for (int i = 0; i < world->model.object_count; ++i) { // the farthest any object moved this frame
		reach = fmax(reach, hs_length(hs_sub(world->state.bodies[i].pos, world->scratch.spring.saved_pos[i])));
		inner = fmin(inner, geom[i].inner);
	}
	// no two objects moved apart by more than the sum of any two inner radii: a pass through shows
	// at the frame's end (first_meeting), so the queries need not cover the paths
	if (2.0 * reach <= 2.0 * inner)
		reach = 0.0;
	for (int i = 0; i < world->model.object_count; ++i) { // every path starts at the frame start
		world->scratch.spring.path_pos[i] = world->scratch.spring.saved_pos[i];
		world->scratch.spring.path_vel[i] = world->scratch.spring.saved_vel[i];
		world->scratch.spring.path_t0[i] = 0.0;
	}
	hs_spring_file_all(world, sys);
	// Meetings in the order of time (no tunnelling): the earliest is answered, then the
	// meetings of its two objects are found again from their new paths; at most 8 per object and
	// frame (a pile in a wedge could bounce on), the rest are answered where the frame leaves them.
	sys->event_count = 0;
	for (int i = 0; i < world->model.object_count; ++i)
		list_meetings(world, sys, i, i, -1, reach);
	hs_spring_event ev;
	for (long budget = 8L * world->model.object_count; budget > 0 && earliest(sys, &ev); --budget) {
		answer(world, sys, ev.i, ev.j, ev.tau, false);
		sys->version[ev.i]++; // their listed meetings are stale: found again from the new paths
		sys->version[ev.j]++;
		list_meetings(world, sys, ev.i, -1, -1, reach);
		list_meetings(world, sys, ev.j, -1, ev.i, reach);
	}
	// where the frame leaves them: resting pairs, overlaps begun before a path restarted, the rest;
	// a separation may push an object into a third one, so the pass goes again (at most
	// HS_SEPARATION_PASSES times) while one moved anything
	if (world->model.object_count > 0)
		memset(sys->moved, 0, (size_t)world->model.object_count);
	for (int pass = 0; pass < HS_SEPARATION_PASSES && end_pass(world, sys, pass == 0); ++pass)
		;
	if (world->scratch.spring.layer_count > 0)
		project_floor_layer(world, sys);
}
