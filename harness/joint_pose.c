// joint_pose.c — one sample of recorded joint positions as the glove model's input (scenarios/
// README.md, "Recorded joint positions"; [H] §3.1: the check points are the joints and the
// fingertips):
//  - the wrist pose: the rigid motion that best carries the hand definition's thumb CMC and index
//    and middle MCPs (which no sensor moves with the wrist sensors neutral) onto the recorded ones
//    (the rotation between the frames the three span); the glove's wrist pitch and yaw stay
//    neutral (the pose takes them: positions alone cannot tell them from the tracker's turn).
//  - the 16 other sensors: the integers (0.5° units) whose kinematics best reach the recorded
//    check points in the wrist frame (least squares over the points recorded): the first sample
//    by full scans of each sensor, every later one by a pattern search from the sample before. A
//    recording made from the glove model gives back its own sensors and pose; a real hand gets
//    the nearest its definition can do.
#include <math.h>

#include "joint_pose.h"

static const int rigid[3] = {0, 4, 8}; // thumb CMC, index MCP, middle MCP

// Σ |kinematics(sensors) − target|² over the check points recorded, in the wrist frame.
static double misfit(const hs_hand_def *def, uint32_t present, const uint8_t s[HS_GLOVE_SENSORS],
                     const hs_vec3 target[HS_HAND_POINTS]) {
	hs_vec3 p[HS_HAND_POINTS], lines[HS_HAND_LINES][2];
	hs_hand_kinematics(def, hs_v3(0, 0, 0), hs_quat_identity(), s, p, lines);
	double e = 0.0;
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		if (present >> i & 1u)
			e += hs_length_sq(hs_sub(p[i], target[i]));
	return e;
}

static bool searched(int k) { return k != HS_SENSOR_WRIST_PITCH && k != HS_SENSOR_WRIST_YAW; }

// Each searched sensor over all its values, in turn, until a sweep changes none (the first sample).
static void scan(const hs_hand_def *def, uint32_t present, uint8_t s[HS_GLOVE_SENSORS],
                 const hs_vec3 target[HS_HAND_POINTS]) {
	double best = misfit(def, present, s, target);
	for (int sweep = 0; sweep < 6; ++sweep) {
		bool changed = false;
		for (int k = 0; k < HS_GLOVE_SENSORS; ++k) {
			if (!searched(k))
				continue;
			uint8_t keep = s[k];
			for (int v = 0; v < 256; ++v) {
				s[k] = (uint8_t)v;
				double e = misfit(def, present, s, target);
				if (e < best) {
					best = e;
					keep = (uint8_t)v;
					changed = true;
				}
			}
			s[k] = keep;
		}
		if (!changed)
			return;
	}
}

// A pattern search from the sensors given: steps 16 down to 1 per sensor, until none improves.
static void refine(const hs_hand_def *def, uint32_t present, uint8_t s[HS_GLOVE_SENSORS],
                   const hs_vec3 target[HS_HAND_POINTS]) {
	double best = misfit(def, present, s, target);
	for (int step = 16; step >= 1; step /= 2) {
		for (int round = 0; round < 64; ++round) {
			bool changed = false;
			for (int k = 0; k < HS_GLOVE_SENSORS; ++k) {
				for (int dir = -1; searched(k) && dir <= 1; dir += 2) {
					int v = (int)s[k] + dir * step;
					if (v < 0 || v > 255)
						continue;
					uint8_t keep = s[k];
					s[k] = (uint8_t)v;
					double e = misfit(def, present, s, target);
					if (e < best) {
						best = e;
						changed = true;
					} else {
						s[k] = keep;
					}
				}
			}
			if (!changed)
				break;
		}
	}
}

// The unit quaternion of a rotation matrix (hs_quat_from_columns).
hs_quat hs_joint_quat_of(double m[3][3]) {
	return hs_quat_from_columns(hs_v3(m[0][0], m[1][0], m[2][0]), hs_v3(m[0][1], m[1][1], m[2][1]),
	                            hs_v3(m[0][2], m[1][2], m[2][2]));
}

// An orthonormal frame (columns) spanned by three points: a→b, then c's part across it.
static bool frame_of3(hs_vec3 a, hs_vec3 b, hs_vec3 c, double f[3][3]) {
	hs_vec3 e1 = hs_sub(b, a), e2 = hs_sub(c, a);
	if (!(hs_length_sq(e1) > 0.0))
		return false;
	e1 = hs_normalize(e1);
	e2 = hs_sub(e2, hs_scale(e1, hs_dot(e2, e1)));
	if (!(hs_length_sq(e2) > 0.0))
		return false;
	e2 = hs_normalize(e2);
	hs_vec3 e3 = hs_cross(e1, e2), cols[3] = {e1, e2, e3};
	for (int k = 0; k < 3; ++k) {
		f[0][k] = cols[k].x;
		f[1][k] = cols[k].y;
		f[2][k] = cols[k].z;
	}
	return true;
}

// The rigid motion (rotation, translation) carrying the definition's thumb CMC and index and
// middle MCPs (wrist frame) onto the recorded ones: the rotation between the frames the three
// points span (Gram-Schmidt), the translation matching their centroids. Only IEEE operations
// (no LAPACK-style library), so the same bits on every machine: an SVD fit differed on i386 and
// aarch64 in the last bits.
bool hs_joint_fit_wrist(const hs_hand_def *def, const hs_vec3 world[HS_HAND_POINTS], hs_quat *rot, hs_vec3 *pos) {
	uint8_t open[HS_GLOVE_SENSORS];
	hs_hand_posture(def, HS_POSTURE_OPEN, 0.0, open);
	hs_vec3 local[HS_HAND_POINTS], lines[HS_HAND_LINES][2];
	hs_hand_kinematics(def, hs_v3(0, 0, 0), hs_quat_identity(), open, local, lines);
	double fl[3][3], fw[3][3], r[3][3];
	if (!frame_of3(local[rigid[0]], local[rigid[1]], local[rigid[2]], fl) ||
	    !frame_of3(world[rigid[0]], world[rigid[1]], world[rigid[2]], fw))
		return false;
	for (int i = 0; i < 3; ++i) // R = Fw Flᵀ
		for (int j = 0; j < 3; ++j)
			r[i][j] = fw[i][0] * fl[j][0] + fw[i][1] * fl[j][1] + fw[i][2] * fl[j][2];
	*rot = hs_joint_quat_of(r);
	hs_vec3 lc = hs_v3(0, 0, 0), wc = hs_v3(0, 0, 0);
	for (int k = 0; k < 3; ++k) {
		lc = hs_add(lc, hs_scale(local[rigid[k]], 1.0 / 3.0));
		wc = hs_add(wc, hs_scale(world[rigid[k]], 1.0 / 3.0));
	}
	*pos = hs_sub(wc, hs_quat_rotate(*rot, lc));
	return true;
}

void hs_joint_fit_sensors(const hs_hand_def *def, uint32_t present, const hs_vec3 local[HS_HAND_POINTS], bool first,
                          uint8_t s[HS_GLOVE_SENSORS]) {
	if (first)
		scan(def, present, s, local);
	else
		refine(def, present, s, local);
}
