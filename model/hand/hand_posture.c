// hand_posture.c — named postures of the glove-driven hand (open, fist, point, pinch, grasp of a
// given width) as glove readings, solved through the kinematics of the 1999 paper §3.1 (hand.c);
// the grasp's thumb by closed-form inverse kinematics; and a reading's grip centre and axis.
#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "glove.h"
#include "hand.h"

// sensor value a × full, rounded to the nearest unit (a in 0..1)
static uint8_t scaled(double a, int full) { return (uint8_t)round(a * (double)full); }

// Full fist (sensor units): fingers MCP 90°, PIP 100° (DIP follows); the thumb folded across
// the middle phalanges of the index and middle fingers (roll 10°, MCP 40°, IP 60°).
#define FIST_MCP 180
#define FIST_PIP 200
#define FIST_THUMB_ROLL 20
#define FIST_THUMB_MCP 80
#define FIST_THUMB_IP 120
// Pinch: the index finger at MCP 50°, PIP 60°; the thumb is solved to meet its tip.
#define PINCH_INDEX_MCP 100
#define PINCH_INDEX_PIP 120
// Grasp: index and middle curl along a fixed schedule in the width w (sensor units at knots,
// linear between): MCP 30°, PIP 80° at 1 cm; PIP 51° at 5 cm; MCP 40°, PIP 25° at 12 cm. Up to
// 5 cm the fingertips hook down behind the object's far face; wider, the fingers keep enough
// curl that the object's top may rise ~1.5 cm above the fingertips without touching a finger.
#define GRASP_MIN 0.01
#define GRASP_MAX 0.12
typedef struct grasp_knot {
	double width; // m
	int mcp, pip; // sensor units
} grasp_knot;
static const grasp_knot GRASP_KNOTS[3] = {{GRASP_MIN, 60, 160}, {0.05, 60, 102}, {GRASP_MAX, 80, 50}};
// largest miss of a solved thumb tip, relative to the metacarpal length
#define REACH_TOLERANCE 0.05

static void set_open(uint8_t s[HS_GLOVE_SENSORS]) {
	for (int i = 0; i < HS_GLOVE_SENSORS; i++)
		s[i] = 0;
	s[HS_SENSOR_WRIST_PITCH] = HS_WRIST_ZERO;
	s[HS_SENSOR_WRIST_YAW] = HS_WRIST_ZERO;
}

static bool def_is_valid(const hs_hand_def *def) {
	if (!(isfinite(def->finger_radius) && def->finger_radius > 0.0) || !isfinite(def->dip_per_pip))
		return false;
	for (int f = 0; f < 5; f++) {
		if (!hs_vec3_is_finite(def->base[f]))
			return false;
		for (int s = 0; s < 3; s++)
			if (!(isfinite(def->segment_length[f][s]) && def->segment_length[f][s] > 0.0))
				return false;
	}
	return true;
}

