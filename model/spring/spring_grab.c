// spring_grab.c — how the spring of "Dynamics in Interaction on the Responsive Workbench" gets and
// loses its object: selection (§3), direct picking, catching and the release (§4.4).
//
// Readings fixed here (the paper leaves them open; docs/model.md §8 "The press is neutral", §9):
//  - Button and selection at the end of each frame (the sample that carries them): a release
//    while the tracker says 'at rest' is a drop, otherwise a throw (the object takes the tracker's
//    velocity estimate, §4.4); a press attaches, in this order, the object the stylus is inside
//    (direct picking, §3), the nearest flying object within catch_radius (catch), or the selection
//    candidate within grab_range (a press inside a flying object counts as a catch). A button held
//    down with nothing attached catches a flying object that arrives within catch_radius (§4.4
//    "block its motion path and press": the press may come before the object).
//  - The candidate ('I want this one', §3) is the object the stylus is inside, else — while the
//    hand's path over the tracker's fit window goes at least select_speed (0.05 m/s: slow
//    approaches select too; tracker noise gives about 0.01 m/s at rest) — the first object hit by a
//    ray from the stylus along that path's heading (up to select_range). A ray that hits nothing
//    keeps the candidate unless the heading has clearly turned away from it (more than 60 deg).
//    With the hand slower than that, ray casting (§3, "for distant objects we use ray casting"):
//    the stylus's pointing ray (its +x axis) picks the first object it hits beyond grab_range, up to
//    select_range, unless the candidate is within grab_range (chosen by the hand's path: it stays);
//    near objects are left to direct picking and the hand's path. A pointing ray that hits no
//    distant object keeps the candidate.
//  - A press with a candidate beyond grab_range (and within select_range) attaches it by the
//    'fishing rod' (§4.4: "wherever spring actions are performed (too) far from the user's body"):
//    the spring's anchor is fixed in the stylus's frame, at the end of a rod from the pen, so the
//    rod's tip moves with the pen and swings as it turns (rod length × angle).
#include "spring_grab.h"
#include "spring_params.h"
#include "spring_technique.h"

// The object the stylus is inside (nearest centre first), -1 when none.
static int direct_pick(const hs_world *world, const hs_spring_system *sys, hs_vec3 s) {
	int best = -1;
	double best_d2 = INFINITY;
	for (int i = 0; i < world->model.object_count; ++i) {
		if (i == sys->attached || !hs_spring_geom_inside(&sys->geom[i], world->state.bodies[i].pos, s))
			continue;
		double d2 = hs_length_sq(hs_sub(world->state.bodies[i].pos, s));
		if (d2 < best_d2) {
			best_d2 = d2;
			best = i;
		}
	}
	return best;
}

// 'I want this one' (§3): a ray along the hand's estimated velocity; first hit, -1 when none.
static int ray_pick(const hs_world *world, const hs_spring_system *sys, hs_vec3 o, hs_vec3 dir) {
	int best = -1;
	double best_t = INFINITY;
	for (int i = 0; i < world->model.object_count; ++i) {
		if (i == sys->attached)
			continue;
		double t = hs_spring_geom_ray(&sys->geom[i], world->state.bodies[i].pos, o, dir, sys->def.select_range);
		if (t >= 0.0 && t < best_t) {
			best_t = t;
			best = i;
		}
	}
	return best;
}

// §4.4 catch: the nearest flying object within catch_radius of s, -1 when none.
static int catch_pick(const hs_world *world, const hs_spring_system *sys, hs_vec3 s) {
	int best = -1;
	double best_d = INFINITY;
	for (int i = 0; i < world->model.object_count; ++i) {
		if (sys->on_floor[i] || world->state.bodies[i].mass == 0.0) // (a massless object never flies)
			continue;
		double d = hs_spring_geom_distance(&sys->geom[i], world->state.bodies[i].pos, s);
		if (d <= sys->def.catch_radius && d < best_d) {
			best_d = d;
			best = i;
		}
	}
	return best;
}

// The hand's speed along its path over the tracker's fit window (the heading's chord over its
// time), 0 until the window is full.
static double path_speed(const hs_spring_system *sys) {
	hs_tracker_sample now, old;
	if (sys->tracker.count < sys->tracker.window || !hs_tracker_sample_at(&sys->tracker, 0, &now) ||
	    !hs_tracker_sample_at(&sys->tracker, sys->tracker.window - 1, &old) || !(now.time > old.time))
		return 0.0;
	return hs_length(hs_sub(now.position, old.position)) / (now.time - old.time);
}

// A clear change of direction: the candidate lies more than 60 deg off the heading.
static bool turned_away(const hs_world *world, const hs_spring_system *sys, hs_vec3 heading) {
	hs_vec3 to = hs_sub(world->state.bodies[sys->candidate].pos, sys->stylus);
	return hs_dot(heading, to) < 0.5 * hs_length(to);
}

// Object i (-1: none) lies within grab_range of the stylus.
static bool within_grab(const hs_world *world, const hs_spring_system *sys, int i) {
	return i >= 0 && hs_spring_geom_distance(&sys->geom[i], world->state.bodies[i].pos, sys->stylus) <= sys->def.grab_range;
}

