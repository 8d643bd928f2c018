// spring_state.c — the spring system's part of the world's state walk (state_walk.h): every field of
// the spring system and its tracker that a later step reads, one 64-bit word each.
//
// Left out, on purpose: the definition and what derives from it (def, the tracker's period, window
// and speeds; each object's mass, x0, k, c come from hs_body and def), what lives in hs_body (the
// world's walk visits it: position, velocity, ...), the frame-start scratch (the world's scratch.spring, written
// before each read), and the geometry cache, which a load empties so the next step rebuilds it from
// the loaded orientations. A load's CHECK pass refuses what would make a later step read out of
// bounds or compute with garbage: indices and enums out of range, flags not 0 or 1, non-finite
// numbers, stylus orientations that are not unit quaternions.
#include <limits.h>
#include <string.h>

#include "spring_state.h"
#include "spring_world.h"
#include "state_fields.h"
#include "state_walk.h"
#include "world_internal.h"
#include "spring_system.h"

#define S hs_spring_system

// Each object's flags, object by object over every slot (the size depends on the definitions only).
static const hs_field object_fields[] = {
    {HS_ALL_AT(S, on_floor, U8), .hi = 1},
    {HS_ALL_AT(S, sliding, U8), .hi = 1},
    {HS_ALL_AT(S, separated, U8), .hi = 1},
};

// The tracker's ring buffer, sample by sample: all of it (unfilled slots are zero).
static const hs_field ring_fields[] = {
    {HS_EACH(S, tracker.ring, time, F64)},
    {HS_EACH(S, tracker.ring, position, VEC3)},
    {HS_EACH(S, tracker.ring, orientation, QUAT)},
    {HS_EACH(S, tracker.ring, button, BOOL)},
};

// A touch's forces the next frame's resting solve starts from (spring_solve.c).
static const hs_field warm_fields[] = {
    {HS_EACH_AT(S, warm, hs_spring_warm, a, INT), .lo = 0, .hi = -1, HS_HI_PLUS(S, capacity)},
    {HS_EACH_AT(S, warm, hs_spring_warm, b, INT), .lo = 0, .hi = -1, HS_HI_PLUS(S, capacity)},
    {HS_EACH_AT(S, warm, hs_spring_warm, normal, F64)},
    {HS_EACH_AT(S, warm, hs_spring_warm, friction, VEC3)},
};

