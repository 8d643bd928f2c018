// scenario_world.c — the world a scenario describes: frame time and duration, gravity, the model
// options (model, model.spring), and the objects with their shapes, names and initial motion.
// Every value is checked at its own line, against the limits of the public API (handspring.h),
// so the world is never asked to refuse what the file said.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hs_bench.h"
#include "overlap.h"
#include "scenario_internal.h"
#include "scenario_parser.h"
#include "suggest.h"

enum {
	MAX_OBJECTS = 100000,    // objects per scenario
	MAX_POLY_ITEMS = 100000, // vertices or faces of one polyhedron
	MAX_FACE_SIZE = 1000,    // vertices of one polyhedron face
};
static const long MAX_FRAMES = 10000000L;
// A scenario's frame time lies within the model's (test_scenario checks the two ranges nest).
#define MIN_DT HS_SCENARIO_MIN_DT
#define MAX_DT HS_SCENARIO_MAX_DT
static const double MAX_LENGTH = 1000.0;                        // m: largest size and coordinate accepted

bool hs_read_dt_value(hs_scenario_parser *p, const yaml_node_t *node, const char *key, double *out) {
	double dt = 0.0;
	const char *s = hs_yaml_is_scalar(node) ? hs_yaml_scalar(node) : "";
	const char *slash = hs_yaml_is_scalar(node) ? memchr(s, '/', node->data.scalar.length) : NULL;
	if (slash) { // a fraction "a/b": 1/60 is exact where 0.0166… is not
		size_t n = node->data.scalar.length, a0 = 0, a1 = (size_t)(slash - s), b0 = a1 + 1, b1 = n;
		while (a0 < a1 && s[a0] == ' ')
			++a0;
		while (a1 > a0 && s[a1 - 1] == ' ')
			--a1;
		while (b0 < b1 && s[b0] == ' ')
			++b0;
		while (b1 > b0 && s[b1 - 1] == ' ')
			--b1;
		double a, b;
		hs_number_kind ka = hs_parse_number(s + a0, a1 - a0, &a), kb = hs_parse_number(s + b0, b1 - b0, &b);
		if (ka == HS_NUMBER_NOT_FINITE || kb == HS_NUMBER_NOT_FINITE)
			return hs_yaml_fail(&p->y, node, "'%s' must be finite, got %s", key, hs_yaml_show(node).text);
		if (ka != HS_NUMBER_OK || kb != HS_NUMBER_OK)
			return hs_yaml_fail(&p->y, node, "'%s' must be a number, got %s", key, hs_yaml_got(node).text);
		if (b == 0.0)
			return hs_yaml_fail(&p->y, node, "'%s' divides by zero: %s", key, hs_yaml_show(node).text);
		dt = a / b;
	} else if (!hs_yaml_number(&p->y, node, key, &dt)) {
		return false;
	}
	if (!(dt >= MIN_DT && dt <= MAX_DT))
		return hs_yaml_fail(&p->y, node, "'%s' must be within [1/2000, 1/12] s, got %s", key, hs_yaml_show(node).text);
	*out = dt;
	return true;
}

// dt: the file's, or the one the load options give instead (already checked by hs_scenario_parse_dt)
bool hs_read_dt(hs_scenario_parser *p, const yaml_node_t *node) {
	if (!hs_read_dt_value(p, node, "dt", &p->s->dt))
		return false;
	if (p->options && p->options->dt > 0.0)
		p->s->dt = p->options->dt;
	return true;
}

bool hs_read_duration(hs_scenario_parser *p, const yaml_node_t *node) {
	double d;
	if (!hs_yaml_number(&p->y, node, "duration", &d))
		return false;
	if (!(d > 0.0))
		return hs_yaml_fail(&p->y, node, "'duration' must be > 0 s, got %s", hs_yaml_show(node).text);
	double frames = d / p->s->dt;
	if (!(frames < (double)MAX_FRAMES + 0.5))
		return hs_yaml_fail(&p->y, node,
		                    frames < 1e15 ? "'duration' is %.0f frames of dt = %g s; at most %ld are allowed"
		                                  : "'duration' is %.6g frames of dt = %g s; at most %ld are allowed",
		                    frames, p->s->dt, MAX_FRAMES);
	long n = (long)llround(frames); // below MAX_FRAMES + 0.5: fits a 32-bit long
	if (n < 1)
		return hs_yaml_fail(&p->y, node, "'duration' must be at least one frame (dt = %g s), got %s", p->s->dt,
		                    hs_yaml_show(node).text);
	p->s->duration = d;
	p->s->frames = n;
	return true;
}

// ---------------------------------------------------------------------------------------------
// model.spring: the options of the spring model (workbench paper §4); read into p->spring

enum { SP_INTEGRATOR, SP_FRICTION, SP_SLIDING, SP_RESTITUTION, SP_WALLS, SP_NOISE_SEED, SP_AT_PRESS, SP_COLLISIONS, SP_TECHNIQUES, SP_COUNT };
static const char *const spring_keys[SP_COUNT] = {"integrator", "friction",   "sliding_friction", "restitution",
                                                  "walls",      "noise_seed", "spring_at_press",  "collisions",
                                                  "techniques"};
static bool read_choice(hs_scenario_parser *p, const yaml_node_t *node, const char *key, const char *first,
                        const char *second, bool *is_second);
static const char *const integrator_names[] = {"exact", "implicit_euler", "semi_implicit_euler", "rk4"};

