// glove.h — the glove's calibration (glove.c): sensor units and joint angles, 0.5° a unit (the 1999
// paper §5.1; docs/model.md §1), and the half turn of an angle, the glove table's entry, which the
// kinematics (hand.c) also computes for an angle no table row holds. Private to model/.
#ifndef HS_GLOVE_H
#define HS_GLOVE_H

#include "hand_internal.h"

// rad per sensor unit: 0.5° (paper §5.1)
#define HS_RAD_PER_UNIT (HS_PI / 360.0)
// sensor units per rad
#define HS_UNITS_PER_RAD (360.0 / HS_PI)
// the wrist sensors read 128 at a straight wrist
#define HS_WRIST_ZERO 128
// the share of the palm arch that rolls the ring finger's base (hand.c, ARCH_SHARE)
#define HS_ARCH_RING_SHARE 0.5

// A joint rotation by a runtime angle. The volatile round trip keeps the compiler from folding
// sin/cos of an angle it can see as a constant (e.g. a posture's fixed sensor value) with its own
// correctly rounded arithmetic, which libm at run time need not match in the last bit.
static inline hs_half_turn hs_half_turn_of(double angle) {
	volatile double opaque = angle;
	double h = 0.5 * opaque; // as hs_quat_from_axis_angle
	hs_half_turn t = {hs_sin(h), hs_cos(h)};
	return t;
}

#endif
