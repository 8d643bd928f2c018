// spring_state.c — the spring system's part of the world's state walk (state.h): every field of
// the spring system and its tracker that a later step reads, one 64-bit word each.
//
// Left out, on purpose: the definition and what derives from it (def, the tracker's period, window
// and speeds; each object's mass, x0, k, c come from hs_body and def), what lives in hs_body (the
// world's walk visits it: position, velocity, ...), the frame-start scratch (saved_pos/vel, written
// before each read), and the geometry cache, which a load empties so the next step rebuilds it from
// the loaded orientations. LOAD checks every value it reads (indices, enums, finite numbers, unit
// quaternions, the ring's head against its count) and reports the first bad one in io->invalid /
// io->why; the loader must then discard the system.
#include "spring.h"
#include "spring_system.h"

#define HS_UNIT_TOLERANCE 1e-6 // |q| or |u| this close to 1 is a unit (hs_world_set_stylus's test)

// Marks the load invalid (the first reason is kept).
static void check(hs_state_io *io, bool ok, const char *why) {
	if (io->mode != HS_STATE_LOAD || ok || io->invalid)
		return;
	io->invalid = true;
	io->why = why;
}

static bool finite_quat(hs_quat q) { return isfinite(q.w) && isfinite(q.x) && isfinite(q.y) && isfinite(q.z); }

static bool unit_quat(hs_quat q) {
	return finite_quat(q) && fabs(sqrt(hs_quat_dot(q, q)) - 1.0) <= HS_UNIT_TOLERANCE;
}

static bool unit_vec3(hs_vec3 v) { return hs_vec3_is_finite(v) && fabs(hs_length(v) - 1.0) <= HS_UNIT_TOLERANCE; }

// An enum or small index through an int word: stored into *field only when within [lo, hi].
static bool state_ranged(hs_state_io *io, int *value, int lo, int hi, const char *why) {
	hs_state_int(io, value);
	bool ok = *value >= lo && *value <= hi;
	check(io, ok, why);
	return io->mode == HS_STATE_LOAD && ok;
}

static void tracker_ring_io(hs_tracker *tr, hs_state_io *io) {
	for (int i = 0; i < HS_TRACKER_CAPACITY; ++i) { // all of it: unfilled slots are zero
		hs_tracker_sample *s = &tr->ring[i];
		hs_state_f64(io, &s->time);
		hs_state_vec3(io, &s->position);
		hs_state_quat(io, &s->orientation);
		hs_state_bool(io, &s->button);
		check(io, isfinite(s->time) && hs_vec3_is_finite(s->position) && finite_quat(s->orientation),
		      "spring: a tracker sample is not finite");
	}
}

// The tracker daemon (§5.1): its clock, ring buffer, estimates and events.
static void tracker_io(hs_tracker *tr, hs_state_io *io) {
	hs_state_long(io, &tr->next_tick);
	hs_state_long(io, &tr->count);
	hs_state_int(io, &tr->head);
	check(io, tr->next_tick >= 0, "spring: the tracker's next tick is negative");
	check(io, tr->count >= 0 && tr->head == (int)((tr->count + HS_TRACKER_CAPACITY - 1) % HS_TRACKER_CAPACITY),
	      "spring: the tracker's ring head does not match its sample count");
	tracker_ring_io(tr, io);
	hs_state_vec3(io, &tr->velocity);
	hs_state_vec3(io, &tr->acceleration);
	hs_state_vec3(io, &tr->heading);
	check(io, hs_vec3_is_finite(tr->velocity) && hs_vec3_is_finite(tr->acceleration) && hs_vec3_is_finite(tr->heading),
	      "spring: a tracker estimate is not finite");
	hs_state_bool(io, &tr->at_rest);
	int event = (int)tr->last_event;
	if (state_ranged(io, &event, HS_TRACKER_EVENT_NONE, HS_TRACKER_EVENT_MOTION_END,
	                 "spring: the tracker's last event is not an hs_tracker_event"))
		tr->last_event = (hs_tracker_event)event;
	hs_state_f64(io, &tr->last_event_time);
	hs_state_long(io, &tr->motion_starts);
	hs_state_long(io, &tr->motion_ends);
	check(io, isfinite(tr->last_event_time) && tr->motion_starts >= 0 && tr->motion_ends >= 0,
	      "spring: the tracker's event time or counts are out of range");
}

