// robust.c — the `robust` block of a scenario: the matrix a sweep runs (frame times × noise seeds)
// and the noise levels of its cells. Which clauses must hold in every cell is each clause's own
// `robust: true` (expect.c); running the matrix is sweep.c.
#include <string.h>

#include "scenario_internal.h"
#include "scenario_parser.h"

enum { R_DT, R_SEEDS, R_GLOVE, R_WRIST, R_WRIST_DEG, R_JOINT, R_PHASES, R_COUNT };
static const char *const robust_keys[R_COUNT] = {"dt",        "seeds",    "glove_units", "wrist_mm",
                                                 "wrist_deg", "joint_mm", "phases"};

// dt: a list of 1 to HS_ROBUST_MAX_DTS frame times, each as the scenario's `dt` takes it.
static bool read_dts(hs_scenario_parser *p, const yaml_node_t *node, hs_robust *r) {
	long n = node->type == YAML_SEQUENCE_NODE ? hs_yaml_length(node) : 0;
	if (n < 1 || n > HS_ROBUST_MAX_DTS)
		return hs_yaml_fail(&p->y, node, "'robust.dt' must be a list of 1 to %d frame times, got %s", HS_ROBUST_MAX_DTS,
		                    node->type == YAML_SEQUENCE_NODE ? "another count" : hs_yaml_got(node).text);
	for (long i = 0; i < n; ++i) {
		const yaml_node_t *item = hs_yaml_item(&p->y, node, i);
		if (!hs_read_dt_value(p, item, "robust.dt", &r->dts[i]))
			return false;
		snprintf(r->dt_text[i], sizeof r->dt_text[i], "%.15s", hs_yaml_show(item).text); // the table shows 15 characters
	}
	r->dt_count = (int)n;
	return true;
}

// glove_units, wrist_mm, wrist_deg, joint_mm: the cells' noise levels (hands only); the ones not
// given are 0.
static bool read_levels(hs_scenario_parser *p, const hs_fields *f, hs_robust *r) {
	int64_t units;
	double mm;
	if (f->value[R_GLOVE]) {
		if (!hs_yaml_integer(&p->y, f->value[R_GLOVE], "glove_units", 0, 255, &units))
			return false;
		r->levels.glove_units = (int)units;
	}
	if (f->value[R_WRIST]) {
		if (!hs_yaml_number(&p->y, f->value[R_WRIST], "wrist_mm", &mm))
			return false;
		if (!(mm >= 0.0 && mm <= 1000.0))
			return hs_yaml_fail(&p->y, f->value[R_WRIST], "'wrist_mm' must be within [0, 1000] mm, got %s",
			                    hs_yaml_show(f->value[R_WRIST]).text);
		r->levels.wrist = mm * 1e-3;
	}
	if (f->value[R_JOINT] && !hs_read_joint_mm(p, f->value[R_JOINT], &r->levels.joint))
		return false;
	return !f->value[R_WRIST_DEG] || hs_read_wrist_deg(p, f->value[R_WRIST_DEG], &r->levels.wrist_rotation);
}

bool hs_read_robust(hs_scenario_parser *p, const yaml_node_t *node, bool hands) {
	hs_robust *r = &p->s->robust;
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(&p->y, node, "'robust' must be a mapping (dt, seeds, glove_units, wrist_mm, wrist_deg, joint_mm, phases), got %s",
		                    hs_yaml_got(node).text);
	hs_fields f;
	if (!hs_yaml_mapping(&p->y, node, robust_keys, R_COUNT, "robust", &f))
		return false;
	memset(r, 0, sizeof *r);
	r->given = true;
	r->seeds = 10;
	r->dt_count = 1; // the file's dt unless a list is given
	r->dts[0] = p->s->dt;
	snprintf(r->dt_text[0], sizeof r->dt_text[0], "%.6g", p->s->dt);
	if (f.value[R_DT] && !read_dts(p, f.value[R_DT], r))
		return false;
	int64_t seeds;
	if (f.value[R_SEEDS]) {
		if (!hs_yaml_integer(&p->y, f.value[R_SEEDS], "seeds", 1, HS_ROBUST_MAX_SEEDS, &seeds))
			return false;
		r->seeds = (int)seeds;
	}
	for (int i = R_GLOVE; i <= R_WRIST_DEG; ++i)
		if (f.key[i] && !hands)
			return hs_yaml_fail(&p->y, f.key[i], "'%s' needs 'hands': the levels are of hand input noise",
			                    robust_keys[i]);
	if (f.value[R_PHASES] && !hs_yaml_bool(&p->y, f.value[R_PHASES], "phases", &r->phases))
		return false;
	r->has_levels = f.value[R_GLOVE] || f.value[R_WRIST] || f.value[R_WRIST_DEG] || f.value[R_JOINT];
	return read_levels(p, &f, r);
}
