// hand.c — the kinematics of the glove-driven virtual hand of the 1999 paper (§3.1, §5.1): the
// chains of the 20 check points and the 60 check lines, palm and wrist, the placement in the world,
// and the caches a hand keeps between readings. The glove's calibration: glove.c; the named
// postures: hand_posture.c.
//
// Frames. The wrist frame (pose from the tracker) has x toward the fingertips, y toward the
// thumb of a right hand, z out of the back of the hand (the palm faces −z). The palm frame is
// the wrist frame turned by wrist pitch (about y) and then yaw (about z); every finger hangs off
// the palm frame. A left hand is computed as a right hand and mirrored (y → −y) in the wrist
// frame, before the wrist pose is applied.
//
// Every joint rotation is built from a runtime angle (sensor value × 0.5°), and fixed design
// rotations use exact cosines (rational, half-angle by sqrt, which is correctly rounded), so no
// sin/cos of a literal is ever folded at compile time with a result that could differ from libm's.
//
// Contract notes not written in handspring.h: `def` must be non-NULL and valid (finite, positive
// lengths and radius) for every function here; a NULL `sensors`, `joints` or output array makes
// the call return without writing anything (hs_hand_joints_from_sensors then returns zero angles).
// The functions never allocate.
#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#if defined(HS_SELFCHECK)
#include <stdio.h>
#include <stdlib.h>
#endif

#include "glove.h"
#include "hand.h"
#include "hand_internal.h"
#include "inline.h"

#include "lanes2.h"
#include "lanes4.h"

// ---------------------------------------------------------------------------------------------
// Defaults

hs_hand_def hs_default_hand_def(void) {
	// Typical adult right hand (round numbers within anthropometric ranges for adults): MCP
	// knuckles at the far edge of the palm, fingers about 2 cm apart, the thumb's CMC joint near
	// the wrist on the thumb side, below the palm.
	hs_hand_def d;
	memset(&d, 0, sizeof d); // padding too: a definition may be hashed or compared bytewise
	d.left = false;
	d.finger_radius = 0.008;
	static const double lengths[5][3] = {
	    {0.040, 0.032, 0.027}, // thumb: metacarpal, proximal, distal
	    {0.040, 0.025, 0.020}, // index: proximal, middle, distal phalanx
	    {0.045, 0.028, 0.021}, // middle
	    {0.042, 0.027, 0.020}, // ring
	    {0.033, 0.020, 0.018}, // little
	};
	for (int f = 0; f < 5; f++)
		for (int s = 0; s < 3; s++)
			d.segment_length[f][s] = lengths[f][s];
	d.base[0] = hs_v3(0.020, 0.025, -0.015); // thumb CMC
	d.base[1] = hs_v3(0.095, 0.025, 0.0);    // index MCP
	d.base[2] = hs_v3(0.095, 0.005, 0.0);    // middle MCP
	d.base[3] = hs_v3(0.092, -0.013, 0.0);   // ring MCP
	d.base[4] = hs_v3(0.090, -0.030, 0.0);   // little MCP
	d.dip_per_pip = 2.0 / 3.0;               // DIP is not sensed (docs/model.md §1)
	return d;
}

// ---------------------------------------------------------------------------------------------
// Kinematics

static const hs_vec3 X_AXIS = {1.0, 0.0, 0.0};
static const hs_vec3 Y_AXIS = {0.0, 1.0, 0.0};
static const hs_vec3 Z_AXIS = {0.0, 0.0, 1.0};

// A rotation about a coordinate axis given by its exact cosine c and the sign of its sine:
// q = (cos θ/2, sin θ/2 · axis), with cos θ/2 = √((1 + c)/2), |sin θ/2| = √((1 − c)/2).
static hs_quat exact_rotation(hs_vec3 axis, double c, double sign) {
	double w = sqrt(0.5 * (1.0 + c)), s = sign * sqrt(0.5 * (1.0 - c));
	return hs_q(w, axis.x * s, axis.y * s, axis.z * s);
}

// hs_quat_from_axis_angle from the half angle's sine and cosine: the same operations
static hs_quat turn_about(hs_vec3 axis, hs_half_turn t) { return hs_q(t.c, axis.x * t.s, axis.y * t.s, axis.z * t.s); }
static hs_quat joint_rotation(hs_vec3 axis, double angle) { return turn_about(axis, hs_half_turn_of(angle)); }

// Thumb design (not sensed; the paper's Fig. 1 leaves it open). At zero sensors the thumb's
// metacarpal points along x turned 22.6° toward +y (cos = 12/13) about the palm z, and tilted
// 16.3° toward the palm (cos = 24/25) about its own y: an open thumb beside the palm. The thumb's
// own frame has x along the bone and z out of the nail; with roll 0 the nail faces +y of the
// metacarpal frame, so flexion (about the thumb's local y, like a finger) swings the thumb
// across the palm toward the fingers; roll turns the nail toward +z, and at roll 90° flexion
// swings it straight toward the palm side (−z): opposition, pad facing the fingertips.
// Thumb abduction turns the metacarpal further toward +y, about the palm z.
#define THUMB_SPLAY_COS (12.0 / 13.0)
#define THUMB_TILT_COS (24.0 / 25.0)

static hs_quat thumb_splay(void) { return exact_rotation(Z_AXIS, THUMB_SPLAY_COS, 1.0); }
// tilt toward −z (about +y), then the −90° turn about x that puts the nail (local z) on +y
static hs_quat thumb_tilt_and_nail(void) {
	hs_quat tilt = exact_rotation(Y_AXIS, THUMB_TILT_COS, 1.0);
	hs_quat nail = exact_rotation(X_AXIS, 0.0, -1.0);
	return hs_quat_mul(tilt, nail);
}