// The stylus: its poses at the end and the start of the coming frame, button, velocity.
static void stylus_io(hs_spring_system *sys, hs_state_io *io) {
	hs_state_bool(io, &sys->has_stylus);
	hs_state_vec3(io, &sys->stylus);
	hs_state_vec3(io, &sys->stylus_prev);
	hs_state_quat(io, &sys->rot);
	hs_state_quat(io, &sys->rot_prev);
	hs_state_bool(io, &sys->button);
	hs_state_bool(io, &sys->button_prev);
	hs_state_vec3(io, &sys->stylus_velocity);
	check(io, hs_vec3_is_finite(sys->stylus) && hs_vec3_is_finite(sys->stylus_prev) &&
	              hs_vec3_is_finite(sys->stylus_velocity),
	      "spring: a stylus position or velocity is not finite");
	check(io, unit_quat(sys->rot) && unit_quat(sys->rot_prev), "spring: a stylus orientation is not a unit quaternion");
}

// The spring: its object, how it got it, its direction, the candidate and the last release.
static void spring_io(hs_spring_system *sys, hs_state_io *io) {
	int n = sys->capacity;
	hs_state_int(io, &sys->attached);
	check(io, sys->attached >= -1 && sys->attached < n, "spring: the attached object index is out of range");
	int kind = (int)sys->attach_kind;
	if (state_ranged(io, &kind, HS_ATTACH_NONE, HS_ATTACH_API, "spring: the attach kind is not an hs_attach_kind"))
		sys->attach_kind = (hs_attach_kind)kind;
	check(io, (sys->attached < 0) == (sys->attach_kind == HS_ATTACH_NONE),
	      "spring: the attach kind does not match the attached object");
	hs_state_vec3(io, &sys->axis);
	check(io, unit_vec3(sys->axis), "spring: the spring's axis is not a unit vector");
	hs_state_int(io, &sys->candidate);
	check(io, sys->candidate >= -1 && sys->candidate < n, "spring: the candidate index is out of range");
	hs_release *r = &sys->release;
	int rkind = (int)r->kind;
	if (state_ranged(io, &rkind, HS_RELEASE_NONE, HS_RELEASE_THROW, "spring: the release kind is not an hs_release_kind"))
		r->kind = (hs_release_kind)rkind;
	int object = (int)r->object.index1;
	if (state_ranged(io, &object, 0, n, "spring: the released object is out of range"))
		r->object.index1 = (uint32_t)object;
	check(io, (r->kind == HS_RELEASE_NONE) == (r->object.index1 == 0),
	      "spring: the release kind does not match its object");
	hs_state_f64(io, &r->time);
	hs_state_vec3(io, &r->velocity);
	hs_state_f64(io, &r->hand_speed);
	check(io, isfinite(r->time) && hs_vec3_is_finite(r->velocity) && isfinite(r->hand_speed) && r->hand_speed >= 0.0,
	      "spring: the last release's numbers are out of range");
}

void hs_spring_state_io(hs_spring_system *sys, hs_state_io *io) {
	for (int i = 0; i < sys->capacity; ++i) { // every slot: the size depends on the definitions only
		hs_state_u8(io, &sys->on_floor[i]);
		hs_state_u8(io, &sys->sliding[i]);
		hs_state_u8(io, &sys->separated[i]);
		check(io, sys->on_floor[i] <= 1 && sys->sliding[i] <= 1 && sys->separated[i] <= 1,
		      "spring: an object's floor flags are not 0 or 1");
	}
	stylus_io(sys, io);
	spring_io(sys, io);
	tracker_io(&sys->tracker, io);
	if (io->mode == HS_STATE_LOAD)
		sys->geom_count = 0; // the geometry cache is rebuilt from the loaded bodies at the next step
}
