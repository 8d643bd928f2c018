// spring_technique.h — the workbench paper's manipulation techniques beyond the spring (§2.2, §3):
// slave, stick, cross-plane, cross-surface, the magnet gesture, the release back home, and
// massless objects (§1, §4.2 "a massless world"); docs/techniques.md.
#ifndef HS_SPRING_TECHNIQUE_H
#define HS_SPRING_TECHNIQUE_H

#include "handspring.h"
#include "hs_math.h"

typedef struct hs_spring_system hs_spring_system;

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
// True when density 0 (a massless object) may be added to the world.
bool hs_spring_massless_allowed(const hs_world *world);
// True when object i moves kinematically (massless, or held by a technique without spring).
bool hs_spring_technique_moves(const hs_world *world, const hs_spring_system *sys, int i);
// Object i through t seconds ending at the frame's end, kinematically (hs_spring_technique_moves).
void hs_spring_technique_advance(hs_world *world, hs_spring_system *sys, int i, double t);
// The frame's start: which objects object–object contacts leave out (massless and kinematic holds).
void hs_spring_technique_prepare(const hs_world *world, hs_spring_system *sys);
// Leaves those objects out of a broad-phase answer about object i (near[0..count)); the new count.
int hs_spring_technique_filter(const hs_world *world, const hs_spring_system *sys, int i, int *near, int count);
// The grab of object i (after the spring attached it): the hold's technique and reference poses.
void hs_spring_technique_grab(hs_world *world, hs_spring_system *sys, int i, hs_attach_kind kind);
// The release of object i (after the spring let it go; `button`: a button release): massless
// objects stop, HS_RELEASE_MODE_RETURN sends it home.
void hs_spring_technique_release(hs_world *world, hs_spring_system *sys, int i, bool button);
// The magnet gesture at the frame's end (time t1, s), before the button acts.
void hs_spring_magnet(hs_world *world, hs_spring_system *sys, double t1);

#endif
