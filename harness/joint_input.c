// joint_input.c — hands driven by recorded joint positions instead of glove angles (issue 13
// item 4): the 21 landmarks of MediaPipe Hands and the 26 joints of OpenXR's XR_EXT_hand_tracking,
// turned at load time into the glove model's own input — a wrist pose and 18 sensor values per
// sample — so that a joint recording drives exactly the hand a glove would (1999 paper §3.1: the
// check points are the joints and the fingertips).
//
// The mapping (docs: scenarios/README.md "Recorded joint positions"):
//  - check points: MediaPipe landmark 1 + i is check point i (thumb CMC, MCP, IP, tip; then each
//    finger's MCP, PIP, DIP, tip); OpenXR: thumb metacarpal, proximal, distal, tip (joints 2-5),
//    then per finger proximal, intermediate, distal, tip (7-10, 12-15, 17-20, 22-25); the fingers'
//    metacarpal joints, the palm and the wrist joint are not check points.
//  - the wrist pose: the rigid motion that best carries the hand definition's thumb CMC and index
//    and middle MCPs (which no sensor moves with the wrist sensors neutral) onto the recorded ones
//    (the rotation between the frames the three span); the glove's wrist pitch and yaw stay neutral (the pose
//    takes them: positions alone cannot tell them from the tracker's turn).
//  - the 16 other sensors: the integers (0.5° units) whose kinematics best reach the recorded
//    check points in the wrist frame (least squares): the first sample by full scans of each
//    sensor, every later one by a pattern search from the sample before. A recording made from
//    the glove model gives back its own sensors and pose; a real hand gets the nearest the
//    default hand can do (its segment lengths are the definition's, not the recording's).
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "joint_input.h"
#include "record.h"
#include "scenario_internal.h"

#define MAX_JOINT_ROWS 1000000
#define MEDIAPIPE_COLUMNS (1 + 21 * 3)
#define OPENXR_COLUMNS (1 + 26 * 7)

static const int openxr_point[HS_HAND_POINTS] = {2, 3, 4, 5, 7, 8, 9, 10, 12, 13, 14, 15, 17, 18, 19, 20, 22, 23, 24, 25};
static const int rigid[3] = {0, 4, 8}; // thumb CMC, index MCP, middle MCP

static void header_of(hs_joint_format format, char *out, size_t size, char *layout) {
	size_t n = (size_t)snprintf(out, size, "t");
	layout[0] = 't';
	int c = 1;
	if (format == HS_JOINTS_MEDIAPIPE) {
		for (int i = 0; i < 21; ++i, c += 3) {
			n += (size_t)snprintf(out + n, size - n, ",x%d,y%d,z%d", i, i, i);
			memcpy(layout + c, "ppp", 3);
		}
	} else {
		for (int j = 0; j < 26; ++j, c += 7) {
			n += (size_t)snprintf(out + n, size - n, ",px%d,py%d,pz%d,qw%d,qx%d,qy%d,qz%d", j, j, j, j, j, j, j);
			memcpy(layout + c, "pppqnnn", 7);
		}
	}
	layout[c] = '\0';
}

hs_joint_format hs_joint_format_of(const char *first_line) {
	if (strncmp(first_line, "t,x0,y0,z0,", 11) == 0)
		return HS_JOINTS_MEDIAPIPE;
	if (strncmp(first_line, "t,px0,py0,pz0,", 14) == 0)
		return HS_JOINTS_OPENXR;
	return HS_JOINTS_NONE;
}

// Σ |kinematics(sensors) − target|² over the check points, in the wrist frame.
static double misfit(const hs_hand_def *def, const uint8_t s[HS_GLOVE_SENSORS], const hs_vec3 target[HS_HAND_POINTS]) {
	hs_vec3 p[HS_HAND_POINTS], lines[HS_HAND_LINES][2];
	hs_hand_kinematics(def, hs_v3(0, 0, 0), hs_quat_identity(), s, p, lines);
	double e = 0.0;
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		e += hs_length_sq(hs_sub(p[i], target[i]));
	return e;
}

static bool searched(int k) { return k != HS_SENSOR_WRIST_PITCH && k != HS_SENSOR_WRIST_YAW; }

