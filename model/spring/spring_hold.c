// spring_hold.c — a technique's hold from the grab to the release ("Dynamics in Interaction on
// the Responsive Workbench" §3); docs/techniques.md.
//
// Readings fixed here:
//  - The technique in force at the grab is the hold's for its whole length (a change applies to
//    the next grab); a massless object is held as the slave when the technique is the spring
//    (it has no weight to stretch one). The grab keeps the stylus's and the object's poses.
//  - Release (§3: "an object can be released with a given speed or sent back to its original
//    position"): HS_RELEASE_MODE_HAND is the spring model's drop or throw; HS_RELEASE_MODE_RETURN
//    puts a button release's object back where it was at the grab (for the magnet: before it
//    came), at rest. A massless object keeps no velocity: it stays where it is let go.
#include <string.h>

#include "spring_system.h"
#include "spring_technique.h"
#include "world_internal.h"

bool hs_spring_massless_allowed(const hs_world *world) { return world->state.spring && world->state.spring->def.techniques; }

// The pointing ray's point on the plane z = h (any distance), or h's point below the stylus.
static hs_vec3 plane_point(const hs_spring_system *sys, double h) {
	hs_vec3 d = hs_quat_rotate(sys->rot, HS_STYLUS_AXIS), s = sys->stylus;
	double t = d.z != 0.0 ? (h - s.z) / d.z : -1.0;
	return t >= 0.0 && t <= sys->def.select_range ? hs_mul_add(s, t, d) : hs_v3(s.x, s.y, h);
}

void hs_spring_technique_grab(hs_world *world, hs_spring_system *sys, int i, hs_attach_kind kind) {
	hs_spring_technique *t = &sys->tech;
	const hs_body *body = &world->state.bodies[i];
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
	hs_body *body = &world->state.bodies[i];
	t->hold = HS_TECHNIQUE_SPRING;
	if (!sys->def.techniques)
		return;
	if (button && t->set.release == HS_RELEASE_MODE_RETURN) {
		body->pos = t->home_pos;
		body->vel = hs_v3(0.0, 0.0, 0.0);
		if (memcmp(&body->rot, &t->home_rot, sizeof body->rot) != 0) {
			body->rot = t->home_rot;
			sys->geom[i] = hs_spring_geom_of(&world->model.shapes[body->shape], body);
			sys->grid_count = -1;
		}
		sys->release.kind = HS_RELEASE_RETURN;
	}
	if (body->mass == 0.0)
		body->vel = hs_v3(0.0, 0.0, 0.0);
	sys->release.velocity = body->vel;
}