void hs_spring_update_candidate(const hs_world *world, hs_spring_system *sys) {
	int pick = direct_pick(world, sys, sys->stylus);
	if (pick >= 0) {
		sys->candidate = pick;
		return;
	}
	hs_vec3 heading = sys->tracker.heading;
	if (hs_length_sq(heading) > 0.0 && path_speed(sys) >= sys->def.select_speed) {
		int hit = ray_pick(world, sys, sys->stylus, heading);
		if (hit >= 0)
			sys->candidate = hit;
		else if (sys->candidate >= 0 && turned_away(world, sys, heading))
			sys->candidate = -1;
	} else if (!within_grab(world, sys, sys->candidate)) { // ray casting: the pointing ray, a distant object
		int hit = ray_pick(world, sys, sys->stylus, hs_quat_rotate(sys->rot, HS_STYLUS_AXIS));
		if (hit >= 0 && !within_grab(world, sys, hit))
			sys->candidate = hit;
	}
	if (sys->candidate == sys->attached)
		sys->candidate = -1;
}

// The spring at the press (§4.4: "the spring can be extended or compressed by keeping the pen
// button depressed while moving the pen"): neutral. Its anchor A = S + offset, with the offset
// fixed here, lies at the rest length x0 from G: straight above G (against gravity; +z without
// gravity) when the stylus is inside the object (a direct pick: the object then hangs 1.2 x0 below
// A once lifted), else on the line from G toward the stylus (a catch or a selection at a
// distance: the spring lies where the user sees it). Nothing moves at the press; the force grows
// only as the pen moves (k d for a displacement d along the spring). hs_world_spring_attach
// (HS_ATTACH_API, scripts and tests) keeps the literal spring from the pen tip (offset 0), so a
// test can set an initial extension by where it holds the stylus.
void hs_spring_attach(hs_world *world, hs_spring_system *sys, int i, hs_attach_kind kind) {
	sys->attached = i;
	sys->attach_kind = kind;
	const hs_body *body = &world->state.bodies[i];
	hs_spring_params sp = hs_spring_params_of(&sys->def, world->model.def.gravity, body->mass);
	hs_spring_geom g = i < sys->geom_count ? sys->geom[i] : hs_spring_geom_of(&world->model.shapes[body->shape], body);
	hs_vec3 d = hs_sub(body->pos, sys->stylus);
	double len = hs_length(d);
	hs_vec3 down = hs_normalize(world->model.def.gravity);
	if (hs_length(down) == 0.0)
		down = hs_v3(0.0, 0.0, -1.0);
	bool inside = hs_spring_geom_inside(&g, body->pos, sys->stylus);
	if (kind == HS_ATTACH_API || sys->def.pen_tip_spring) { // the literal spring from the pen tip
		sys->axis = len > 0.0 ? hs_scale(d, 1.0 / len) : down;
		sys->anchor_offset = hs_v3(0.0, 0.0, 0.0);
	} else {
		sys->axis = inside || !(len > 1e-9 * sp.x0) ? down : hs_scale(d, 1.0 / len); // unit A → G
		sys->anchor_offset = hs_sub(hs_mul_add(body->pos, -sp.x0, sys->axis), sys->stylus);
		if (kind == HS_ATTACH_ROD) // the rod: fixed in the stylus's frame
			sys->anchor_offset = hs_quat_inv_rotate(sys->rot, sys->anchor_offset);
	}
	if (sys->candidate == i)
		sys->candidate = -1;
	hs_spring_technique_grab(world, sys, i, kind); // a technique without spring (spring_hold.c)
}

void hs_spring_press(hs_world *world, hs_spring_system *sys) {
	if (sys->attached >= 0)
		return;
	hs_vec3 s = sys->stylus;
	int pick = direct_pick(world, sys, s);
	if (pick >= 0) { // inside a flying object is catching it too
		bool flying = !sys->on_floor[pick] && world->state.bodies[pick].mass > 0.0;
		hs_spring_attach(world, sys, pick, flying ? HS_ATTACH_CATCH : HS_ATTACH_PICK);
		return;
	}
	int best = catch_pick(world, sys, s);
	if (best >= 0) {
		hs_spring_attach(world, sys, best, HS_ATTACH_CATCH);
		return;
	}
	int c = sys->candidate;
	if (c < 0)
		return;
	double d = hs_spring_geom_distance(&sys->geom[c], world->state.bodies[c].pos, s);
	if (d <= sys->def.grab_range)
		hs_spring_attach(world, sys, c, HS_ATTACH_SELECT);
	else if (d <= sys->def.select_range) // too far to reach: the fishing rod
		hs_spring_attach(world, sys, c, HS_ATTACH_ROD);
}

void hs_spring_hold(hs_world *world, hs_spring_system *sys) {
	int best = catch_pick(world, sys, sys->stylus);
	if (best >= 0)
		hs_spring_attach(world, sys, best, HS_ATTACH_CATCH);
}

void hs_spring_detach(hs_world *world, hs_spring_system *sys, bool classify, double time) {
	int i = sys->attached;
	hs_body *body = &world->state.bodies[i];
	hs_release *r = &sys->release;
	r->object = hs_object_handle(&world->model, i);
	r->time = time;
	r->hand_speed = hs_length(sys->tracker.velocity);
	if (classify && !sys->tracker.at_rest) { // §4.4 throw: the object takes the hand's velocity
		r->kind = HS_RELEASE_THROW;
		body->vel = sys->tracker.velocity;
	} else { // §4.4 drop: the object just loses the spring
		r->kind = HS_RELEASE_DROP;
	}
	r->velocity = body->vel;
	sys->attached = -1;
	sys->attach_kind = HS_ATTACH_NONE;
	sys->anchor_offset = hs_v3(0.0, 0.0, 0.0);
	hs_spring_technique_release(world, sys, i, classify); // massless, or sent home (spring_hold.c)
}
