// spring_world.c — the public API of the spring model (handspring.h): switching a world to it,
// the stylus, attaching and detaching by hand, and what a user reads back.
#include <stdlib.h>
#include <string.h>

#include "spring_world.h"
#include "state.h"
#include "world_internal.h"
#include "spring_grab.h"
#include "spring_params.h"

void hs_spring_system_destroy(hs_spring_system *system) {
	if (!system)
		return;
	free(system->geom);
	free(system->on_floor);
	free(system->sliding);
	free(system->separated);
	free(system->saved_pos);
	free(system->saved_vel);
	hs_hgrid_free(&system->grid);
	free(system->near);
	free(system->touch);
	free(system->path_pos);
	free(system->path_vel);
	free(system->path_t0);
	free(system->events);
	free(system->version);
	free(system->nb);
	free(system->nb_start);
	free(system->nb_pos);
	free(system->box_lo);
	free(system->box_hi);
	free(system->nb_lo);
	free(system->nb_hi);
	free(system->params);
	free(system->params_mass);
	free(system->moved);
	free(system->active);
	free(system->warm);
	free(system->layer);
	free(system->in_layer);
	free(system->rest_index);
	free(system->rest);
	free(system->load);
	free(system->held);
	free(system);
}

hs_status hs_world_enable_springs(hs_world *world, const hs_spring_def *def) {
	if (!world || !hs_spring_def_valid(def))
		return HS_ERR_INVALID_ARGUMENT;
	hs_spring_system *sys = calloc(1, sizeof *sys);
	if (!sys)
		return HS_ERR_NO_MEMORY;
	size_t cap = world->def.max_objects > 0 ? (size_t)world->def.max_objects : 1;
	sys->geom = calloc(cap, sizeof *sys->geom);
	sys->on_floor = calloc(cap, sizeof *sys->on_floor);
	sys->sliding = calloc(cap, sizeof *sys->sliding);
	sys->separated = calloc(cap, sizeof *sys->separated);
	sys->saved_pos = calloc(cap, sizeof *sys->saved_pos);
	sys->saved_vel = calloc(cap, sizeof *sys->saved_vel);
	sys->near = calloc(cap, sizeof *sys->near);
	sys->nb_capacity = (int)(HS_SPRING_NEAR_PER_OBJECT * cap);
	sys->nb = calloc((size_t)sys->nb_capacity, sizeof *sys->nb);
	sys->nb_start = calloc(cap + 1, sizeof *sys->nb_start);
	sys->nb_pos = calloc(cap, sizeof *sys->nb_pos);
	sys->box_lo = calloc(cap, sizeof *sys->box_lo);
	sys->box_hi = calloc(cap, sizeof *sys->box_hi);
	sys->nb_lo = calloc(cap, sizeof *sys->nb_lo);
	sys->nb_hi = calloc(cap, sizeof *sys->nb_hi);
	sys->path_pos = calloc(cap, sizeof *sys->path_pos);
	sys->path_vel = calloc(cap, sizeof *sys->path_vel);
	sys->path_t0 = calloc(cap, sizeof *sys->path_t0);
	sys->moved = calloc(cap, sizeof *sys->moved);
	sys->event_capacity = (int)(HS_SPRING_TOUCHES_PER_OBJECT * cap);
	sys->events = calloc((size_t)sys->event_capacity, sizeof *sys->events);
	sys->version = calloc(cap, sizeof *sys->version);
	sys->params = calloc(cap, sizeof *sys->params);
	sys->params_mass = calloc(cap, sizeof *sys->params_mass);
	sys->touch_capacity = (int)(HS_SPRING_TOUCHES_PER_OBJECT * cap);
	sys->touch = calloc((size_t)sys->touch_capacity, sizeof *sys->touch);
	sys->warm = calloc((size_t)sys->touch_capacity, sizeof *sys->warm);
	sys->layer = calloc(cap, sizeof *sys->layer);
	sys->in_layer = calloc(cap, sizeof *sys->in_layer);
	sys->active = calloc(cap, sizeof *sys->active);
	sys->rest_index = malloc(cap * sizeof *sys->rest_index);
	for (size_t i = 0; sys->rest_index && i < cap; ++i)
		sys->rest_index[i] = -1;
	for (size_t i = 0; sys->params_mass && i < cap; ++i)
		sys->params_mass[i] = NAN; // no parameters cached
	sys->rest = calloc(cap, sizeof *sys->rest);
	sys->load = calloc(cap, sizeof *sys->load);
	sys->held = calloc(cap, sizeof *sys->held);
	bool grid = hs_hgrid_alloc(&sys->grid, (int)cap, 3);
	sys->grid_count = -1;
	if (!sys->geom || !sys->on_floor || !sys->sliding || !sys->separated || !sys->saved_pos || !sys->saved_vel ||
	    !sys->near || !sys->nb || !sys->nb_start || !sys->nb_pos || !sys->box_lo || !sys->box_hi || !sys->nb_lo || !sys->nb_hi || !grid || !sys->touch || !sys->warm || !sys->layer || !sys->in_layer || !sys->active || !sys->rest_index || !sys->rest || !sys->load ||
	    !sys->held || !sys->path_pos || !sys->path_vel || !sys->path_t0 || !sys->events || !sys->version || !sys->params || !sys->params_mass ||
	    !sys->moved) {
		hs_spring_system_destroy(sys);
		return HS_ERR_NO_MEMORY;
	}
	sys->def = *def;
	sys->capacity = (int)cap;
	hs_tracker_init(&sys->tracker, def, (double)world->frame * world->def.dt);
	sys->rot = sys->rot_prev = hs_quat_identity();
	sys->attached = -1;
	sys->candidate = -1;
	sys->axis = hs_v3(0.0, 0.0, -1.0);
	hs_spring_system_destroy(world->spring);
	world->spring = sys;
	return HS_OK;
}