// Places the thumb tip at `target` (right hand, palm frame = wrist frame, abduction as set in s):
// closed-form inverse kinematics for roll, MCP and IP, rounded to sensor units, then the best of
// the neighbouring unit combinations (roll, MCP, IP ± 1, abduction + 0..1), compared in a fixed
// order with a strict '<' so the result is deterministic. False when the target is out of reach.
static bool thumb_reach(const hs_hand_def *def, hs_vec3 target, uint8_t s[HS_GLOVE_SENSORS]) {
	hs_hand_joints j = hs_hand_joints_from_sensors(def, s);
	// metacarpal frame before roll: splay, abduction, tilt; its x along the bone
	hs_quat m = hs_hand_thumb_base(j.thumb_abduction);
	hs_vec3 d = hs_quat_inv_rotate(m, hs_sub(target, def->base[0]));
	// In the metacarpal frame the nail after roll φ points along (0, cos φ, sin φ), the pad the
	// other way, and flexion keeps the proximal and distal bones in the plane of x and the pad:
	// tip = (L0 + a, −b cos φ, −b sin φ), (a, b) the planar two-bone reach.
	double l0 = def->segment_length[0][0], l1 = def->segment_length[0][1], l2 = def->segment_length[0][2];
	double a = d.x - l0, b = sqrt(d.y * d.y + d.z * d.z);
	double roll = hs_atan2(-d.z, -d.y);
	double c = (a * a + b * b - l1 * l1 - l2 * l2) / (2.0 * l1 * l2);
	if (!(c >= -1.0 && c <= 1.0))
		return false;
	double ip = hs_acos(c);
	double mcp = hs_atan2(b, a) - hs_atan2(l2 * hs_sin(ip), l1 + l2 * hs_cos(ip));
	hs_hand_joints want = j;
	want.thumb_roll = roll;
	want.thumb_mcp = mcp;
	want.thumb_ip = ip;
	uint8_t guess[HS_GLOVE_SENSORS];
	hs_hand_sensors_from_angles(&want, guess);
	const int keys[3] = {HS_SENSOR_THUMB_ROLL, HS_SENSOR_THUMB_MCP, HS_SENSOR_THUMB_IP};
	uint8_t trial[HS_GLOVE_SENSORS], best[HS_GLOVE_SENSORS];
	for (int i = 0; i < HS_GLOVE_SENSORS; i++)
		trial[i] = best[i] = s[i];
	double best_err = INFINITY;
	for (int ab = 0; ab <= 1; ab++) {
		int abd = (int)s[HS_SENSOR_THUMB_ABDUCTION] + ab;
		if (abd > 255)
			continue;
		for (int n = 0; n < 27; n++) {
			int step[3] = {n % 3 - 1, (n / 3) % 3 - 1, n / 9 - 1};
			bool inside = true;
			for (int k = 0; k < 3; k++) {
				int v = (int)guess[keys[k]] + step[k];
				if (v < 0 || v > 255)
					inside = false;
				else
					trial[keys[k]] = (uint8_t)v;
			}
			if (!inside)
				continue;
			trial[HS_SENSOR_THUMB_ABDUCTION] = (uint8_t)abd;
			double err = hs_distance(hs_hand_thumb_tip(def, trial), target);
			if (err < best_err) {
				best_err = err;
				for (int i = 0; i < HS_GLOVE_SENSORS; i++)
					best[i] = trial[i];
			}
		}
	}
	// out of the glove's range (an angle clamped to 0..127.5°): the tip misses by far more than
	// the few tenths of a millimetre one sensor unit moves it
	if (!(best_err <= REACH_TOLERANCE * l0))
		return false;
	for (int i = 0; i < HS_GLOVE_SENSORS; i++)
		s[i] = best[i];
	return true;
}

// Grasp of a w-wide object from above (palm down): index and middle fingertips on the far (+x)
// face, the thumb tip on the near (−x) face, each tip r/2 inside its face, so the thumb tip sits
// at the fingertip mean − (w − r) x̂. The fingers follow the closure schedule above (a smaller
// object, a tighter curl); the thumb is then solved to the target computed from the fingers'
// rounded sensor values, so the grip axis is +x to within one sensor unit of the thumb.
// Ring and little fingers are folded as in a full fist, away from a small object.
static hs_status grasp(const hs_hand_def *def, double w, uint8_t s[HS_GLOVE_SENSORS]) {
	set_open(s);
	int k = w <= GRASP_KNOTS[1].width ? 0 : 1;
	const grasp_knot *a = &GRASP_KNOTS[k], *b = &GRASP_KNOTS[k + 1];
	double t = (w - a->width) / (b->width - a->width);
	uint8_t mcp = (uint8_t)round((double)a->mcp + t * (double)(b->mcp - a->mcp));
	uint8_t pip = (uint8_t)round((double)a->pip + t * (double)(b->pip - a->pip));
	s[HS_SENSOR_INDEX_MCP] = s[HS_SENSOR_MIDDLE_MCP] = mcp;
	s[HS_SENSOR_INDEX_PIP] = s[HS_SENSOR_MIDDLE_PIP] = pip;
	s[HS_SENSOR_RING_MCP] = s[HS_SENSOR_LITTLE_MCP] = FIST_MCP;
	s[HS_SENSOR_RING_PIP] = s[HS_SENSOR_LITTLE_PIP] = FIST_PIP;
	hs_vec3 tips = hs_scale(hs_add(hs_hand_right_point(def, s, 7), hs_hand_right_point(def, s, 11)), 0.5);
	hs_vec3 target = hs_sub(tips, hs_v3(w - def->finger_radius, 0.0, 0.0));
	return thumb_reach(def, target, s) ? HS_OK : HS_ERR_INVALID_ARGUMENT;
}

