// step_spring.c — one frame of a spring world: the spring model of "Dynamics in Interaction on
// the Responsive Workbench" (§4–§5) for every object, the step's stages in order, each a function
// below that names its section. Stages call the concepts below them; none calls back up here.
//
// A tracked stylus moves objects through a critically damped spring attached at the centre of mass
// (§4.2, §4.4). Forces act at G only (no torque, objects keep their orientation): gravity, the
// spring, its damper (spring_params.c, spring_integrate.c), the ground's normal force, friction
// (§4.2) and the walls (§4.5, spring_contact.c). A frame: each object alone through the frame (on
// the floor or in the air), then object–object collisions (spring_collide.c), then the tracker
// daemon's samples of the frame (tracker.c, §5.1), then selection and the button at the frame end
// (spring_grab.c), then the per-object flags the world reports.
#include <string.h>

#include "motion.h"
#include "spring_body.h"
#include "spring_collide.h"
#include "spring_contact.h"
#include "spring_grab.h"
#include "spring_rest.h"
#include "spring_technique.h"
#include "step.h"
#include "world_internal.h"

// Forgets the cached parameters when the definition or gravity they came from changed.
static void check_params_cache(const hs_world *world, hs_spring_system *sys) {
	const hs_spring_def *d = &sys->def;
	double key[8] = {d->rest_length_ref, d->rest_mass_ref, d->rest_exponent, d->rest_length_min,
	                 d->rest_length_max, world->model.def.gravity.x, world->model.def.gravity.y, world->model.def.gravity.z};
	if (memcmp(key, sys->params_key, sizeof key) == 0)
		return;
	memcpy(sys->params_key, key, sizeof key);
	for (int i = 0; i < sys->capacity; ++i)
		sys->params_mass[i] = NAN;
}

static int floor_contacts(hs_world *world, const hs_spring_system *sys, int i) {
	if (sys->geom[i].sphere)
		return 1;
	hs_body *body = &world->state.bodies[i];
	hs_motion_pose_vertices(&world->model, &world->scratch, body);
	return hs_motion_floor_points(&world->model, &world->scratch, body);
}

// §4.2: the end of the frame for every object: the numeric guard, then what the world reports
// (floor contacts, resting, the spring's object grasped). In: bodies, the frame-start state.
// Out: the bodies' flags.
static void finish_bodies(hs_world *world, hs_spring_system *sys) {
	for (int i = 0; i < world->model.object_count; ++i) {
		hs_body *body = &world->state.bodies[i];
		if (!hs_vec3_is_finite(body->pos) || !hs_vec3_is_finite(body->vel)) {
			body->pos = world->scratch.spring.saved_pos[i]; // an explicit integrator blew up: freeze, count, go on
			body->vel = world->scratch.spring.saved_vel[i];
			hs_world_note_fault(&world->counters, &world->state, i);
		}
		body->prev = world->scratch.spring.saved_pos[i];
		bool still = body->vel.x == 0.0 && body->vel.y == 0.0 && body->vel.z == 0.0;
		body->grounded = sys->on_floor[i];
		body->asleep = (sys->on_floor[i] || sys->held[i]) && still && !sys->separated[i] && i != sys->attached;
		body->contact = (uint8_t)(i == sys->attached ? HS_CONTACT_GRASP : HS_CONTACT_NONE);
		body->floor_contacts = sys->on_floor[i] ? floor_contacts(world, sys, i) : 0;
	}
}

// §4.2: the frame's inputs: geometry of the objects added since the last frame, the spring
// parameters' cache, the stylus's velocity over the frame. In: bodies, stylus. Out: sys->geom,
// the parameters' cache, sys->stylus_velocity.
static void prepare_frame(hs_world *world, hs_spring_system *sys) {
	int n = world->model.object_count;
	if (sys->geom_count < n) // the broad phase's levels follow the geometry
		sys->grid_count = -1;
	for (int i = sys->geom_count; i < n; ++i) // objects added since the last frame
		sys->geom[i] = hs_spring_geom_of(&world->model.shapes[world->state.bodies[i].shape], &world->state.bodies[i]);
	sys->geom_count = n;
	check_params_cache(world, sys);
	hs_spring_technique_prepare(world, sys); // massless objects and kinematic holds meet no one
	sys->stylus_velocity = hs_scale(hs_sub(sys->stylus, sys->stylus_prev), 1.0 / world->model.def.dt);
}

