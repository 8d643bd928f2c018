// contact_rules.h — the contact rules of the 1999 paper §3.1-3.2 (contact_rules.c): a contact's C, B
// and normal (eq. 1-2, Fig. 3-4), a check line across an edge ((B)), [H]'s letter for a check point
// ((A)), and which contacts count (docs/model.md §3). Private to contact_*.c.
#ifndef HS_CONTACT_RULES_H
#define HS_CONTACT_RULES_H

#include "contact_part.h"
#include "contact_pass.h"

// The finger of a contact's part: check point i is on finger i / 4, check line j on j / 12 (§3.1).
static inline int hs_contact_finger_of(int part) {
	return part < HS_HAND_POINTS ? part / 4 : (part - HS_HAND_POINTS) / 12;
}

// A contact found in the body frame `f`: C = `point` on the surface, B = `finger` where the part
// drives it (eq. 1-2), `normal` the face normal or the edge's pseudo-normal; `t` when in the frame.
void hs_contact_push(const hs_contact_pass *cp, int object, int hand, int part, bool edge, int feature, const hs_frame *f,
                     hs_vec3 point, hs_vec3 normal, hs_vec3 finger, double t);
// The pseudo-normal of edge e (Fig. 4): the unit vector from G to the edge line's nearest point.
hs_vec3 hs_contact_edge_normal(const hs_shape *shape, int e);
// §3.2 (B): check line j across the part now, entering and leaving through faces c.face_in and
// c.face_out; `d` NULL when it reached the object this frame, else its motion since it touched.
void hs_contact_line_across(const hs_contact_pass *cp, int object, int h, int j, const hs_part *part, const hs_frame *body,
                            hs_vec3 p0, hs_vec3 p1, hs_clip c, const hs_vec3 *d);
// §3.2 (A) to the letter (paper_contacts): check point i, from a to b (body frame), inside the part.
void hs_contact_paper_point(const hs_contact_pass *cp, int object, int h, int i, const hs_part *part, const hs_frame *body,
                            hs_vec3 a, hs_vec3 b, double grow);
// A part inside the object now and a frame ago, that touched nothing then, lay outside it before
// the object's last move: the object came onto the finger (pushed by another, or falling). It
// touches, drawn back to the surface like a finger that sank in. Else the part started inside
// (a hand placed inside an object): it touches nothing until it has come out.
static inline bool hs_contact_came_onto(const hs_contact_pass *cp, int object, const hs_part *part, hs_vec3 prev_point, double grow) {
	if (cp->frame == 0)
		return false; // nothing has moved yet (an object's pose a frame ago is its initial parabola's)
	const hs_body *body = &cp->bodies[object];
	hs_frame last = frame_before_last_step(body);
	return !inside_part(cp->model, &cp->model->shapes[body->shape], part, to_body(&last, prev_point), grow);
}

static inline bool hs_contact_line_came_onto(const hs_contact_pass *cp, int object, const hs_part *part, const hs_vec3 prev[2],
                                             double grow) {
	if (cp->frame == 0)
		return false;
	const hs_body *body = &cp->bodies[object];
	hs_frame last = frame_before_last_step(body);
	return !clip_part(cp->model, &cp->model->shapes[body->shape], part, to_body(&last, prev[0]), to_body(&last, prev[1]), grow).hit;
}

// The contacts from `first` on, less the parts that trail another of their finger, then less the
// hovering check points no other part of their hand backs; each returns how many are left.
int hs_contact_drop_trailing(const hs_contact_pass *cp, int first);
int hs_contact_keep_hovering(const hs_contact_pass *cp, int first, int n);

#endif
