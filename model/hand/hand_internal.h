// hand_internal.h — a hand placed in a world (1999 paper §3.1: 20 check points, 60 check lines
// from the glove sensors and the tracked wrist).
#ifndef HS_HAND_INTERNAL_H
#define HS_HAND_INTERNAL_H

#include <stdbool.h>
#include <stdint.h>

#include "handspring.h"
#include "lanes2.h"

// The hand's path through a step (hand_sweep.c): a piece per this many degrees a finger chain or
// the wrist turns, at most HS_HAND_PATH_MAX pieces.
#define HS_HAND_PATH_DEG 10.0
#define HS_HAND_PATH_MAX 8

// Wrist poses kept beyond the last step's (for a release's velocity, manipulate.c): at least
// HS_HAND_OLDER (the default 50 ms window needs 5 at 120 frames/s), more when the world's
// release_window_s needs them (hs_hand.model.older_capacity), at most HS_HAND_OLDER_MAX.
#define HS_HAND_OLDER 7
// Pairs of different fingers (5 choose 2), hs_finger_pair.
#define HS_FINGER_PAIRS 10
#define HS_HAND_OLDER_MAX (HS_MAX_RELEASE_FRAMES - 1)

// The sine and cosine of half a joint angle (what hs_quat_from_axis_angle computes).
typedef struct hs_half_turn {
	double s, c;
} hs_half_turn;

// The glove table's rows: for sensor value v, the half turn of v × 0.5° (flexions, roll, thumb
// and index abduction, the palm arch), of −v × 0.5° (the ring finger's spread), of half that (the
// ring finger's share of the arch), of dip_per_pip × v × 0.5° (a DIP from its PIP's sensor) and of
// (v − 128) × 0.5° (the wrist).
enum { HS_GLOVE_UNIT, HS_GLOVE_MINUS, HS_GLOVE_HALF, HS_GLOVE_DIP, HS_GLOVE_WRIST, HS_GLOVE_ROWS };
typedef struct hs_glove_table {
	hs_half_turn rows[HS_GLOVE_ROWS][256];
} hs_glove_table;

// One hand in its palm frame, right-handed: check points and segment orientations.
typedef struct hs_hand_pose {
	hs_vec3 points[HS_HAND_POINTS];
	hs_quat segment[15]; // finger × 3 + segment: x along the bone, z toward the back (nail)
} hs_hand_pose;

// A hand's definition: fixed when the hand is built, read-only while stepping (in the saved state
// only through the world's checksum).
typedef struct hs_hand_model {
	hs_hand_def def;
	// how many older wrist poses are kept (hs_hand_older_capacity of the world's definition); the
	// state holds that many, the rest of hs_hand_state's arrays is unused
	int older_capacity;
	// built with the hand (hs_glove_table_build): a new reading's kinematics looks its sines up,
	// the same values the sines of its angles give
	hs_glove_table glove;
} hs_hand_model;

// A hand's per-frame state: saved, loaded and hashed (state.c's field table hand_fields lists
// every field, in the order they are written). 55 words instead of the 866 of the points and lines.
typedef struct hs_hand_state {
	hs_vec3 wrist_pos;
	hs_quat wrist_rot;
	uint8_t sensors[HS_GLOVE_SENSORS];
	hs_vec3 prev_wrist_pos; // the reading the previous points were placed from
	hs_quat prev_wrist_rot;
	uint8_t prev_sensors[HS_GLOVE_SENSORS];
	// a joint-driven hand's input (def.joint_driven; in place of the sensors): its check points in
	// the wrist frame now and at the end of the last step
	hs_vec3 joints[HS_HAND_POINTS], prev_joints[HS_HAND_POINTS];
	bool placed; // set at least once: before that its previous points are its current ones
	// tracking (hs_world_set_hand_tracked): untracked is the input for the next step; lost_frames
	// counts the steps run untracked since it was last seen (docs/model.md §3 "Tracking loss")
	bool untracked;
	int lost_frames;
	// the most open each pair of fingertips has been lately (m; pair k of hs_finger_pair): the
	// larger of their distance now and the last peak less 20 mm/s. A new grasp needs its two fingers
	// to have closed from it by grasp_close_mm (grasp.c)
	double pair_open[HS_FINGER_PAIRS];
	// the wrist poses at the ends of the steps before the last one, newest first (older_pos[0]: two
	// frames ago), older_count of them (at most model.older_capacity): a release takes the hand's
	// motion over its last frames
	int older_count;
	hs_vec3 older_pos[HS_HAND_OLDER_MAX];
	hs_quat older_rot[HS_HAND_OLDER_MAX];
	// which check points (bit i) and check lines (bit j) touched an object at the end of the last
	// step: a part found inside an object it did not reach this frame is in contact only if it
	// touched before (rectification, contact.c); else it started inside and touches nothing
	uint32_t touch_points;
	uint64_t touch_lines;
	// which check points and lines started inside an object (or were in one before they touched
	// it) and have not come out of it by grasp_release_mm since: they touch nothing (contact.c)
	uint32_t embed_points;
	uint64_t embed_lines;
} hs_hand_state;

