// hand.h — what the postures (hand_posture.c) read of the glove-driven hand's kinematics (hand.c,
// the 1999 paper §3.1), for a right hand in the wrist frame. Private to model/.
#ifndef HS_HAND_H
#define HS_HAND_H

#include <stdint.h>

#include "hand_internal.h"

// Check point i of reading s.
hs_vec3 hs_hand_right_point(const hs_hand_def *def, const uint8_t s[HS_GLOVE_SENSORS], int i);
// The thumb tip (check point 3) of reading s, the thumb's chain alone.
hs_vec3 hs_hand_thumb_tip(const hs_hand_def *def, const uint8_t s[HS_GLOVE_SENSORS]);
// The thumb metacarpal's frame before its roll: splay, abduction by the angle, tilt; x along the bone.
hs_quat hs_hand_thumb_base(double thumb_abduction);

#endif
