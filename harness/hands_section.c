// hands_section.c — the `hands` section of a scenario (1999 paper §5.1: glove + tracker): each
// hand's definition and its keys (postures, sensor lists or joint angles) or recording
// (hand_record.c), added to the world. Driving them per frame is hands.c's.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hands.h"
#include "scenario_internal.h"
#include "scenario_parser.h"

enum { MAX_HANDS = 64, MAX_HAND_KEYS = 100000 };
static const double MAX_LENGTH = 1000.0; // m: largest coordinate accepted

static const char *const posture_names[] = {"open", "fist", "pinch", "point", "grasp"};

// posture: a word (open, fist, pinch, point) or a one-key mapping { fist: 0.5 } / { grasp: 0.05 }
static bool read_posture(hs_scenario_parser *p, const yaml_node_t *node, const hs_hand_def *def,
                         double out[HS_GLOVE_SENSORS]) {
	int which = -1;
	double amount = 1.0;
	const yaml_node_t *amount_node = node;
	if (hs_yaml_is_scalar(node)) {
		for (int i = 0; i < 5; ++i)
			if (hs_yaml_scalar_is(node, posture_names[i]))
				which = i;
		if (which == HS_POSTURE_GRASP)
			return hs_yaml_fail(&p->y, node, "posture 'grasp' needs the object's width: { grasp: 0.05 }");
	} else if (node->type == YAML_MAPPING_NODE && node->data.mapping.pairs.top - node->data.mapping.pairs.start == 1) {
		const yaml_node_t *k = yaml_document_get_node(&p->y.doc, node->data.mapping.pairs.start[0].key);
		amount_node = yaml_document_get_node(&p->y.doc, node->data.mapping.pairs.start[0].value);
		for (int i = 0; k && hs_yaml_is_scalar(k) && i < 5; ++i)
			if (hs_yaml_scalar_is(k, posture_names[i]))
				which = i;
		if (which >= 0 && !hs_yaml_number(&p->y, amount_node, posture_names[which], &amount))
			return false;
	}
	if (which < 0)
		return hs_yaml_fail(&p->y, node,
		                    "'posture' must be open, fist, pinch, point or a mapping like { grasp: 0.05 }, got %s",
		                    hs_yaml_got(node).text);
	uint8_t sensors[HS_GLOVE_SENSORS];
	if (hs_hand_posture(def, (hs_posture)which, amount, sensors) != HS_OK)
		return hs_yaml_fail(&p->y, amount_node,
		                    which == HS_POSTURE_GRASP ? "posture 'grasp' width must be within [0.01, 0.12] m, got %s"
		                                              : "posture '%s' amount must be within [0, 1], got %s",
		                    which == HS_POSTURE_GRASP ? hs_yaml_show(amount_node).text : posture_names[which],
		                    hs_yaml_show(amount_node).text);
	for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
		out[i] = sensors[i];
	return true;
}

static bool read_sensor_list(hs_scenario_parser *p, const yaml_node_t *node, double out[HS_GLOVE_SENSORS]) {
	if (node->type != YAML_SEQUENCE_NODE)
		return hs_yaml_fail(&p->y, node, "'sensors' must be a list of 18 integers from 0 to 255, got %s",
		                    hs_yaml_got(node).text);
	if (hs_yaml_length(node) != HS_GLOVE_SENSORS)
		return hs_yaml_fail(&p->y, node, "'sensors' must be a list of 18 integers from 0 to 255, got %ld",
		                    hs_yaml_length(node));
	for (int i = 0; i < HS_GLOVE_SENSORS; ++i) {
		int64_t v;
		if (!hs_yaml_integer(&p->y, hs_yaml_item(&p->y, node, i), "sensors", 0, 255, &v))
			return false;
		out[i] = (double)v;
	}
	return true;
}

