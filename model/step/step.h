// step.h — the step pipelines, one per kind of world (hs_world_def.kind): each a short list of
// stages, called by hs_world_step (world_step.c) and by nothing below them.
#ifndef HS_STEP_H
#define HS_STEP_H

#include "world_internal.h"

// One frame of a hand world (the 1999 paper): step_hand.c.
void hs_step_hand(hs_world *world);
// One frame of a spring world (the Responsive Workbench paper): step_spring.c.
void hs_step_spring(hs_world *world);

#endif
