// hand_script.c — one hand's input (1999 paper §5.1: glove + tracker) as keys in time: sampled per
// frame, with a thrower's error or without, and read from a recorded glove+tracker file (the
// `hands` section that writes keys: hands.c).
#include <math.h>
#include <stdlib.h>

#include "hand_script.h"
#include "record.h"

static const long MAX_RECORD_ROWS = 10000000L;
static const char *const RECORD_HEADER =
    "t,x,y,z,qw,qx,qy,qz,s0,s1,s2,s3,s4,s5,s6,s7,s8,s9,s10,s11,s12,s13,s14,s15,s16,s17";

// Sensors in whole units: a key's value, or the linear value between two keys, rounded.
static void sensors_between(const hs_hand_key *a, const hs_hand_key *b, double u, uint8_t sensors[HS_GLOVE_SENSORS]) {
	for (int i = 0; i < HS_GLOVE_SENSORS; ++i) {
		double v = a->sensors[i] + u * (b->sensors[i] - a->sensors[i]);
		long r = lround(v);
		sensors[i] = (uint8_t)(r < 0 ? 0 : (r > 255 ? 255 : r));
	}
}

// The keys around t (a at or before it, b after) and the fraction u of the way from a to b; before
// the first key and after the last the nearest key holds (u = 0). False when the hand is untracked
// at t (scenarios/README.md, "Recorded joint positions"): the key at or before t is, or t lies
// between a tracked key and an untracked one; the hand then holds a's pose (an untracked key holds
// the last tracked pose): nothing is interpolated across the gap.
static bool bracket(const hs_hand_script *script, double t, const hs_hand_key **ka, const hs_hand_key **kb, double *u) {
	const hs_hand_key *keys = script->keys;
	int n = script->key_count;
	const hs_hand_key *a = &keys[0], *b = &keys[0];
	*u = 0.0;
	if (t >= keys[n - 1].t) {
		a = b = &keys[n - 1];
	} else if (t > keys[0].t) {
		int lo = 0, hi = n - 1; // keys[lo].t <= t < keys[hi].t
		while (hi - lo > 1) {
			int mid = (lo + hi) / 2;
			if (keys[mid].t <= t)
				lo = mid;
			else
				hi = mid;
		}
		a = &keys[lo];
		b = &keys[hi];
		*u = (t - a->t) / (b->t - a->t);
	}
	*ka = a;
	*kb = b;
	if (!a->tracked || (*u > 0.0 && !b->tracked)) {
		*kb = a;
		*u = 0.0;
		return false;
	}
	return true;
}

bool hs_hand_script_sample(const hs_hand_script *script, double t, hs_vec3 *wrist, hs_quat *rot,
                           uint8_t sensors[HS_GLOVE_SENSORS]) {
	const hs_hand_key *a, *b;
	double u;
	if (!bracket(script, t, &a, &b, &u)) {
		*wrist = a->wrist;
		*rot = a->rot;
		sensors_between(a, a, 0.0, sensors);
		return false;
	}
	*wrist = hs_lerp(a->wrist, b->wrist, u);
	*rot = u > 0.0 ? hs_quat_slerp(a->rot, b->rot, u) : a->rot;
	sensors_between(a, b, u, sensors);
	return true;
}

void hs_hand_script_joints(const hs_hand_script *script, double t, hs_vec3 joints[HS_HAND_POINTS]) {
	const hs_hand_key *a, *b;
	double u;
	bracket(script, t, &a, &b, &u);
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		joints[i] = u > 0.0 ? hs_lerp(a->joints[i], b->joints[i], u) : a->joints[i];
}

bool hs_record_load(const char *path, hs_hand_script *script, hs_error *err) {
	script->key_count = 0;
	script->keys = NULL;
	hs_record_rows rows;
	if (!hs_record_read(path, "recorded input", RECORD_HEADER, "t,x,y,z,qw,qx,qy,qz,s0,...,s17", 8 + HS_GLOVE_SENSORS,
	                    MAX_RECORD_ROWS, &rows, err))
		return false;
	script->keys = calloc((size_t)rows.count, sizeof *script->keys);
	bool ok = script->keys != NULL || hs_set_error(err, path, 1, "out of memory");
	for (long r = 0; ok && r < rows.count; ++r) {
		const double *v = &rows.values[r * (8 + HS_GLOVE_SENSORS)];
		for (int i = 0; i < HS_GLOVE_SENSORS && ok; ++i)
			if (v[8 + i] < 0 || v[8 + i] > 255 || v[8 + i] != floor(v[8 + i]))
				ok = hs_set_error(err, path, (unsigned long)rows.lines[r],
				                  "sensor s%d must be an integer from 0 to 255, got %.17g", i, v[8 + i]);
		if (!ok)
			break;
		hs_hand_key *key = &script->keys[script->key_count++];
		key->t = v[0];
		key->tracked = true; // a glove + tracker file has no untracked samples
		key->wrist = hs_v3(v[1], v[2], v[3]);
		key->rot = hs_quat_normalize(hs_q(v[4], v[5], v[6], v[7]));
		for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
			key->sensors[i] = v[8 + i];
	}
	hs_record_rows_free(&rows);
	if (!ok)
		hs_hand_script_clear(script);
	return ok;
}

void hs_hand_script_clear(hs_hand_script *script) {
	free(script->keys);
	script->keys = NULL;
	script->key_count = 0;
}

bool hs_thrower_sample(const hs_thrower *thrower, const hs_hand_script *script, double t, hs_vec3 *wrist,
                       hs_quat *rot, uint8_t sensors[HS_GLOVE_SENSORS]) {
	t -= thrower->delay;
	bool tracked = hs_hand_script_sample(script, t, wrist, rot, sensors);
	if (!(t > thrower->from))
		return tracked;
	hs_vec3 arm = hs_scale(hs_sub(*wrist, thrower->pivot), thrower->scale);
	*wrist = hs_add(thrower->pivot, hs_quat_rotate(thrower->turn, arm));
	if (thrower->timing != 0.0) { // the glove as the script has it `timing` earlier
		hs_vec3 w;
		hs_quat r;
		hs_hand_script_sample(script, t - thrower->timing, &w, &r, sensors);
	}
	return tracked;
}
