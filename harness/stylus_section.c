// stylus_section.c — the `stylus` section of a scenario (workbench paper §3–§5): keyframes or a
// recorded tracker file (stylus_script.c reads the file and samples the script per frame).
#include <stdlib.h>
#include <string.h>

#include "scenario_internal.h"
#include "scenario_parser.h"
#include "stylus_script.h"

static const long MAX_STYLUS_KEYS = 10000000L;
static const double MAX_LENGTH = 1000.0; // m: largest coordinate accepted

enum { SK_T, SK_POSITION, SK_RPY, SK_QUAT, SK_BUTTON, SK_TECHNIQUE, SK_RELEASE, SK_MAGNET, SK_COUNT };
static const char *const stylus_key_keys[SK_COUNT] = {"t",      "position", "rpy_deg", "quat",
                                                      "button", "technique", "release", "magnet"};
static const char *const technique_names[] = {"spring", "slave", "stick", "cross_plane", "cross_surface"};
static const char *const release_names[] = {"hand", "return"};

// A key's techniques (docs/techniques.md): only in a world made with them.
static bool read_key_techniques(hs_scenario_parser *p, const hs_fields *f, hs_stylus_key *key) {
	for (int k = SK_TECHNIQUE; k <= SK_MAGNET; ++k)
		if (f->value[k] && !p->spring.techniques)
			return hs_yaml_fail(&p->y, f->value[k], "'%s' needs 'techniques: true' in model.spring", stylus_key_keys[k]);
	if (f->value[SK_TECHNIQUE]) {
		int w = hs_yaml_word(f->value[SK_TECHNIQUE], technique_names, 5);
		if (w < 0)
			return hs_yaml_fail(&p->y, f->value[SK_TECHNIQUE],
			                    "'technique' must be spring, slave, stick, cross_plane or cross_surface, got %s",
			                    hs_yaml_got(f->value[SK_TECHNIQUE]).text);
		key->technique = (hs_technique)w; // the names are in the enum's order
	}
	if (f->value[SK_RELEASE]) {
		int w = hs_yaml_word(f->value[SK_RELEASE], release_names, 2);
		if (w < 0)
			return hs_yaml_fail(&p->y, f->value[SK_RELEASE], "'release' must be hand or return, got %s",
			                    hs_yaml_got(f->value[SK_RELEASE]).text);
		key->release = (hs_release_mode)w;
	}
	if (f->value[SK_MAGNET] && !hs_yaml_bool(&p->y, f->value[SK_MAGNET], "magnet", &key->magnet))
		return false;
	p->s->stylus.techniques = p->s->stylus.techniques || f->value[SK_TECHNIQUE] || f->value[SK_RELEASE] || f->value[SK_MAGNET];
	return true;
}

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
	key->technique = previous ? previous->technique : HS_TECHNIQUE_SPRING;
	key->release = previous ? previous->release : HS_RELEASE_MODE_HAND;
	key->magnet = previous ? previous->magnet : false;
	if (f.value[SK_POSITION] &&
	    !hs_yaml_bounded_vec3(&p->y, f.value[SK_POSITION], "position", MAX_LENGTH, "m", &key->position))
		return false;
	if (f.value[SK_RPY] && !hs_yaml_rpy(&p->y, f.value[SK_RPY], "rpy_deg", &key->rot))
		return false;
	if (f.value[SK_QUAT] && !hs_yaml_quat(&p->y, f.value[SK_QUAT], "quat", &key->rot))
		return false;
	if (f.value[SK_BUTTON] && !hs_yaml_bool(&p->y, f.value[SK_BUTTON], "button", &key->button))
		return false;
	return read_key_techniques(p, &f, key);
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

enum { ST_KEYS, ST_RECORD, ST_GESTURE, ST_COUNT };
static const char *const stylus_keys[ST_COUNT] = {"keys", "record", "gesture"};

enum { GE_BODY, GE_FAR, GE_NEAR, GE_WITHIN, GE_COUNT };
static const char *const gesture_keys[GE_COUNT] = {"body", "far", "near", "within"};

// A number of the gesture within (lo, hi].
static bool read_gesture_number(hs_scenario_parser *p, const yaml_node_t *v, const char *key, double lo, double hi,
                                const char *unit, double *out) {
	if (!hs_yaml_number(&p->y, v, key, out))
		return false;
	if (!(*out > lo && *out <= hi))
		return hs_yaml_fail(&p->y, v, "'%s' must be within (%g, %g] %s, got %s", key, lo, hi, unit, hs_yaml_show(v).text);
	return true;
}

// The magnet gesture's geometry (docs/techniques.md): the shoulder point and the thresholds.
static bool read_gesture(hs_scenario_parser *p, const yaml_node_t *node, hs_technique_def *g) {
	if (!p->spring.techniques)
		return hs_yaml_fail(&p->y, node, "'gesture' needs 'techniques: true' in model.spring");
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(&p->y, node, "'gesture' must be a mapping like { body: [x, y, z], far: 0.6 }, got %s",
		                    hs_yaml_got(node).text);
	hs_fields f;
	if (!hs_yaml_mapping(&p->y, node, gesture_keys, GE_COUNT, "gesture", &f))
		return false;
	if (f.value[GE_BODY] && !hs_yaml_bounded_vec3(&p->y, f.value[GE_BODY], "body", MAX_LENGTH, "m", &g->body))
		return false;
	if (f.value[GE_FAR] && !read_gesture_number(p, f.value[GE_FAR], "far", 0.0, MAX_LENGTH, "m", &g->magnet_far))
		return false;
	if (f.value[GE_NEAR] && !read_gesture_number(p, f.value[GE_NEAR], "near", 0.0, MAX_LENGTH, "m", &g->magnet_near))
		return false;
	if (f.value[GE_WITHIN] && !read_gesture_number(p, f.value[GE_WITHIN], "within", 0.0, 1e6, "s", &g->magnet_within))
		return false;
	if (!(g->magnet_near < g->magnet_far))
		return hs_yaml_fail(&p->y, node, "'gesture' near (%g m) must be less than far (%g m)", g->magnet_near,
		                    g->magnet_far);
	p->s->stylus.techniques = true;
	return true;
}

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
	s->stylus.gesture = hs_default_technique_def();
	if (f.value[ST_GESTURE] && !read_gesture(p, f.value[ST_GESTURE], &s->stylus.gesture))
		return false;
	if (f.value[ST_KEYS])
		return read_stylus_keys(p, f.value[ST_KEYS], &s->stylus);
	return read_stylus_record(p, f.value[ST_RECORD], &s->stylus);
}
