// grasp.c — a grasp under real input (1999 paper §3.2 (2), Fig. 2, Fig. 12; docs/model.md §3).
//
// [H] holds an object while two contacts' normals are >= the threshold apart and lets it go the
// first frame they are not. Under glove noise (±2° a sensor) a fingertip that rests on a face
// leaves it and comes back, and the grasp ends at random. Here the end has hysteresis:
//  - the grasp continues while the fingers that touched the object when it began have not opened
//    (their tips' spread or their reach) more than grasp_open_mm from then, and a part of the
//    holder is still within grasp_release_mm of the object;
//  - once it has ended, the releasing hand's contacts do not act on the object (no push, no new
//    grasp) until that hand is clear of it by grasp_release_mm, another finger touches it, or its
//    five fingers close again by grasp_open_mm: no 2 <-> 3 flicker, no drag while opening.
#include "broadphase.h"
#include "contact.h"
#if defined(HS_SELFCHECK)
#include <stdio.h>
#include <stdlib.h>
#endif
#include "grasp.h"
#include "inline.h"

hs_vec3 hs_grasp_held_pos(const hs_body *body, const hs_hand *hand) {
	return hs_add(hand->state.wrist_pos, hs_quat_rotate(hand->state.wrist_rot, body->grip_pos));
}

void hs_grasp_follow_wrist(hs_body *body, const hs_hand *hand) {
	body->pos = hs_grasp_held_pos(body, hand);
	body->rot = hs_quat_normalize(hs_quat_mul(hand->state.wrist_rot, body->grip_rot));
}

void hs_grasp_slip(hs_body *body, const hs_hand *hand) {
	body->grip_pos = hs_quat_inv_rotate(hand->state.wrist_rot, hs_sub(body->pos, hand->state.wrist_pos));
	body->grip_rot = hs_quat_normalize(hs_quat_mul(hs_quat_conj(hand->state.wrist_rot), body->rot));
}

// The finger of a check point (i / 4) or check line (j / 12), §3.1.
static int finger_of(int part) { return part < HS_HAND_POINTS ? part / 4 : (part - HS_HAND_POINTS) / 12; }

// How open the fingers in `fingers` are (m): the spread of their tips (check point 4f + 3; twice
// their mean distance from their centroid: for two tips, their distance apart; 0 for one) into *spread, and the mean reach of each
// tip from its finger's base (check point 4f) into *reach. A grasp posture opens by the spread
// (the thumb moves away from the fingers; its MCP even straightens as it closes), a hand laid flat
// by the reach (curled fingers extend). No rigid motion of the hand changes either.
static HS_FORCE_INLINE void hand_opening(const hs_hand *hand, unsigned fingers, double *spread, double *reach) {
	hs_vec3 tips[5], c = hs_v3(0, 0, 0);
	int m = 0;
	*spread = *reach = 0.0;
	for (int f = 0; f < 5; ++f)
		if (fingers >> f & 1u) {
			tips[m] = hand->cache.points[4 * f + 3];
			*reach += hs_length(hs_sub(tips[m], hand->cache.points[4 * f]));
			c = hs_add(c, tips[m++]);
		}
	if (m == 0)
		return;
	c = hs_scale(c, 1.0 / m);
	for (int k = 0; k < m; ++k)
		*spread += hs_length(hs_sub(tips[k], c));
	*spread *= 2.0 / m; // for two tips: their distance
	*reach /= m;
}

// The pair index of two different fingers a < b (HS_FINGER_PAIRS of them): 0-3 the thumb with
// the index to the little finger, 4-6 the index with the next three, 7-8 the middle, 9 ring-little.
static int finger_pair(int a, int b) {
	static const int first[4] = {0, 4, 7, 9};
	return first[a] + (b - a - 1);
}

void hs_grasp_reset_pairs(hs_hand *hand) {
	for (int a = 0; a < 4; ++a)
		for (int b = a + 1; b < 5; ++b)
			hand->state.pair_open[finger_pair(a, b)] = hs_length(hs_sub(hand->cache.points[4 * a + 3], hand->cache.points[4 * b + 3]));
}

