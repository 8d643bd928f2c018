// contact_grasp.c — the grasp test of the 1999 paper §3.2 (2) and Fig. 4 (two contact normals at
// least the threshold apart), the contact state of Fig. 2, and the rectification of a check point
// that penetrated an object (§3.2; docs/model.md §3).
#include "contact.h"
#include "contact_rules.h"

// Grasp when n_i · n_j <= cos(threshold) + eps: with a bare comparison rounding would decide the
// 90 deg case (two adjoining cube faces) and two builds could disagree (docs/model.md §3).
#define HS_GRASP_EPS 1e-9

hs_vec3 hs_contact_rectify(const hs_world_model *model, const hs_body *bodies, hs_vec3 p) {
	for (int i = 0; i < model->object_count; ++i) {
		const hs_body *body = &bodies[i];
		const hs_shape *shape = &model->shapes[body->shape];
		if (hs_length_sq(hs_sub(p, body->pos)) > shape->radius * shape->radius)
			continue;
		hs_frame f = frame_of(body);
		hs_vec3 b = to_body(&f, p);
		for (int k = 0; k < shape->part_count; ++k) {
			const hs_part *part = &shape->parts[k];
			if (!inside_part(model, shape, part, b, 0.0))
				continue;
			const hs_face *face = &shape->faces[nearest_face(model, shape, part, b)];
			return to_world(&f, hs_mul_add(b, face->offset - hs_dot(face->normal, b), face->normal));
		}
	}
	return p;
}

double hs_grasp_limit(double grasp_threshold_deg) {
	return hs_cos(grasp_threshold_deg * (HS_PI / 180.0)) + HS_GRASP_EPS;
}

hs_contact_state hs_contact_classify(const hs_contact *contacts, int count, double grasp_limit, bool any_contacts) {
	if (count == 0)
		return HS_CONTACT_NONE;
	if (count == 1)
		return HS_CONTACT_PUSH_ONE;
	return hs_contact_grasps(contacts, count, 0, grasp_limit, any_contacts) ? HS_CONTACT_GRASP : HS_CONTACT_PUSH_MANY;
}


// Two contacts may make a grasp when they lie on different hands or different fingers
// (docs/model.md §3 "Two fingers make a grasp": two points of one finger sunk into an object are
// not a grasp), or with the paper's "any two contacts" rule (§3.2 (2)).
static bool may_grasp(const hs_contact *a, const hs_contact *b, bool any_contacts) {
	return any_contacts || a->hand.index1 != b->hand.index1 || hs_contact_finger_of(a->part) != hs_contact_finger_of(b->part);
}

bool hs_contact_grasps(const hs_contact *contacts, int count, uint32_t hand1, double grasp_limit, bool any_contacts) {
	for (int i = 0; i < count; ++i) {
		if (hand1 && contacts[i].hand.index1 != hand1)
			continue;
		for (int j = i + 1; j < count; ++j)
			if ((!hand1 || contacts[j].hand.index1 == hand1) && may_grasp(&contacts[i], &contacts[j], any_contacts) &&
			    hs_dot(contacts[i].normal, contacts[j].normal) <= grasp_limit)
				return true; // two normals at >= the threshold (§3.2 (2))
	}
	return false;
}
