// grasp.c — a grasp under real input (1999 paper §3.2 (2), Fig. 2, Fig. 12; docs/model.md §3).
//
// [H] holds an object while two contacts' normals are >= the threshold apart and lets it go the
// first frame they are not. Under glove noise (±2° a sensor) a fingertip that rests on a face
// leaves it and comes back, and the grasp ends at random. Here the end has hysteresis:
//  - the grasp continues while the fingertips of the fingers that touched the object when it began
//    have not spread more than grasp_open_mm wider than they were then, and the holder's contacts
//    with the object grown by grasp_release_mm still grasp;
//  - once it has ended, the releasing hand's contacts do not act on the object (no push, no new
//    grasp) until that hand no longer touches it or those fingertips close again by more than
//    grasp_open_mm from their widest spread since: no 2 <-> 3 flicker and no drag while opening.
#include "contact.h"
#include "grasp.h"

void hs_grasp_follow_wrist(hs_body *body, const hs_hand *hand) {
	body->pos = hs_add(hand->wrist_pos, hs_quat_rotate(hand->wrist_rot, body->grip_pos));
	body->rot = hs_quat_normalize(hs_quat_mul(hand->wrist_rot, body->grip_rot));
}

hs_vec3 hs_part_displacement(const hs_hand *hand, const hs_contact *c) {
	if (c->part < HS_HAND_POINTS)
		return hs_sub(hand->points[c->part], hand->prev_points[c->part]);
	int j = c->part - HS_HAND_POINTS;
	hs_vec3 d0 = hs_sub(hand->lines[j][0], hand->prev_lines[j][0]);
	hs_vec3 d1 = hs_sub(hand->lines[j][1], hand->prev_lines[j][1]);
	return hs_scale(hs_add(d0, d1), 0.5);
}

// The finger of a check point (i / 4) or check line (j / 12), §3.1.
static int finger_of(int part) { return part < HS_HAND_POINTS ? part / 4 : (part - HS_HAND_POINTS) / 12; }

// The spread of the fingertips (check point 4f + 3) of the fingers in `fingers`: their mean
// distance from their centroid (m; 0 for fewer than two). It grows as a hand opens, whatever its
// joints do (the grasp posture straightens the thumb's MCP as it closes), and no rigid motion of
// the hand changes it.
static double tip_spread(const hs_hand *hand, unsigned fingers) {
	hs_vec3 tips[5], c = hs_v3(0, 0, 0);
	int m = 0;
	for (int f = 0; f < 5; ++f)
		if (fingers >> f & 1u) {
			tips[m] = hand->points[4 * f + 3];
			c = hs_add(c, tips[m++]);
		}
	if (m < 2)
		return 0.0;
	c = hs_scale(c, 1.0 / m);
	double sum = 0.0;
	for (int k = 0; k < m; ++k)
		sum += hs_length(hs_sub(tips[k], c));
	return sum / m;
}

void hs_grasp_begin(hs_world *world, hs_body *body, int h, const hs_contact *cs, int n) {
	const hs_hand *hand = &world->hands[h];
	body->grasped_by = h + 1;
	body->grip_pos = hs_quat_inv_rotate(hand->wrist_rot, hs_sub(body->pos, hand->wrist_pos));
	body->grip_rot = hs_quat_normalize(hs_quat_mul(hs_quat_conj(hand->wrist_rot), body->rot));
	body->grip_fingers = 0;
	for (int k = 0; k < n; ++k)
		if (cs[k].hand.index1 == (uint32_t)h + 1)
			body->grip_fingers |= (uint8_t)(1u << finger_of(cs[k].part));
	body->grip_spread = tip_spread(hand, body->grip_fingers);
	body->released_by = 0;
}

// The grasp goes on (the object has followed the wrist): the holding fingertips have not spread
// more than grasp_open_mm wider than when it began, and the holder's contacts with the object grown by
// grasp_release_mm still grasp (§3.2 (2) with the margin; contacts found here are not kept).
static bool grasp_continues(hs_world *world, int i, const hs_body *before, int first) {
	hs_body *body = &world->bodies[i];
	const hs_hand *hand = &world->hands[body->grasped_by - 1];
	if (tip_spread(hand, body->grip_fingers) - body->grip_spread > world->def.grasp_open_mm * 1e-3)
		return false;
	int n = hs_contact_detect_grown(world, i, before, world->def.grasp_release_mm * 1e-3);
	bool holds = hs_contact_grasps(&world->contacts[first], n, (uint32_t)body->grasped_by, world->grasp_limit,
	                               world->def.grasp_any_contacts);
	world->contact_count = first;
	return holds;
}

// After a grasp ended, the releasing hand's contacts are set aside until it no longer touches the
// object or its holding fingertips close again by grasp_open_mm from the widest spread since the
// release (kept in grip_spread). Returns the count left.
static int set_aside_released(hs_world *world, hs_body *body, int first, int n) {
	if (!body->released_by)
		return n;
	uint32_t r = (uint32_t)body->released_by;
	const hs_hand *hand = &world->hands[r - 1];
	double spread = tip_spread(hand, body->grip_fingers);
	if (spread > body->grip_spread)
		body->grip_spread = spread;
	hs_contact *cs = &world->contacts[first];
	int kept = 0;
	for (int k = 0; k < n; ++k)
		if (cs[k].hand.index1 != r)
			cs[kept++] = cs[k];
	bool closes = body->grip_spread - spread > world->def.grasp_open_mm * 1e-3;
	if (kept == n || closes) { // untouched by that hand, or closing on it again: the rule lapses
		body->released_by = 0;
		return n;
	}
	world->contact_count = first + kept;
	return kept;
}

hs_contact_state hs_grasp_detect(hs_world *world, int i, int first, int *n, bool *continues) {
	hs_body *body = &world->bodies[i];
	*continues = false;
	if (body->grasped_by > 0 && !body->released_by) {
		hs_body before = *body;
		hs_grasp_follow_wrist(body, &world->hands[body->grasped_by - 1]);
		if (grasp_continues(world, i, &before, first)) {
			*continues = true;
			*n = hs_contact_detect(world, i, &before);
			return HS_CONTACT_GRASP;
		}
		body->pos = before.pos; // the holder let go: the release rule starts
		body->rot = before.rot;
		body->released_by = body->grasped_by;
	}
	*n = hs_contact_detect(world, i, NULL);
	*n = set_aside_released(world, body, first, *n);
	return hs_contact_classify(&world->contacts[first], *n, world->grasp_limit, world->def.grasp_any_contacts);
}