static hs_status pinch(const hs_hand_def *def, double amount, uint8_t s[HS_GLOVE_SENSORS]) {
	uint8_t full[HS_GLOVE_SENSORS];
	set_open(full);
	full[HS_SENSOR_INDEX_MCP] = PINCH_INDEX_MCP;
	full[HS_SENSOR_INDEX_PIP] = PINCH_INDEX_PIP;
	if (!thumb_reach(def, hs_hand_right_point(def, full, 7), full))
		return HS_ERR_INVALID_ARGUMENT;
	set_open(s);
	for (int i = 0; i < HS_SENSOR_WRIST_PITCH; i++)
		s[i] = scaled(amount, full[i]);
	return HS_OK;
}

hs_status hs_hand_posture(const hs_hand_def *def, hs_posture posture, double amount,
                          uint8_t sensors[HS_GLOVE_SENSORS]) {
	if (def == NULL || sensors == NULL || !def_is_valid(def))
		return HS_ERR_INVALID_ARGUMENT;
	switch (posture) {
	case HS_POSTURE_OPEN: // amount is not used
		set_open(sensors);
		return HS_OK;
	case HS_POSTURE_FIST:
	case HS_POSTURE_POINT:
		if (!(amount >= 0.0 && amount <= 1.0))
			return HS_ERR_INVALID_ARGUMENT;
		set_open(sensors);
		for (int k = posture == HS_POSTURE_POINT ? 1 : 0; k < 4; k++) {
			sensors[HS_SENSOR_INDEX_MCP + 2 * k] = scaled(amount, FIST_MCP);
			sensors[HS_SENSOR_INDEX_PIP + 2 * k] = scaled(amount, FIST_PIP);
		}
		sensors[HS_SENSOR_THUMB_ROLL] = scaled(amount, FIST_THUMB_ROLL);
		sensors[HS_SENSOR_THUMB_MCP] = scaled(amount, FIST_THUMB_MCP);
		sensors[HS_SENSOR_THUMB_IP] = scaled(amount, FIST_THUMB_IP);
		return HS_OK;
	case HS_POSTURE_PINCH:
		if (!(amount >= 0.0 && amount <= 1.0))
			return HS_ERR_INVALID_ARGUMENT;
		return pinch(def, amount, sensors);
	case HS_POSTURE_GRASP:
		if (!(amount >= GRASP_MIN && amount <= GRASP_MAX))
			return HS_ERR_INVALID_ARGUMENT;
		return grasp(def, amount, sensors);
	}
	return HS_ERR_INVALID_ARGUMENT;
}

void hs_hand_grip(const hs_hand_def *def, const uint8_t sensors[HS_GLOVE_SENSORS], hs_vec3 *center,
                  hs_vec3 *axis) {
	if (def == NULL || sensors == NULL) // documented: nothing written
		return;
	hs_vec3 p[HS_HAND_POINTS];
	hs_hand_kinematics(def, hs_v3(0.0, 0.0, 0.0), hs_quat_identity(), sensors, p, NULL);
	hs_vec3 thumb = p[3], fingers = hs_scale(hs_add(p[7], p[11]), 0.5);
	hs_vec3 d = hs_sub(fingers, thumb);
	double len = hs_length(d);
	if (center != NULL)
		*center = hs_scale(hs_add(thumb, fingers), 0.5);
	if (axis != NULL) // the tips coincide: +x of the wrist frame
		*axis = len > 0.0 ? hs_scale(d, 1.0 / len) : hs_v3(1.0, 0.0, 0.0);
}
