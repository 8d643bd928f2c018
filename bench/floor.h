// floor.h — the floor of the honest frame's contact detection (bench/floor.c, floor_detect.c): its
// input in structures of arrays, its memory from frame to frame, and what it finds.
#ifndef HS_BENCH_FLOOR_H
#define HS_BENCH_FLOOR_H

#include "bench.h"

/// The hand after the step: 20 check points; 60 check lines, their first ends at [0, 60) and their
/// second ends at [60, 120) (m).
typedef struct floor_hand {
	double px[HS_HAND_POINTS], py[HS_HAND_POINTS], pz[HS_HAND_POINTS];
	double lx[2 * HS_HAND_LINES], ly[2 * HS_HAND_LINES], lz[2 * HS_HAND_LINES];
} floor_hand;

/// The cubes' poses: centres (m) and unit quaternions.
typedef struct floor_poses {
	double x[BENCH_FLOOR_CUBES], y[BENCH_FLOOR_CUBES], z[BENCH_FLOOR_CUBES];
	double qw[BENCH_FLOOR_CUBES], qx[BENCH_FLOOR_CUBES], qy[BENCH_FLOOR_CUBES], qz[BENCH_FLOOR_CUBES];
} floor_poses;

/// One frame: the hand now, the cubes where they are tested and where they were when it began.
typedef struct floor_input {
	floor_hand hand;
	floor_poses now, before;
	uint16_t held; ///< bit i: cube i is held (it moves with the hand; a moving cube)
} floor_input;

/// What the floor keeps from frame to frame (as handspring's hand does: which parts touch, which
/// started inside), and its constants.
typedef struct floor_state {
	uint32_t touch_points, embed_points;
	uint64_t touch_lines, embed_lines;
	double margin;        ///< m: grasp_release_mm
	double finger_radius; ///< m: the check lines' distance from the finger axes
	bool forget;          ///< true: no memory of parts that started inside (to show the comparison fails)
} floor_state;

/// The contacts of one frame: per cube, bit i of points[c] for check point i, bit j of lines[c] for line j.
typedef struct floor_found {
	uint32_t points[BENCH_FLOOR_CUBES];
	uint64_t lines[BENCH_FLOOR_CUBES];
} floor_found;

/// One frame of the check: `in` now, `prev` the frame before (its hand a frame ago, its cubes where
/// that frame began; the first frame passes itself).
void floor_detect(floor_state *st, const floor_input *in, const floor_input *prev, floor_found *out);

#endif
