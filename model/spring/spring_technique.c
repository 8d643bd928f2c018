// spring_technique.c — how an object held by a technique without spring follows the stylus
// ("Dynamics in Interaction on the Responsive Workbench" §2.2, §3), and massless objects (§1:
// "a massless world can always be created by setting all masses to zero"); docs/techniques.md.
//
// Readings fixed here (the paper names the techniques in a sentence each):
//  - Slave (§3: "translation and rotation are applied directly to the object"): G = G0 + (S − S0)
//    and q = ΔR q0, ΔR = R R0⁻¹: the pen's motion since the grab, the turn about the object's own G.
//  - Stick (§2.2: "follows translations and rotations (center of rotation is the user's hand)"):
//    G = S + ΔR (G0 − S0), q = ΔR q0: rigid on the pen.
//  - Cross-plane (§3: "translated by the ray intersections in a plane with z = const"): the plane
//    is z = G0.z; G = P + (G0 − P0), P the pointing ray's point on it (P0 at the grab), so nothing
//    jumps at the grab; a ray that misses it within select_range leaves the object where it is.
//  - Cross-surface (§3: "the ray intersects surfaces of other objects (eg. a landscape)"): the
//    pointing ray's first hit on another object or the floor within select_range, P; the object
//    sits on it: G = P + (0, 0, bottom), bottom the height of G above its bounding box's floor.
//  - Each moves the object to its pose at the frame's end, with the velocity of that move; the
//    floor and the walls still bound it; object–object contacts leave it out while held (it
//    passes through others and they through it; the physics takes it back at the release).
//  - A massless object (density 0) has no weight, friction or inertia: free, it stays where it
//    is; held, it follows as the slave (or the technique chosen); it never touches other objects.
#include <string.h>

#include "spring_technique.h"
#include "world_internal.h"
#include "spring_contact.h"
#include "spring_system.h"

static bool massless(const hs_world *world, int i) { return world->state.bodies[i].mass == 0.0; }

bool hs_spring_technique_moves(const hs_world *world, const hs_spring_system *sys, int i) {
	return massless(world, i) || (i == sys->attached && sys->tech.hold != HS_TECHNIQUE_SPRING);
}

// The pen's pointing ray (its +x axis).
static hs_vec3 ray_dir(const hs_spring_system *sys) { return hs_quat_rotate(sys->rot, HS_STYLUS_AXIS); }

// The pointing ray's point on the plane z = h within select_range; false when it misses.
static bool ray_plane(const hs_spring_system *sys, double h, hs_vec3 *p) {
	hs_vec3 s = sys->stylus, d = ray_dir(sys);
	if (d.z == 0.0)
		return false;
	double t = (h - s.z) / d.z;
	if (!(t >= 0.0 && t <= sys->def.select_range))
		return false;
	*p = hs_mul_add(s, t, d);
	return true;
}

// The pointing ray's first hit on the floor or an object other than i within select_range.
static bool ray_surface(const hs_world *world, const hs_spring_system *sys, int i, hs_vec3 *p) {
	hs_vec3 s = sys->stylus, d = ray_dir(sys);
	double best = d.z < 0.0 ? -s.z / d.z : INFINITY; // the floor
	for (int j = 0; j < world->model.object_count; ++j) {
		if (j == i)
			continue;
		double t = hs_spring_geom_ray(&sys->geom[j], world->state.bodies[j].pos, s, d, sys->def.select_range);
		if (t >= 0.0 && t < best)
			best = t;
	}
	if (!(best >= 0.0 && best <= sys->def.select_range))
		return false;
	*p = hs_mul_add(s, best, d);
	return true;
}

// Object i's pose under the hold's technique at the frame's end; false when it stays.
static bool target_pose(const hs_world *world, const hs_spring_system *sys, int i, hs_vec3 *p, hs_quat *q) {
	const hs_spring_technique *t = &sys->tech;
	hs_quat turn = hs_quat_mul(sys->rot, hs_quat_conj(t->grab_rot)); // ΔR = R R0⁻¹
	*q = world->state.bodies[i].rot;
	switch (t->hold) {
	case HS_TECHNIQUE_SLAVE:
		*p = hs_add(t->grab_pos, hs_sub(sys->stylus, t->grab_stylus));
		*q = hs_quat_normalize(hs_quat_mul(turn, t->grab_obj_rot));
		return true;
	case HS_TECHNIQUE_STICK:
		*p = hs_add(sys->stylus, hs_quat_rotate(turn, hs_sub(t->grab_pos, t->grab_stylus)));
		*q = hs_quat_normalize(hs_quat_mul(turn, t->grab_obj_rot));
		return true;
	case HS_TECHNIQUE_CROSS_PLANE:
		if (!ray_plane(sys, t->grab_pos.z, p))
			return false;
		*p = hs_add(*p, t->plane_offset);
		return true;
	case HS_TECHNIQUE_CROSS_SURFACE:
		if (!ray_surface(world, sys, i, p))
			return false;
		p->z -= sys->geom[i].lo.z;
		return true;
	default:
		return false;
	}
}

void hs_spring_technique_advance(hs_world *world, hs_spring_system *sys, int i, double t) {
	hs_body *body = &world->state.bodies[i];
	hs_vec3 p = body->pos;
	hs_quat q = body->rot;
	if (i == sys->attached && !target_pose(world, sys, i, &p, &q)) {
		p = body->pos;
		q = body->rot;
	}
	if (memcmp(&q, &body->rot, sizeof q) != 0) { // turned: its reach changes with it
		body->rot = q;
		sys->geom[i] = hs_spring_geom_of(&world->model.shapes[body->shape], body);
		sys->grid_count = -1;
		sys->nb_state = HS_NEAR_STALE;
	}
	const hs_spring_geom *g = &sys->geom[i];
	if (p.z < -g->lo.z) // the floor bounds it
		p.z = -g->lo.z;
	hs_spring_wall_project(&sys->def.walls, g, &p, NULL);
	body->vel = t > 0.0 && !massless(world, i) ? hs_scale(hs_sub(p, body->pos), 1.0 / t) : hs_v3(0.0, 0.0, 0.0);
	body->pos = p;
	sys->on_floor[i] = p.z + g->lo.z <= world->model.def.floor_tolerance;
	sys->sliding[i] = 0;
	world->counters.object_steps++;
}

void hs_spring_technique_prepare(const hs_world *world, hs_spring_system *sys) {
	sys->tech.filter = false;
	if (!sys->def.techniques)
		return;
	for (int i = 0; i < world->model.object_count && !sys->tech.filter; ++i)
		sys->tech.filter = hs_spring_technique_moves(world, sys, i);
}

int hs_spring_technique_filter(const hs_world *world, const hs_spring_system *sys, int i, int *near, int count) {
	if (!sys->tech.filter)
		return count;
	if (hs_spring_technique_moves(world, sys, i)) { // it meets no one: itself only (callers skip it)
		near[0] = i;
		return 1;
	}
	int kept = 0;
	for (int k = 0; k < count; ++k)
		if (!hs_spring_technique_moves(world, sys, near[k]))
			near[kept++] = near[k];
	return kept;
}