// A coefficient in [0, hi] (hi < 0: no upper bound).
// A length of a shape: (0, MAX_LENGTH] m.
static bool check_length(hs_scenario_parser *p, const yaml_node_t *node, const char *key, double v) {
	if (v > 0.0 && v <= MAX_LENGTH)
		return true;
	return hs_yaml_fail(&p->y, node, "'%s' must be within (0, %g] m, got %s", key, MAX_LENGTH, hs_yaml_show(node).text);
}

static bool read_coefficient(hs_scenario_parser *p, const yaml_node_t *node, const char *key, double hi, double *out) {
	if (!hs_yaml_number(&p->y, node, key, out))
		return false;
	if (hi >= 0.0 && !(*out >= 0.0 && *out <= hi))
		return hs_yaml_fail(&p->y, node, "'%s' must be within [0, %g], got %s", key, hi, hs_yaml_show(node).text);
	if (hi < 0.0 && !(*out >= 0.0))
		return hs_yaml_fail(&p->y, node, "'%s' must be >= 0, got %s", key, hs_yaml_show(node).text);
	return true;
}

static bool read_spring(hs_scenario_parser *p, const yaml_node_t *node) {
	hs_spring_def *d = &p->spring;
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(&p->y, node, "'spring' must be a mapping, got %s", hs_yaml_got(node).text);
	hs_fields f;
	if (!hs_yaml_mapping(&p->y, node, spring_keys, SP_COUNT, "model.spring", &f))
		return false;
	if (f.value[SP_INTEGRATOR]) {
		const yaml_node_t *v = f.value[SP_INTEGRATOR];
		int i = 0;
		while (i < 4 && !hs_yaml_scalar_is(v, integrator_names[i]))
			++i;
		if (i == 4)
			return hs_yaml_fail(&p->y, v,
			                    "'integrator' must be exact, implicit_euler, semi_implicit_euler or rk4, got %s",
			                    hs_yaml_got(v).text);
		d->integrator = (hs_integrator)i; // the names are in the enum's order
	}
	if (f.value[SP_FRICTION]) {
		if (!read_coefficient(p, f.value[SP_FRICTION], "friction", -1.0, &d->friction_static))
			return false;
		d->friction_sliding = d->friction_static; // §4.2: "At small speeds μ is constant"
	}
	if (f.value[SP_SLIDING]) {
		if (!read_coefficient(p, f.value[SP_SLIDING], "sliding_friction", -1.0, &d->friction_sliding))
			return false;
		if (d->friction_sliding > d->friction_static)
			return hs_yaml_fail(&p->y, f.value[SP_SLIDING],
			                    "'sliding_friction' must not exceed 'friction' (%g), got %s", d->friction_static,
			                    hs_yaml_show(f.value[SP_SLIDING]).text);
	}
	if (f.value[SP_RESTITUTION] && !read_coefficient(p, f.value[SP_RESTITUTION], "restitution", 1.0, &d->restitution))
		return false;
	if (f.value[SP_WALLS]) {
		double w[4];
		const yaml_node_t *e[4];
		if (!hs_yaml_numbers(&p->y, f.value[SP_WALLS], "walls", 4, " [x_min, x_max, y_min, y_max]", w, e))
			return false;
		for (int i = 0; i < 4; ++i)
			if (!(fabs(w[i]) <= MAX_LENGTH))
				return hs_yaml_fail(&p->y, e[i], "'walls' must be within [-%g, %g] m, got %s", MAX_LENGTH, MAX_LENGTH,
				                    hs_yaml_show(e[i]).text);
		if (!(w[0] < w[1]))
			return hs_yaml_fail(&p->y, e[1], "'walls' x_max must be greater than x_min (%g), got %s", w[0],
			                    hs_yaml_show(e[1]).text);
		if (!(w[2] < w[3]))
			return hs_yaml_fail(&p->y, e[3], "'walls' y_max must be greater than y_min (%g), got %s", w[2],
			                    hs_yaml_show(e[3]).text);
		d->walls.enabled = true;
		d->walls.x_min = w[0];
		d->walls.x_max = w[1];
		d->walls.y_min = w[2];
		d->walls.y_max = w[3];
	}
	if (f.value[SP_NOISE_SEED]) { // the Fastrak's static accuracy (§5.1), from a seeded generator
		int64_t seed;
		if (!hs_yaml_integer(&p->y, f.value[SP_NOISE_SEED], "noise_seed", 0, 4294967295LL, &seed))
			return false;
		p->seeded = p->noise.stylus = true; // the harness draws it: the model adds none (d->noise stays off)
		p->seed = (unsigned long)seed;
	}
	if (f.value[SP_TECHNIQUES] && !hs_yaml_bool(&p->y, f.value[SP_TECHNIQUES], "techniques", &d->techniques))
		return false; // the techniques beyond the spring and massless objects (docs/techniques.md)
	// the workbench paper's letter, one rule each (docs/model.md §11): the default first
	return read_choice(p, f.value[SP_AT_PRESS], "spring_at_press", "rest", "pen_tip", &d->pen_tip_spring) &&
	       read_choice(p, f.value[SP_COLLISIONS], "collisions", "resting", "paper", &d->paper_collisions);
}

// Checked here, at its own line, against the API's limit (hs_world_create would only say
// "invalid argument" at the objects).
bool hs_read_gravity(hs_scenario_parser *p, const yaml_node_t *node, hs_world_def *def) {
	return hs_yaml_bounded_vec3(&p->y, node, "gravity", HS_MAX_GRAVITY, "m/s^2", &def->gravity);
}

