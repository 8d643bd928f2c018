// body.h — one object of a world (1999 paper §4.1; the spring model's integrated velocity).
#ifndef HS_BODY_H
#define HS_BODY_H

#include <stdint.h>

#include "handspring.h"

// Model part (set by hs_world_add_object, read-only while stepping; not in the saved state):
// `shape`, `mass`. Every other field is STATE: state.c's field table (body_fields) lists them all,
// one entry each, and a field added here must be added there (save, load, check and hash all
// follow that one table).
typedef struct hs_body {
	hs_vec3 pos;  // P(t): centre of gravity, m
	hs_vec3 prev; // P(t - dt), m (§4.1: Verlet needs it)
	hs_quat rot;  // orientation, body → world
	hs_quat spin; // relative rotation per frame, carried over after release (§4.1)
	int shape;    // MODEL: index into the world's model.shapes
	int floor_contacts;
	uint8_t contact;  // hs_contact_state
	uint8_t grounded; // touched the floor at the end of the last frame: §4.2 tipping, not free flight
	uint8_t asleep;   // stable and at rest: skipped until something touches it
	uint8_t held;     // moved by a hand this frame: free motion does not run
	double mass;      // MODEL: kg, density × volume (spring model)
	double restitution; // MODEL: e of the spring model's object collisions, < 0: the model's (hs_object_def)
	hs_vec3 vel;      // m/s: the spring model integrates velocity explicitly
	hs_quat rot_prev; // orientation at t - dt: a released object keeps rot * rot_prev⁻¹ (§4.1)
	int grasped_by;   // hand index + 1 holding it (0: none)
	hs_vec3 grip_pos; // pose in the grasping wrist frame, fixed when the grasp began (§3.2 (2))
	hs_quat grip_rot;
	double grip_spread;   // m: the holding fingertips' spread when the grasp began; after it ended, the whole hand's most open since (grasp.c)
	double grip_reach;    // m: the holding fingertips' mean reach from their bases when the grasp began (grasp.c)
	uint8_t grip_fingers; // bit f: finger f touched the object when the grasp began
	int released_by;      // hand index + 1 whose grasp ended on opening: its parts moving away do not act
	uint8_t carried;  // moved along with a hand-moved object this frame (§4.3)
} hs_body;

#endif