bool hs_world_springs_enabled(const hs_world *world) { return world && world->spring; }

hs_status hs_world_spring_def(const hs_world *world, hs_spring_def *out) {
	if (!world || !world->spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	*out = world->spring->def;
	return HS_OK;
}

hs_status hs_world_set_stylus(hs_world *world, hs_vec3 position, hs_quat orientation, bool button) {
	if (!world || !world->spring || !hs_vec3_is_finite(position) || !hs_quat_is_finite(orientation) ||
	    fabs(sqrt(hs_quat_dot(orientation, orientation)) - 1.0) > 1e-6)
		return HS_ERR_INVALID_ARGUMENT;
	hs_spring_system *sys = world->spring;
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
	if (i < 0 || !world->spring || !world->spring->has_stylus)
		return HS_ERR_INVALID_ARGUMENT;
	hs_spring_system *sys = world->spring;
	if (sys->attached >= 0 && sys->attached != i)
		hs_spring_detach(world, sys, false, hs_world_time(world));
	hs_spring_attach(world, sys, i, HS_ATTACH_API);
	hs_digest_all_stale(world);
	return HS_OK;
}

hs_status hs_world_spring_detach(hs_world *world) {
	if (!world || !world->spring)
		return HS_ERR_INVALID_ARGUMENT;
	if (world->spring->attached >= 0)
		hs_spring_detach(world, world->spring, false, hs_world_time(world));
	hs_digest_all_stale(world);
	return HS_OK;
}


hs_status hs_world_spring_state(const hs_world *world, hs_spring_state *out) {
	if (!world || !world->spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	const hs_spring_system *sys = world->spring;
	memset(out, 0, sizeof *out);
	out->attached = hs_object_handle(world, sys->attached);
	out->attach_kind = sys->attach_kind;
	out->candidate = hs_object_handle(world, sys->candidate);
	out->stylus = sys->stylus;
	out->stylus_orientation = sys->rot;
	out->button = sys->button;
	out->stylus_velocity = sys->stylus_velocity;
	if (sys->attached >= 0) {
		const hs_body *body = &world->bodies[sys->attached];
		hs_spring_params sp = hs_spring_params_of(&sys->def, world, body->mass);
		out->anchor = hs_spring_anchor(sys);
		out->length = hs_distance(body->pos, out->anchor);
		out->extension = out->length - sp.x0;
		out->force = hs_spring_force(&sp, sys->axis, body->pos, body->vel, out->anchor,
		                             hs_spring_anchor_velocity(sys, world->def.dt));
	}
	return HS_OK;
}

hs_status hs_world_spring_object(const hs_world *world, hs_object_id id, hs_spring_object *out) {
	int i = hs_object_index(world, id);
	if (i < 0 || !world->spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	const hs_spring_system *sys = world->spring;
	const hs_body *body = &world->bodies[i];
	hs_spring_params sp = hs_spring_params_of(&sys->def, world, body->mass);
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
	if (!world || !world->spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	const hs_tracker *tr = &world->spring->tracker;
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
	if (!world || !world->spring || !out || !hs_tracker_sample_at(&world->spring->tracker, age, out))
		return HS_ERR_INVALID_ARGUMENT;
	return HS_OK;
}

hs_status hs_world_spring_last_release(const hs_world *world, hs_release *out) {
	if (!world || !world->spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	*out = world->spring->release;
	out->object = hs_object_handle(world, (int)out->object.index1 - 1); // the state keeps the index only
	return HS_OK;
}