// §4.2-§4.5: each object alone through the frame, on the floor or in the air (spring_body.c);
// those the resting contacts hold stay still. In: bodies, the rest solve's loads and holds. Out:
// bodies, sys->on_floor and sliding, the frame-start state (saved_pos, saved_vel).
static void move_objects(hs_world *world, hs_spring_system *sys) {
	int n = world->model.object_count;
	for (int i = 0; i < n; ++i) {
		world->scratch.spring.saved_pos[i] = world->state.bodies[i].pos;
		world->scratch.spring.saved_vel[i] = world->state.bodies[i].vel;
	}
	for (int i = 0; i < n; ++i) {
		if (!sys->held[i]) {
			if (hs_spring_technique_moves(world, sys, i)) // no spring, no weight: spring_technique.c
				hs_spring_technique_advance(world, sys, i, world->model.def.dt);
			else
				hs_spring_advance(sys, i, &world->state.bodies[i], &world->model.def, world->model.def.dt, &world->counters);
			continue;
		}
		world->state.bodies[i].vel = hs_v3(0.0, 0.0, 0.0); // held still by its contacts: not stepped
		sys->on_floor[i] = sys->rest[sys->rest_index[i]].floor;
		sys->sliding[i] = false;
	}
}

// §4.5: object–object collisions in the order of time (spring_collide.c), then each object back
// above the floor and inside the walls. In: bodies after their own frames. Out: bodies,
// sys->separated.
static void collide_objects(hs_world *world, hs_spring_system *sys) {
	int n = world->model.object_count;
	if (n > 0) // (n is never negative; the test keeps gcc's size analysis quiet)
		memset(sys->separated, 0, (size_t)n);
	hs_spring_collide(world, sys);
	for (int i = 0; i < n; ++i) { // separation may have pushed an object through the floor or a wall
		hs_body *body = &world->state.bodies[i];
		if (body->pos.z < -sys->geom[i].lo.z)
			body->pos.z = -sys->geom[i].lo.z;
		hs_spring_wall_project(&sys->def.walls, &sys->geom[i], &body->pos, NULL);
	}
}

// §5.1: the tracker daemon's samples of the frame, from the stylus's poses at its start and end.
// In: the stylus. Out: sys->tracker.
static void sample_tracker(hs_world *world, hs_spring_system *sys) {
	double t0 = (double)world->state.frame * world->model.def.dt, t1 = (double)(world->state.frame + 1) * world->model.def.dt;
	if (sys->has_stylus)
		hs_tracker_advance(&sys->tracker, t0, t1, sys->stylus_prev, sys->rot_prev, sys->stylus, sys->rot,
		                   sys->button);
	else
		hs_tracker_skip(&sys->tracker, t1);
}

// §3 and §4.4: selection, then the button at the frame end: a press attaches, a button held
// catches, a release drops or throws (spring_grab.c). In: the tracker, the button, bodies. Out:
// sys->candidate, the spring (attached, anchor), the last release.
static void press_and_release(hs_world *world, hs_spring_system *sys) {
	double t1 = (double)(world->state.frame + 1) * world->model.def.dt;
	hs_spring_update_candidate(world, sys);
	hs_spring_magnet(world, sys, t1); // §3: the magnet gesture (spring_hold.c)
	if (sys->button && !sys->button_prev)
		hs_spring_press(world, sys);
	else if (sys->button && sys->attached < 0) // held in the object's path: it is caught on arrival
		hs_spring_hold(world, sys);
	else if (!sys->button && sys->button_prev && sys->attached >= 0)
		hs_spring_detach(world, sys, true, t1);
}

// The frame's end: this frame's stylus becomes the previous one; every object is hashed again
// (the spring model keeps no awake list); a fault counted without an object is still the first;
// the frame counts. In: `faults`, the fault count the frame began with.
static void end_frame(hs_world *world, hs_spring_system *sys, long faults) {
	sys->stylus_prev = sys->stylus;
	sys->rot_prev = sys->rot;
	sys->button_prev = sys->button;
	hs_digest_all_stale(&world->cache);
	if (world->counters.numeric_faults > faults && world->state.first_fault_frame < 0)
		world->state.first_fault_frame = world->state.frame;
	world->state.frame++;
}

void hs_step_spring(hs_world *world) {
	hs_spring_system *sys = world->state.spring;
	long faults = world->counters.numeric_faults;
	prepare_frame(world, sys);     // §4.2: new objects' geometry, the stylus's velocity
	if (!sys->def.paper_collisions)
		hs_spring_rest(world, sys); // §4.5: touching objects' impulses, then their forces for the frame
	move_objects(world, sys);      // §4.2-§4.5: each object alone, on the floor or in the air
	collide_objects(world, sys);   // §4.5: collisions in the order of time
	sample_tracker(world, sys);    // §5.1: the tracker daemon's samples of the frame
	press_and_release(world, sys); // §3, §4.4: selection, press, catch, drop or throw
	finish_bodies(world, sys);     // §4.2: the numeric guard, what the world reports
	end_frame(world, sys, faults); // the frame counts
}
