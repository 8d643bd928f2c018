// hand_record.c — a hand's `record:` (scenarios/README.md, "Hands" and "Recorded joint
// positions"): a file name, or a mapping of the file and how to read a joint recording (frame,
// units, placement, minimum confidence, whether the hand takes the recording's size, what the
// joints drive: the fitted glove hand or the check points themselves). The file is
// a glove + tracker recording or a joint recording, as its header says.
#include <stdlib.h>
#include <string.h>

#include "hand_script.h"
#include "joint_input.h"
#include "scenario_internal.h"
#include "scenario_parser.h"

enum { R_FILE, R_FRAME, R_UNITS, R_ORIGIN, R_RPY, R_MIN_CONFIDENCE, R_FIT_HAND, R_DRIVE, R_COUNT };
static const char *const record_keys[R_COUNT] = {"file",    "frame",          "units",    "origin",
                                                 "rpy_deg", "min_confidence", "fit_hand", "drive"};
static const char *const drives[2] = {"glove", "joints"}; // drive: what the recorded joints drive
static const double MAX_ORIGIN = 1000.0; // m, as every position

// A word among `names`, with the line that says it.
static bool read_word(hs_scenario_parser *p, const yaml_node_t *node, const char *key, const char *const *names,
                      int count, const char *list, hs_joint_said *said) {
	int w = hs_yaml_is_scalar(node) ? hs_yaml_word(node, names, count) : -1;
	if (w < 0)
		return hs_yaml_fail(&p->y, node, "'%s' must be %s, got %s", key, list, hs_yaml_got(node).text);
	said->value = w;
	said->line = hs_yaml_line(node);
	return true;
}

// The keys of a `record:` mapping that say how to read a joint recording.
static bool read_options(hs_scenario_parser *p, const hs_fields *f, hs_joint_options *o) {
	const yaml_node_t *const *v = f->value;
	if (v[R_FRAME] &&
	    !read_word(p, v[R_FRAME], "frame", hs_joint_frame_names, HS_JOINT_FRAMES, HS_JOINT_FRAME_LIST, &o->frame))
		return false;
	if (v[R_UNITS] &&
	    !read_word(p, v[R_UNITS], "units", hs_joint_unit_names, HS_JOINT_UNIT_COUNT, HS_JOINT_UNIT_LIST, &o->units))
		return false;
	if (v[R_ORIGIN] && !hs_yaml_bounded_vec3(&p->y, v[R_ORIGIN], "origin", MAX_ORIGIN, "m", &o->origin))
		return false;
	if (v[R_RPY] && !hs_yaml_rpy(&p->y, v[R_RPY], "rpy_deg", &o->rot))
		return false;
	o->placed = v[R_ORIGIN] || v[R_RPY];
	if (v[R_MIN_CONFIDENCE]) {
		if (!hs_yaml_number(&p->y, v[R_MIN_CONFIDENCE], "min_confidence", &o->min_confidence))
			return false;
		if (!(o->min_confidence >= 0.0 && o->min_confidence <= 1.0))
			return hs_yaml_fail(&p->y, v[R_MIN_CONFIDENCE], "'min_confidence' must be within [0, 1], got %s",
			                    hs_yaml_show(v[R_MIN_CONFIDENCE]).text);
	}
	if (v[R_DRIVE]) {
		hs_joint_said drive;
		if (!read_word(p, v[R_DRIVE], "drive", drives, 2, "glove or joints", &drive))
			return false;
		o->drive_joints = drive.value == 1;
	}
	return !v[R_FIT_HAND] || hs_yaml_bool(&p->y, v[R_FIT_HAND], "fit_hand", &o->fit_hand);
}

// What the load of hand h's joint recording found: for hs_scenario_hand_fit, and the warning
// when neither the file nor the scenario says the frame.
static bool note_fit(hs_scenario_parser *p, int h, const yaml_node_t *file, const char *full,
                     const hs_joint_report *r) {
	hs_hand_fit *fit = &p->s->hands.fits[h];
	fit->joints = true;
	fit->samples = r->samples;
	fit->rms_mm = r->rms_mm;
	fit->record = strdup(hs_yaml_scalar(file));
	if (!fit->record)
		return hs_yaml_fail(&p->y, file, "out of memory");
	char shown[HS_SHOWN_PATH + 4];
	if (r->frame_assumed &&
	    !hs_scenario_warn(p->s, "%s:%lu: warning: the recording says no frame (@frame, or frame: in the scenario's "
	                            "record): read as z_up (x forward, y left, z up)%s",
	                      hs_shown_path(full, shown), r->header_line, r->units_assumed ? ", in m" : ""))
		return hs_yaml_fail(&p->y, file, "out of memory");
	return true;
}

bool hs_read_hand_record(hs_scenario_parser *p, const yaml_node_t *node, int h, bool side_given, hs_hand_def *def) {
	hs_hands *hands = &p->s->hands;
	hs_joint_options o = hs_joint_options_default();
	o.scenario = p->y.path;
	o.hand = hands->names[h];
	o.side_given = side_given;
	hs_fields f;
	memset(&f, 0, sizeof f);
	const yaml_node_t *file = node;
	if (node->type == YAML_SEQUENCE_NODE)
		return hs_yaml_fail(&p->y, node, "'record' must be a file name or a mapping like { file: joints.csv, frame: "
		                                 "y_up }, got a list");
	if (node->type == YAML_MAPPING_NODE) {
		if (!hs_yaml_mapping(&p->y, node, record_keys, R_COUNT, "record", &f) || !read_options(p, &f, &o))
			return false;
		if (!(file = f.value[R_FILE]))
			return hs_yaml_fail(&p->y, node, "a 'record' mapping needs 'file'");
	}
	char *full = hs_yaml_sibling_file(&p->y, file, file == node ? "record" : "file");
	if (!full)
		return false;
	bool ok = true;
	if (!hs_joint_file_is_joints(full)) { // a glove + tracker file: only its name
		for (int k = R_FRAME; k < R_COUNT && ok; ++k)
			if (f.value[k])
				ok = hs_yaml_fail(&p->y, f.key[k], "'%s' is for joint recordings (MediaPipe, OpenXR): %s is not one",
				                  record_keys[k], hs_yaml_show(file).text);
		ok = ok && hs_record_load(full, &hands->scripts[h], p->y.err);
	} else {
		hs_joint_report report;
		ok = hs_joint_record_load(full, &o, def, &hands->scripts[h], &report, p->y.err) &&
		     note_fit(p, h, file, full, &report);
	}
	free(full);
	return ok;
}
