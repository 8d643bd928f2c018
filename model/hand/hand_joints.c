// hand_joints.c — a hand driven by tracked joint positions instead of a glove (docs/model.md §1
// "Joint-driven hands"). [H] §3.1 checks contact at the joints and fingertips and along the finger
// segments between them; an optical tracker gives those joints directly, so the hand's shape is the
// 20 points as given and no kinematics stands between them and the contact model (the glove's 18
// sensors cannot place a real hand's joints: fitted to a real pinch, its fingertips stayed 25-30 mm
// apart where the real ones closed to 18 mm). Each segment's frame, which places its four check
// lines around it, has x along the segment and z as near the back of the hand (the wrist frame's
// +z) as x allows.
#include <math.h>

#include "hand_internal.h"

static hs_vec3 mirror_if(bool left, hs_vec3 v) { return left ? hs_v3(v.x, -v.y, v.z) : v; }

// The frame of a segment from a to b (right-hand wrist frame): x along it, z the back of the hand
// (+z) less its part along x, or +y where the segment points nearly along z. A segment of no
// length (two joints recorded at one place) keeps the wrist's axes.
static hs_quat segment_frame(hs_vec3 a, hs_vec3 b) {
	hs_vec3 d = hs_sub(b, a);
	double len = hs_length(d);
	if (!(len > 0.0))
		return hs_quat_identity();
	hs_vec3 x = hs_scale(d, 1.0 / len);
	hs_vec3 ref = fabs(x.z) < 0.9 ? hs_v3(0.0, 0.0, 1.0) : hs_v3(0.0, 1.0, 0.0);
	hs_vec3 z = hs_normalize(hs_sub(ref, hs_scale(x, hs_dot(ref, x))));
	return hs_quat_from_columns(x, hs_cross(z, x), z);
}

void hs_hand_joint_pose(const hs_hand_def *def, const hs_vec3 joints[HS_HAND_POINTS], hs_hand_pose *pose) {
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		pose->points[i] = joints[i];
	for (int s = 0; s < 15; ++s) { // the frames of the right hand's mirror image (hs_hand_segment_lines)
		int a = 4 * (s / 3) + s % 3;
		pose->segment[s] = segment_frame(mirror_if(def->left, joints[a]), mirror_if(def->left, joints[a + 1]));
	}
}

void hs_hand_joint_shape(const hs_hand_def *def, const hs_vec3 joints[HS_HAND_POINTS], hs_vec3 points[HS_HAND_POINTS],
                         hs_vec3 lines[HS_HAND_LINES][2]) {
	hs_hand_pose pose;
	hs_hand_joint_pose(def, joints, &pose);
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		points[i] = pose.points[i];
	for (int s = 0; lines && s < 15; ++s)
		hs_hand_segment_lines(def, pose.points, pose.segment, s, &lines[4 * s]);
}