// The palm arch rolls the ring and little finger bases toward the palm (this fraction of the
// arch angle), about the line through the middle finger's MCP parallel to the palm's x.
static const double ARCH_SHARE[4] = {0.0, 0.0, HS_ARCH_RING_SHARE, 1.0};

typedef hs_hand_pose hand_pose; // (hand_internal.h: a hand keeps one, its fingers' cache)

// What the kinematics of one reading reads: its angles, and the glove table (NULL: the sines
// are computed) with the reading it is indexed by.
typedef struct reading {
	const hs_hand_def *def;
	hs_hand_joints j;
	const hs_glove_table *table;
	const uint8_t *v;
} reading;

// The half turn of a joint angle: the table's row at the sensor's value, or computed.
static hs_half_turn turn_of(const reading *r, int row, int sensor, double angle) {
	return r->table ? r->table->rows[row][r->v[sensor]] : hs_half_turn_of(angle);
}

// Points and frames of one chain from its base frame `q` and its three flexions; the first
// flexion (thumb: none, the metacarpal is rigid in its base frame) is in flex[0], and turn[s] is
// its half turn (read only where the flexion is not 0).
static HS_FORCE_INLINE void chain(const hs_hand_def *def, int f, hs_vec3 base, hs_quat q, const double flex[3],
                  const hs_half_turn turn[3], hand_pose *out) {
	hs_vec3 p = base;
	out->points[f * 4] = p;
	for (int s = 0; s < 3; s++) {
		if (flex[s] != 0.0)
			q = hs_quat_mul(q, turn_about(Y_AXIS, turn[s]));
		out->segment[f * 3 + s] = q;
		p = hs_add(p, hs_quat_rotate(q, hs_v3(def->segment_length[f][s], 0.0, 0.0)));
		out->points[f * 4 + s + 1] = p;
	}
}

// The half turn of a flexion, looked up only when it turns.
static hs_half_turn flex_turn(const reading *r, int row, int sensor, double angle) {
	hs_half_turn none = {0.0, 1.0};
	return angle != 0.0 ? turn_of(r, row, sensor, angle) : none;
}

static void thumb_pose(const reading *r, hand_pose *out) {
	const hs_hand_joints *j = &r->j;
	hs_quat q = hs_quat_mul(thumb_splay(), turn_about(Z_AXIS, turn_of(r, HS_GLOVE_UNIT, HS_SENSOR_THUMB_ABDUCTION,
	                                                                      j->thumb_abduction)));
	q = hs_quat_mul(q, thumb_tilt_and_nail());
	q = hs_quat_mul(q, turn_about(X_AXIS, turn_of(r, HS_GLOVE_UNIT, HS_SENSOR_THUMB_ROLL, j->thumb_roll)));
	const double flex[3] = {0.0, j->thumb_mcp, j->thumb_ip};
	const hs_half_turn turn[3] = {{0.0, 1.0},
	                              flex_turn(r, HS_GLOVE_UNIT, HS_SENSOR_THUMB_MCP, j->thumb_mcp),
	                              flex_turn(r, HS_GLOVE_UNIT, HS_SENSOR_THUMB_IP, j->thumb_ip)};
	chain(r->def, 0, r->def->base[0], q, flex, turn, out);
}

// The half turn of finger k's abduction about the palm z at its MCP: middle fixed, index toward
// +y, ring and little toward −y. *spread: the angle.
static hs_half_turn spread_turn(const reading *r, int k, double *spread) {
	const hs_hand_joints *j = &r->j;
	*spread = 0.0;
	if (k == 0)
		*spread = j->abduction[0];
	else if (k == 2)
		*spread = -j->abduction[1];
	else if (k == 3)
		*spread = -(j->abduction[1] + j->abduction[2]);
	if (k == 3) // the sum of two readings: no row
		return hs_half_turn_of(*spread);
	if (k == 1) // the angle 0: the row's value 0 (0 × 0.5°)
		return r->table ? r->table->rows[HS_GLOVE_UNIT][0] : hs_half_turn_of(*spread);
	return k == 0 ? turn_of(r, HS_GLOVE_UNIT, HS_SENSOR_INDEX_MIDDLE_ABDUCTION, *spread)
	              : turn_of(r, HS_GLOVE_MINUS, HS_SENSOR_MIDDLE_RING_ABDUCTION, *spread);
}

static void finger_pose(const reading *r, int k, hand_pose *out) {
	const hs_hand_def *def = r->def;
	const hs_hand_joints *j = &r->j;
	int f = k + 1; // k: 0 index .. 3 little
	double spread;
	hs_quat q = turn_about(Z_AXIS, spread_turn(r, k, &spread));
	hs_vec3 base = def->base[f];
	double arch = ARCH_SHARE[k] * j->palm_arch;
	if (arch != 0.0) {
		// positive roll about x moves a base on the −y side of the pivot toward −z (the palm)
		hs_quat roll = turn_about(X_AXIS, turn_of(r, k == 3 ? HS_GLOVE_UNIT : HS_GLOVE_HALF, HS_SENSOR_PALM_ARCH, arch));
		hs_vec3 pivot = hs_v3(base.x, def->base[2].y, def->base[2].z);
		base = hs_add(pivot, hs_quat_rotate(roll, hs_sub(base, pivot)));
		q = hs_quat_mul(roll, q);
	}
	const double flex[3] = {j->mcp[k], j->pip[k], j->dip[k]};
	int mcp = HS_SENSOR_INDEX_MCP + 2 * k, pip = HS_SENSOR_INDEX_PIP + 2 * k;
	const hs_half_turn turn[3] = {flex_turn(r, HS_GLOVE_UNIT, mcp, flex[0]), flex_turn(r, HS_GLOVE_UNIT, pip, flex[1]),
	                              flex_turn(r, HS_GLOVE_DIP, pip, flex[2])};
	chain(def, f, base, q, flex, turn, out);
}

