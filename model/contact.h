// contact.h — hand-object contacts (1999 paper §3.2: (A) check points in faces, (B) check lines
// across edges) and their classification (Fig. 2).
#ifndef HS_CONTACT_H
#define HS_CONTACT_H

#include <stdbool.h>
#include <stdint.h>

#include "world_internal.h"

// True when the hand's path through the frame may reach the body's bounding sphere grown by
// `grow`, or work is not skipped: the bounding-volume test before a hand's narrow tests (Fig. 2).
static inline bool hs_contact_hand_near(const hs_world *world, const hs_body *body, const hs_hand *hand, double grow) {
	double reach = world->shapes[body->shape].radius + grow + hand->sweep_radius;
	return !world->def.skip_work || hs_length_sq(hs_sub(body->pos, hand->sweep_center)) <= reach * reach;
}

// Where an object's G is and how it is turned.
typedef struct hs_pose {
	hs_vec3 pos;
	hs_quat rot;
} hs_pose;

// Appends the contacts of every hand with the object to world->contacts; returns how many.
// `before` is the object's pose one frame ago when it has moved since (NULL: it has not).
int hs_contact_detect(hs_world *world, int object, const hs_pose *before);
// The same against the object's parts grown by `grow` (m): a finger part within `grow` of the
// surface touches it (the grasp's release margin, docs/model.md §3). Contact points are
// projected on the faces themselves.
int hs_contact_detect_grown(hs_world *world, int object, const hs_pose *before, double grow);
// §3.2 rectification of a check point: p moved to the nearest face of the convex part of the
// first object (in index order) it lies in, or p itself (hs_world_hand_rectified_points).
hs_vec3 hs_contact_rectify(const hs_world *world, hs_vec3 p);
// The largest n_i · n_j of a grasp: cos(threshold) plus a tolerance (DESIGN.md), once per world.
double hs_grasp_limit(double grasp_threshold_deg);
// Fig. 2: the contact state of a set of contacts (grasp when two normals are >= threshold apart,
// on different fingers or hands unless `any_contacts`, the paper's rule).
hs_contact_state hs_contact_classify(const hs_contact *contacts, int count, double grasp_limit, bool any_contacts);
// True when two of the contacts (only those of hand index + 1 `hand1`, or all when 0) grasp: their
// normals are >= the threshold apart and, unless `any_contacts`, they lie on different fingers or
// hands.
bool hs_contact_grasps(const hs_contact *contacts, int count, uint32_t hand1, double grasp_limit, bool any_contacts);

#endif