// True when contacts a and b press toward each other across the object (docs/model.md §3 "Grasp
// start"): each one's push into the object (−normal) lies within the opposition cone of the line
// from it to the other, model->oppose_cos the cosine of that cone's half-angle.
static bool opposed(const hs_world_model *model, const hs_contact *a, const hs_contact *b) {
	hs_vec3 d = hs_sub(b->point, a->point);
	double len = hs_length(d);
	if (!(len > 1e-9)) // one point: nothing to squeeze between
		return false;
	double limit = model->oppose_cos * len;
	return -hs_dot(a->normal, d) >= limit && hs_dot(b->normal, d) >= limit;
}

// How much a pair's tips may part in a frame and still count as closing: HS_PAIR_STILL (m, the
// noise of a glove or tracker past its deadband) and HS_PAIR_DRIFT (m/s) times the frame time.
#define HS_PAIR_STILL 2e-3
#define HS_PAIR_DRIFT 0.05

// True when fingers a < b of the hand have closed by grasp_close_mm from where their tips were when
// the pair's reference was last set (hs_hand.state.pair_open: the hand's first pose, its return
// from a tracking loss, its last release) and are not opening now (their tips parted by at most HS_PAIR_STILL
// plus HS_PAIR_DRIFT dt since the last frame): a hand that closed on one object and opens again is not closing.
static bool pair_closing(const hs_world_def *def, const hs_hand *hand, int a, int b) {
	double d = hs_length(hs_sub(hand->cache.points[4 * a + 3], hand->cache.points[4 * b + 3]));
	double before = hs_length(hs_sub(hand->cache.prev_points[4 * a + 3], hand->cache.prev_points[4 * b + 3]));
	return hand->state.pair_open[finger_pair(a, b)] - d >= def->grasp_close_mm * 1e-3 &&
	       d <= before + HS_PAIR_STILL + HS_PAIR_DRIFT * def->dt;
}

// True when the fingers of contacts a and b (one hand, different fingers) have closed by
// grasp_close_mm from their reference (hs_hand.state.pair_open, pair_closing).
static bool closing(const hs_world_def *def, const hs_hand *hands, const hs_contact *a, const hs_contact *b) {
	if (a->hand.index1 != b->hand.index1) // two hands squeezing from either side
		return true;
	int fa = finger_of(a->part), fb = finger_of(b->part);
	if (fa == fb) // the paper's any-two rule (grasp_rule: any) on one finger: no pair to close
		return true;
	if (fa > fb) {
		int t = fa;
		fa = fb;
		fb = t;
	}
	return pair_closing(def, &hands[a->hand.index1 - 1], fa, fb);
}

// A new grasp (§3.2 (2) with the realistic start, docs/model.md §3): two contacts whose normals lie
// at least the threshold apart (on different fingers or hands unless grasp_rule is any), pressing
// toward each other across the object (grasp_opposed), on fingers that are closing (grasp_close_mm)
// unless the object is `taking_over` from a hand that let it go this frame: another hand already
// squeezing it (a handover) holds it on without closing again.
bool hs_grasp_starts(const hs_world_model *model, const hs_hand *hands, const hs_contact *cs, int n, bool taking_over) {
	bool any = model->def.grasp_any_contacts, oppose = model->def.grasp_opposed;
	bool close = model->def.grasp_close_mm > 0.0 && !taking_over;
	for (int i = 0; i < n; ++i)
		for (int j = i + 1; j < n; ++j) {
			const hs_contact *a = &cs[i], *b = &cs[j];
			if (!(any || a->hand.index1 != b->hand.index1 || finger_of(a->part) != finger_of(b->part)))
				continue;
			if (hs_dot(a->normal, b->normal) > model->grasp_limit)
				continue;
			if ((!oppose || opposed(model, a, b)) && (!close || closing(&model->def, hands, a, b)))
				return true;
		}
	return false;
}