// 18 joint angles in degrees, in the sensor order of handspring.h
static bool read_angle_list(hs_scenario_parser *p, const yaml_node_t *node, double out[HS_GLOVE_SENSORS]) {
	double deg[HS_GLOVE_SENSORS];
	const yaml_node_t *elements[HS_GLOVE_SENSORS];
	if (!hs_yaml_numbers(&p->y, node, "angles_deg", HS_GLOVE_SENSORS, " in the glove's sensor order", deg, elements))
		return false;
	for (int i = 0; i < HS_GLOVE_SENSORS; ++i) {
		bool wrist = i == HS_SENSOR_WRIST_PITCH || i == HS_SENSOR_WRIST_YAW;
		double lo = wrist ? -64.0 : 0.0, hi = wrist ? 63.5 : 127.5; // what 8 bits at 0.5 deg can say
		if (!(deg[i] >= lo && deg[i] <= hi))
			return hs_yaml_fail(&p->y, elements[i], "'angles_deg' entry %d must be within [%g, %g] deg, got %s", i + 1,
			                    lo, hi, hs_yaml_show(elements[i]).text);
		out[i] = deg[i] / 0.5 + (wrist ? 128.0 : 0.0);
	}
	return true;
}

enum { K_T, K_WRIST, K_GRIP, K_RPY, K_QUAT, K_POSTURE, K_SENSORS, K_ANGLES, K_PART0, K_COUNT = K_PART0 + 10 };
// a finger part may be placed instead of the wrist (writing a scenario needs no hidden geometry;
// scenarios/README.md "Hands"): tips and bases
// (check points finger × 4 + 3 and finger × 4)
static const char *const key_keys[K_COUNT] = {
    "t",          "wrist",     "grip",       "rpy_deg",    "quat",        "posture",    "sensors",
    "angles_deg", "thumb_tip", "index_tip",  "middle_tip", "ring_tip",    "little_tip", "thumb_base",
    "index_base", "middle_base", "ring_base", "little_base"};

// The check point a finger-part key names (K_PART0 + k).
static int part_point(int k) { return k < 5 ? k * 4 + 3 : (k - 5) * 4; }

static bool read_key(hs_scenario_parser *p, const yaml_node_t *node, const hs_hand_def *def,
                     const hs_hand_key *previous, hs_hand_key *key) {
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(&p->y, node,
		                    "a hand key must be a mapping like { t: 0, wrist: [x, y, z], posture: open }, got %s",
		                    hs_yaml_got(node).text);
	hs_fields f;
	if (!hs_yaml_mapping(&p->y, node, key_keys, K_COUNT, "hand key", &f))
		return false;
	if (!f.value[K_T])
		return hs_yaml_fail(&p->y, node, "hand key is missing 't'");
	if (!hs_yaml_time(&p->y, f.value[K_T], "t", p->s->duration, &key->t))
		return false;
	if (previous && !(key->t > previous->t))
		return hs_yaml_fail(&p->y, f.value[K_T], "hand keys must go forward in time: t = %s after t = %g",
		                    hs_yaml_show(f.value[K_T]).text, previous->t);
	static const int exclusive[][2] = {
	    {K_WRIST, K_GRIP}, {K_RPY, K_QUAT}, {K_POSTURE, K_SENSORS}, {K_POSTURE, K_ANGLES}, {K_SENSORS, K_ANGLES}};
	for (size_t i = 0; i < sizeof exclusive / sizeof exclusive[0]; ++i)
		if (!hs_yaml_exclusive(&p->y, &f, key_keys, exclusive[i][0], exclusive[i][1], "give one"))
			return false;
	int placed = (f.value[K_WRIST] != NULL) + (f.value[K_GRIP] != NULL), part = -1;
	for (int k = 0; k < 10; ++k)
		if (f.value[K_PART0 + k]) {
			placed++;
			part = k;
		}
	if (placed > 1)
		return hs_yaml_fail(&p->y, node, "a hand key places the hand once: give one of 'wrist', 'grip' or a finger part");
	if (!previous && placed == 0)
		return hs_yaml_fail(&p->y, node, "the first hand key needs 'wrist', 'grip' or a finger part (e.g. 'index_tip')");
	key->tracked = true; // a keyframe is always tracked
	// what a key leaves out it keeps from the key before (the first: identity, open hand)
	key->rot = previous ? previous->rot : hs_quat_identity();
	key->wrist = previous ? previous->wrist : hs_v3(0, 0, 0);
	if (previous) {
		memcpy(key->sensors, previous->sensors, sizeof key->sensors);
	} else {
		uint8_t open[HS_GLOVE_SENSORS];
		hs_hand_posture(def, HS_POSTURE_OPEN, 0.0, open);
		for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
			key->sensors[i] = open[i];
	}
	if (f.value[K_RPY] && !hs_yaml_rpy(&p->y, f.value[K_RPY], "rpy_deg", &key->rot))
		return false;
	if (f.value[K_QUAT] && !hs_yaml_quat(&p->y, f.value[K_QUAT], "quat", &key->rot))
		return false;
	if (f.value[K_POSTURE] && !read_posture(p, f.value[K_POSTURE], def, key->sensors))
		return false;
	if (f.value[K_SENSORS] && !read_sensor_list(p, f.value[K_SENSORS], key->sensors))
		return false;
	if (f.value[K_ANGLES] && !read_angle_list(p, f.value[K_ANGLES], key->sensors))
		return false;
	if (f.value[K_WRIST] && !hs_yaml_bounded_vec3(&p->y, f.value[K_WRIST], "wrist", MAX_LENGTH, "m", &key->wrist))
		return false;
	if (f.value[K_GRIP]) { // place the wrist so the posture's grip centre lands on this point
		hs_vec3 grip, center, axis;
		if (!hs_yaml_bounded_vec3(&p->y, f.value[K_GRIP], "grip", MAX_LENGTH, "m", &grip))
			return false;
		uint8_t sensors[HS_GLOVE_SENSORS];
		for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
			sensors[i] = (uint8_t)lround(key->sensors[i]);
		hs_hand_grip(def, sensors, &center, &axis);
		key->wrist = hs_sub(grip, hs_quat_rotate(key->rot, center));
	}
	if (part >= 0) { // place the wrist so that this finger part lands on the point
		hs_vec3 target, points[HS_HAND_POINTS], lines[HS_HAND_LINES][2];
		if (!hs_yaml_bounded_vec3(&p->y, f.value[K_PART0 + part], key_keys[K_PART0 + part], MAX_LENGTH, "m", &target))
			return false;
		uint8_t sensors[HS_GLOVE_SENSORS];
		for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
			sensors[i] = (uint8_t)lround(key->sensors[i]);
		hs_hand_kinematics(def, hs_v3(0.0, 0.0, 0.0), key->rot, sensors, points, lines);
		key->wrist = hs_sub(target, points[part_point(part)]);
	}
	return true;
}

