// grasp.h — when a grasp begins, continues and ends under real input (1999 paper §3.2 (2);
// docs/model.md §3 "Grasp continuation and release").
#ifndef HS_GRASP_H
#define HS_GRASP_H

#include <stdbool.h>

#include "world_internal.h"

// Where the wrist's present pose carries a held object's G (the grip pose fixed when the grasp began).
hs_vec3 hs_grasp_held_pos(const hs_body *body, const hs_hand *hand);
// §3.2 (2): a held object follows its wrist rigidly, at the pose fixed when the grasp began.
void hs_grasp_follow_wrist(hs_body *body, const hs_hand *hand);
// A held object the floor pushed back up (hs_motion_keep_above_floor) keeps that pose in the grip:
// it slid in the fingers rather than sinking, so it is not carried lower once lifted.
void hs_grasp_slip(hs_body *body, const hs_hand *hand);
// The grasp of hand index `h` begins: fixes the object's pose in the wrist frame, the glove's
// reading and the fingers touching it (cs[0..n)), and ends any release rule (docs/model.md §3).
void hs_grasp_begin(hs_world *world, hs_body *body, int h, const hs_contact *cs, int n);
// A hand's fingertip pairs' peaks set to their distances now (its first pose, a return from a loss).
void hs_grasp_reset_pairs(hs_hand *hand);
// Every grasp of hand index h ends where it is, with no velocity, and the hand's fingers are set
// aside from those objects as after an opening (a hand the tracker lost, tracking.c).
void hs_grasp_let_go_in_place(hs_world *world, int h);
// True when contacts cs[0..n) may begin a grasp (docs/model.md §3 "Grasp start"); `taking_over`:
// the hand that held the object let it go this frame (no closing needed).
bool hs_grasp_starts(const hs_world_model *model, const hs_hand *hands, const hs_contact *cs, int n, bool taking_over);
// Fig. 2 for object i: its contacts (appended from world->out.contacts[first], *n of them) and state.
// A held object whose grasp continues has moved with its wrist and *continues is set; else it is
// classified where it was, without the contacts the release rule sets aside.
hs_contact_state hs_grasp_detect(hs_world *world, int i, int first, int *n, bool *continues);

#endif