// Spread plus reach of all five fingers: how open the whole hand is (m).
static double whole_hand_opening(const hs_hand *hand) {
	double spread, reach;
	hand_opening(hand, 31u, &spread, &reach);
	return spread + reach;
}

void hs_grasp_begin(hs_body *body, const hs_hand *hand, int h, const hs_contact *cs, int n) {
	body->grasped_by = h + 1;
	hs_grasp_slip(body, hand); // the pose it has now, in the wrist frame
	body->grip_fingers = 0;
	for (int k = 0; k < n; ++k)
		if (cs[k].hand.index1 == (uint32_t)h + 1)
			body->grip_fingers |= (uint8_t)(1u << finger_of(cs[k].part));
	hand_opening(hand, body->grip_fingers, &body->grip_spread, &body->grip_reach);
	body->released_by = 0;
}

void hs_grasp_let_go_in_place(const hs_world_model *model, hs_body *bodies, hs_world_cache *cache, const hs_hand *hand,
                               int h) {
	for (int i = 0; i < model->object_count; ++i) {
		hs_body *b = &bodies[i];
		if (b->grasped_by != h + 1)
			continue;
		b->grasped_by = 0;
		b->released_by = h + 1; // its fingers, still around it, do not take it again at once
		b->grip_spread = whole_hand_opening(hand);
		b->prev = b->pos; // no velocity: it drops from where it is
		b->rot_prev = b->rot;
		b->spin = hs_quat_identity();
		hs_wake(bodies, cache, i);
		hs_digest_stale(cache, i);
	}
}

// True when the holder's contacts among cs[0..n) still hold: any of them when the grasp was made
// by several fingers, else a grasping pair (§3.2 (2)).
static bool holder_holds(const hs_world_model *model, const hs_contact *cs, int n, uint32_t holder, unsigned fingers) {
	if ((fingers & (fingers - 1u)) == 0)
		return hs_contact_grasps(cs, n, holder, model->grasp_limit, model->def.grasp_any_contacts);
	for (int k = 0; k < n; ++k)
		if (cs[k].hand.index1 == holder)
			return true;
	return false;
}

// The grasp goes on (the object has followed the wrist) while the holding fingers have neither
// spread nor reached out (hand_opening) more than grasp_open_mm from when the grasp began, and one
// of the holder's parts lies within grasp_release_mm of the object: the object is rigid in the
// wrist frame, so fingers that do not open still clamp it, though one has come off the surface.
// Held by one finger (grasp_rule: any), the holder's contacts with the object grown by
// grasp_release_mm must still grasp (§3.2 (2) with the margin). On true, the frame's contacts
// (ungrown) are in cp->out->contacts from `first` and *n says how many. The ungrown contacts are a
// subset of the grown ones, so they are tried first: the grown test runs only when they do not
// hold (a finger lifted off within the margin), which keeps a held object at one detection a frame.
static bool grasp_continues(const hs_contact_pass *cp, hs_body *body, int i, const hs_pose *before, int first, int *n) {
	if (cp->model->def.paper_grasp_end) { // [H] §3.2: "successive instances in which grasping is recognized"
		*n = hs_contact_detect(cp, i, before);
		return hs_contact_classify(&cp->out->contacts[first], *n, cp->model->grasp_limit, cp->model->def.grasp_any_contacts) ==
		       HS_CONTACT_GRASP;
	}
	uint32_t holder = (uint32_t)body->grasped_by;
	const hs_hand *hand = &cp->hands[holder - 1];
	unsigned fingers = body->grip_fingers;
	double spread, reach, margin = cp->model->def.grasp_open_mm * 1e-3;
	hand_opening(hand, fingers, &spread, &reach);
	// measured from the most closed grip since the grasp began: a hand that closes on after the
	// grasp and then opens lets go once it opened by the margin, not only past where it began
	body->grip_spread = spread < body->grip_spread ? spread : body->grip_spread;
	body->grip_reach = reach < body->grip_reach ? reach : body->grip_reach;
	if (spread - body->grip_spread > margin || reach - body->grip_reach > margin)
		return false;
	*n = hs_contact_detect(cp, i, before);
	if (holder_holds(cp->model, &cp->out->contacts[first], *n, holder, fingers))
		return true;
	cp->out->contact_count = first;
	int grown = hs_contact_detect_grown(cp, i, before, cp->model->def.grasp_release_mm * 1e-3);
	bool holds = holder_holds(cp->model, &cp->out->contacts[first], grown, holder, fingers);
	cp->out->contact_count = first;
	if (holds)
		*n = hs_contact_detect(cp, i, before);
	return holds;
}

