// hand_sweep.c — the hand's path through a step.
//
// Between two readings a check point moves along an arc (the joints and the wrist turn), not a
// chord: a finger that curls 90 deg within one frame sweeps its tip along a quarter circle whose
// chord cuts up to 29 % of the finger's length inside it, through objects the finger never
// touches (the seed scene's neighbouring cube). When a finger chain or the wrist turns by more
// than HS_HAND_PATH_DEG in a frame, the path runs through the kinematics of readings interpolated
// between the two (sensors to the nearest unit, the wrist by lerp and slerp), every HS_HAND_PATH_DEG
// at most, up to HS_HAND_PATH_MAX pieces: a chord of 10 deg of arc stays within 0.4 % of the
// radius of its arc (0.8 mm for a fingertip 0.2 m from the wrist). Glove noise of ±4 units turns a
// chain by about 5 deg: a noisy frame costs nothing more.
#include <math.h>
#include <stdlib.h>

#include "hand_sweep.h"

// deg per sensor unit (paper §5.1)
#define DEG_PER_UNIT 0.5

static int delta(const hs_hand *hand, int sensor) { return abs((int)hand->state.sensors[sensor] - (int)hand->state.prev_sensors[sensor]); }

// The largest turn (deg) of any part of the hand relative to the wrist over the frame: the sum of
// the sensed joint changes along each finger chain (the DIP follows 2/3 of the PIP), the palm and
// wrist joints counted for all.
static double chain_turn_deg(const hs_hand *hand) {
	int thumb = delta(hand, HS_SENSOR_THUMB_ROLL) + delta(hand, HS_SENSOR_THUMB_MCP) + delta(hand, HS_SENSOR_THUMB_IP) +
	            delta(hand, HS_SENSOR_THUMB_ABDUCTION);
	int worst = thumb;
	for (int f = 0; f < 4; ++f) {
		int chain = delta(hand, HS_SENSOR_INDEX_MCP + 2 * f) + 2 * delta(hand, HS_SENSOR_INDEX_PIP + 2 * f);
		if (f > 0)
			chain += delta(hand, HS_SENSOR_INDEX_MIDDLE_ABDUCTION + f - 1);
		if (f < 3)
			chain += delta(hand, HS_SENSOR_INDEX_MIDDLE_ABDUCTION + f);
		worst = chain > worst ? chain : worst;
	}
	int palm = delta(hand, HS_SENSOR_PALM_ARCH) + delta(hand, HS_SENSOR_WRIST_PITCH) + delta(hand, HS_SENSOR_WRIST_YAW);
	return (worst + palm) * DEG_PER_UNIT;
}

// A joint-driven hand: the largest turn of any segment relative to the wrist over the frame
// (its frame now against a frame ago).
static double joint_turn_deg(const hs_hand *hand) {
	double worst = 0.0;
	for (int s = 0; s < 15; ++s) {
		double a = hs_quat_angle(hs_quat_mul(hand->cache.local->segment[s], hs_quat_conj(hand->cache.prev_local->segment[s])));
		worst = a > worst ? a : worst;
	}
	return worst * (180.0 / HS_PI);
}

static double wrist_turn_deg(const hs_hand *hand) {
	hs_quat a = hand->state.prev_wrist_rot, b = hand->state.wrist_rot;
	if (a.w == b.w && a.x == b.x && a.y == b.y && a.z == b.z)
		return 0.0;
	return hs_quat_angle(hs_quat_mul(b, hs_quat_conj(a))) * (180.0 / HS_PI);
}

// True when the frame's turn, chain + wrist_turn_deg, is certainly at most HS_HAND_PATH_DEG: the
// wrist's angle 2 atan2(v, |w|) is at most 2 v / |w| (atan x <= x), with a slack far above the
// rounding of either. Most frames the bound settles it and the arc tangent is not taken.
static bool turn_within_a_piece(const hs_hand *hand, double chain) {
	hs_quat r = hs_quat_mul(hand->state.wrist_rot, hs_quat_conj(hand->state.prev_wrist_rot));
	double v = sqrt(r.x * r.x + r.y * r.y + r.z * r.z), w = fabs(r.w);
	return w > 0.0 && chain + 2.0 * (v / w) * (180.0 / HS_PI) * (1.0 + 1e-9) < HS_HAND_PATH_DEG;
}

// The smallest sphere holding spheres (c0, r0) and (c1, r1).
static void merge_spheres(hs_vec3 c0, double r0, hs_vec3 c1, double r1, hs_vec3 *c, double *r) {
	double d = hs_length(hs_sub(c1, c0));
	if (d + r0 <= r1) {
		*c = c1;
		*r = r1;
	} else if (d + r1 <= r0) {
		*c = c0;
		*r = r0;
	} else {
		*r = 0.5 * (d + r0 + r1);
		*c = hs_mul_add(c0, (*r - r0) / d, hs_sub(c1, c0));
	}
}

// The farthest squared distance from c of the parts in one pose (hs_hand_farthest_sq).
static double farthest_sq(hs_vec3 c, const hs_vec3 points[HS_HAND_POINTS], const hs_vec3 lines[HS_HAND_LINES][2],
                          double r_sq) {
	return hs_hand_farthest_sq(c, &lines[0][0], 2 * HS_HAND_LINES, hs_hand_farthest_sq(c, points, HS_HAND_POINTS, r_sq));
}

