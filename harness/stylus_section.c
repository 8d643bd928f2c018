// stylus_section.c — the `stylus` section of a scenario (workbench paper §3–§5): keyframes or a
// recorded tracker file (stylus_script.c reads the file and samples the script per frame).
#include <stdlib.h>
#include <string.h>

#include "scenario_internal.h"
#include "scenario_parser.h"
#include "stylus_script.h"

static const long MAX_STYLUS_KEYS = 10000000L;
static const double MAX_LENGTH = 1000.0; // m: largest coordinate accepted

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
