// spring_technique_state.h — what the manipulation techniques keep (spring_technique.h): part of
// the spring system (spring_system.h) and of the world's state (spring_state.c).
#ifndef HS_SPRING_TECHNIQUE_STATE_H
#define HS_SPRING_TECHNIQUE_STATE_H

#include "handspring.h"
#include "hs_math.h"

// What the techniques keep. STATE (spring_state.c walks it while def.techniques is on): the
// settings, the hold's grab and home, the magnet's memory; `filter` is a cache of the frame.
typedef struct hs_spring_technique {
	hs_technique_def set;  // in force: the next grab's technique, the release, the magnet
	int hold;              // hs_technique of the attached object (HS_TECHNIQUE_SPRING when none)
	hs_vec3 grab_stylus;   // the stylus at the grab
	hs_quat grab_rot;
	hs_vec3 grab_pos;      // the object's G and orientation at the grab
	hs_quat grab_obj_rot;
	hs_vec3 plane_offset;  // cross-plane: G − the ray's point on the plane at the grab
	hs_vec3 home_pos;      // where the release in HS_RELEASE_MODE_RETURN sends it
	hs_quat home_rot;
	int magnet_object;     // the candidate last seen with the arm extended, -1 when none
	double magnet_seen;    // s: when
	bool filter;           // CACHE: some object is left out of object–object contacts this frame
} hs_spring_technique;

// The settings' defaults and the state of a new system.
void hs_spring_technique_init(hs_spring_technique *t);

#endif