#if defined(__SSE2__)
// Two segment frames turned by q: hs_quat_mul(q, b0) and hs_quat_mul(q, b1), one per lane, each
// lane doing that function's products and sums in its order (the same bits).
static void turn_two_frames(hs_quat q, const hs_quat *b0, const hs_quat *b1, hs_quat *o0, hs_quat *o1) {
	const __m128d aw = _mm_set1_pd(q.w), ax = _mm_set1_pd(q.x), ay = _mm_set1_pd(q.y), az = _mm_set1_pd(q.z);
	__m128d bw = _mm_set_pd(b1->w, b0->w), bx = _mm_set_pd(b1->x, b0->x), by = _mm_set_pd(b1->y, b0->y),
	        bz = _mm_set_pd(b1->z, b0->z);
	__m128d w = _mm_sub_pd(_mm_sub_pd(_mm_sub_pd(_mm_mul_pd(aw, bw), _mm_mul_pd(ax, bx)), _mm_mul_pd(ay, by)),
	                       _mm_mul_pd(az, bz));
	__m128d x = _mm_sub_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(aw, bx), _mm_mul_pd(ax, bw)), _mm_mul_pd(ay, bz)),
	                       _mm_mul_pd(az, by));
	__m128d y = _mm_add_pd(_mm_add_pd(_mm_sub_pd(_mm_mul_pd(aw, by), _mm_mul_pd(ax, bz)), _mm_mul_pd(ay, bw)),
	                       _mm_mul_pd(az, bx));
	__m128d z = _mm_add_pd(_mm_sub_pd(_mm_add_pd(_mm_mul_pd(aw, bz), _mm_mul_pd(ax, by)), _mm_mul_pd(ay, bx)),
	                       _mm_mul_pd(az, bw));
	double lw[2], lx[2], ly[2], lz[2];
	_mm_storeu_pd(lw, w);
	_mm_storeu_pd(lx, x);
	_mm_storeu_pd(ly, y);
	_mm_storeu_pd(lz, z);
	*o0 = hs_q(lw[0], lx[0], ly[0], lz[0]);
	*o1 = hs_q(lw[1], lx[1], ly[1], lz[1]);
}
#endif

// The fingers `fingers` (bit f) of `in` turned by q into `pose`: each point hs_quat_rotate(q, p),
// each segment frame hs_quat_mul(q, s). With SSE2, two at a time, one per lane, each lane doing
// those functions' operations in their order (the same bits).
static void turn_pose(hs_quat q, const hand_pose *in, hand_pose *pose, unsigned fingers) {
	for (; fingers; fingers &= fingers - 1u) {
		int f = hs_lowest_bit(fingers), i = 4 * f, s = 3 * f;
#if defined(__SSE2__)
		for (int k = 0; k < 4; k += 2)
			hs_lanes2_store(hs_lanes2_rotate(q, hs_lanes2_load(&in->points[i + k], &in->points[i + k + 1])),
			                &pose->points[i + k], &pose->points[i + k + 1]);
		turn_two_frames(q, &in->segment[s], &in->segment[s + 1], &pose->segment[s], &pose->segment[s + 1]);
		pose->segment[s + 2] = hs_quat_mul(q, in->segment[s + 2]);
#else
		for (int k = 0; k < 4; k++)
			pose->points[i + k] = hs_quat_rotate(q, in->points[i + k]);
		for (int k = 0; k < 3; k++)
			pose->segment[s + k] = hs_quat_mul(q, in->segment[s + k]);
#endif
	}
}

// The sensors each finger's chain reads (bit s: sensor s), thumb, index .. little.
#define SENSOR(s) (1u << (s))
static const uint32_t FINGER_SENSORS[5] = {
    SENSOR(HS_SENSOR_THUMB_ROLL) | SENSOR(HS_SENSOR_THUMB_MCP) | SENSOR(HS_SENSOR_THUMB_IP) |
        SENSOR(HS_SENSOR_THUMB_ABDUCTION),
    SENSOR(HS_SENSOR_INDEX_MCP) | SENSOR(HS_SENSOR_INDEX_PIP) | SENSOR(HS_SENSOR_INDEX_MIDDLE_ABDUCTION),
    SENSOR(HS_SENSOR_MIDDLE_MCP) | SENSOR(HS_SENSOR_MIDDLE_PIP),
    SENSOR(HS_SENSOR_RING_MCP) | SENSOR(HS_SENSOR_RING_PIP) | SENSOR(HS_SENSOR_MIDDLE_RING_ABDUCTION) |
        SENSOR(HS_SENSOR_PALM_ARCH),
    SENSOR(HS_SENSOR_LITTLE_MCP) | SENSOR(HS_SENSOR_LITTLE_PIP) | SENSOR(HS_SENSOR_MIDDLE_RING_ABDUCTION) |
        SENSOR(HS_SENSOR_RING_LITTLE_ABDUCTION) | SENSOR(HS_SENSOR_PALM_ARCH)};
