// spring_grab.h — selection ('I want this one', §3), picking, catching and the release (drop or
// throw, §4.4): how the spring gets and loses its object.
#ifndef HS_SPRING_GRAB_H
#define HS_SPRING_GRAB_H

#include "spring_system.h"
#include "world_internal.h"

// The selection candidate after the frame's tracker samples.
void hs_spring_update_candidate(const hs_world *world, hs_spring_system *sys);
// A button press: attaches the spring to the picked, caught or selected object (if any).
void hs_spring_press(hs_world *world, hs_spring_system *sys);
// Attaches the spring to object i.
void hs_spring_attach(hs_world *world, hs_spring_system *sys, int i, hs_attach_kind kind);
// The button held down with nothing on the spring (§4.4 "block its motion path and press"): a
// flying object that arrives within catch_radius of the stylus is caught.
void hs_spring_hold(hs_world *world, hs_spring_system *sys);
// Detaches the attached object at `time` (s): with `classify`, a throw when the hand moves.
void hs_spring_detach(hs_world *world, hs_spring_system *sys, bool classify, double time);

#endif