// How far the hand that let an object go must be from it before its parts act on it again (m): a
// hand that follows through after a throw stays within millimetres of what it threw, and cleared
// by grasp_release_mm (5 mm) one frame it shoved it the next.
#define HS_RELEASE_CLEAR 0.02

// True when a finger part of hand index + 1 `r` lies within HS_RELEASE_CLEAR of object i.
static bool hand_within_margin(const hs_contact_pass *cp, int i, uint32_t r) {
	bool near = hs_contact_hand_within(cp, i, (int)r - 1, HS_RELEASE_CLEAR);
#if defined(HS_SELFCHECK)
	// the rule it stands for: the grown test's contacts, one of them that hand's (then dropped)
	int at = cp->out->contact_count, n = hs_contact_detect_grown(cp, i, NULL, HS_RELEASE_CLEAR);
	bool any = false;
	for (int k = 0; k < n; ++k)
		any = any || cp->out->contacts[at + k].hand.index1 == r;
	cp->out->contact_count = at;
	if (any != near && cp->out->contact_count + n < cp->out->contact_capacity) {
		fprintf(stderr, "selfcheck: hs_contact_hand_within differs from the grown test's contacts\n");
		abort();
	}
#endif
	return near;
}

// True when some pair of fingertips of the hand has closed by grasp_close_mm (hs_hand.state.pair_open).
static bool hand_closing(const hs_world_def *def, const hs_hand *hand) {
	for (int a = 0; a < 4; ++a)
		for (int b = a + 1; b < 5; ++b)
			if (pair_closing(def, hand, a, b))
				return true;
	return false;
}

// After a grasp ended, the releasing hand's contacts are set aside (§3.2 with a release rule,
// docs/model.md §3) until no part of that hand is within grasp_release_mm of the object, another of its fingers than
// those that held it touches it while the hand closes, or its five fingers close (whole_hand_opening) by grasp_open_mm
// from the most open since the release (kept in grip_spread): it closes on the object again. Returns the
// count of contacts left.
static int set_aside_released(const hs_contact_pass *cp, hs_world_cache *cache, hs_body *body, int i, int first, int n) {
	if (!body->released_by)
		return n;
	uint32_t r = (uint32_t)body->released_by;
	const hs_hand *hand = &cp->hands[r - 1];
	double spread = whole_hand_opening(hand);
	if (spread > body->grip_spread) { // the object may sleep meanwhile: its hash digest is stale
		body->grip_spread = spread;
		hs_digest_stale(cache, i);
	}
	hs_contact *cs = &cp->out->contacts[first];
	int kept = 0;
	bool other_finger = false;
	for (int k = 0; k < n; ++k) {
		if (cs[k].hand.index1 != r)
			cs[kept++] = cs[k];
		else if (!(((unsigned)body->grip_fingers >> finger_of(cs[k].part)) & 1u))
			other_finger = true;
	}
	// another finger counts only once the hand has stopped opening (with grasp_close_mm: its five
	// fingers closed by HS_PAIR_STILL from the most open since the release): an opening hand's other
	// fingers brushing the object it just let go shoved it, and while a hand opens, some pairs of its
	// tips come nearer as others part, so no pair's closing tells it
	double closed = body->grip_spread - spread;
	bool closes = (other_finger && (!(cp->model->def.grasp_close_mm > 0.0) || closed >= HS_PAIR_STILL)) ||
	              closed > cp->model->def.grasp_open_mm * 1e-3;
	if (kept == n && !closes && hand_within_margin(cp, i, r))
		return n; // the object falls clear of a finger it rested on: still that hand's release
	if (kept == n || closes) { // the rule lapses
		body->released_by = 0;
		hs_digest_stale(cache, i);
		return n;
	}
	cp->out->contact_count = first + kept;
	return kept;
}