#define WRIST_SENSORS (SENSOR(HS_SENSOR_WRIST_PITCH) | SENSOR(HS_SENSOR_WRIST_YAW))

// The sensors (bit s) whose values differ between a and b.
static uint32_t sensors_changed(const uint8_t a[HS_GLOVE_SENSORS], const uint8_t b[HS_GLOVE_SENSORS]) {
	uint32_t changed = 0;
	int i = 0;
#if defined(__SSE2__)
	__m128i eq = _mm_cmpeq_epi8(_mm_loadu_si128((const __m128i *)(const void *)a),
	                            _mm_loadu_si128((const __m128i *)(const void *)b));
	changed = ~(uint32_t)_mm_movemask_epi8(eq) & 0xFFFFu;
	i = 16;
#endif
	for (; i < HS_GLOVE_SENSORS; ++i)
		changed |= (uint32_t)(a[i] != b[i]) << i;
	return changed;
}

// the whole hand in the wrist frame of a right hand; `cache` (NULL: none) keeps each finger's
// chain for the sensors it reads (the same function of the same values: the same bits). Returns
// the fingers (bit f) whose points and frames are those of the last shape made through the cache:
// chain kept, wrist sensors unchanged; their points and frames in `out` are left as they are.
static unsigned hand_pose_wrist(const reading *r, hand_pose *out, hs_hand *cache) {
	const hs_hand_joints *j = &r->j;
	hand_pose *palm_pose = cache ? &cache->cache.palm_pose : out;
	unsigned same = 0, kept = 0; // kept: fingers whose chains the cache holds for these sensors
	if (cache) {
		uint32_t changed = cache->cache.palm_ready ? sensors_changed(cache->cache.palm_sensors, r->v) : ~0u;
		for (int f = 0; f < 5; f++)
			kept |= (unsigned)!(changed & FINGER_SENSORS[f]) << f;
		same = changed & WRIST_SENSORS ? 0u : kept;
		memcpy(cache->cache.palm_sensors, r->v, sizeof cache->cache.palm_sensors);
		cache->cache.palm_ready = true;
	}
	for (int f = 0; f < 5; f++) {
		if (kept >> f & 1u)
			continue;
		if (f == 0)
			thumb_pose(r, palm_pose);
		else
			finger_pose(r, f - 1, palm_pose);
	}
	if (j->wrist_pitch == 0.0 && j->wrist_yaw == 0.0) { // palm frame = wrist frame
		for (unsigned todo = palm_pose != out ? 31u & ~same : 0u; todo; todo &= todo - 1u) {
			int f = hs_lowest_bit(todo);
			memcpy(&out->points[4 * f], &palm_pose->points[4 * f], 4 * sizeof out->points[0]);
			memcpy(&out->segment[3 * f], &palm_pose->segment[3 * f], 3 * sizeof out->segment[0]);
		}
		return same;
	}
	hs_quat palm = hs_quat_mul(turn_about(Z_AXIS, turn_of(r, HS_GLOVE_WRIST, HS_SENSOR_WRIST_YAW, j->wrist_yaw)),
	                           turn_about(Y_AXIS, turn_of(r, HS_GLOVE_WRIST, HS_SENSOR_WRIST_PITCH, j->wrist_pitch)));
	turn_pose(palm, palm_pose, out, 31u & ~same); // the same fingers' turned points are the last shape's
	return same;
}

static hs_vec3 mirror_if(bool left, hs_vec3 v) { return left ? hs_v3(v.x, -v.y, v.z) : v; }

// The shape in the wrist frame without its lines: the check points (mirrored for a left hand)
// and each segment's frame. With a cache (the hand), `out` is its local shape, which holds the
// last shape made through it: fingers that stayed the same (returned) are not written again.
static unsigned local_pose(const hs_hand_def *def, const hs_glove_table *table, const uint8_t sensors[HS_GLOVE_SENSORS],
                           hand_pose *out, hs_hand *cache) {
	reading r = {def, hs_hand_joints_from_sensors(def, sensors), table, sensors};
	unsigned same = hand_pose_wrist(&r, out, cache);
	for (unsigned todo = def->left ? 31u & ~same : 0u; todo; todo &= todo - 1u) {
		int f = hs_lowest_bit(todo);
		for (int i = 4 * f; i < 4 * f + 4; i++)
			out->points[i] = mirror_if(true, out->points[i]);
	}
	return same;
}

void hs_hand_local_shape_with(const hs_hand_def *def, const hs_glove_table *table,
                              const uint8_t sensors[HS_GLOVE_SENSORS], hs_vec3 points[HS_HAND_POINTS],
                              hs_vec3 lines[HS_HAND_LINES][2]) {
	hand_pose pose;
	local_pose(def, table, sensors, &pose, NULL);
	memcpy(points, pose.points, sizeof pose.points);
	for (int s = 0; s < 15; s++)
		hs_hand_segment_lines(def, pose.points, pose.segment, s, &lines[s * 4]);
}

void hs_hand_local_shape(const hs_hand_def *def, const uint8_t sensors[HS_GLOVE_SENSORS],
                         hs_vec3 points[HS_HAND_POINTS], hs_vec3 lines[HS_HAND_LINES][2]) {
	hs_hand_local_shape_with(def, NULL, sensors, points, lines);
}