// A hand's caches, rebuilt from the state after a load (hs_hand_refresh): the check points and
// lines now and one frame ago (the kinematics of those two readings, §3.1: bit for bit what
// hs_world_set_hand computed), the shape in the wrist frame and the bounding spheres.
typedef struct hs_hand_cache {
	// points and lines of (sensors, wrist) and of (prev_sensors, prev_wrist); zero until placed.
	// The points are placed with the reading; a finger segment's 4 lines only when something reads
	// them (hs_hand_ready_segment): bit s of lines_ready / prev_lines_ready says segment s's are
	// there. Most frames the contact tests reach a third of the segments (the rest are culled by
	// their check points), and the lines are most of what placing a hand costs.
	// Each pair lives in two buffers (point_buf, line_buf; hs_hand_init_buffers): the end of a step
	// makes the current ones the previous ones by pointing prev_* at the same buffer, nothing copied
	// (hs_hand_keep_previous), and the next placement writes the other buffer (hs_hand_place_points).
	// Pointers into the hand itself: a hand copied by value shares its original's buffers.
	hs_vec3 *points, *prev_points;
	// the same points as rows of x, y and z (placed with them), for the four-lane culls (contact.c):
	// finger f's four at [4 f, 4 f + 3]; the spare places are read past the last finger, never used
	double point_rows[3][HS_HAND_POINTS + 4];
	hs_vec3 (*lines)[2], (*prev_lines)[2];
	uint16_t lines_ready, prev_lines_ready;
	// points written in place by their user (hs_hand_points_moved, the tests): the end of a step
	// copies them and the placed lines into the previous ones, as a caller writing the current
	// points next expects the previous ones to stay
	bool copy_previous;
	hs_vec3 point_buf[2][HS_HAND_POINTS];
	hs_vec3 line_buf[2][HS_HAND_LINES][2];
	// what a segment's lines are placed from: the wrist matrix, and for a frame ago the shape in the
	// wrist frame too (prev_local; the current one is `local`), in local_buf: the same buffer while
	// the glove reading stays, the other one once it changes (hs_hand_update_shape)
	hs_mat3 place_m, prev_place_m;
	hs_hand_pose *prev_local;
	// bounding sphere of the check points and lines (radius < 0: touches nothing)
	hs_vec3 center;
	double radius;
	// the shape in the wrist frame for `sensors`, recomputed only when the glove reading changes:
	// the check points, each segment's frame, and the lines of the segments in local_ready
	hs_hand_pose *local; // check points and segment frames
	hs_hand_pose local_buf[2];
	uint8_t local_twins; // fingers (bit f) whose points and frames local_buf holds twice, the same
	hs_vec3 local_lines[HS_HAND_LINES][2];
	uint16_t local_ready;
	hs_vec3 local_center; // its bounding sphere in the wrist frame
	double local_radius;
	// the bounding sphere at the end of the last step (of prev_points and prev_lines)
	hs_vec3 prev_center;
	double prev_radius;
	// filled by hs_hand_sweep at the start of each step's hand pass: the pieces of the parts' path
	// through the frame (path_steps; for > 1, the parts at k / path_steps of the way in
	// path_points[k - 1], path_lines[k - 1]) and the bounding sphere of the whole path
	int path_steps;
	hs_vec3 path_points[HS_HAND_PATH_MAX - 1][HS_HAND_POINTS];
	hs_vec3 path_lines[HS_HAND_PATH_MAX - 1][HS_HAND_LINES][2];
	hs_vec3 sweep_center;
	double sweep_radius;
	// made by hs_hand_finger_spheres when a contact test first reads it after the points moved
	// (finger_spheres_ready, cleared by hs_hand_sweep, hs_hand_place_points and
	// hs_hand_keep_previous): finger f's 4 check points now, a frame ago and on the path between
	// lie within finger_reach[f] - finger_radius of finger_center[f], so its check lines lie within
	// finger_reach[f] of it (contact.c passes over a finger far from a part)
	hs_vec3 finger_center[5];
	double finger_reach[5];
	bool finger_spheres_ready;
	// each finger's chain in the palm frame (before the wrist sensors' turn), made from the sensor
	// values of the last shape made through it (palm_sensors, once palm_ready): a glove's deadband
	// keeps about half the fingers' readings from one frame to the next, and their chains are not
	// computed again
	hs_hand_pose palm_pose;
	uint8_t palm_sensors[HS_GLOVE_SENSORS];
	bool palm_ready;
} hs_hand_cache;

