// spring_technique.h — the workbench paper's manipulation techniques beyond the spring (§2.2, §3):
// slave, stick, cross-plane, cross-surface, the magnet gesture, the release back home, and
// massless objects (§1, §4.2 "a massless world"); docs/techniques.md.
#ifndef HS_SPRING_TECHNIQUE_H
#define HS_SPRING_TECHNIQUE_H

#include "spring_technique_state.h"

typedef struct hs_spring_system hs_spring_system;

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