// Each searched sensor over all its values, in turn, until a sweep changes none (the first sample).
static void scan(const hs_hand_def *def, uint8_t s[HS_GLOVE_SENSORS], const hs_vec3 target[HS_HAND_POINTS]) {
	double best = misfit(def, s, target);
	for (int sweep = 0; sweep < 6; ++sweep) {
		bool changed = false;
		for (int k = 0; k < HS_GLOVE_SENSORS; ++k) {
			if (!searched(k))
				continue;
			uint8_t keep = s[k];
			for (int v = 0; v < 256; ++v) {
				s[k] = (uint8_t)v;
				double e = misfit(def, s, target);
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
static void refine(const hs_hand_def *def, uint8_t s[HS_GLOVE_SENSORS], const hs_vec3 target[HS_HAND_POINTS]) {
	double best = misfit(def, s, target);
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
					double e = misfit(def, s, target);
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

// The unit quaternion of a rotation matrix (Shepperd: from the largest of the four squares).
static hs_quat quat_of(double m[3][3]) {
	double tr = m[0][0] + m[1][1] + m[2][2];
	hs_quat q;
	if (tr > 0.0) {
		double s = 2.0 * sqrt(1.0 + tr);
		q = hs_q(0.25 * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s);
	} else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
		double s = 2.0 * sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]);
		q = hs_q((m[2][1] - m[1][2]) / s, 0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s);
	} else if (m[1][1] > m[2][2]) {
		double s = 2.0 * sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]);
		q = hs_q((m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s);
	} else {
		double s = 2.0 * sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]);
		q = hs_q((m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s);
	}
	return hs_quat_normalize(q);
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
static bool fit_wrist(const hs_hand_def *def, const hs_vec3 world[HS_HAND_POINTS], hs_quat *rot, hs_vec3 *pos) {
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
	*rot = quat_of(r);
	hs_vec3 lc = hs_v3(0, 0, 0), wc = hs_v3(0, 0, 0);
	for (int k = 0; k < 3; ++k) {
		lc = hs_add(lc, hs_scale(local[rigid[k]], 1.0 / 3.0));
		wc = hs_add(wc, hs_scale(world[rigid[k]], 1.0 / 3.0));
	}
	*pos = hs_sub(wc, hs_quat_rotate(*rot, lc));
	return true;
}

bool hs_joint_record_load(const char *path, hs_joint_format format, const hs_hand_def *def, hs_hand_script *script,
                          hs_error *err) {
	script->key_count = 0;
	script->keys = NULL;
	char header[4096], layout[HS_RECORD_MAX_COLUMNS + 1];
	header_of(format, header, sizeof header, layout);
	int columns = format == HS_JOINTS_MEDIAPIPE ? MEDIAPIPE_COLUMNS : OPENXR_COLUMNS;
	const char *shown = format == HS_JOINTS_MEDIAPIPE ? "t,x0,y0,z0,...,x20,y20,z20 (MediaPipe Hands, m)"
	                                                  : "t,px0,py0,pz0,qw0,qx0,qy0,qz0,...,qz25 (OpenXR hand joints, m)";
	hs_record_rows rows;
	if (!hs_record_read_layout(path, "recorded joint positions", header, shown, columns, layout, MAX_JOINT_ROWS, &rows,
	                           err))
		return false;
	script->keys = calloc((size_t)rows.count, sizeof *script->keys);
	bool ok = script->keys != NULL || hs_set_error(err, path, 1, "out of memory");
	uint8_t s[HS_GLOVE_SENSORS];
	hs_hand_posture(def, HS_POSTURE_OPEN, 0.0, s);
	for (long r = 0; ok && r < rows.count; ++r) {
		const double *v = &rows.values[r * columns];
		hs_vec3 world[HS_HAND_POINTS], local[HS_HAND_POINTS];
		for (int i = 0; i < HS_HAND_POINTS; ++i) {
			int c = format == HS_JOINTS_MEDIAPIPE ? 1 + 3 * (i + 1) : 1 + 7 * openxr_point[i];
			world[i] = hs_v3(v[c], v[c + 1], v[c + 2]);
		}
		hs_hand_key *key = &script->keys[script->key_count];
		if (!fit_wrist(def, world, &key->rot, &key->wrist)) {
			ok = hs_set_error(err, path, (unsigned long)rows.lines[r],
			                  "cannot fit the wrist: the thumb CMC and the index and middle MCPs are in one line");
			break;
		}
		for (int i = 0; i < HS_HAND_POINTS; ++i)
			local[i] = hs_quat_inv_rotate(key->rot, hs_sub(world[i], key->wrist));
		if (r == 0)
			scan(def, s, local);
		else
			refine(def, s, local);
		key->t = v[0];
		key->tracked = true;
		for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
			key->sensors[i] = s[i];
		script->key_count++;
	}
	hs_record_rows_free(&rows);
	if (!ok)
		hs_hand_script_clear(script);
	return ok;
}

// The OpenXR orientation of a joint whose bone runs along `forward` (unit) with the back of the hand
// toward `up`: −Z along the bone, +Y toward the back of the hand (XR_EXT_hand_tracking).
static hs_quat openxr_frame(hs_vec3 forward, hs_vec3 up) {
	hs_vec3 z = hs_neg(forward);
	hs_vec3 y = hs_sub(up, hs_scale(z, hs_dot(up, z)));
	y = hs_length_sq(y) > 0.0 ? hs_normalize(y) : hs_normalize(hs_cross(z, hs_v3(1, 0, 0)));
	hs_vec3 x = hs_cross(y, z);
	double m[3][3] = {{x.x, y.x, z.x}, {x.y, y.y, z.y}, {x.z, y.z, z.z}};
	return quat_of(m);
}

static void openxr_joint(FILE *out, hs_vec3 p, hs_quat q) {
	fprintf(out, ",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", p.x, p.y, p.z, q.w, q.x, q.y, q.z);
}

void hs_joint_write_header(FILE *out, hs_joint_format format) {
	char header[4096], layout[HS_RECORD_MAX_COLUMNS + 1];
	header_of(format, header, sizeof header, layout);
	fprintf(out, "%s\n", header);
}

void hs_joint_write_row(FILE *out, hs_joint_format format, double t, const hs_hand_def *def, hs_vec3 wrist,
                        hs_quat rot, const uint8_t sensors[HS_GLOVE_SENSORS]) {
	hs_vec3 p[HS_HAND_POINTS], lines[HS_HAND_LINES][2];
	hs_hand_kinematics(def, wrist, rot, sensors, p, lines);
	fprintf(out, "%.17g", t);
	if (format == HS_JOINTS_MEDIAPIPE) {
		fprintf(out, ",%.17g,%.17g,%.17g", wrist.x, wrist.y, wrist.z); // landmark 0: the wrist
		for (int i = 0; i < HS_HAND_POINTS; ++i)
			fprintf(out, ",%.17g,%.17g,%.17g", p[i].x, p[i].y, p[i].z);
		fputc('\n', out);
		return;
	}
	hs_vec3 up = hs_quat_rotate(rot, hs_v3(0, 0, 1)), along = hs_quat_rotate(rot, hs_v3(1, 0, 0));
	openxr_joint(out, hs_scale(hs_add(wrist, p[8]), 0.5), openxr_frame(along, up)); // 0 palm
	openxr_joint(out, wrist, openxr_frame(along, up));                               // 1 wrist
	for (int f = 0; f < 5; ++f) {
		if (f > 0) { // a finger's metacarpal joint: on the way from the wrist to its base
			hs_vec3 m = hs_add(wrist, hs_scale(hs_sub(p[f * 4], wrist), 0.3));
			openxr_joint(out, m, openxr_frame(hs_normalize(hs_sub(p[f * 4], m)), up));
		}
		for (int j = 0; j < 4; ++j) {
			hs_vec3 a = p[f * 4 + j], b = j < 3 ? p[f * 4 + j + 1] : p[f * 4 + j];
			hs_vec3 dir = j < 3 ? hs_sub(b, a) : hs_sub(p[f * 4 + 3], p[f * 4 + 2]);
			openxr_joint(out, a, openxr_frame(hs_normalize(dir), up));
		}
	}
	fputc('\n', out);
}

bool hs_scenario_export_joints(hs_scenario *scenario, int hand, const char *format, double rate, FILE *out,
                               hs_error *err) {
	hs_joint_format f = strcmp(format, "mediapipe") == 0 ? HS_JOINTS_MEDIAPIPE
	                    : strcmp(format, "openxr") == 0  ? HS_JOINTS_OPENXR
	                                                     : HS_JOINTS_NONE;
	const hs_hands *hands = &scenario->hands;
	if (f == HS_JOINTS_NONE)
		return hs_set_error(err, hs_scenario_name(scenario), 0, "unknown joint format '%s' (mediapipe or openxr)", format);
	if (hand < 0 || hand >= hands->count)
		return hs_set_error(err, hs_scenario_name(scenario), 0, "the scenario has %d hand(s), no hand %d", hands->count, hand + 1);
	if (!(rate >= 1.0 && rate <= 10000.0))
		return hs_set_error(err, hs_scenario_name(scenario), 0, "the rate must be within [1, 10000] Hz, got %g", rate);
	hs_joint_write_header(out, f);
	double dt = 1.0 / rate, duration = (double)hs_scenario_frame_count(scenario) * hs_scenario_dt(scenario);
	for (long k = 0; (double)k * dt <= duration + 1e-9; ++k) { // the script's input, as the world gets it
		hs_vec3 wrist;
		hs_quat rot;
		uint8_t sensors[HS_GLOVE_SENSORS];
		hs_hand_script_sample(&hands->scripts[hand], (double)k * dt, &wrist, &rot, sensors);
		hs_joint_write_row(out, f, (double)k * dt, &hands->defs[hand], wrist, rot, sensors);
	}
	return true;
}
