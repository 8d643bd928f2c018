// joint_frame.c — a joint recording's frame and units into the library's frame, then the
// scenario's placement (scenarios/README.md, "Recorded joint positions"). The frame changes are
// permutations and signs, exact, so a recording written in any frame gives the same bits as the
// same recording written in z_up.
#include <string.h>

#include "joint_frame.h"

const char *const hs_joint_frame_names[HS_JOINT_FRAMES] = {"z_up", "y_up", "unity", "mediapipe"};
const char *const hs_joint_unit_names[HS_JOINT_UNIT_COUNT] = {"m", "cm", "mm"};

int hs_joint_word(const char *word, size_t n, const char *const *names, int count) {
	for (int i = 0; i < count; ++i)
		if (strlen(names[i]) == n && memcmp(word, names[i], n) == 0)
			return i;
	return -1;
}

// A division by a power of ten is correctly rounded, a product by 0.01 is not.
double hs_joint_metres(hs_joint_units units, double v) {
	return units == HS_JOINT_CM ? v / 100.0 : units == HS_JOINT_MM ? v / 1000.0 : v;
}

hs_vec3 hs_joint_place_point(const hs_joint_place *place, hs_vec3 recorded) {
	double x = hs_joint_metres(place->units, recorded.x), y = hs_joint_metres(place->units, recorded.y),
	       z = hs_joint_metres(place->units, recorded.z);
	hs_vec3 p;
	switch (place->frame) {
	case HS_JOINT_Y_UP: // forward = −z (away from the viewer), left = −x, up = y
		p = hs_v3(-z, -x, y);
		break;
	case HS_JOINT_UNITY: // forward = z, left = −x, up = y (a left-handed frame: a mirror)
		p = hs_v3(z, -x, y);
		break;
	case HS_JOINT_MEDIAPIPE: // forward = z (away from the camera), left = −x, up = −y
		p = hs_v3(z, -x, -y);
		break;
	default:
		p = hs_v3(x, y, z);
		break;
	}
	return place->placed ? hs_add(place->origin, hs_quat_rotate(place->rot, p)) : p;
}