// The contact state of an object no hand holds (docs/model.md §3 "Grasp start"): a grasp by the
// contacts' normals (Fig. 2) begins only as hs_grasp_starts allows, else they push at several
// points. A push by a closing hand becomes a grasp when the object grown by grasp_release_mm is
// grasped (a pinch of a small object: the first fingertip to touch would push it away from the
// others before they reach it).
static hs_contact_state start_or_push(const hs_contact_pass *cp, const hs_body *body, int i, int first, int *n,
                                      hs_contact_state state) {
	if (state == HS_CONTACT_GRASP)
		return hs_grasp_starts(cp->model, cp->hands, &cp->out->contacts[first], *n, false) ? state : HS_CONTACT_PUSH_MANY;
	if (state == HS_CONTACT_NONE || !(cp->model->def.grasp_close_mm > 0.0) || body->released_by)
		return state;
	bool closing_hand = false;
	for (int k = 0; k < *n && !closing_hand; ++k)
		closing_hand = hand_closing(&cp->model->def, &cp->hands[cp->out->contacts[first + k].hand.index1 - 1]);
	if (!closing_hand)
		return state;
	cp->out->contact_count = first;
	int grown = hs_contact_detect_grown(cp, i, NULL, cp->model->def.grasp_release_mm * 1e-3);
	if (hs_grasp_starts(cp->model, cp->hands, &cp->out->contacts[first], grown, false)) {
		*n = grown;
		return HS_CONTACT_GRASP;
	}
	cp->out->contact_count = first;
	*n = hs_contact_detect(cp, i, NULL);
	return state;
}

hs_contact_state hs_grasp_detect(const hs_contact_pass *cp, hs_world_cache *cache, hs_body *body, int i, int first, int *n,
                                 bool *continues) {
	*continues = false;
	if (body->grasped_by > 0 && !body->released_by) {
		hs_pose before = {body->pos, body->rot};
		hs_grasp_follow_wrist(body, &cp->hands[body->grasped_by - 1]);
		if (grasp_continues(cp, body, i, &before, first, n)) {
			*continues = true;
			return HS_CONTACT_GRASP;
		}
		// the holder let go: the release rule starts. The fingers are judged against the object
		// where the hand carried it this frame (they open around it, in the hand's frame); left
		// where it was, a hand that lets go while moving fast would sweep through it.
		body->released_by = cp->model->def.paper_grasp_end ? 0 : body->grasped_by; // the letter sets no hand aside
		body->grip_spread = whole_hand_opening(&cp->hands[body->grasped_by - 1]);
		// a hand that let go must close anew to grasp again: its pairs' peaks start from here
		hs_grasp_reset_pairs(&cp->hands[body->grasped_by - 1]);
		*n = hs_contact_detect(cp, i, &before);
		*n = set_aside_released(cp, cache, body, i, first, *n);
		hs_contact_state state =
		    hs_contact_classify(&cp->out->contacts[first], *n, cp->model->grasp_limit, cp->model->def.grasp_any_contacts);
		if (state == HS_CONTACT_GRASP && !hs_grasp_starts(cp->model, cp->hands, &cp->out->contacts[first], *n, true))
			state = HS_CONTACT_PUSH_MANY;
		if (state == HS_CONTACT_NONE) { // it flies from its last held pose (manipulate.c, release)
			body->pos = before.pos;
			body->rot = before.rot;
		}
		return state;
	}
	*n = hs_contact_detect(cp, i, NULL);
	*n = set_aside_released(cp, cache, body, i, first, *n);
	return start_or_push(cp, body, i, first, n,
	                     hs_contact_classify(&cp->out->contacts[first], *n, cp->model->grasp_limit, cp->model->def.grasp_any_contacts));
}