// The parts at k/S of the way: the kinematics of the interpolated reading (a joint-driven hand:
// the shape of its joints interpolated linearly in the wrist frame).
static void place_between(hs_hand *hand, int k, int steps) {
	double t = (double)k / steps;
	hs_vec3 local_points[HS_HAND_POINTS], local_lines[HS_HAND_LINES][2];
	if (hand->model.def.joint_driven) {
		hs_vec3 joints[HS_HAND_POINTS];
		for (int i = 0; i < HS_HAND_POINTS; ++i)
			joints[i] = hs_lerp(hand->state.prev_joints[i], hand->state.joints[i], t);
		hs_hand_joint_shape(&hand->model.def, joints, local_points, local_lines);
	} else {
		uint8_t sensors[HS_GLOVE_SENSORS];
		for (int i = 0; i < HS_GLOVE_SENSORS; ++i) // to the nearest unit, halves up: integers only
			sensors[i] = (uint8_t)(((int)hand->state.prev_sensors[i] * (steps - k) + (int)hand->state.sensors[i] * k + steps / 2) / steps);
		hs_hand_local_shape_with(&hand->model.def, &hand->model.glove, sensors, local_points, local_lines);
	}
	hs_hand_place(local_points, (const hs_vec3(*)[2])local_lines, hs_lerp(hand->state.prev_wrist_pos, hand->state.wrist_pos, t),
	              hs_quat_slerp(hand->state.prev_wrist_rot, hand->state.wrist_rot, t), hand->cache.path_points[k - 1],
	              hand->cache.path_lines[k - 1]);
}

void hs_hand_sweep(hs_hand *hand, bool chords_only) {
	hand->cache.path_steps = 1;
	hand->cache.finger_spheres_ready = false;
	if (!hand->state.placed || hand->cache.radius < 0.0) {
		hand->cache.sweep_center = hand->cache.center;
		hand->cache.sweep_radius = hand->cache.radius;
		return;
	}
	double turn = 0.0; // (only read above HS_HAND_PATH_DEG)
	if (!chords_only) {
		double chain = hand->model.def.joint_driven ? joint_turn_deg(hand) : chain_turn_deg(hand);
		if (!turn_within_a_piece(hand, chain))
			turn = chain + wrist_turn_deg(hand);
	}
	if (turn > HS_HAND_PATH_DEG)
		hand->cache.path_steps = turn >= HS_HAND_PATH_DEG * HS_HAND_PATH_MAX ? HS_HAND_PATH_MAX
		                                                                  : (int)ceil(turn / HS_HAND_PATH_DEG);
	if (hand->cache.path_steps == 1) { // chords: within the two spheres' hull
		merge_spheres(hand->cache.prev_center, hand->cache.prev_radius, hand->cache.center, hand->cache.radius, &hand->cache.sweep_center,
		              &hand->cache.sweep_radius);
		return;
	}
	hs_hand_ready_all(hand); // the path's sphere holds every line
	hs_vec3 c = hs_scale(hs_add(hand->cache.prev_center, hand->cache.center), 0.5);
	double r_sq = farthest_sq(c, hand->cache.points, (const hs_vec3(*)[2])hand->cache.lines, 0.0);
	r_sq = farthest_sq(c, hand->cache.prev_points, (const hs_vec3(*)[2])hand->cache.prev_lines, r_sq);
	for (int k = 1; k < hand->cache.path_steps; ++k) {
		place_between(hand, k, hand->cache.path_steps);
		r_sq = farthest_sq(c, hand->cache.path_points[k - 1], (const hs_vec3(*)[2])hand->cache.path_lines[k - 1], r_sq);
	}
	hand->cache.sweep_center = c;
	hand->cache.sweep_radius = sqrt(r_sq) + 1e-6; // as hs_hand_update_bounds: rounding never leaves a part outside
}

// The 4 check points of finger f in one of the hand's poses through the frame: k = 0 a frame ago,
// path_steps now, the path's pieces between.
static const hs_vec3 *finger_points(const hs_hand *hand, int k, int f) {
	const hs_vec3 *p = k == 0 ? hand->cache.prev_points : k == hand->cache.path_steps ? hand->cache.points : hand->cache.path_points[k - 1];
	return p + 4 * f;
}

void hs_hand_finger_spheres(hs_hand *hand) {
	if (hand->cache.finger_spheres_ready)
		return;
	int poses = hand->cache.path_steps + 1;
	for (int f = 0; f < 5; ++f) {
		hs_vec3 sum = hs_v3(0.0, 0.0, 0.0);
		for (int k = 0; k < poses; ++k) {
			const hs_vec3 *p = finger_points(hand, k, f);
			sum = hs_add(sum, hs_add(hs_add(p[0], p[1]), hs_add(p[2], p[3])));
		}
		hs_vec3 c = hs_scale(sum, 1.0 / (4.0 * poses));
		// the lines' ends lie finger_radius from the points; rounding far below the micrometre
		hand->cache.finger_center[f] = c;
		double r_sq = 0.0; // (a NaN point makes the centre NaN: the sphere then culls nothing)
		for (int k = 0; k < poses; ++k)
			r_sq = hs_hand_farthest_sq(c, finger_points(hand, k, f), 4, r_sq);
		hand->cache.finger_reach[f] = (sqrt(r_sq) + hand->model.def.finger_radius) * (1.0 + 1e-9) + 1e-6;
	}
	hand->cache.finger_spheres_ready = true;
}