enum { IN_GLOVE, IN_WRIST, IN_SEED, IN_WRIST_DEG, IN_JOINT, IN_COUNT };
static const char *const input_noise_keys[IN_COUNT] = {"glove_units", "wrist_mm", "seed", "wrist_deg", "joint_mm"};

bool hs_read_joint_mm(hs_scenario_parser *p, const yaml_node_t *node, double *joint) {
	double mm;
	if (!hs_yaml_number(&p->y, node, "joint_mm", &mm))
		return false;
	if (!(mm >= 0.0 && mm <= 100.0))
		return hs_yaml_fail(&p->y, node, "'joint_mm' must be within [0, 100] mm, got %s", hs_yaml_show(node).text);
	*joint = mm * 1e-3;
	return true;
}

// model.input_noise: a glove's and a tracker's noise on hand input, from a seeded generator.
static bool read_input_noise(hs_scenario_parser *p, const yaml_node_t *node) {
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(&p->y, node, "'input_noise' must be a mapping, got %s", hs_yaml_got(node).text);
	hs_fields f;
	if (!hs_yaml_mapping(&p->y, node, input_noise_keys, IN_COUNT, "model.input_noise", &f))
		return false;
	int64_t v;
	if (!f.value[IN_SEED])
		return hs_yaml_fail(&p->y, node, "'input_noise' needs a 'seed' (an integer within [0, 4294967295])");
	if (!hs_yaml_integer(&p->y, f.value[IN_SEED], "seed", 0, 4294967295LL, &v))
		return false;
	p->seeded = true;
	p->seed = (unsigned long)v;
	if (f.value[IN_GLOVE]) {
		if (!hs_yaml_integer(&p->y, f.value[IN_GLOVE], "glove_units", 0, 255, &v))
			return false;
		p->noise.glove_units = (int)v;
	}
	if (f.value[IN_WRIST]) {
		double mm;
		if (!hs_yaml_number(&p->y, f.value[IN_WRIST], "wrist_mm", &mm))
			return false;
		if (!(mm >= 0.0 && mm <= 1000.0))
			return hs_yaml_fail(&p->y, f.value[IN_WRIST], "'wrist_mm' must be within [0, 1000] mm, got %s",
			                    hs_yaml_show(f.value[IN_WRIST]).text);
		p->noise.wrist = mm * 1e-3;
	}
	if (f.value[IN_JOINT] && !hs_read_joint_mm(p, f.value[IN_JOINT], &p->noise.joint))
		return false;
	return !f.value[IN_WRIST_DEG] || hs_read_wrist_deg(p, f.value[IN_WRIST_DEG], &p->noise.wrist_rotation);
}

bool hs_read_wrist_deg(hs_scenario_parser *p, const yaml_node_t *node, double *rad) {
	double deg;
	if (!hs_yaml_number(&p->y, node, "wrist_deg", &deg))
		return false;
	if (!(deg >= 0.0 && deg <= 180.0))
		return hs_yaml_fail(&p->y, node, "'wrist_deg' must be within [0, 180] deg, got %s", hs_yaml_show(node).text);
	*rad = deg * (HS_PI / 180.0);
	return true;
}

// A key of two values (absent: *second unchanged): *second is true for `second`; anything else is
// one error line naming both.
static bool read_choice(hs_scenario_parser *p, const yaml_node_t *node, const char *key, const char *first,
                        const char *second, bool *is_second) {
	if (!node)
		return true;
	if (hs_yaml_scalar_is(node, first) || hs_yaml_scalar_is(node, second)) {
		*is_second = hs_yaml_scalar_is(node, second);
		return true;
	}
	return hs_yaml_fail(&p->y, node, "'%s' must be %s or %s, got %s", key, first, second, hs_yaml_got(node).text);
}

// The release velocity's estimator (docs/model.md §4 "Release"): release_fit and release_window_s,
// flat keys so that a campaign overrides one at a time.
static bool read_release(hs_scenario_parser *p, const yaml_node_t *fit, const yaml_node_t *window, hs_world_def *def) {
	if (fit && hs_yaml_scalar_is(fit, "object")) // the 1999 paper's letter: eq. 3 from the object
		def->release_fit = HS_RELEASE_FIT_OBJECT;
	else if (fit) {
		bool quadratic = false;
		if (!hs_yaml_scalar_is(fit, "mean") && !hs_yaml_scalar_is(fit, "quadratic"))
			return hs_yaml_fail(&p->y, fit, "'release_fit' must be mean, quadratic or object, got %s", hs_yaml_got(fit).text);
		quadratic = hs_yaml_scalar_is(fit, "quadratic");
		def->release_fit = quadratic ? HS_RELEASE_FIT_QUADRATIC : HS_RELEASE_FIT_MEAN;
	}
	if (!window)
		return true;
	if (!hs_yaml_number(&p->y, window, "release_window_s", &def->release_window_s))
		return false;
	if (!(def->release_window_s >= 0.0 && def->release_window_s <= HS_MAX_RELEASE_WINDOW))
		return hs_yaml_fail(&p->y, window, "'release_window_s' must be within [0, %g] s, got %s",
		                    HS_MAX_RELEASE_WINDOW, hs_yaml_show(window).text);
	return true;
}

