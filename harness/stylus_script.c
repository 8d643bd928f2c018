// stylus_script.c — the spring model's input (workbench paper §3–§5): the `stylus` section
// (keyframes or a recorded tracker file), sampled per frame.
//
// Every frame the stylus is sampled at the frame's end time and given to hs_world_set_stylus before
// hs_world_step (the library moves it linearly within the frame). Positions are linear between
// keys, orientations slerped, and the button is a step: a key's button holds from the key's time
// on. A frame whose end lies within STYLUS_TIME_SLOP of a key's time counts as reaching it, so a
// key at t = 1.2 s takes effect at the end of frame 72 of dt = 1/60 s whatever the rounding of 72 dt.
#include <stdlib.h>
#include <string.h>

#include "file_read.h"
#include "record.h"
#include "stylus_script.h"

static const double STYLUS_TIME_SLOP = 1e-9; // s
static const long MAX_STYLUS_KEYS = 10000000L;
static const char *const STYLUS_HEADER = "t,x,y,z,qw,qx,qy,qz,button";

// The last key with t_k <= t, or -1.
static int stylus_key_at(const hs_stylus_key *keys, int n, double t) {
	if (n == 0 || keys[0].t > t)
		return -1;
	int lo = 0, hi = n; // keys[lo].t <= t; keys[hi].t > t (hi = n: none)
	while (hi - lo > 1) {
		int mid = lo + (hi - lo) / 2;
		if (keys[mid].t <= t)
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

void hs_stylus_sample(const hs_stylus_script *script, double t, hs_vec3 *position, hs_quat *rot, bool *button) {
	const hs_stylus_key *keys = script->keys;
	int n = script->count;
	int a = stylus_key_at(keys, n, t);
	if (a < 0) { // before the first key: it holds
		*position = keys[0].position;
		*rot = keys[0].rot;
	} else if (a == n - 1) { // after the last: it holds
		*position = keys[a].position;
		*rot = keys[a].rot;
	} else {
		double u = (t - keys[a].t) / (keys[a + 1].t - keys[a].t);
		*position = hs_lerp(keys[a].position, keys[a + 1].position, u);
		*rot = u > 0.0 ? hs_quat_slerp(keys[a].rot, keys[a + 1].rot, u) : keys[a].rot;
	}
	int b = stylus_key_at(keys, n, t + STYLUS_TIME_SLOP);
	*button = keys[b < 0 ? 0 : b].button;
}

// A recorded tracker file: the header t,x,y,z,qw,qx,qy,qz,button, then one sample per line at any
// rate (strictly increasing t, s; position m; a unit quaternion, renormalised; button 0 or 1).
bool hs_stylus_record_load(const char *path, hs_stylus_script *script, hs_error *err) {
	hs_record_rows rows;
	if (!hs_record_read(path, "recorded stylus input", STYLUS_HEADER, STYLUS_HEADER, 9, MAX_STYLUS_KEYS, &rows, err))
		return false;
	script->keys = calloc((size_t)rows.count, sizeof *script->keys);
	bool ok = script->keys != NULL || hs_set_error(err, path, 1, "out of memory");
	for (long r = 0; ok && r < rows.count; ++r) {
		const double *v = &rows.values[r * 9];
		if (v[8] != 0.0 && v[8] != 1.0) {
			ok = hs_set_error(err, path, (unsigned long)rows.lines[r], "button must be 0 or 1, got %.17g", v[8]);
			break;
		}
		hs_stylus_key *key = &script->keys[script->count++];
		key->t = v[0];
		key->position = hs_v3(v[1], v[2], v[3]);
		key->rot = hs_quat_normalize(hs_q(v[4], v[5], v[6], v[7])); // a unit quaternion: checked by the reader
		key->button = v[8] == 1.0;
	}
	hs_record_rows_free(&rows);
	return ok;
}

void hs_stylus_drive(hs_world *world, const hs_stylus_script *script, double t, hs_noise *noise) {
	if (script->count == 0)
		return;
	hs_vec3 position;
	hs_quat rot;
	bool button;
	hs_stylus_sample(script, t, &position, &rot, &button);
	if (noise)
		hs_noise_stylus(noise, &position, &rot);
	hs_world_set_stylus(world, position, rot, button); // the keys were validated: finite, unit
	if (!script->techniques)
		return;
	int k = stylus_key_at(script->keys, script->count, t + STYLUS_TIME_SLOP); // a step, as the button
	const hs_stylus_key *key = &script->keys[k < 0 ? 0 : k];
	hs_technique_def def = script->gesture;
	def.technique = key->technique;
	def.release = key->release;
	def.magnet = key->magnet;
	hs_world_spring_set_technique(world, &def); // validated with the section (model.spring.techniques)
}