// A step's hand pass's scratch (contact.c), never read before written in the same pass: check
// points that touched and have come off the surface by less than grasp_release_mm (the contact's
// hysteresis): they stay touching; and the embedded parts of the next frame.
typedef struct hs_hand_scratch {
	uint32_t near_points, embed_points_next;
	uint64_t embed_lines_next;
} hs_hand_scratch;

// A hand of a world, its fields grouped by role as struct hs_world's are (docs/architecture.md
// "The world's data").
typedef struct hs_hand {
	hs_hand_model model;
	hs_hand_state state;
	hs_hand_cache cache;
	hs_hand_scratch scratch;
} hs_hand;

// The hand's shape in its wrist frame (depends on the sensors only) and its placement.
void hs_hand_local_shape(const hs_hand_def *def, const uint8_t sensors[HS_GLOVE_SENSORS],
                         hs_vec3 points[HS_HAND_POINTS], hs_vec3 lines[HS_HAND_LINES][2]);
// The same from the glove table of `def` (NULL: the sines computed): the same bits.
void hs_hand_local_shape_with(const hs_hand_def *def, const hs_glove_table *table,
                              const uint8_t sensors[HS_GLOVE_SENSORS], hs_vec3 points[HS_HAND_POINTS],
                              hs_vec3 lines[HS_HAND_LINES][2]);
// Check lines (§3.1) of segment s of a shape in the wrist frame (its points and segment frames).
void hs_hand_segment_lines(const hs_hand_def *def, const hs_vec3 points[HS_HAND_POINTS], const hs_quat segment[15],
                           int s, hs_vec3 out[4][2]);
// A joint-driven hand's shape in the wrist frame (hand_joints.c): the points as given, each
// segment's frame from its two points; lines (may be NULL) as hs_hand_segment_lines places them.
void hs_hand_joint_pose(const hs_hand_def *def, const hs_vec3 joints[HS_HAND_POINTS], hs_hand_pose *pose);
void hs_hand_joint_shape(const hs_hand_def *def, const hs_vec3 joints[HS_HAND_POINTS], hs_vec3 points[HS_HAND_POINTS],
                         hs_vec3 lines[HS_HAND_LINES][2]);
// Fills the glove table of a hand definition (once, when the hand is built).
void hs_glove_table_build(const hs_hand_def *def, hs_glove_table *table);
// The glove's deadband (docs/model.md §1), a play operator per sensor: used[i] is held[i] (the
// value used last) moved the least that brings it within ±band (0..HS_MAX_GLOVE_DEADBAND) of
// raw[i], the reading.
void hs_glove_deadband(const uint8_t held[HS_GLOVE_SENSORS], int band, const uint8_t raw[HS_GLOVE_SENSORS],
                       uint8_t used[HS_GLOVE_SENSORS]);
void hs_hand_place(const hs_vec3 local_points[HS_HAND_POINTS], const hs_vec3 local_lines[HS_HAND_LINES][2],
                   hs_vec3 wrist_position, hs_quat wrist_orientation, hs_vec3 points[HS_HAND_POINTS],
                   hs_vec3 lines[HS_HAND_LINES][2]);
