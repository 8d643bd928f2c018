// spring_state_tmp.c — TEMPORARY: the spring system's part of the state walk (state.h), written
// against spring.c and tracker.c as they are on the day the state block landed. The spring
// branch defines hs_spring_state_io in spring.c itself; the integrator deletes this file then.
// The two struct definitions below are copies of spring.c's private ones and must match them.
#include <gsl/gsl_rng.h>
#include <limits.h>

#include "spring_internal.h"
#include "state.h"

typedef struct body_geom { // copy of spring.c's
	hs_vec3 lo, hi;
	double radius;
	bool sphere;
} body_geom;

struct hs_spring_system { // copy of spring.c's
	hs_spring_def def;
	gsl_rng *rng;
	hs_tracker tracker;
	int geom_count;
	body_geom *geom;
	uint8_t *on_floor;
	uint8_t *sliding;
	uint8_t *separated;
	hs_vec3 *saved_pos;
	hs_vec3 *saved_vel;
	bool has_stylus;
	hs_vec3 stylus, stylus_prev;
	hs_quat rot, rot_prev;
	bool button, button_prev;
	hs_vec3 stylus_velocity;
	int attached;
	hs_attach_kind attach_kind;
	hs_vec3 axis;
	int candidate;
	hs_release release;
};

// GSL's mt19937 state (gsl/rng/mt.c): the generator is state while the model still holds it
// (DESIGN.md wants the noise drawn by the harness; the spring branch moves it out).
#define MT_N 624
typedef struct mt_state {
	unsigned long mt[MT_N];
	int mti;
} mt_state;

static uint64_t def_checksum(const hs_spring_def *d) {
	const double numbers[] = {d->friction_static, d->friction_sliding, d->restitution, d->walls.x_min,
	                          d->walls.x_max, d->walls.y_min, d->walls.y_max, d->rest_length_ref,
	                          d->rest_mass_ref, d->rest_exponent, d->rest_length_min, d->rest_length_max,
	                          d->tracker_rate, d->rest_speed, d->motion_speed, d->catch_radius,
	                          d->grab_range, d->select_range, d->noise_position, d->noise_orientation};
	uint64_t h = hs_state_mix(0x5350524E47ull, (uint64_t)d->integrator);
	h = hs_state_mix(h, d->walls.enabled ? 1u : 0u);
	h = hs_state_mix(h, (uint64_t)d->tracker_window);
	h = hs_state_mix(h, d->noise ? 1u : 0u);
	h = hs_state_mix(h, (uint64_t)d->noise_seed);
	for (size_t i = 0; i < sizeof numbers / sizeof numbers[0]; ++i)
		h = hs_state_mix_f64(h, numbers[i]);
	return h;
}

static void rng_io(hs_state_io *io, gsl_rng *rng) {
	if (!rng)
		return;
	mt_state *s = gsl_rng_state(rng);
	for (int i = 0; i < MT_N; ++i) {
		uint64_t v = s->mt[i];
		hs_state_u64(io, &v);
		if (v > 0xFFFFFFFFu)
			hs_state_refuse(io, "a generator word beyond 32 bits");
		if (io->mode == HS_STATE_LOAD)
			s->mt[i] = (unsigned long)v;
	}
	hs_state_int_range(io, &s->mti, 0, MT_N);
}

static void sample_io(hs_state_io *io, hs_tracker_sample *s) {
	hs_state_f64(io, &s->time);
	hs_state_vec3(io, &s->position);
	hs_state_quat(io, &s->orientation); // zero in slots never filled
	hs_state_bool(io, &s->button);
}

static void tracker_io(hs_state_io *io, hs_tracker *t) {
	hs_state_long(io, &t->next_tick);
	hs_state_long_range(io, &t->count, 0, LONG_MAX);
	hs_state_int_range(io, &t->head, 0, HS_TRACKER_CAPACITY - 1);
	for (int i = 0; i < HS_TRACKER_CAPACITY; ++i)
		sample_io(io, &t->ring[i]);
	hs_state_vec3(io, &t->velocity);
	hs_state_vec3(io, &t->acceleration);
	hs_state_vec3(io, &t->heading);
	hs_state_bool(io, &t->at_rest);
	int event = (int)t->last_event;
	hs_state_int_range(io, &event, HS_TRACKER_EVENT_NONE, HS_TRACKER_EVENT_MOTION_END);
	if (io->mode == HS_STATE_LOAD)
		t->last_event = (hs_tracker_event)event;
	hs_state_f64(io, &t->last_event_time);
	hs_state_long_range(io, &t->motion_starts, 0, LONG_MAX);
	hs_state_long_range(io, &t->motion_ends, 0, LONG_MAX);
}

static void enum_io(hs_state_io *io, int *v, int lo, int hi) { hs_state_int_range(io, v, lo, hi); }

static void release_io(hs_state_io *io, hs_release *r) {
	int kind = (int)r->kind, object = (int)r->object.index1;
	enum_io(io, &kind, HS_RELEASE_NONE, HS_RELEASE_THROW);
	enum_io(io, &object, 0, io->objects);
	hs_state_f64(io, &r->time);
	hs_state_vec3(io, &r->velocity);
	hs_state_f64(io, &r->hand_speed);
	if (io->mode == HS_STATE_LOAD) {
		r->kind = (hs_release_kind)kind;
		r->object = (hs_object_id){(uint32_t)object, 0, 0}; // as spring.c makes it today
	}
}

void hs_spring_state_io(hs_spring_system *sys, hs_state_io *io) {
	hs_state_def(io, def_checksum(&sys->def), "another spring definition");
	rng_io(io, sys->rng);
	tracker_io(io, &sys->tracker);
	for (int i = 0; i < io->objects; ++i) {
		hs_state_u8_range(io, &sys->on_floor[i], 1);
		hs_state_u8_range(io, &sys->sliding[i], 1);
	}
	hs_state_bool(io, &sys->has_stylus);
	hs_state_vec3(io, &sys->stylus);
	hs_state_vec3(io, &sys->stylus_prev);
	hs_state_rotation(io, &sys->rot);
	hs_state_rotation(io, &sys->rot_prev);
	hs_state_bool(io, &sys->button);
	hs_state_bool(io, &sys->button_prev);
	hs_state_vec3(io, &sys->stylus_velocity);
	int kind = (int)sys->attach_kind;
	hs_state_int_range(io, &sys->attached, -1, io->objects - 1);
	enum_io(io, &kind, HS_ATTACH_NONE, HS_ATTACH_API);
	hs_state_vec3(io, &sys->axis);
	hs_state_int_range(io, &sys->candidate, -1, io->objects - 1);
	release_io(io, &sys->release);
	if (io->mode == HS_STATE_LOAD) {
		sys->attach_kind = (hs_attach_kind)kind;
		sys->geom_count = 0; // the geometry cache is rebuilt from the bodies at the next step
	}
}