enum { H_NAME, H_SIDE, H_FINGER_RADIUS, H_KEYS, H_RECORD, H_COUNT };
static const char *const hand_keys[H_COUNT] = {"name", "side", "finger_radius", "keys", "record"};

// name, side and finger radius: the hand's definition
static bool read_hand_def(hs_scenario_parser *p, const yaml_node_t *node, const hs_fields *f, int index,
                          hs_hand_def *def) {
	hs_hands *hands = &p->s->hands;
	if (!f->value[H_NAME])
		return hs_yaml_fail(&p->y, node, "hand %d is missing 'name'", index + 1);
	if (!hs_yaml_text(&p->y, f->value[H_NAME], "name", &hands->names[index]))
		return false;
	for (int h = 0; h < index; ++h)
		if (strcmp(hands->names[h], hands->names[index]) == 0)
			return hs_yaml_fail(&p->y, f->value[H_NAME], "duplicate hand name '%s'", hands->names[index]);
	*def = hs_default_hand_def();
	if (f->value[H_SIDE]) {
		if (hs_yaml_scalar_is(f->value[H_SIDE], "left"))
			def->left = true;
		else if (!hs_yaml_scalar_is(f->value[H_SIDE], "right"))
			return hs_yaml_fail(&p->y, f->value[H_SIDE], "'side' must be left or right, got %s",
			                    hs_yaml_got(f->value[H_SIDE]).text);
	}
	if (f->value[H_FINGER_RADIUS]) {
		if (!hs_yaml_number(&p->y, f->value[H_FINGER_RADIUS], "finger_radius", &def->finger_radius))
			return false;
		if (!(def->finger_radius > 0.0 && def->finger_radius <= 0.05))
			return hs_yaml_fail(&p->y, f->value[H_FINGER_RADIUS], "'finger_radius' must be within (0, 0.05] m, got %s",
			                    hs_yaml_show(f->value[H_FINGER_RADIUS]).text);
	}
	return true;
}

