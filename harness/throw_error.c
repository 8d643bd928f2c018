// throw_error.c — a human thrower's error on one throw (hs_throw_error, docs/campaigns.md): the
// swing scaled and turned about where it starts, the fingers opening early or late against the arm.
// Applied to the script's readings before the input noise, as a person's arm and hand would differ
// from one throw to the next before any tracker or glove measures them (hs_thrower_sample,
// hand_script.c). This file sets a hand's thrower from the error.
#include <math.h>

#include "hand_script.h"
#include "scenario_internal.h"
#include "scenario_parser.h"

static const double MAX_TIMING = 1.0; // s

// The turn: elevation about the horizontal line across the swing (up positive), then azimuth
// about the vertical.
static hs_quat swing_turn(const hs_hand_script *script, const hs_throw_error *e, hs_vec3 pivot) {
	hs_vec3 end;
	hs_quat r;
	uint8_t glove[HS_GLOVE_SENSORS];
	hs_hand_script_sample(script, e->release, &end, &r, glove);
	hs_vec3 d = hs_sub(end, pivot), across = hs_v3(1, 0, 0);
	hs_vec3 flat = hs_v3(d.x, d.y, 0.0);
	double len = hs_length(flat);
	if (len > 1e-9) // flat × z: turning about it by a positive angle lifts the swing
		across = hs_v3(flat.y / len, -flat.x / len, 0.0);
	hs_quat up = hs_quat_from_axis_angle(across, e->elevation);
	hs_quat side = hs_quat_from_axis_angle(hs_v3(0, 0, 1), e->azimuth);
	return hs_quat_normalize(hs_quat_mul(side, up));
}

static bool finite_in(double v, double lo, double hi) { return isfinite(v) && v >= lo && v <= hi; }

bool hs_throw_error_set(hs_scenario_parser *p, const yaml_node_t *root, const hs_throw_error *e) {
	hs_hands *hands = &p->s->hands;
	if (e->hand < 0 || e->hand >= hands->count)
		return hs_yaml_fail(&p->y, root, "throw error: hand %d does not exist (the file has %d hands)", e->hand,
		                    hands->count);
	if (!finite_in(e->from, 0.0, p->s->duration) || !finite_in(e->release, e->from, p->s->duration) ||
	    !(e->release > e->from))
		return hs_yaml_fail(&p->y, root, "throw error: need 0 <= from < release <= duration %g s, got %g and %g",
		                    p->s->duration, e->from, e->release);
	if (!finite_in(e->timing, -MAX_TIMING, MAX_TIMING) || !finite_in(e->delay, 0.0, MAX_TIMING) || !(isfinite(e->speed) && e->speed > -1.0) ||
	    !finite_in(e->azimuth, -HS_PI, HS_PI) || !finite_in(e->elevation, -HS_PI, HS_PI))
		return hs_yaml_fail(&p->y, root,
		                    "throw error: timing within [-1, 1] s, delay within [0, 1] s, speed above -1, angles "
		                    "within [-pi, pi], got %g s, %g s, %g, %g and %g rad",
		                    e->timing, e->delay, e->speed, e->azimuth, e->elevation);
	const hs_hand_script *script = &hands->scripts[e->hand];
	hs_thrower *t = &hands->thrower;
	hs_quat r;
	uint8_t glove[HS_GLOVE_SENSORS];
	hs_hand_script_sample(script, e->from, &t->pivot, &r, glove);
	t->turn = swing_turn(script, e, t->pivot);
	t->hand = e->hand;
	t->from = e->from;
	t->timing = e->timing;
	t->delay = e->delay;
	t->scale = 1.0 + e->speed;
	t->active = true;
	return true;
}
