// joint_frame.h — where a joint recording's numbers are (scenarios/README.md, "Recorded joint
// positions"): the frame and units they are written in, mapped into the library's frame (x
// forward, y left, z up, metres; docs/model.md §1), then the scenario's rigid placement.
#ifndef HS_HARNESS_JOINT_FRAME_H
#define HS_HARNESS_JOINT_FRAME_H

#include <stdbool.h>

#include "handspring.h"

typedef enum hs_joint_frame {
	HS_JOINT_Z_UP,      // x forward, y left, z up: the library's own
	HS_JOINT_Y_UP,      // right-handed, x right, y up, z toward the viewer (OpenXR, Leap Motion)
	HS_JOINT_UNITY,     // left-handed, x right, y up, z forward
	HS_JOINT_MEDIAPIPE, // MediaPipe world landmarks: x right, y down, z away from the camera
	HS_JOINT_FRAMES
} hs_joint_frame;

typedef enum hs_joint_units { HS_JOINT_M, HS_JOINT_CM, HS_JOINT_MM, HS_JOINT_UNIT_COUNT } hs_joint_units;

extern const char *const hs_joint_frame_names[HS_JOINT_FRAMES];
extern const char *const hs_joint_unit_names[HS_JOINT_UNIT_COUNT];
#define HS_JOINT_FRAME_LIST "z_up, y_up, unity or mediapipe"
#define HS_JOINT_UNIT_LIST "m, cm or mm"

// The index of `word` (n bytes) among `names`, or -1.
int hs_joint_word(const char *word, size_t n, const char *const *names, int count);

// How a recorded point becomes a point of the scene: units, frame, then the rigid placement
// (rotation `rot` then `origin`) when `placed`.
typedef struct hs_joint_place {
	hs_joint_frame frame;
	hs_joint_units units;
	bool placed;
	hs_vec3 origin; // m
	hs_quat rot;
} hs_joint_place;

// A length in the recording's units, in metres.
double hs_joint_metres(hs_joint_units units, double v);
// A recorded point in the scene.
hs_vec3 hs_joint_place_point(const hs_joint_place *place, hs_vec3 recorded);

#endif