// A number option of `model` within [lo, hi] (its unit in `unit`), when given.
static bool read_bounded(hs_scenario_parser *p, const yaml_node_t *v, const char *name, double lo, double hi,
                         const char *unit, double *out) {
	if (!v)
		return true;
	if (!hs_yaml_number(&p->y, v, name, out))
		return false;
	if (!(*out >= lo && *out <= hi))
		return hs_yaml_fail(&p->y, v, "'%s' must be within [%g, %g] %s, got %s", name, lo, hi, unit, hs_yaml_show(v).text);
	return true;
}

// How a grasp starts and what a lost hand does (docs/model.md §3 "Grasp start", "Tracking loss"):
// grasp_opposed, grasp_close_mm, tracking_hold_s.
static bool read_grasp_start(hs_scenario_parser *p, const hs_fields *f, int first, hs_world_def *def) {
	if (f->value[first] && !hs_yaml_bool(&p->y, f->value[first], "grasp_opposed", &def->grasp_opposed))
		return false;
	return read_bounded(p, f->value[first + 1], "grasp_close_mm", 0.0, 1000.0, "mm", &def->grasp_close_mm) &&
	       read_bounded(p, f->value[first + 2], "tracking_hold_s", 0.0, HS_MAX_TRACKING_HOLD, "s", &def->tracking_hold_s);
}

// `letter` first (the whole of a paper's letter: hs_world_def_letter), then the finer switches
// that restore one rule of the letter each, and the grasp's end margins (docs/model.md §11).
static bool read_letter_rules(hs_scenario_parser *p, const hs_fields *f, int first, hs_world_def *def) {
	const yaml_node_t *letter = f->value[first];
	if (letter) {
		hs_letter l = HS_LETTER_NONE;
		if (hs_yaml_scalar_is(letter, "hand1999"))
			l = HS_LETTER_HAND1999;
		else if (hs_yaml_scalar_is(letter, "workbench"))
			l = HS_LETTER_WORKBENCH;
		else if (!hs_yaml_scalar_is(letter, "none"))
			return hs_yaml_fail(&p->y, letter, "'letter' must be none, hand1999 or workbench, got %s", hs_yaml_got(letter).text);
		def->spring = p->spring; // the spring options are kept apart until the world is made (scenario.c)
		hs_world_def_letter(def, l);
		p->spring = def->spring;
	}
	return read_choice(p, f->value[first + 1], "grasp_end", "margins", "paper", &def->paper_grasp_end) &&
	       read_choice(p, f->value[first + 2], "floor_push", "floor", "paper", &def->paper_floor_push) &&
	       read_choice(p, f->value[first + 3], "push_end", "stop", "paper", &def->paper_push_end) &&
	       read_choice(p, f->value[first + 4], "tipping", "edge", "paper", &def->paper_tipping) &&
	       read_choice(p, f->value[first + 5], "carry", "rigid", "paper", &def->paper_carry) &&
	       read_bounded(p, f->value[first + 6], "grasp_release_mm", 0.0, 1000.0, "mm", &def->grasp_release_mm) &&
	       read_bounded(p, f->value[first + 7], "grasp_open_mm", 0.0, 1000.0, "mm", &def->grasp_open_mm);
}

bool hs_read_model(hs_scenario_parser *p, const yaml_node_t *node, hs_world_def *def) {
	static const char *const names[] = {"grasp_threshold_deg", "stacking",       "floor_tolerance",
	                                    "skip_work",           "spring",         "input_noise",
	                                    "grasp_rule",          "contacts",       "glove_deadband",
	                                    "release_fit",         "release_window_s", "grasp_opposed",
	                                    "grasp_close_mm",      "tracking_hold_s",  "landing",
	                                    "letter",              "grasp_end",        "floor_push",
	                                    "push_end",            "tipping",          "carry",
	                                    "grasp_release_mm",    "grasp_open_mm"};
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(&p->y, node, "'model' must be a mapping, got %s", hs_yaml_got(node).text);
	hs_fields f;
	if (!hs_yaml_mapping(&p->y, node, names, 23, "model", &f) || !read_letter_rules(p, &f, 15, def) ||
	    !read_grasp_start(p, &f, 11, def))
		return false;
	bool stacking_support = def->stacking == HS_STACKING_SUPPORT;
	// the realistic rule first, the paper's letter second (docs/model.md §3, §6)
	if (!read_choice(p, f.value[7], "contacts", "rectified", "paper", &def->paper_contacts) ||
	    !read_choice(p, f.value[6], "grasp_rule", "fingers", "any", &def->grasp_any_contacts) ||
	    !read_choice(p, f.value[14], "landing", "path", "paper", &def->paper_landing) ||
	    !read_choice(p, f.value[1], "stacking", "paper", "support", &stacking_support))
		return false;
	def->stacking = stacking_support ? HS_STACKING_SUPPORT : HS_STACKING_PAPER;
	if (f.value[0]) {
		if (!hs_yaml_number(&p->y, f.value[0], names[0], &def->grasp_threshold_deg))
			return false;
		if (!(def->grasp_threshold_deg > 0.0 && def->grasp_threshold_deg <= 180.0))
			return hs_yaml_fail(&p->y, f.value[0], "'grasp_threshold_deg' must be within (0, 180] deg, got %s",
			                    hs_yaml_show(f.value[0]).text);
	}
	if (f.value[2]) {
		if (!hs_yaml_number(&p->y, f.value[2], names[2], &def->floor_tolerance))
			return false;
		if (!(def->floor_tolerance > 0.0 && def->floor_tolerance <= 0.01))
			return hs_yaml_fail(&p->y, f.value[2], "'floor_tolerance' must be within (0, 0.01] m, got %s",
			                    hs_yaml_show(f.value[2]).text);
	}
	bool skip_work = !p->skip_work_off;
	if (f.value[3] && !hs_yaml_bool(&p->y, f.value[3], names[3], &skip_work))
		return false;
	p->skip_work_off = !skip_work;
	int64_t band = def->glove_deadband;
	if (f.value[8] && !hs_yaml_integer(&p->y, f.value[8], names[8], 0, HS_MAX_GLOVE_DEADBAND, &band))
		return false;
	def->glove_deadband = (int)band;
	if (!read_release(p, f.value[9], f.value[10], def))
		return false;
	if (f.value[4]) {
		p->spring_key = f.key[4];
		if (!read_spring(p, f.value[4]))
			return false;
	}
	if (f.value[5]) {
		p->input_noise_key = f.key[5];
		if (!read_input_noise(p, f.value[5]))
			return false;
	}
	return true;
}