// The spring system's state, in walk order (enums travel as int words within their range).
static const hs_field spring_fields[] = {
    {HS_GROUP("object flags", object_fields), HS_COUNT_AT(S, capacity)},
    // the stylus: its poses at the end and the start of the coming frame, button, velocity
    {HS_ONE(S, has_stylus, BOOL)},
    {HS_ONE(S, stylus, VEC3)},
    {HS_ONE(S, stylus_prev, VEC3)},
    {HS_ONE(S, rot, ROTATION)},
    {HS_ONE(S, rot_prev, ROTATION)},
    {HS_ONE(S, button, BOOL)},
    {HS_ONE(S, button_prev, BOOL)},
    {HS_ONE(S, stylus_velocity, VEC3)},
    // the spring: its object, how it got it, its direction, its anchor offset, the candidate and the last release
    {HS_ONE(S, attached, INT), .lo = -1, .hi = -1, HS_HI_PLUS(S, capacity)},
    {HS_ONE(S, attach_kind, INT), .lo = HS_ATTACH_NONE, .hi = HS_ATTACH_MAGNET},
    {HS_ONE(S, axis, VEC3)},
    {HS_ONE(S, anchor_offset, VEC3)},
    {HS_ONE(S, candidate, INT), .lo = -1, .hi = -1, HS_HI_PLUS(S, capacity)},
    {HS_ONE(S, release.kind, INT), .lo = HS_RELEASE_NONE, .hi = HS_RELEASE_RETURN},
    {HS_ONE(S, release.object.index1, U32), .lo = 0, .hi = 0, HS_HI_PLUS(S, capacity)}, // index + 1 (0: none)
    {HS_ONE(S, release.time, F64)},
    {HS_ONE(S, release.velocity, VEC3)},
    {HS_ONE(S, release.hand_speed, F64)},
    // the tracker daemon (§5.1): its clock, ring buffer, estimates and events
    {HS_ONE(S, tracker.next_tick, LONG), .lo = 0, .hi = LONG_MAX},
    {HS_ONE(S, tracker.count, LONG), .lo = 0, .hi = LONG_MAX},
    {HS_ONE(S, tracker.head, INT), .lo = 0, .hi = HS_TRACKER_CAPACITY - 1},
    {HS_GROUP("tracker.ring", ring_fields), .count = HS_TRACKER_CAPACITY},
    {HS_ONE(S, tracker.velocity, VEC3)},
    {HS_ONE(S, tracker.acceleration, VEC3)},
    {HS_ONE(S, tracker.heading, VEC3)},
    {HS_ONE(S, tracker.at_rest, BOOL)},
    {HS_ONE(S, tracker.last_event, INT), .lo = HS_TRACKER_EVENT_NONE, .hi = HS_TRACKER_EVENT_MOTION_END},
    {HS_ONE(S, tracker.last_event_time, F64)},
    {HS_ONE(S, tracker.motion_starts, LONG), .lo = 0, .hi = LONG_MAX},
    {HS_ONE(S, tracker.motion_ends, LONG), .lo = 0, .hi = LONG_MAX},
    // the techniques (spring_technique.c), only in worlds made with them (def.techniques): their
    // settings, the hold's grab and home, the magnet's memory
    {HS_ONE(S, tech.set.technique, INT), .lo = HS_TECHNIQUE_SPRING, .hi = HS_TECHNIQUE_CROSS_SURFACE, HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.set.release, INT), .lo = HS_RELEASE_MODE_HAND, .hi = HS_RELEASE_MODE_RETURN, HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.set.magnet, BOOL), HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.set.body, VEC3), HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.set.magnet_far, F64), HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.set.magnet_near, F64), HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.set.magnet_within, F64), HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.hold, INT), .lo = HS_TECHNIQUE_SPRING, .hi = HS_TECHNIQUE_CROSS_SURFACE, HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.grab_stylus, VEC3), HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.grab_rot, ROTATION), HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.grab_pos, VEC3), HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.grab_obj_rot, ROTATION), HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.plane_offset, VEC3), HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.home_pos, VEC3), HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.home_rot, ROTATION), HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.magnet_object, INT), .lo = -1, .hi = -1, HS_HI_PLUS(S, capacity), HS_WHEN(S, def.techniques)},
    {HS_ONE(S, tech.magnet_seen, F64), HS_WHEN(S, def.techniques)},
    // the touches' warm-start forces: every slot, so the size depends on the definitions only;
    // those beyond the count are zero (CHECK refuses others), and a hash leaves them out: a hash
    // every frame of a 1000-object box mixed 8000 slots for its touches (+8 % instructions a
    // frame), a default world's 512 for none
    {HS_GROUP("warm", warm_fields), HS_COUNTED(S, warm_count), HS_COUNT_AT(S, touch_capacity)},
};

#undef S

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
	if (d->techniques) // (mixed only when on: the checksum of a world without them is as it was)
		h = hs_state_mix(h, 0x54454348ull); // "TECH"
	for (size_t i = 0; i < sizeof numbers / sizeof numbers[0]; ++i)
		h = hs_state_mix_f64(h, numbers[i]);
	if (d->pen_tip_spring || d->paper_collisions) // the letter's rules: only when set (older checksums stay)
		h = hs_state_mix(h, 0x57424c4554u ^ ((d->pen_tip_spring ? 1u : 0u) | (d->paper_collisions ? 2u : 0u)));
	return h;
}

void hs_spring_state_io(hs_spring_system *sys, hs_state_io *io) {
	hs_state_def(io, def_checksum(&sys->def), "the spring definition differs");
	if (io->mode == HS_STATE_HASH) // every frame: the walk inlined over the constant table
		hs_fields_walk(io, spring_fields, HS_FIELDS_COUNT(spring_fields), sys, NULL);
	else
		hs_fields_io(io, spring_fields, HS_FIELDS_COUNT(spring_fields), sys, NULL);
	if (io->mode == HS_STATE_LOAD)
		sys->geom_count = 0; // the geometry cache is rebuilt from the loaded bodies at the next step
}
