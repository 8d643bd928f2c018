// tracking.c — hands the tracker loses and finds again (docs/model.md §3 "Tracking loss").
//
// An optical tracker loses a hand for a few frames (occlusion, the hand leaving the view) and
// finds it again, often elsewhere. The 1999 paper's glove never drops out, so it has no rule for
// this. Here a lost hand is held where it was last seen (the caller sets that pose); it keeps what
// it holds for tracking_hold_s (a blink of the tracker is no reason to drop a carried object), then
// lets it go in place, with no velocity (a throw needs a hand the tracker saw moving), and touches
// nothing (hs_contact_hand_near) until it is seen again. The first frame it is seen again it is
// placed anew, as at its first pose: its path through the gap is unknown, so the jump sweeps no
// object and gives no release velocity; a grasp it still kept is let go in place when it came back
// further from where it was lost than a hand carrying something moves in that time
// (HS_TRACKING_JUMP plus HS_TRACKING_SPEED times the time since it was last seen): else the object
// would jump with it. At 12 frames/s a carry at 0.35 m/s moves 6 cm over one lost frame.
#include <limits.h>

#include "grasp.h"
#include "hand_internal.h"
#include "tracking.h"

#define HS_TRACKING_JUMP 0.05 // m
#define HS_TRACKING_SPEED 0.5 // m/s

bool hs_tracking_update(hs_hand *hand, int hold_frames, double dt) {
	if (hand->state.untracked) {
		if (hand->state.lost_frames < INT_MAX)
			hand->state.lost_frames++;
		return hand->state.lost_frames == hold_frames + 1;
	}
	if (hand->state.lost_frames == 0)
		return false;
	bool kept = hand->state.lost_frames <= hold_frames;
	double reach = HS_TRACKING_JUMP + HS_TRACKING_SPEED * (hand->state.lost_frames + 1) * dt;
	bool let_go = kept && hs_length(hs_sub(hand->state.wrist_pos, hand->state.prev_wrist_pos)) > reach;
	hs_hand_keep_previous(hand);
	hand->state.older_count = 0;
	hs_grasp_reset_pairs(hand);
	hand->state.lost_frames = 0;
	return let_go;
}