static bool read_keys(hs_scenario_parser *p, const yaml_node_t *keys, const hs_hand_def *def, hs_hand_script *script) {
	if (keys->type != YAML_SEQUENCE_NODE)
		return hs_yaml_fail(&p->y, keys, "'keys' must be a list of 1 to %d keys, got %s", MAX_HAND_KEYS,
		                    hs_yaml_got(keys).text);
	long n = hs_yaml_length(keys);
	if (n < 1 || n > MAX_HAND_KEYS)
		return hs_yaml_fail(&p->y, keys, "'keys' must be a list of 1 to %d keys, got %ld", MAX_HAND_KEYS, n);
	script->keys = calloc((size_t)n, sizeof *script->keys);
	if (!script->keys)
		return hs_yaml_fail(&p->y, keys, "out of memory");
	for (long k = 0; k < n; ++k) {
		if (!read_key(p, hs_yaml_item(&p->y, keys, k), def, k ? &script->keys[k - 1] : NULL, &script->keys[k]))
			return false;
		script->key_count = (int)k + 1;
	}
	return true;
}

static bool read_hand(hs_scenario_parser *p, const yaml_node_t *node, int index) {
	hs_hands *hands = &p->s->hands;
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(&p->y, node, "hand %d must be a mapping, got %s", index + 1, hs_yaml_got(node).text);
	hs_fields f;
	hs_hand_def def;
	if (!hs_yaml_mapping(&p->y, node, hand_keys, H_COUNT, "hand", &f) || !read_hand_def(p, node, &f, index, &def))
		return false;
	if (!f.value[H_KEYS] && !f.value[H_RECORD])
		return hs_yaml_fail(&p->y, node, "hand '%s' needs 'keys' or 'record'", hands->names[index]);
	if (!hs_yaml_exclusive(&p->y, &f, hand_keys, H_KEYS, H_RECORD, "give one"))
		return false;
	hs_hand_script *script = &hands->scripts[index];
	if (f.value[H_KEYS] ? !read_keys(p, f.value[H_KEYS], &def, script)
	                    : !hs_read_hand_record(p, f.value[H_RECORD], index, f.value[H_SIDE] != NULL, &def))
		return false; // a joint recording may have fitted the definition to its hand: it is added as fitted
	hs_status status = HS_OK;
	hands->defs[index] = def;
	hands->ids[index] = hs_world_add_hand(p->s->world, &def, &status);
	if (hands->ids[index].index1 == 0)
		return hs_yaml_fail(&p->y, node, "hand '%s': cannot add it to the world: %s", hands->names[index],
		                    hs_status_string(status));
	return true;
}

bool hs_count_hands(hs_scenario_parser *p, const yaml_node_t *node, hs_world_def *def) {
	if (node->type != YAML_SEQUENCE_NODE)
		return hs_yaml_fail(&p->y, node, "'hands' must be a list of 1 to %d hands, got %s", MAX_HANDS,
		                    hs_yaml_got(node).text);
	if (hs_yaml_length(node) < 1 || hs_yaml_length(node) > MAX_HANDS)
		return hs_yaml_fail(&p->y, node, "'hands' must be a list of 1 to %d hands, got %ld", MAX_HANDS,
		                    hs_yaml_length(node));
	def->max_hands = (int)hs_yaml_length(node);
	return true;
}

bool hs_read_hands(hs_scenario_parser *p, const yaml_node_t *node) {
	hs_hands *hands = &p->s->hands;
	long n = hs_yaml_length(node);
	hands->names = calloc((size_t)n, sizeof *hands->names);
	hands->ids = calloc((size_t)n, sizeof *hands->ids);
	hands->scripts = calloc((size_t)n, sizeof *hands->scripts);
	hands->defs = calloc((size_t)n, sizeof *hands->defs);
	hands->fits = calloc((size_t)n, sizeof *hands->fits);
	if (!hands->names || !hands->ids || !hands->scripts || !hands->defs || !hands->fits)
		return hs_yaml_fail(&p->y, node, "out of memory");
	hands->count = (int)n;
	for (int h = 0; h < hands->count; ++h)
		if (!read_hand(p, hs_yaml_item(&p->y, node, h), h))
			return false;
	return true;
}