#if HS_LANES4
// place_vectors_rows four vectors at a time, one in each lane of AVX registers (the same bits): the
// first n - n % 4 of them.
HS_AVX static void place_vectors_avx(const hs_mat3 *m, const hs_vec3 *w, const hs_vec3 *v, hs_vec3 *out, int n,
                                     double (*rows)[HS_HAND_POINTS + 4]) {
	const hs_mat3 mm = *m; // (copies: out cannot change them, their broadcasts leave the loop)
	const hs_vec3 ww = *w;
	for (int i = 0; i + 3 < n; i += 4) {
		hs_lanes4 o = hs_lanes4_place(mm, ww, hs_lanes4_load(&v[i]));
		hs_lanes4_store(o, &out[i]);
		if (rows) {
			_mm256_storeu_pd(&rows[0][i], o.x);
			_mm256_storeu_pd(&rows[1][i], o.y);
			_mm256_storeu_pd(&rows[2][i], o.z);
		}
	}
}
#endif

// out[i] = w + m v[i] for n vectors (at most 2 HS_HAND_LINES): hs_add(w, hs_mat3_mul(m, v[i])); with
// `rows`, the same values also as rows of x, y and z (the hand's point_rows). With SSE2, two vectors
// at a time, one in each lane, with AVX four: each lane does that expression's products and sums in
// its order, so the bits are the same (no fused multiply-add: -ffp-contract=off).
static HS_FORCE_INLINE void place_vectors_two(hs_mat3 m, hs_vec3 w, const hs_vec3 *v, hs_vec3 *out, int i, int n,
                                              double (*rows)[HS_HAND_POINTS + 4]) {
#if defined(__SSE2__)
	const __m128d r0x = _mm_set1_pd(m.r0.x), r0y = _mm_set1_pd(m.r0.y), r0z = _mm_set1_pd(m.r0.z);
	const __m128d r1x = _mm_set1_pd(m.r1.x), r1y = _mm_set1_pd(m.r1.y), r1z = _mm_set1_pd(m.r1.z);
	const __m128d r2x = _mm_set1_pd(m.r2.x), r2y = _mm_set1_pd(m.r2.y), r2z = _mm_set1_pd(m.r2.z);
	const __m128d wx = _mm_set1_pd(w.x), wy = _mm_set1_pd(w.y), wz = _mm_set1_pd(w.z);
	for (; i + 1 < n; i += 2) {
		hs_lanes2 in = hs_lanes2_load(&v[i], &v[i + 1]);
		__m128d x = in.x, y = in.y, z = in.z;
		__m128d ox = _mm_add_pd(wx, _mm_add_pd(_mm_add_pd(_mm_mul_pd(r0x, x), _mm_mul_pd(r0y, y)), _mm_mul_pd(r0z, z)));
		__m128d oy = _mm_add_pd(wy, _mm_add_pd(_mm_add_pd(_mm_mul_pd(r1x, x), _mm_mul_pd(r1y, y)), _mm_mul_pd(r1z, z)));
		__m128d oz = _mm_add_pd(wz, _mm_add_pd(_mm_add_pd(_mm_mul_pd(r2x, x), _mm_mul_pd(r2y, y)), _mm_mul_pd(r2z, z)));
		hs_lanes2_store((hs_lanes2){ox, oy, oz}, &out[i], &out[i + 1]);
		if (rows) {
			_mm_storeu_pd(&rows[0][i], ox);
			_mm_storeu_pd(&rows[1][i], oy);
			_mm_storeu_pd(&rows[2][i], oz);
		}
	}
#endif
	for (; i < n; i++) {
		out[i] = hs_add(w, hs_mat3_mul(m, v[i]));
		if (rows) {
			rows[0][i] = out[i].x;
			rows[1][i] = out[i].y;
			rows[2][i] = out[i].z;
		}
	}
}

#if HS_LANES4 && defined(HS_SELFCHECK)
// Sanitizer builds: the four lanes' placement has the bits of the two-lane path's.
static void check_place_four(hs_mat3 m, hs_vec3 w, const hs_vec3 *v, const hs_vec3 *out, int n,
                             double (*rows)[HS_HAND_POINTS + 4]) {
	hs_vec3 two[2 * HS_HAND_LINES];
	double two_rows[3][HS_HAND_POINTS + 4];
	if (n > 2 * HS_HAND_LINES || (rows && n > HS_HAND_POINTS + 4))
		abort();
	place_vectors_two(m, w, v, two, 0, n, rows ? two_rows : NULL);
	bool same = memcmp(two, out, (size_t)n * sizeof two[0]) == 0;
	for (int k = 0; rows && k < 3; ++k)
		same = same && memcmp(two_rows[k], rows[k], (size_t)n * sizeof rows[k][0]) == 0;
	if (!same) {
		fprintf(stderr, "selfcheck: vectors placed in four lanes differ from the two-lane path\n");
		abort();
	}
}
#else
static inline void check_place_four(hs_mat3 m, hs_vec3 w, const hs_vec3 *v, const hs_vec3 *out, int n,
                                    double (*rows)[HS_HAND_POINTS + 4]) {
	(void)m, (void)w, (void)v, (void)out, (void)n, (void)rows;
}
#endif

static HS_FORCE_INLINE void place_vectors_rows(hs_mat3 m, hs_vec3 w, const hs_vec3 *v, hs_vec3 *out, int n,
                                               double (*rows)[HS_HAND_POINTS + 4]) {
	int i = 0;
#if HS_LANES4
	if (hs_cpu_has_avx()) {
		place_vectors_avx(&m, &w, v, out, n, rows);
		i = n - n % 4;
	}
#endif
	place_vectors_two(m, w, v, out, i, n, rows);
#if HS_LANES4
	if (hs_cpu_has_avx())
		check_place_four(m, w, v, out, n, rows);
#endif
}

