// scenario_parser.h — reading a scenario file's sections into an hs_scenario. Each section's
// reader lives beside its concept: the world (scenario_world.c), hands (hands_section.c), the
// stylus (stylus_section.c), expectations (expect.c); scenario.c calls them in order.
#ifndef HS_HARNESS_SCENARIO_PARSER_H
#define HS_HARNESS_SCENARIO_PARSER_H

#include "handspring.h"
#include "hs_harness.h"
#include "noise.h"
#include "yaml_read.h"

typedef struct hs_name_entry {
	const char *name;
	int index;
} hs_name_entry;

typedef struct hs_scenario_parser {
	hs_yaml y;
	hs_scenario *s;
	hs_name_entry *sorted;         // object names in strcmp order, for duplicates and lookups by name
	hs_spring_def spring;          // model.spring, read before the world exists
	const yaml_node_t *spring_key; // where model.spring was given (NULL: not given)
	hs_noise_options noise;        // model.spring.noise_seed, model.input_noise
	bool seeded;                   // a noise seed was given: the scenario draws noise
	unsigned long seed;
	const yaml_node_t *input_noise_key; // where model.input_noise was given (NULL: not given)
	const hs_scenario_options *options; // what the caller overrides (NULL: nothing)
	double stylus_scale;                // the stylus noise's scale (0: as it is)
	bool skip_work_off;                 // model.skip_work: false (set on the world once made, hs_bench.h)
} hs_scenario_parser;

// scenario_world.c
bool hs_read_dt(hs_scenario_parser *p, const yaml_node_t *node);
// A frame time (a number or a fraction "1/60") within the scenario range; `key` names it in messages.
bool hs_read_dt_value(hs_scenario_parser *p, const yaml_node_t *node, const char *key, double *out);
// wrist_deg (model.input_noise, robust): degrees within [0, 180], into radians
bool hs_read_wrist_deg(hs_scenario_parser *p, const yaml_node_t *node, double *rad);
// joint_mm (model.input_noise, robust): millimetres within [0, 100], into metres
bool hs_read_joint_mm(hs_scenario_parser *p, const yaml_node_t *node, double *joint);
bool hs_read_duration(hs_scenario_parser *p, const yaml_node_t *node);
bool hs_read_gravity(hs_scenario_parser *p, const yaml_node_t *node, hs_world_def *def);
bool hs_read_model(hs_scenario_parser *p, const yaml_node_t *node, hs_world_def *def);
// Creates the world (room for exactly these objects) and adds them.
bool hs_read_objects(hs_scenario_parser *p, const yaml_node_t *node, hs_world_def def);
// Index of the object named by a scalar, or -1: the one lookup by name.
int hs_find_object(const hs_scenario_parser *p, const yaml_node_t *node);
// Fails with "unknown object 'N' in WHERE", the nearest name and, when there are few, all of them.
bool hs_unknown_object(const hs_scenario_parser *p, const yaml_node_t *node, const char *where);

// hands_section.c: the world's room for hands (before it is created), then the hands
bool hs_count_hands(hs_scenario_parser *p, const yaml_node_t *node, hs_world_def *def);
bool hs_read_hands(hs_scenario_parser *p, const yaml_node_t *node);
// hand_record.c: hand h's `record:` (a file name or a mapping) into its script; a joint recording
// may fit `def` to the recorded hand. `side_given`: the hand's side is written.
bool hs_read_hand_record(hs_scenario_parser *p, const yaml_node_t *node, int h, bool side_given, hs_hand_def *def);
// stylus_section.c: the stylus's script (a stylus makes the scenario's world a spring world)
bool hs_read_stylus(hs_scenario_parser *p, const yaml_node_t *node);
// expect.c: the clauses, then everything the run records (so stepping never allocates)
bool hs_read_expect(hs_scenario_parser *p, const yaml_node_t *node);
bool hs_prepare_checks(hs_scenario_parser *p, const yaml_node_t *root);
// throw_error.c: a thrower's error on one hand's script (a load option; `root` for messages)
bool hs_throw_error_set(hs_scenario_parser *p, const yaml_node_t *root, const hs_throw_error *e);
// robust.c: the `robust` block (the sweep's matrix and noise levels)
bool hs_read_robust(hs_scenario_parser *p, const yaml_node_t *node, bool hands);

#endif
