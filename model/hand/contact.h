// contact.h — hand-object contacts (1999 paper §3.2: (A) check points in faces, (B) check lines
// across edges) and their classification (Fig. 2).
#ifndef HS_CONTACT_H
#define HS_CONTACT_H

#include <stdbool.h>
#include <stdint.h>

#include "contact_pass.h"
#include "world_internal.h"

// True when the hand's path through the frame may reach the body's bounding sphere grown by
// `grow`, or work is not skipped: the bounding-volume test before a hand's narrow tests (Fig. 2).
// How far beyond a part a finger part can still count (contact.c): a check point that touched stays
// touching within the release margin, a check point or line that started inside stays so within
// twice it; the bounding-volume tests reach that much further while the hand has such parts.
static inline double hs_contact_keep(const hs_world_model *model, const hs_hand *hand) {
	if (model->def.paper_contacts)
		return 0.0;
	bool embedded = hand->state.embed_points || hand->state.embed_lines;
	return 1e-3 * model->def.grasp_release_mm * (embedded ? 2.0 : hand->state.touch_points ? 1.0 : 0.0);
}

// True when the hand's path through the frame may reach a part or body of bounding sphere (c, r)
// and growth factor k (part_reach.h) grown by `grow`, or one of the hand's parts that still count
// beyond it (hs_contact_keep) lies within reach of it now.
static inline bool hs_contact_sphere_near(const hs_world_model *model, const hs_hand *hand, hs_vec3 c, double r, double k,
                                          double grow) {
	double d_sq = hs_length_sq(hs_sub(c, hand->cache.sweep_center)), reach = r + k * grow + hand->cache.sweep_radius;
	if (d_sq <= reach * reach)
		return true;
	double keep = k * hs_contact_keep(model, hand);
	if (!(keep > 0.0) || d_sq > (reach + keep) * (reach + keep))
		return false;
	if (hand->state.embed_lines) // (seldom: not looked at more closely)
		return true;
	double r_keep = (r + k * grow + keep) * (r + k * grow + keep);
	for (uint32_t kept = hand->state.touch_points | hand->state.embed_points; kept; kept &= kept - 1u)
		if (hs_length_sq(hs_sub(hand->cache.points[hs_lowest_bit(kept)], c)) <= r_keep)
			return true;
	return false;
}

static inline bool hs_contact_hand_near(const hs_world_model *model, const hs_body *body, const hs_hand *hand, double grow) {
	if (hand->state.lost_frames > model->hold_frames) // lost past the hold: it touches nothing (tracking.c)
		return false;
	return !model->skip_work || hs_contact_sphere_near(model, hand, body->pos, model->shapes[body->shape].radius,
	                                                 model->shape_grow_reach[body->shape], grow);
}

// Where an object's G is and how it is turned.
typedef struct hs_pose {
	hs_vec3 pos;
	hs_quat rot;
} hs_pose;

// Appends the contacts of every hand with the object to cp->out->contacts; returns how many.
// `before` is the object's pose one frame ago when it has moved since (NULL: it has not).
int hs_contact_detect(const hs_contact_pass *cp, int object, const hs_pose *before);
// The same against the object's parts grown by `grow` (m): a finger part within `grow` of the
// surface touches it (the grasp's release margin, docs/model.md §3). Contact points are
// projected on the faces themselves.
int hs_contact_detect_grown(const hs_contact_pass *cp, int object, const hs_pose *before, double grow);
// True when hs_contact_detect_grown(cp, object, NULL, grow) would give hand index h a contact
// (grow > 0): found without making the contacts, at the first one.
bool hs_contact_hand_within(const hs_contact_pass *cp, int object, int h, double grow);
// §3.2 rectification of a check point: p moved to the nearest face of the convex part of the
// first object (in index order) it lies in, or p itself (hs_world_hand_rectified_points). Reads
// the model and the bodies alone.
hs_vec3 hs_contact_rectify(const hs_world_model *model, const hs_body *bodies, hs_vec3 p);
// The largest n_i · n_j of a grasp: cos(threshold) plus a tolerance (docs/model.md §3), once per world.
double hs_grasp_limit(double grasp_threshold_deg);
// Fig. 2: the contact state of a set of contacts (grasp when two normals are >= threshold apart,
// on different fingers or hands unless `any_contacts`, the paper's rule).
hs_contact_state hs_contact_classify(const hs_contact *contacts, int count, double grasp_limit, bool any_contacts);
// True when two of the contacts (only those of hand index + 1 `hand1`, or all when 0) grasp: their
// normals are >= the threshold apart and, unless `any_contacts`, they lie on different fingers or
// hands.
bool hs_contact_grasps(const hs_contact *contacts, int count, uint32_t hand1, double grasp_limit, bool any_contacts);

#endif