static HS_FORCE_INLINE void place_vectors(hs_mat3 m, hs_vec3 w, const hs_vec3 *v, hs_vec3 *out, int n) {
	place_vectors_rows(m, w, v, out, n, NULL);
}

void hs_hand_place(const hs_vec3 local_points[HS_HAND_POINTS], const hs_vec3 local_lines[HS_HAND_LINES][2],
                   hs_vec3 wrist_position, hs_quat wrist_orientation, hs_vec3 points[HS_HAND_POINTS],
                   hs_vec3 lines[HS_HAND_LINES][2]) {
	hs_mat3 m = hs_mat3_from_quat(wrist_orientation); // 140 vectors, one orientation
	if (points != NULL)
		place_vectors(m, wrist_position, local_points, points, HS_HAND_POINTS);
	if (lines != NULL)
		place_vectors(m, wrist_position, &local_lines[0][0], &lines[0][0], 2 * HS_HAND_LINES);
}

void hs_hand_kinematics(const hs_hand_def *def, hs_vec3 wrist_position, hs_quat wrist_orientation,
                        const uint8_t sensors[HS_GLOVE_SENSORS], hs_vec3 points[HS_HAND_POINTS],
                        hs_vec3 lines[HS_HAND_LINES][2]) {
	if (def == NULL || sensors == NULL) // documented: nothing written
		return;
	hs_vec3 local_points[HS_HAND_POINTS], local_lines[HS_HAND_LINES][2];
	hs_hand_local_shape(def, sensors, local_points, local_lines);
	hs_hand_place(local_points, (const hs_vec3(*)[2])local_lines, wrist_position, wrist_orientation, points, lines);
}

// ---------------------------------------------------------------------------------------------
// A hand in a world: the caches derived from its sensors and wrist pose (hand_internal.h)

// Segment s's lines in the wrist frame, computed once for a reading.
static void ready_local(hs_hand *hand, int s) {
	if ((unsigned)hand->cache.local_ready >> s & 1u)
		return;
	hs_hand_segment_lines(&hand->model.def, hand->cache.local->points, hand->cache.local->segment, s, &hand->cache.local_lines[4 * s]);
	hand->cache.local_ready = (uint16_t)(hand->cache.local_ready | 1u << s);
}

// The bounding sphere of a shape in the wrist frame: about the mean check point, through the
// farthest check point and finger_radius beyond, where the line ends beside it lie (each is
// finger_radius from a check point; the relative slack is far above rounding). The lines are not
// computed for it: most frames the contact tests read a third of them.
static void local_bounds(hs_hand *hand) {
	const hs_vec3 *points = hand->cache.local->points;
	hs_vec3 c = hs_v3(0, 0, 0);
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		c = hs_add(c, points[i]);
	c = hs_scale(c, 1.0 / HS_HAND_POINTS);
	double r_sq = hs_hand_farthest_sq(c, points, HS_HAND_POINTS, 0.0);
	hand->cache.local_center = c;
	hand->cache.local_radius = (sqrt(r_sq) + hand->model.def.finger_radius) * (1.0 + 1e-9) + 1e-12;
}

#if defined(HS_SELFCHECK)
// Sanitizer builds: the shape made through the cache (some fingers kept from the last one) has the
// bits of the shape made afresh.
static void check_shape(const hs_hand *hand) {
	hand_pose fresh;
	local_pose(&hand->model.def, &hand->model.glove, hand->state.sensors, &fresh, NULL);
	if (memcmp(&fresh, hand->cache.local, sizeof fresh) != 0) {
		fprintf(stderr, "selfcheck: a hand's shape through its cache differs from the shape made afresh\n");
		abort();
	}
}
#else
static inline void check_shape(const hs_hand *hand) { (void)hand; }
#endif

// The other one of a pair of buffers of points or lines (OTHER_BUF) or of shapes (OTHER_POSE).
#define OTHER_BUF(buf, p) ((p) == (buf)[0] ? (buf)[1] : (buf)[0])
#define OTHER_POSE(buf, p) ((p) == &(buf)[0] ? &(buf)[1] : &(buf)[0])

void hs_hand_update_shape(hs_hand *hand) {
	hs_hand_cache *c = &hand->cache;
	hs_hand_pose *last = c->local; // the last shape made through the cache
	bool moved = c->local == c->prev_local;
	if (moved) // the previous reading's shape stays in its buffer
		c->local = OTHER_POSE(c->local_buf, c->prev_local);
	if (hand->model.def.joint_driven) {
		hs_hand_joint_pose(&hand->model.def, hand->state.joints, c->local);
		c->local_twins = 0;
		c->local_ready = 0;
		local_bounds(hand);
		return;
	}
	unsigned same = local_pose(&hand->model.def, &hand->model.glove, hand->state.sensors, c->local, hand);
	// the fingers kept (not written) that the other buffer does not hold already
	for (unsigned todo = moved ? same & ~(unsigned)c->local_twins : 0u; todo; todo &= todo - 1u) {
		int f = hs_lowest_bit(todo);
		memcpy(&c->local->points[4 * f], &last->points[4 * f], 4 * sizeof last->points[0]);
		memcpy(&c->local->segment[3 * f], &last->segment[3 * f], 3 * sizeof last->segment[0]);
	}
	c->local_twins = (uint8_t)(moved ? same : c->local_twins & same);
	check_shape(hand);
	hand->cache.local_ready = (uint16_t)(hand->cache.local_ready & hs_finger_parts(same, 3)); // a finger's lines as they were
	local_bounds(hand);
}

