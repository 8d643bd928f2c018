// spring_hold.c — a technique's hold from the grab to the release, and the magnet gesture
// ("Dynamics in Interaction on the Responsive Workbench" §3); docs/techniques.md.
//
// Readings fixed here:
//  - The technique in force at the grab is the hold's for its whole length (a change applies to
//    the next grab); a massless object is held as the slave when the technique is the spring
//    (it has no weight to stretch one). The grab keeps the stylus's and the object's poses.
//  - Release (§3: "an object can be released with a given speed or sent back to its original
//    position"): HS_RELEASE_MODE_HAND is the spring model's drop or throw; HS_RELEASE_MODE_RETURN
//    puts a button release's object back where it was at the grab (for the magnet: before it
//    came), at rest. A massless object keeps no velocity: it stays where it is let go.
//  - The magnet (§3: "a fully extended hand bends in the elbow and moves into his working sphere"),
//    from the tracked stylus alone (the workbench tracks the pen and the head, not the arm): with
//    nothing on the spring, the arm counts as extended while the stylus is at least magnet_far
//    from the shoulder point `body`, and the selection candidate then (the pointing ray or the
//    hand's path, spring_grab.c) is remembered with the time; when the stylus comes within
//    magnet_near of `body` no more than magnet_within after it was last extended, that object is
//    brought to the pen (G at the stylus, at rest) and held as the slave. A slow return or a
//    reach that stops short of the sphere grabs nothing; the button is not used (it releases).
#include <string.h>

#include "spring_grab.h"
#include "spring_technique.h"
#include "world_internal.h"

void hs_spring_technique_init(hs_spring_technique *t) {
	memset(t, 0, sizeof *t);
	t->set = hs_default_technique_def();
	t->hold = HS_TECHNIQUE_SPRING;
	t->grab_rot = t->grab_obj_rot = t->home_rot = hs_quat_identity();
	t->magnet_object = -1;
}

bool hs_spring_massless_allowed(const hs_world *world) { return world->spring && world->spring->def.techniques; }

// The pointing ray's point on the plane z = h (any distance), or h's point below the stylus.
static hs_vec3 plane_point(const hs_spring_system *sys, double h) {
	hs_vec3 d = hs_quat_rotate(sys->rot, HS_STYLUS_AXIS), s = sys->stylus;
	double t = d.z != 0.0 ? (h - s.z) / d.z : -1.0;
	return t >= 0.0 && t <= sys->def.select_range ? hs_mul_add(s, t, d) : hs_v3(s.x, s.y, h);
}

void hs_spring_technique_grab(hs_world *world, hs_spring_system *sys, int i, hs_attach_kind kind) {
	hs_spring_technique *t = &sys->tech;
	const hs_body *body = &world->bodies[i];
	t->hold = HS_TECHNIQUE_SPRING;
	if (!sys->def.techniques)
		return;
	t->hold = (int)t->set.technique;
	if (kind == HS_ATTACH_MAGNET || (t->hold == HS_TECHNIQUE_SPRING && body->mass == 0.0))
		t->hold = HS_TECHNIQUE_SLAVE;
	t->grab_stylus = sys->stylus;
	t->grab_rot = sys->rot;
	t->grab_pos = body->pos;
	t->grab_obj_rot = body->rot;
	t->plane_offset = hs_sub(body->pos, plane_point(sys, body->pos.z));
	if (kind != HS_ATTACH_MAGNET) { // the magnet keeps where the object came from
		t->home_pos = body->pos;
		t->home_rot = body->rot;
	}
}

void hs_spring_technique_release(hs_world *world, hs_spring_system *sys, int i, bool button) {
	hs_spring_technique *t = &sys->tech;
	hs_body *body = &world->bodies[i];
	t->hold = HS_TECHNIQUE_SPRING;
	if (!sys->def.techniques)
		return;
	if (button && t->set.release == HS_RELEASE_MODE_RETURN) {
		body->pos = t->home_pos;
		body->vel = hs_v3(0.0, 0.0, 0.0);
		if (memcmp(&body->rot, &t->home_rot, sizeof body->rot) != 0) {
			body->rot = t->home_rot;
			sys->geom[i] = hs_spring_geom_of(world, body);
			sys->grid_count = -1;
		}
		sys->release.kind = HS_RELEASE_RETURN;
	}
	if (body->mass == 0.0)
		body->vel = hs_v3(0.0, 0.0, 0.0);
	sys->release.velocity = body->vel;
}

void hs_spring_magnet(hs_world *world, hs_spring_system *sys, double t1) {
	hs_spring_technique *t = &sys->tech;
	if (!sys->def.techniques || !t->set.magnet || sys->attached >= 0)
		return;
	double reach = hs_distance(sys->stylus, t->set.body);
	if (reach >= t->set.magnet_far) {
		if (sys->candidate >= 0) {
			t->magnet_object = sys->candidate;
			t->magnet_seen = t1;
		}
		return;
	}
	if (t->magnet_object < 0 || reach > t->set.magnet_near)
		return;
	int i = t->magnet_object;
	t->magnet_object = -1;
	if (t1 - t->magnet_seen > t->set.magnet_within)
		return; // too slow: no gesture
	hs_body *body = &world->bodies[i];
	t->home_pos = body->pos;
	t->home_rot = body->rot;
	body->pos = sys->stylus; // brought to the pen, at rest
	body->vel = hs_v3(0.0, 0.0, 0.0);
	hs_spring_attach(world, sys, i, HS_ATTACH_MAGNET);
}