enum {
	O_NAME,
	O_SHAPE,
	O_SIZE,
	O_THICKNESS,
	O_VERTICES,
	O_FACES,
	O_POSITION,
	O_RPY,
	O_QUAT,
	O_VELOCITY,
	O_ANGULAR,
	O_DENSITY,
	O_RESTITUTION,
	O_COUNT
};
static const char *const object_keys[O_COUNT] = {
    "name", "shape", "size", "thickness", "vertices", "faces", "position", "rpy_deg", "quat", "velocity",
    "angular_velocity_deg", "density", "restitution",
};

static bool is_name_char(char c) {
	return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

// Pass 1: every object's name (present, well formed), so later messages can name the object.
static bool read_object_name(hs_scenario_parser *p, const yaml_node_t *node, long index, char **out) {
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(&p->y, node, "object %ld must be a mapping, got %s", index + 1, hs_yaml_got(node).text);
	hs_fields f;
	if (!hs_yaml_mapping(&p->y, node, object_keys, O_COUNT, "object", &f))
		return false;
	const yaml_node_t *v = f.value[O_NAME];
	if (!v)
		return hs_yaml_fail(&p->y, node, "object %ld is missing 'name'", index + 1);
	if (!hs_yaml_is_scalar(v) || v->data.scalar.length == 0)
		return hs_yaml_fail(&p->y, v, "'name' must be a text, got %s", hs_yaml_got(v).text);
	for (size_t i = 0; i < v->data.scalar.length; ++i)
		if (!is_name_char(hs_yaml_scalar(v)[i]))
			return hs_yaml_fail(&p->y, v, "object name '%s' may only use letters, digits, '_' and '-'",
			                    hs_yaml_show(v).text);
	if (v->data.scalar.length > HS_MAX_NAME)
		return hs_yaml_fail(&p->y, v, "object name '%s' is longer than %d characters", hs_yaml_show(v).text,
		                    HS_MAX_NAME);
	return hs_yaml_text(&p->y, v, "name", out);
}

static int compare_names(const void *a, const void *b) {
	const hs_name_entry *x = a, *y = b;
	int c = strcmp(x->name, y->name);
	return c ? c : (x->index > y->index) - (x->index < y->index);
}

static bool read_polyhedron(hs_scenario_parser *p, const hs_fields *f, const yaml_node_t *obj, const char *name,
                            hs_shape **shape) {
	const yaml_node_t *vn = f->value[O_VERTICES], *fn = f->value[O_FACES];
	if (!vn)
		return hs_yaml_fail(&p->y, obj, "object '%s' is missing 'vertices'", name);
	if (!fn)
		return hs_yaml_fail(&p->y, obj, "object '%s' is missing 'faces'", name);
	if (vn->type != YAML_SEQUENCE_NODE || hs_yaml_length(vn) < 4 || hs_yaml_length(vn) > MAX_POLY_ITEMS)
		return hs_yaml_fail(&p->y, vn, "'vertices' must be a list of 4 to %d points [x, y, z], got %s", MAX_POLY_ITEMS,
		            vn->type == YAML_SEQUENCE_NODE ? "another count" : hs_yaml_got(vn).text);
	if (fn->type != YAML_SEQUENCE_NODE || hs_yaml_length(fn) < 4 || hs_yaml_length(fn) > MAX_POLY_ITEMS)
		return hs_yaml_fail(&p->y, fn, "'faces' must be a list of 4 to %d faces [i, j, k, ...], got %s", MAX_POLY_ITEMS,
		            fn->type == YAML_SEQUENCE_NODE ? "another count" : hs_yaml_got(fn).text);
	int vcount = (int)hs_yaml_length(vn), fcount = (int)hs_yaml_length(fn);
	long total = 0;
	for (int i = 0; i < fcount; ++i) {
		const yaml_node_t *face = hs_yaml_item(&p->y, fn, i);
		if (face->type != YAML_SEQUENCE_NODE || hs_yaml_length(face) < 3 || hs_yaml_length(face) > MAX_FACE_SIZE)
			return hs_yaml_fail(&p->y, face, "each face must be a list of 3 to %d vertex indices, got %s",
			                    MAX_FACE_SIZE,
			                    face->type == YAML_SEQUENCE_NODE ? "another count" : hs_yaml_got(face).text);
		total += hs_yaml_length(face);
	}
	hs_vec3 *vertices = malloc((size_t)vcount * sizeof *vertices);
	int *sizes = malloc((size_t)fcount * sizeof *sizes);
	int *indices = malloc((size_t)total * sizeof *indices);
	bool ok = vertices && sizes && indices;
	if (!ok)
		hs_yaml_fail(&p->y, obj, "out of memory");
	for (int i = 0; ok && i < vcount; ++i)
		ok = hs_yaml_vec3(&p->y, hs_yaml_item(&p->y, vn, i), "vertices", &vertices[i]);
	long k = 0;
	for (int i = 0; ok && i < fcount; ++i) {
		const yaml_node_t *face = hs_yaml_item(&p->y, fn, i);
		sizes[i] = (int)hs_yaml_length(face);
		for (int j = 0; ok && j < sizes[i]; ++j) {
			int64_t index;
			const yaml_node_t *e = hs_yaml_item(&p->y, face, j);
			ok = hs_yaml_integer(&p->y, e, "faces", 0, vcount - 1, &index); // indices into 'vertices'
			if (ok)
				indices[k++] = (int)index;
		}
	}
	if (ok) {
		char why[256] = "";
		hs_status status = HS_OK;
		*shape = hs_shape_polyhedron(vertices, vcount, indices, sizes, fcount, why, sizeof why, &status);
		if (!*shape)
			ok = hs_yaml_fail(&p->y, obj, "shape is degenerate: %s", why[0] ? why : hs_status_string(status));
	}
	free(vertices);
	free(sizes);
	free(indices);
	return ok;
}

// The built-in shapes: one row each, with how many numbers `size` takes and how they are made.
typedef hs_shape *(*shape_maker)(const double v[3], double thickness, hs_status *status);

static hs_shape *make_cube(const double v[3], double t, hs_status *st) {
	(void)t;
	return hs_shape_box(hs_v3(v[0], v[0], v[0]), st);
}
static hs_shape *make_box(const double v[3], double t, hs_status *st) {
	(void)t;
	return hs_shape_box(hs_v3(v[0], v[1], v[2]), st);
}
static hs_shape *make_pyramid(const double v[3], double t, hs_status *st) {
	(void)t;
	return hs_shape_pyramid(v[0], v[1], st);
}
static hs_shape *make_l_block(const double v[3], double t, hs_status *st) {
	return hs_shape_l_block(hs_v3(v[0], v[1], v[2]), t, st);
}
static hs_shape *make_ellipsoid(const double v[3], double t, hs_status *st) {
	(void)t;
	return hs_shape_ellipsoid(hs_v3(v[0], v[1], v[2]), st);
}
static hs_shape *make_sphere(const double v[3], double t, hs_status *st) {
	(void)t;
	return hs_shape_sphere(v[0], st);
}

enum { SH_L_BLOCK = 3, SH_POLYHEDRON = 6, SH_COUNT = 7 };
static const struct {
	const char *name;
	int sizes;        // numbers in `size`: 1 a scalar, else a list
	const char *what; // what `size` holds, for messages
	shape_maker make;
} shapes[SH_COUNT] = {
    {"cube", 1, " (the edge)", make_cube},
    {"box", 3, " [x, y, z]", make_box},
    {"pyramid", 2, " [base, height]", make_pyramid},
    {"l_block", 3, " [x, y, z]", make_l_block},
    {"ellipsoid", 3, " [a, b, c] (semi-axes)", make_ellipsoid},
    {"sphere", 1, " (the radius)", make_sphere},
    {"polyhedron", 0, "", NULL}, // vertices and faces instead: read_polyhedron
};

// `size` (and an l_block's `thickness`) of a built-in shape.
static bool read_size(hs_scenario_parser *p, const hs_fields *f, const yaml_node_t *obj, const char *name, int sh,
                      double v[3], double *thickness) {
	const yaml_node_t *size = f->value[O_SIZE];
	if (!size)
		return hs_yaml_fail(&p->y, obj, "object '%s' is missing 'size'", name);
	const yaml_node_t *e[3] = {size, size, size};
	int n = shapes[sh].sizes;
	if (n == 1) {
		if (!hs_yaml_is_scalar(size))
			return hs_yaml_fail(&p->y, size, "'size' of a %s must be a number%s, got %s", shapes[sh].name,
			                    shapes[sh].what, hs_yaml_got(size).text);
		if (!hs_yaml_number(&p->y, size, "size", &v[0]))
			return false;
	} else if (!hs_yaml_numbers(&p->y, size, "size", n, shapes[sh].what, v, e)) {
		return false;
	}
	for (int i = 0; i < n; ++i)
		if (!check_length(p, e[i], "size", v[i]))
			return false;
	if (sh != SH_L_BLOCK)
		return true;
	const yaml_node_t *t = f->value[O_THICKNESS];
	if (!t)
		return hs_yaml_fail(&p->y, obj, "object '%s' is missing 'thickness'", name);
	if (!hs_yaml_number(&p->y, t, "thickness", thickness))
		return false;
	double limit = fmin(v[0], v[2]); // foot height and upright width stay inside the bounding box
	if (!(*thickness > 0.0 && *thickness < limit))
		return hs_yaml_fail(&p->y, t, "'thickness' must be within (0, %g) m (less than size x and z), got %s", limit,
		                    hs_yaml_show(t).text);
	return true;
}

// "unknown shape 'cub': did you mean 'cube'? (expected cube, box, ... or polyhedron)"
static bool unknown_shape(hs_scenario_parser *p, const yaml_node_t *kind) {
	const char *names[SH_COUNT];
	for (int i = 0; i < SH_COUNT; ++i)
		names[i] = shapes[i].name;
	char why[HS_ERROR_TEXT];
	snprintf(why, sizeof why, "unknown shape %s", hs_yaml_got(kind).text);
	if (hs_yaml_is_scalar(kind))
		hs_suggest_append(why, sizeof why, hs_yaml_scalar(kind), kind->data.scalar.length, names, SH_COUNT, 0);
	snprintf(why + strlen(why), sizeof why - strlen(why), " (expected cube, box, pyramid, l_block, ellipsoid, sphere or polyhedron)");
	return hs_yaml_fail(&p->y, kind, "%s", why);
}

static bool read_shape(hs_scenario_parser *p, const hs_fields *f, const yaml_node_t *obj, const char *name,
                       hs_shape **shape) {
	const yaml_node_t *kind = f->value[O_SHAPE];
	if (!kind)
		return hs_yaml_fail(&p->y, obj, "object '%s' is missing 'shape'", name);
	int sh = 0;
	while (sh < SH_COUNT && !hs_yaml_scalar_is(kind, shapes[sh].name))
		++sh;
	if (sh == SH_COUNT)
		return unknown_shape(p, kind);
	if (sh != SH_POLYHEDRON && f->key[O_VERTICES])
		return hs_yaml_fail(&p->y, f->key[O_VERTICES], "'vertices' is only for shape polyhedron");
	if (sh != SH_POLYHEDRON && f->key[O_FACES])
		return hs_yaml_fail(&p->y, f->key[O_FACES], "'faces' is only for shape polyhedron");
	if (sh != SH_L_BLOCK && f->key[O_THICKNESS])
		return hs_yaml_fail(&p->y, f->key[O_THICKNESS], "'thickness' is only for shape l_block");
	if (sh == SH_POLYHEDRON) {
		if (f->key[O_SIZE])
			return hs_yaml_fail(&p->y, f->key[O_SIZE], "a polyhedron takes 'vertices' and 'faces', not 'size'");
		return read_polyhedron(p, f, obj, name, shape);
	}
	double v[3] = {0.0, 0.0, 0.0}, thickness = 0.0;
	if (!read_size(p, f, obj, name, sh, v, &thickness))
		return false;
	hs_status status = HS_OK;
	*shape = shapes[sh].make(v, thickness, &status);
	if (!*shape)
		return hs_yaml_fail(&p->y, obj, "cannot make the %s: %s", shapes[sh].name, hs_status_string(status));
	return true;
}

// The pose, initial motion and density of an object (the shape is read before). Speeds are checked
// against the API's HS_MAX_SPEED at their own line, not refused later by hs_world_add_object.
static bool read_object_def(hs_scenario_parser *p, const hs_fields *f, const yaml_node_t *obj, const char *name,
                            hs_object_def *def) {
	static const char *const names[O_COUNT] = {[O_RPY] = "rpy_deg", [O_QUAT] = "quat"};
	if (!f->value[O_POSITION])
		return hs_yaml_fail(&p->y, obj, "object '%s' is missing 'position'", name);
	if (!hs_yaml_exclusive(&p->y, f, names, O_RPY, O_QUAT, "give one orientation") ||
	    !hs_yaml_bounded_vec3(&p->y, f->value[O_POSITION], "position", MAX_LENGTH, "m", &def->position))
		return false;
	if (f->value[O_RPY] && !hs_yaml_rpy(&p->y, f->value[O_RPY], "rpy_deg", &def->orientation))
		return false;
	if (f->value[O_QUAT] && !hs_yaml_quat(&p->y, f->value[O_QUAT], "quat", &def->orientation))
		return false;
	if (f->value[O_VELOCITY] &&
	    !hs_yaml_bounded_vec3(&p->y, f->value[O_VELOCITY], "velocity", HS_MAX_SPEED, "m/s", &def->velocity))
		return false;
	if (f->value[O_ANGULAR]) {
		hs_vec3 w = {0.0, 0.0, 0.0};
		if (!hs_yaml_bounded_vec3(&p->y, f->value[O_ANGULAR], "angular_velocity_deg", HS_MAX_SPEED * (180.0 / HS_PI),
		                          "deg/s", &w))
			return false;
		def->angular_velocity = hs_scale(w, HS_PI / 180.0);
	}
	if (f->value[O_DENSITY]) {
		if (!hs_yaml_number(&p->y, f->value[O_DENSITY], "density", &def->density))
			return false;
		bool massless = def->density == 0.0 && hs_world_springs_enabled(p->s->world) && p->spring.techniques;
		if (!(def->density > 0.0) && !massless)
			return hs_yaml_fail(&p->y, f->value[O_DENSITY],
			                    "'density' must be > 0 kg/m^3, got %s",
			                    hs_yaml_show(f->value[O_DENSITY]).text);
	}
	if (f->value[O_RESTITUTION]) {
		if (!hs_yaml_number(&p->y, f->value[O_RESTITUTION], "restitution", &def->restitution))
			return false;
		if (!(def->restitution >= 0.0 && def->restitution <= 1.0))
			return hs_yaml_fail(&p->y, f->value[O_RESTITUTION], "'restitution' must be in [0, 1], got %s",
			                    hs_yaml_show(f->value[O_RESTITUTION]).text);
	}
	return true;
}

static bool read_object(hs_scenario_parser *p, const yaml_node_t *obj, int index) {
	hs_scenario *s = p->s;
	const char *name = s->object_names[index];
	hs_fields f;
	if (!hs_yaml_mapping(&p->y, obj, object_keys, O_COUNT, "object", &f))
		return false;
	hs_object_def def = hs_default_object_def();
	hs_shape *shape = NULL;
	if (!read_shape(p, &f, obj, name, &shape))
		return false;
	bool ok = read_object_def(p, &f, obj, name, &def);
	hs_status status = HS_OK;
	if (ok) {
		def.shape = hs_world_add_shape(s->world, shape, &status);
		if (def.shape.index1 == 0)
			ok = hs_yaml_fail(&p->y, obj, "object '%s': cannot add its shape to the world: %s", name,
			                  hs_status_string(status));
	}
	hs_shape_destroy(shape);
	if (ok) {
		s->ids[index] = hs_world_add_object(s->world, &def, &status);
		if (s->ids[index].index1 == 0)
			ok =
			    hs_yaml_fail(&p->y, obj, "object '%s': cannot add it to the world: %s", name, hs_status_string(status));
	}
	return ok;
}

bool hs_read_objects(hs_scenario_parser *p, const yaml_node_t *node, hs_world_def def) {
	hs_scenario *s = p->s;
	if (node->type != YAML_SEQUENCE_NODE)
		return hs_yaml_fail(&p->y, node, "'objects' must be a list of objects, got %s", hs_yaml_got(node).text);
	long n = hs_yaml_length(node);
	if (n < 1 || n > MAX_OBJECTS)
		return hs_yaml_fail(&p->y, node, "'objects' must hold 1 to %d objects, got %ld", MAX_OBJECTS, n);
	s->object_count = (int)n;
	s->object_names = calloc((size_t)n, sizeof *s->object_names);
	s->ids = calloc((size_t)n, sizeof *s->ids);
	if (!s->object_names || !s->ids)
		return hs_yaml_fail(&p->y, node, "out of memory");
	for (int i = 0; i < s->object_count; ++i)
		if (!read_object_name(p, hs_yaml_item(&p->y, node, i), i, &s->object_names[i]))
			return false;
	// duplicate names: sort, then report the earliest object that repeats an earlier name
	hs_name_entry *sorted = p->sorted = malloc((size_t)n * sizeof *sorted);
	if (!sorted)
		return hs_yaml_fail(&p->y, node, "out of memory");
	for (int i = 0; i < s->object_count; ++i)
		sorted[i] = (hs_name_entry){s->object_names[i], i};
	qsort(sorted, (size_t)n, sizeof *sorted, compare_names);
	int dup = -1, first = -1;
	for (int i = 1; i < s->object_count; ++i)
		if (strcmp(sorted[i].name, sorted[i - 1].name) == 0 &&
		    (i < 2 || strcmp(sorted[i - 1].name, sorted[i - 2].name) != 0) && (dup < 0 || sorted[i].index < dup)) {
			dup = sorted[i].index;
			first = sorted[i - 1].index;
		}
	if (dup >= 0) {
		hs_fields f;
		const yaml_node_t *obj = hs_yaml_item(&p->y, node, dup), *first_obj = hs_yaml_item(&p->y, node, first);
		hs_yaml_mapping(&p->y, obj, object_keys, O_COUNT, "object", &f); // succeeded in pass 1
		return hs_yaml_fail(&p->y, f.value[O_NAME], "duplicate object name '%s' (first at line %lu)",
		                    s->object_names[dup], hs_yaml_line(first_obj));
	}
	def.max_objects = s->object_count;
	def.max_shapes = s->object_count;
	hs_status status = HS_OK;
	s->world = hs_world_create(&def, &status);
	if (!s->world)
		return hs_yaml_fail(&p->y, node, "cannot create the world: %s", hs_status_string(status));
	if (p->skip_work_off) // a benchmark's knob (hs_bench.h), set before any object
		hs_world_set_skip_work(s->world, false);
	for (int i = 0; i < s->object_count; ++i)
		if (!read_object(p, hs_yaml_item(&p->y, node, i), i))
			return false;
	int a, b;
	double depth;
	if (hs_find_overlap(s->world, &a, &b, &depth))
		return hs_yaml_fail(&p->y, hs_yaml_item(&p->y, node, b),
		                    "objects '%s' (line %lu) and '%s' overlap: a point of one lies %.3g mm inside the other "
		                    "(objects may touch, not overlap by more than %g mm)",
		                    s->object_names[a], hs_yaml_line(hs_yaml_item(&p->y, node, a)), s->object_names[b],
		                    depth * 1e3, HS_OVERLAP_TOLERANCE * 1e3);
	return true;
}


bool hs_unknown_object(const hs_scenario_parser *p, const yaml_node_t *node, const char *where) {
	char why[HS_ERROR_TEXT];
	snprintf(why, sizeof why, "unknown object '%s' in %s", hs_yaml_show(node).text, where);
	const hs_scenario *s = p->s;
	hs_suggest_append(why, sizeof why, hs_yaml_scalar(node), node->data.scalar.length,
	                  (const char *const *)s->object_names, s->object_count, 1);
	return hs_yaml_fail(&p->y, node, "%s", why);
}

int hs_find_object(const hs_scenario_parser *p, const yaml_node_t *node) {
	size_t n = node->data.scalar.length;
	if (n > HS_MAX_NAME || memchr(hs_yaml_scalar(node), '\0', n))
		return -1;
	hs_name_entry key = {hs_yaml_scalar(node), -1};
	int lo = 0, hi = p->s->object_count;
	while (lo < hi) { // first entry not below key
		int mid = lo + (hi - lo) / 2;
		if (compare_names(&p->sorted[mid], &key) < 0)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo < p->s->object_count && strcmp(p->sorted[lo].name, key.name) == 0 ? p->sorted[lo].index : -1;
}