void hs_hand_init_buffers(hs_hand *hand) {
	hand->cache.points = hand->cache.point_buf[0];
	hand->cache.prev_points = hand->cache.point_buf[1];
	hand->cache.lines = hand->cache.line_buf[0];
	hand->cache.prev_lines = hand->cache.line_buf[1];
	hand->cache.local = &hand->cache.local_buf[0];
	hand->cache.prev_local = &hand->cache.local_buf[1];
	hand->cache.local_twins = 0;
}

void hs_hand_place_points(hs_hand *hand) {
	hs_hand_cache *c = &hand->cache;
	if (c->points == c->prev_points) // the previous reading's points and lines stay in their buffers
		c->points = OTHER_BUF(c->point_buf, c->prev_points);
	if (c->lines == c->prev_lines)
		c->lines = OTHER_BUF(c->line_buf, c->prev_lines);
	hand->cache.place_m = hs_mat3_from_quat(hand->state.wrist_rot); // as hs_hand_place
	place_vectors_rows(hand->cache.place_m, hand->state.wrist_pos, hand->cache.local->points, hand->cache.points, HS_HAND_POINTS, hand->cache.point_rows);
	hand->cache.lines_ready = 0;
	hand->cache.finger_spheres_ready = false;
}

// The previous points, lines and shape in buffers of their own, a copy of the current ones where
// they shared them: rare paths (a load, a test writing points), the cost is no matter.
static void unshare(hs_hand_cache *c) {
	if (c->prev_points == c->points) {
		c->prev_points = OTHER_BUF(c->point_buf, c->points);
		memcpy(c->prev_points, c->points, sizeof c->point_buf[0]);
	}
	if (c->prev_lines == c->lines) {
		c->prev_lines = OTHER_BUF(c->line_buf, c->lines);
		memcpy(c->prev_lines, c->lines, sizeof c->line_buf[0]);
	}
	if (c->prev_local == c->local) {
		c->prev_local = OTHER_POSE(c->local_buf, c->local);
		*c->prev_local = *c->local;
		c->local_twins = 31;
	}
}

void hs_hand_points_moved(hs_hand *hand) {
	hand->cache.copy_previous = true;
	unshare(&hand->cache);
	for (int i = 0; i < HS_HAND_POINTS; ++i) {
		hand->cache.point_rows[0][i] = hand->cache.points[i].x;
		hand->cache.point_rows[1][i] = hand->cache.points[i].y;
		hand->cache.point_rows[2][i] = hand->cache.points[i].z;
	}
}

void hs_hand_place_segment(hs_hand *hand, int s) {
	unsigned bit = 1u << s;
	if (!(hand->cache.lines_ready & bit)) {
		ready_local(hand, s);
		place_vectors(hand->cache.place_m, hand->state.wrist_pos, &hand->cache.local_lines[4 * s][0], &hand->cache.lines[4 * s][0], 8);
		hand->cache.lines_ready = (uint16_t)(hand->cache.lines_ready | bit);
	}
	if (!(hand->cache.prev_lines_ready & bit)) { // not read last frame: from the shape kept with it
		hs_vec3 local[4][2];
		hs_hand_segment_lines(&hand->model.def, hand->cache.prev_local->points, hand->cache.prev_local->segment, s, local);
		place_vectors(hand->cache.prev_place_m, hand->state.prev_wrist_pos, &local[0][0], &hand->cache.prev_lines[4 * s][0], 8);
		hand->cache.prev_lines_ready = (uint16_t)(hand->cache.prev_lines_ready | bit);
	}
}

void hs_hand_ready_all(hs_hand *hand) {
	for (int s = 0; s < 15; ++s)
		hs_hand_ready_segment(hand, s);
}

void hs_hand_update_bounds(hs_hand *hand) {
	if (!hand->state.placed) { // touches nothing until it is set
		hand->cache.center = hs_v3(0, 0, 0);
		hand->cache.radius = -1.0;
		return;
	}
	// kept in the wrist frame with the shape; grown by a micrometre so the rounding of the
	// placement can never leave a check point outside it
	hand->cache.center = hs_add(hand->state.wrist_pos, hs_quat_rotate(hand->state.wrist_rot, hand->cache.local_center));
	hand->cache.radius = hand->cache.local_radius + 1e-6;
}

void hs_hand_keep_previous(hs_hand *hand) {
	hand->cache.finger_spheres_ready = false;
	hand->cache.prev_center = hand->cache.center;
	hand->cache.prev_radius = hand->cache.radius;
	if (hand->cache.copy_previous) {
		memcpy(hand->cache.prev_points, hand->cache.points, HS_HAND_POINTS * sizeof hand->cache.points[0]);
		for (unsigned todo = hand->cache.lines_ready; todo; todo &= todo - 1u) { // the placed segments' lines
			int s = hs_lowest_bit(todo);
			memcpy(hand->cache.prev_lines[4 * s], hand->cache.lines[4 * s], sizeof hand->cache.lines[0] * 4);
		}
	} else { // the same buffers: the next placement writes the other ones (hs_hand_place_points)
		hand->cache.prev_points = hand->cache.points;
		hand->cache.prev_lines = hand->cache.lines;
	}
	hand->cache.prev_lines_ready = hand->cache.lines_ready; // the others from the shape they would be placed from
	hand->cache.prev_place_m = hand->cache.place_m;
	hand->cache.prev_local = hand->cache.local; // the same shape (hs_hand_update_shape moves off it)
	hand->state.prev_wrist_pos = hand->state.wrist_pos;
	hand->state.prev_wrist_rot = hand->state.wrist_rot;
	memcpy(hand->state.prev_sensors, hand->state.sensors, sizeof hand->state.sensors);
	if (hand->model.def.joint_driven)
		memcpy(hand->state.prev_joints, hand->state.joints, sizeof hand->state.joints);
}