// Recomputes the wrist-frame shape cache and its bounding sphere from hand->sensors.
void hs_hand_update_shape(hs_hand *hand);
// The largest of r_sq and the squared distances from c to the n vectors v (a NaN distance is
// passed over; a maximum, so the bits do not depend on the order it is taken in).
// With SSE2, two distances at a time, one per lane, each as hs_length_sq(hs_sub(v, c)).
static inline double hs_hand_farthest_sq(hs_vec3 c, const hs_vec3 *v, int n, double r_sq) {
	int i = 0;
#if defined(__SSE2__)
	const __m128d cx = _mm_set1_pd(c.x), cy = _mm_set1_pd(c.y), cz = _mm_set1_pd(c.z);
	__m128d most = _mm_set1_pd(r_sq);
	for (; i + 1 < n; i += 2) {
		hs_lanes2 in = hs_lanes2_load(&v[i], &v[i + 1]);
		__m128d dx = _mm_sub_pd(in.x, cx), dy = _mm_sub_pd(in.y, cy), dz = _mm_sub_pd(in.z, cz);
		__m128d d = _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz));
		most = _mm_max_pd(d, most); // d > most ? d : most, lane by lane (NaN: most)
	}
	double lanes[2];
	_mm_storeu_pd(lanes, most);
	r_sq = lanes[1] > lanes[0] ? lanes[1] : lanes[0];
#endif
	for (; i < n; ++i) {
		double d = hs_length_sq(hs_sub(v[i], c));
		r_sq = d > r_sq ? d : r_sq;
	}
	return r_sq;
}

// Points the current and previous points, lines and shape at their own buffers (a new hand, after
// memset: hs_world_add_hand).
void hs_hand_init_buffers(hs_hand *hand);
// Places the check points from the shape cache and the wrist pose; the lines wait (lines_ready 0).
void hs_hand_place_points(hs_hand *hand);
// Makes point_rows the points again: for code that writes a hand's points itself (the tests); from
// then on the end of a step copies the points into the previous ones (copy_previous).
void hs_hand_points_moved(hs_hand *hand);
#define HS_HAND_ALL_SEGMENTS 0x7fffu
// The parts of the fingers in `fingers` (bit f) when each finger has `per` in a row: check points
// (4: 4 f to 4 f + 3) or finger segments (3: 3 f to 3 f + 2).
static inline uint32_t hs_finger_parts(unsigned fingers, int per) {
	uint32_t parts = 0, one = (1u << per) - 1u;
	for (int f = 0; f < 5; ++f)
		if (fingers >> f & 1u)
			parts |= one << (per * f);
	return parts;
}
// The index of the lowest set bit of m (not 0): the loops over a mask of parts or fingers.
static inline int hs_lowest_bit(uint32_t m) {
#if defined(__GNUC__)
	return __builtin_ctz(m);
#else
	int i = 0;
	while (!(m >> i & 1u))
		++i;
	return i;
#endif
}
// Places finger segment s's lines now and a frame ago where they are not yet: the same bits as
// placing all of them with the reading.
void hs_hand_place_segment(hs_hand *hand, int s);
static inline void hs_hand_ready_segment(hs_hand *hand, int s) {
	if (!((unsigned)(hand->cache.lines_ready & hand->cache.prev_lines_ready) >> s & 1u))
		hs_hand_place_segment(hand, s);
}
// Every segment's lines, now and a frame ago (a path through the frame reads them all).
void hs_hand_ready_all(hs_hand *hand);
// The world bounding sphere from the wrist pose and the shape cache (radius -1 before placement).
void hs_hand_update_bounds(hs_hand *hand);
// The reading of this frame becomes the previous one (the end of a step, a first placement).
void hs_hand_keep_previous(hs_hand *hand);
// The end of a step, before hs_hand_keep_previous: the previous wrist pose joins the older ones.
void hs_hand_age_wrist(hs_hand *hand);
// The wrist pose `frames` steps before this frame's (0: this frame's, 1: the previous one), 0 ≤
// frames ≤ older_count + 1.
void hs_hand_past_wrist(const hs_hand *hand, int frames, hs_vec3 *pos, hs_quat *rot);
// How many frames a release's velocity is taken over for a window of `window_s` at `dt`: the
// nearest whole number, at least 1, at most HS_MAX_RELEASE_FRAMES.
int hs_release_window_frames(double window_s, double dt);
// The older wrist poses a hand keeps for that window: its frames less one (the pose a frame back
// is prev_wrist), at least HS_HAND_OLDER.
int hs_hand_older_capacity(double window_s, double dt);
// Rebuilds every cache from the state alone (after hs_world_load_state).
void hs_hand_refresh(hs_hand *hand);

#endif
