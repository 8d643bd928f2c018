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
#include "scenario_internal.h"
#include "scenario_parser.h"
#include "stylus_script.h"

static const double STYLUS_TIME_SLOP = 1e-9; // s
static const long MAX_STYLUS_KEYS = 10000000L;
static const double MAX_LENGTH = 1000.0; // m: largest coordinate accepted
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

enum { SK_T, SK_POSITION, SK_RPY, SK_QUAT, SK_BUTTON, SK_COUNT };
static const char *const stylus_key_keys[SK_COUNT] = {"t", "position", "rpy_deg", "quat", "button"};

// What a key leaves out it keeps from the key before (the first: identity orientation, button up).
static bool read_stylus_key(hs_scenario_parser *p, const yaml_node_t *node, const hs_stylus_key *previous,
                            hs_stylus_key *key) {
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(&p->y, node,
		                    "a stylus key must be a mapping like { t: 0, position: [x, y, z], button: false }, got %s",
		                    hs_yaml_got(node).text);
	hs_fields f;
	if (!hs_yaml_mapping(&p->y, node, stylus_key_keys, SK_COUNT, "stylus key", &f))
		return false;
	if (!f.value[SK_T])
		return hs_yaml_fail(&p->y, node, "stylus key is missing 't'");
	if (!hs_yaml_time(&p->y, f.value[SK_T], "t", p->s->duration, &key->t))
		return false;
	if (previous && !(key->t > previous->t))
		return hs_yaml_fail(&p->y, f.value[SK_T], "stylus keys must go forward in time: t = %s after t = %g",
		                    hs_yaml_show(f.value[SK_T]).text, previous->t);
	if (!hs_yaml_exclusive(&p->y, &f, stylus_key_keys, SK_RPY, SK_QUAT, "give one"))
		return false;
	if (!previous && !f.value[SK_POSITION])
		return hs_yaml_fail(&p->y, node, "the first stylus key needs 'position'");
	key->position = previous ? previous->position : hs_v3(0.0, 0.0, 0.0);
	key->rot = previous ? previous->rot : hs_quat_identity();
	key->button = previous ? previous->button : false;
	if (f.value[SK_POSITION] &&
	    !hs_yaml_bounded_vec3(&p->y, f.value[SK_POSITION], "position", MAX_LENGTH, "m", &key->position))
		return false;
	if (f.value[SK_RPY] && !hs_yaml_rpy(&p->y, f.value[SK_RPY], "rpy_deg", &key->rot))
		return false;
	if (f.value[SK_QUAT] && !hs_yaml_quat(&p->y, f.value[SK_QUAT], "quat", &key->rot))
		return false;
	if (f.value[SK_BUTTON] && !hs_yaml_bool(&p->y, f.value[SK_BUTTON], "button", &key->button))
		return false;
	return true;
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

static bool read_stylus_keys(hs_scenario_parser *p, const yaml_node_t *keys, hs_stylus_script *script) {
	if (keys->type != YAML_SEQUENCE_NODE)
		return hs_yaml_fail(&p->y, keys, "'keys' must be a list of 1 to %ld keys, got %s", MAX_STYLUS_KEYS,
		                    hs_yaml_got(keys).text);
	long n = hs_yaml_length(keys);
	if (n < 1 || n > MAX_STYLUS_KEYS)
		return hs_yaml_fail(&p->y, keys, "'keys' must be a list of 1 to %ld keys, got %ld", MAX_STYLUS_KEYS, n);
	script->keys = calloc((size_t)n, sizeof *script->keys);
	if (!script->keys)
		return hs_yaml_fail(&p->y, keys, "out of memory");
	for (long k = 0; k < n; ++k) {
		if (!read_stylus_key(p, hs_yaml_item(&p->y, keys, k), k ? &script->keys[k - 1] : NULL, &script->keys[k]))
			return false;
		script->count = (int)k + 1;
	}
	return true;
}

static bool read_stylus_record(hs_scenario_parser *p, const yaml_node_t *node, hs_stylus_script *script) {
	char *full = hs_yaml_sibling_file(&p->y, node, "record");
	if (!full)
		return false;
	bool ok = hs_stylus_record_load(full, script, p->y.err);
	free(full);
	return ok;
}

enum { ST_KEYS, ST_RECORD, ST_COUNT };
static const char *const stylus_keys[ST_COUNT] = {"keys", "record"};

bool hs_read_stylus(hs_scenario_parser *p, const yaml_node_t *node) {
	hs_scenario *s = p->s;
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(&p->y, node, "'stylus' must be a mapping with 'keys' or 'record', got %s",
		                    hs_yaml_got(node).text);
	hs_fields f;
	if (!hs_yaml_mapping(&p->y, node, stylus_keys, ST_COUNT, "stylus", &f))
		return false;
	if (!f.value[ST_KEYS] && !f.value[ST_RECORD])
		return hs_yaml_fail(&p->y, node, "'stylus' needs 'keys' or 'record'");
	if (!hs_yaml_exclusive(&p->y, &f, stylus_keys, ST_KEYS, ST_RECORD, "give one"))
		return false;
	s->springs = true; // the world was made a spring world (read_scenario: def.kind)
	if (f.value[ST_KEYS])
		return read_stylus_keys(p, f.value[ST_KEYS], &s->stylus);
	return read_stylus_record(p, f.value[ST_RECORD], &s->stylus);
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
}