void hs_hand_age_wrist(hs_hand *hand) {
	if (!hand->state.placed)
		return;
	size_t keep = (size_t)(hand->model.older_capacity - 1);
	memmove(&hand->state.older_pos[1], &hand->state.older_pos[0], keep * sizeof hand->state.older_pos[0]);
	memmove(&hand->state.older_rot[1], &hand->state.older_rot[0], keep * sizeof hand->state.older_rot[0]);
	hand->state.older_pos[0] = hand->state.prev_wrist_pos;
	hand->state.older_rot[0] = hand->state.prev_wrist_rot;
	if (hand->state.older_count < hand->model.older_capacity)
		hand->state.older_count++;
}

void hs_hand_past_wrist(const hs_hand *hand, int frames, hs_vec3 *pos, hs_quat *rot) {
	*pos = frames == 0 ? hand->state.wrist_pos : frames == 1 ? hand->state.prev_wrist_pos : hand->state.older_pos[frames - 2];
	*rot = frames == 0 ? hand->state.wrist_rot : frames == 1 ? hand->state.prev_wrist_rot : hand->state.older_rot[frames - 2];
}

int hs_release_window_frames(double window_s, double dt) {
	double n = floor(window_s / dt + 0.5);
	return n < 1.0 ? 1 : n > HS_MAX_RELEASE_FRAMES ? HS_MAX_RELEASE_FRAMES : (int)n;
}

int hs_hand_older_capacity(double window_s, double dt) {
	int n = hs_release_window_frames(window_s, dt) - 1;
	return n > HS_HAND_OLDER ? n : HS_HAND_OLDER;
}

void hs_hand_refresh(hs_hand *hand) {
	hs_hand_cache *c = &hand->cache;
	unshare(c); // `local` keeps the last shape made through the cache
	if (!hand->state.placed) { // as hs_world_add_hand left it
		memset(c->point_buf, 0, sizeof c->point_buf);
		memset(c->point_rows, 0, sizeof c->point_rows);
		memset(c->line_buf, 0, sizeof c->line_buf);
		memset(c->local->points, 0, sizeof c->local->points);
		memset(hand->cache.local_lines, 0, sizeof hand->cache.local_lines);
		hand->cache.palm_ready = false; // its shape is no longer the last one made through the cache
		hand->cache.lines_ready = hand->cache.prev_lines_ready = hand->cache.local_ready = HS_HAND_ALL_SEGMENTS;
		hand->cache.local_center = hs_v3(0, 0, 0);
		hand->cache.local_radius = 0.0;
		hs_hand_update_bounds(hand);
		hand->cache.prev_center = hand->cache.center;
		hand->cache.prev_radius = hand->cache.radius;
		return;
	}
	// the previous points and bounds: the same calls that placed them, on the previous reading;
	// its lines from the shape kept for them
	if (hand->model.def.joint_driven)
		hs_hand_joint_pose(&hand->model.def, hand->state.prev_joints, hand->cache.local);
	else
		local_pose(&hand->model.def, &hand->model.glove, hand->state.prev_sensors, hand->cache.local, hand);
	hand->cache.local_ready = 0;
	local_bounds(hand);
	hand->cache.prev_place_m = hs_mat3_from_quat(hand->state.prev_wrist_rot);
	place_vectors(hand->cache.prev_place_m, hand->state.prev_wrist_pos, hand->cache.local->points, hand->cache.prev_points, HS_HAND_POINTS);
	*hand->cache.prev_local = *hand->cache.local;
	hand->cache.local_twins = 31;
	hand->cache.prev_lines_ready = 0;
	hand->cache.center = hs_add(hand->state.prev_wrist_pos, hs_quat_rotate(hand->state.prev_wrist_rot, hand->cache.local_center));
	hand->cache.radius = hand->cache.local_radius + 1e-6;
	hand->cache.prev_center = hand->cache.center;
	hand->cache.prev_radius = hand->cache.radius;
	hs_hand_update_shape(hand);
	hs_hand_place_points(hand);
	hs_hand_update_bounds(hand);
}

// ---------------------------------------------------------------------------------------------
// What the postures (hand_posture.c) solve through

hs_vec3 hs_hand_right_point(const hs_hand_def *def, const uint8_t s[HS_GLOVE_SENSORS], int i) {
	reading r = {def, hs_hand_joints_from_sensors(def, s), NULL, s};
	hand_pose pose;
	hand_pose_wrist(&r, &pose, NULL);
	return pose.points[i];
}

hs_vec3 hs_hand_thumb_tip(const hs_hand_def *def, const uint8_t s[HS_GLOVE_SENSORS]) {
	reading r = {def, hs_hand_joints_from_sensors(def, s), NULL, s};
	hand_pose pose;
	thumb_pose(&r, &pose);
	return pose.points[3];
}

hs_quat hs_hand_thumb_base(double thumb_abduction) {
	return hs_quat_mul(hs_quat_mul(thumb_splay(), joint_rotation(Z_AXIS, thumb_abduction)),
	                   exact_rotation(Y_AXIS, THUMB_TILT_COS, 1.0));
}
