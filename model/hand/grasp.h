// grasp.h — when a grasp begins, continues and ends under real input (1999 paper §3.2 (2);
// docs/model.md §3 "Grasp continuation and release").
#ifndef HS_GRASP_H
#define HS_GRASP_H

#include <stdbool.h>

#include "contact.h"

// Where the wrist's present pose carries a held object's G (the grip pose fixed when the grasp began).
hs_vec3 hs_grasp_held_pos(const hs_body *body, const hs_hand *hand);
// §3.2 (2): a held object follows its wrist rigidly, at the pose fixed when the grasp began.
void hs_grasp_follow_wrist(hs_body *body, const hs_hand *hand);
// A held object the floor pushed back up (hs_motion_keep_above_floor) keeps that pose in the grip:
// it slid in the fingers rather than sinking, so it is not carried lower once lifted.
void hs_grasp_slip(hs_body *body, const hs_hand *hand);
// The grasp of `hand`, hand index `h`, begins: fixes the object's pose in the wrist frame, the
// glove's reading and the fingers touching it (cs[0..n)), and ends any release rule (docs/model.md §3).
void hs_grasp_begin(hs_body *body, const hs_hand *hand, int h, const hs_contact *cs, int n);
// A hand's fingertip pairs' peaks set to their distances now (its first pose, a return from a loss).
void hs_grasp_reset_pairs(hs_hand *hand);
// Every grasp of `hand`, hand index h, ends where it is, with no velocity, and the hand's fingers
// are set aside from those objects as after an opening (a hand the tracker lost, tracking.c). Reads
// the model's object count; writes the bodies it let go, wakes them and marks their digests stale
// (cache).
void hs_grasp_let_go_in_place(const hs_world_model *model, hs_body *bodies, hs_world_cache *cache, const hs_hand *hand,
                               int h);
// True when contacts cs[0..n) may begin a grasp (docs/model.md §3 "Grasp start"); `taking_over`:
// the hand that held the object let it go this frame (no closing needed).
bool hs_grasp_starts(const hs_world_model *model, const hs_hand *hands, const hs_contact *cs, int n, bool taking_over);
// Fig. 2 for object i (`body`, cp->bodies[i]): its contacts (appended from cp->out->contacts[first],
// *n of them) and state. A held object whose grasp continues has moved with its wrist and
// *continues is set; else it is classified where it was, without the contacts the release rule
// sets aside. Writes the body (its grip, its release rule, a pose it followed the wrist to), the
// hands' pair references when one lets go, and the digests (cache) of what changed unseen.
hs_contact_state hs_grasp_detect(const hs_contact_pass *cp, hs_world_cache *cache, hs_body *body, int i, int first, int *n,
                                 bool *continues);

#endif
