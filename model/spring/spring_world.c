// spring_world.c — the public API of the spring model (handspring.h): the stylus, attaching and
// detaching by hand, and what a user reads back. hs_world_create makes the model (spring_system.c).
#include <string.h>

#include "spring_world.h"
#include "world_internal.h"
#include "spring_grab.h"
#include "spring_params.h"
#include "spring_technique.h"

bool hs_world_springs_enabled(const hs_world *world) { return world && world->state.spring; }

hs_status hs_world_spring_def(const hs_world *world, hs_spring_def *out) {
	if (!world || !world->state.spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	*out = world->state.spring->def;
	return HS_OK;
}

hs_status hs_world_set_stylus(hs_world *world, hs_vec3 position, hs_quat orientation, bool button) {
	if (!world || !world->state.spring || !hs_vec3_is_finite(position) || !hs_quat_is_finite(orientation) ||
	    fabs(sqrt(hs_quat_dot(orientation, orientation)) - 1.0) > 1e-6)
		return HS_ERR_INVALID_ARGUMENT;
	hs_spring_system *sys = world->state.spring;
	sys->stylus = position;
	sys->rot = hs_quat_normalize(orientation);
	sys->button = button;
	if (!sys->has_stylus) { // the first pose: the stylus has been there all along
		sys->has_stylus = true;
		sys->stylus_prev = sys->stylus;
		sys->rot_prev = sys->rot;
	}
	return HS_OK;
}


hs_status hs_world_spring_attach(hs_world *world, hs_object_id id) {
	int i = hs_object_index(world, id);
	if (i < 0 || !world->state.spring || !world->state.spring->has_stylus)
		return HS_ERR_INVALID_ARGUMENT;
	hs_spring_system *sys = world->state.spring;
	if (sys->attached >= 0 && sys->attached != i)
		hs_spring_detach(world, sys, false, hs_world_time(world));
	hs_spring_attach(world, sys, i, HS_ATTACH_API);
	hs_digest_all_stale(&world->cache);
	return HS_OK;
}

hs_status hs_world_spring_detach(hs_world *world) {
	if (!world || !world->state.spring)
		return HS_ERR_INVALID_ARGUMENT;
	if (world->state.spring->attached >= 0)
		hs_spring_detach(world, world->state.spring, false, hs_world_time(world));
	hs_digest_all_stale(&world->cache);
	return HS_OK;
}


hs_status hs_world_spring_state(const hs_world *world, hs_spring_state *out) {
	if (!world || !world->state.spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	const hs_spring_system *sys = world->state.spring;
	memset(out, 0, sizeof *out);
	out->attached = hs_object_handle(&world->model, sys->attached);
	out->attach_kind = sys->attach_kind;
	out->technique = sys->attached >= 0 ? (hs_technique)sys->tech.hold : HS_TECHNIQUE_SPRING;
	out->candidate = hs_object_handle(&world->model, sys->candidate);
	out->stylus = sys->stylus;
	out->stylus_orientation = sys->rot;
	out->button = sys->button;
	out->stylus_velocity = sys->stylus_velocity;
	if (sys->attached >= 0 && sys->tech.hold != HS_TECHNIQUE_SPRING) {
		out->anchor = sys->stylus; // no spring: nothing stretches
	} else if (sys->attached >= 0) {
		const hs_body *body = &world->state.bodies[sys->attached];
		hs_spring_params sp = hs_spring_params_of(&sys->def, world->model.def.gravity, body->mass);
		out->anchor = hs_spring_anchor(sys);
		out->length = hs_distance(body->pos, out->anchor);
		out->extension = out->length - sp.x0;
		out->force = hs_spring_force(&sp, sys->axis, body->pos, body->vel, out->anchor,
		                             hs_spring_anchor_velocity(sys, world->model.def.dt));
	}
	return HS_OK;
}

hs_status hs_world_spring_object(const hs_world *world, hs_object_id id, hs_spring_object *out) {
	int i = hs_object_index(world, id);
	if (i < 0 || !world->state.spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	const hs_spring_system *sys = world->state.spring;
	const hs_body *body = &world->state.bodies[i];
	hs_spring_params sp = hs_spring_params_of(&sys->def, world->model.def.gravity, body->mass);
	memset(out, 0, sizeof *out);
	out->mass = sp.mass;
	out->rest_length = sp.x0;
	out->stiffness = sp.k;
	out->damping = sp.c;
	out->omega = sp.omega;
	out->velocity = body->vel;
	out->on_floor = sys->on_floor[i] != 0;
	out->sliding = sys->sliding[i] != 0;
	out->attached = i == sys->attached;
	return HS_OK;
}

hs_status hs_world_tracker_state(const hs_world *world, hs_tracker_state *out) {
	if (!world || !world->state.spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	const hs_tracker *tr = &world->state.spring->tracker;
	memset(out, 0, sizeof *out);
	out->sample_count = tr->count;
	if (!hs_tracker_sample_at(tr, 0, &out->newest))
		out->newest.orientation = hs_quat_identity();
	out->velocity = tr->velocity;
	out->acceleration = tr->acceleration;
	out->speed = hs_length(tr->velocity);
	out->heading = tr->heading;
	out->at_rest = tr->at_rest;
	out->last_event = tr->last_event;
	out->last_event_time = tr->last_event_time;
	out->motion_starts = tr->motion_starts;
	out->motion_ends = tr->motion_ends;
	return HS_OK;
}

hs_status hs_world_tracker_sample(const hs_world *world, int age, hs_tracker_sample *out) {
	if (!world || !world->state.spring || !out || !hs_tracker_sample_at(&world->state.spring->tracker, age, out))
		return HS_ERR_INVALID_ARGUMENT;
	return HS_OK;
}

hs_status hs_world_spring_last_release(const hs_world *world, hs_release *out) {
	if (!world || !world->state.spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	*out = world->state.spring->release;
	out->object = hs_object_handle(&world->model, (int)out->object.index1 - 1); // the state keeps the index only
	return HS_OK;
}
