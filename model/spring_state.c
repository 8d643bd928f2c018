// spring_state.c — the spring system's part of the world's state walk (state_walk.h): every field of
// the spring system and its tracker that a later step reads, one 64-bit word each.
//
// Left out, on purpose: the definition and what derives from it (def, the tracker's period, window
// and speeds; each object's mass, x0, k, c come from hs_body and def), what lives in hs_body (the
// world's walk visits it: position, velocity, ...), the frame-start scratch (saved_pos/vel, written
// before each read), and the geometry cache, which a load empties so the next step rebuilds it from
// the loaded orientations. A load's CHECK pass refuses what would make a later step read out of
// bounds or compute with garbage: indices and enums out of range, flags not 0 or 1, non-finite
// numbers, stylus orientations that are not unit quaternions.
#include <string.h>

#include "spring_state.h"
#include "spring_world.h"
#include "state_walk.h"
#include "world_internal.h"
#include "spring_system.h"

// An enum stored as an int word, within [lo, hi].
static void enum_io(hs_state_io *io, int *stored, int lo, int hi) { hs_state_int_range(io, stored, lo, hi); }

static void tracker_ring_io(hs_tracker *tr, hs_state_io *io) {
	for (int i = 0; i < HS_TRACKER_CAPACITY; ++i) { // all of it: unfilled slots are zero
		hs_tracker_sample *s = &tr->ring[i];
		hs_state_f64(io, &s->time);
		hs_state_vec3(io, &s->position);
		hs_state_quat(io, &s->orientation);
		hs_state_bool(io, &s->button);
	}
}

// The tracker daemon (§5.1): its clock, ring buffer, estimates and events.
static void tracker_io(hs_tracker *tr, hs_state_io *io) {
	hs_state_long_range(io, &tr->next_tick, 0, LONG_MAX);
	hs_state_long_range(io, &tr->count, 0, LONG_MAX);
	hs_state_int_range(io, &tr->head, 0, HS_TRACKER_CAPACITY - 1);
	tracker_ring_io(tr, io);
	hs_state_vec3(io, &tr->velocity);
	hs_state_vec3(io, &tr->acceleration);
	hs_state_vec3(io, &tr->heading);
	hs_state_bool(io, &tr->at_rest);
	int event = (int)tr->last_event;
	enum_io(io, &event, HS_TRACKER_EVENT_NONE, HS_TRACKER_EVENT_MOTION_END);
	tr->last_event = (hs_tracker_event)event;
	hs_state_f64(io, &tr->last_event_time);
	hs_state_long_range(io, &tr->motion_starts, 0, LONG_MAX);
	hs_state_long_range(io, &tr->motion_ends, 0, LONG_MAX);
}

// The stylus: its poses at the end and the start of the coming frame, button, velocity.
static void stylus_io(hs_spring_system *sys, hs_state_io *io) {
	hs_state_bool(io, &sys->has_stylus);
	hs_state_vec3(io, &sys->stylus);
	hs_state_vec3(io, &sys->stylus_prev);
	hs_state_rotation(io, &sys->rot);
	hs_state_rotation(io, &sys->rot_prev);
	hs_state_bool(io, &sys->button);
	hs_state_bool(io, &sys->button_prev);
	hs_state_vec3(io, &sys->stylus_velocity);
}

// The spring: its object, how it got it, its direction, its anchor offset, the candidate and the last release.
static void spring_io(hs_spring_system *sys, hs_state_io *io) {
	int n = sys->capacity;
	hs_state_int_range(io, &sys->attached, -1, n - 1);
	int kind = (int)sys->attach_kind;
	enum_io(io, &kind, HS_ATTACH_NONE, HS_ATTACH_ROD);
	sys->attach_kind = (hs_attach_kind)kind;
	hs_state_vec3(io, &sys->axis);
	hs_state_vec3(io, &sys->anchor_offset);
	hs_state_int_range(io, &sys->candidate, -1, n - 1);
	hs_release *r = &sys->release;
	int rkind = (int)r->kind;
	enum_io(io, &rkind, HS_RELEASE_NONE, HS_RELEASE_THROW);
	r->kind = (hs_release_kind)rkind;
	int object = (int)r->object.index1; // index + 1 (0: none); the world tag is rebuilt below
	hs_state_int_range(io, &object, 0, n);
	r->object.index1 = (uint32_t)object;
	hs_state_f64(io, &r->time);
	hs_state_vec3(io, &r->velocity);
	hs_state_f64(io, &r->hand_speed);
}

// The touches' forces the next frame's resting solve starts from (spring_solve.c): every slot, so
// the size depends on the definitions only; those beyond the count are zero (CHECK refuses
// others), and HASH leaves them out: a hash every frame of a 1000-object box mixed 8000 slots for
// its touches (+8 % instructions a frame), a default world's 512 for none.
static void warm_io(hs_spring_system *sys, hs_state_io *io) {
	int last = sys->capacity - 1;
	int count = hs_state_count(io, &sys->warm_count, sys->touch_capacity);
	int slots = io->mode == HS_STATE_HASH ? count : sys->touch_capacity;
	for (int k = 0; k < slots; ++k) {
		hs_spring_warm *w = &sys->warm[k];
		if (k < count) {
			hs_state_int_range(io, &w->a, 0, last);
			hs_state_int_range(io, &w->b, 0, last);
			hs_state_f64(io, &w->normal);
			hs_state_vec3(io, &w->friction);
			continue;
		}
		uint64_t zero[6] = {0};
		for (int q = 0; q < 6; ++q)
			hs_state_zero(io, &zero[q]);
		if (io->mode == HS_STATE_LOAD)
			*w = (hs_spring_warm){0, 0, 0.0, {0.0, 0.0, 0.0}};
	}
}

// The spring definition as one checksum: a state saved under other spring parameters is refused.
static uint64_t def_checksum(const hs_spring_def *d) {
	const double numbers[] = {d->friction_static, d->friction_sliding, d->restitution, d->walls.x_min,
	                          d->walls.x_max,     d->walls.y_min,      d->walls.y_max, d->rest_length_ref,
	                          d->rest_mass_ref,   d->rest_exponent,    d->rest_length_min, d->rest_length_max,
	                          d->tracker_rate,    d->rest_speed,       d->motion_speed, d->catch_radius,
	                          d->grab_range,      d->select_range,     d->select_speed};
	uint64_t h = hs_state_mix(0x5350524E47ull, (uint64_t)d->integrator); // "SPRNG"
	h = hs_state_mix(h, d->walls.enabled ? 1u : 0u);
	h = hs_state_mix(h, (uint64_t)(int64_t)d->tracker_window);
	for (size_t i = 0; i < sizeof numbers / sizeof numbers[0]; ++i)
		h = hs_state_mix_f64(h, numbers[i]);
	return h;
}

void hs_spring_state_io(hs_spring_system *sys, hs_state_io *io) {
	hs_state_def(io, def_checksum(&sys->def), "the spring definition differs");
	for (int i = 0; i < sys->capacity; ++i) { // every slot: the size depends on the definitions only
		hs_state_u8_range(io, &sys->on_floor[i], 1);
		hs_state_u8_range(io, &sys->sliding[i], 1);
		hs_state_u8_range(io, &sys->separated[i], 1);
	}
	stylus_io(sys, io);
	spring_io(sys, io);
	tracker_io(&sys->tracker, io);
	warm_io(sys, io);
	if (io->mode == HS_STATE_LOAD)
		sys->geom_count = 0; // the geometry cache is rebuilt from the loaded bodies at the next step
}
