// expect_predicates.c — the rows of the predicate table: for each predicate of an `expect` clause,
// how its value is read and how a check is judged at the end (what it captures: capture.c). The
// table at the end of this file is the one list of predicates; adding one is adding a row.
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "expect_table.h"
#include "scenario_internal.h"

static const char *const attach_names[] = {"none", "pick", "catch", "select", "api", "rod", "magnet"};
static const char *const release_names[] = {"none", "drop", "throw", "return"};

// "not reached" for a check whose frames the run never got to.
static bool not_reached(const hs_scenario *s, hs_verdict *v) {
	snprintf(v->measured, sizeof v->measured, "not reached: the run stopped at frame %ld of %ld", s->frame, s->frames);
	return false;
}

// ---------------------------------------------------------------------------------------------
// parsing a predicate's value (f->value[c->pred])

static const yaml_node_t *value_of(const hs_fields *f, const hs_clause *c) { return f->value[c->pred]; }
static const char *name_of(const hs_clause *c) { return hs_predicates[c->pred].name; }

static bool parse_near(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	if (!hs_yaml_vec3(&p->y, value_of(f, c), "near", &c->target))
		return false;
	c->axes = 7;
	const yaml_node_t *axes = f->value[HS_E_AXES];
	if (!axes)
		return true;
	c->axes = 0;
	bool ok = hs_yaml_is_scalar(axes) && axes->data.scalar.length > 0 && axes->data.scalar.length <= 3;
	for (size_t i = 0; ok && i < axes->data.scalar.length; ++i) {
		char a = hs_yaml_scalar(axes)[i];
		unsigned bit = a == 'x' ? 1u : a == 'y' ? 2u : a == 'z' ? 4u : 0u;
		ok = bit != 0 && !(c->axes & bit);
		c->axes |= bit;
	}
	if (!ok)
		return hs_yaml_fail(&p->y, axes, "'axes' must be distinct letters from \"xyz\", got %s", hs_yaml_got(axes).text);
	return true;
}

static bool parse_vector(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	return hs_yaml_vec3(&p->y, value_of(f, c), name_of(c), &c->target);
}

// a direction in the object's own frame: not zero, stored as a unit vector
static bool parse_direction(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	if (!hs_yaml_vec3(&p->y, value_of(f, c), name_of(c), &c->target))
		return false;
	double len = hs_length(c->target);
	if (!(len > 0.0))
		return hs_yaml_fail(&p->y, value_of(f, c), "'%s' must be a direction, got the zero vector", name_of(c));
	c->target = hs_scale(c->target, 1.0 / len);
	return true;
}

static bool parse_flag(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	return hs_yaml_bool(&p->y, value_of(f, c), name_of(c), &c->flag);
}

// true, false, or how it got there
static bool parse_attached(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	const yaml_node_t *v = value_of(f, c);
	int kind = hs_yaml_word(v, attach_names, 4); // "api" is no way a scenario attaches
	if (kind <= HS_ATTACH_NONE && hs_yaml_is_scalar(v) && hs_yaml_scalar_is(v, "rod"))
		kind = HS_ATTACH_ROD;
	if (kind <= HS_ATTACH_NONE && hs_yaml_is_scalar(v) && hs_yaml_scalar_is(v, "magnet"))
		kind = HS_ATTACH_MAGNET;
	if (kind > HS_ATTACH_NONE) {
		c->flag = true;
		c->count = kind;
	} else if (!(hs_yaml_is_scalar(v) && hs_yaml_bool(&p->y, v, name_of(c), &c->flag))) {
		return hs_yaml_fail(&p->y, v, "'attached' must be true, false, pick, catch, select, rod or magnet, got %s", hs_yaml_got(v).text);
	}
	return true;
}

static bool parse_released(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	const yaml_node_t *v = value_of(f, c);
	int kind = hs_yaml_word(v, release_names, 4);
	if (kind < 0)
		return hs_yaml_fail(&p->y, v, "'released' must be drop, throw, return or none, got %s", hs_yaml_got(v).text);
	c->count = kind;
	return true;
}

// conserved: the clause's group — every object ("*"), a list of names, or one name.
static bool read_group(hs_scenario_parser *p, const yaml_node_t *obj, hs_clause *c) {
	hs_expectations *e = &p->s->expect;
	long n = obj->type == YAML_SEQUENCE_NODE ? hs_yaml_length(obj) : 1;
	if (hs_yaml_scalar_is(obj, "*")) {
		c->all_objects = true;
		n = p->s->object_count;
	} else if (obj->type == YAML_SEQUENCE_NODE && n < 1) { // more names than objects repeat one: caught below
		return hs_yaml_fail(&p->y, obj, "'object' must list at least one object name");
	}
	c->first_member = e->member_total;
	int *grown = realloc(e->members, (size_t)(e->member_total + n) * sizeof *grown);
	if (!grown)
		return hs_yaml_fail(&p->y, obj, "out of memory");
	e->members = grown;
	for (long i = 0; i < n; ++i) {
		int index = (int)i;
		if (!c->all_objects) {
			const yaml_node_t *m = obj->type == YAML_SEQUENCE_NODE ? hs_yaml_item(&p->y, obj, i) : obj;
			if (!hs_yaml_is_scalar(m))
				return hs_yaml_fail(&p->y, m, "'object' must be an object name, a list of names or \"*\", got %s",
				                    hs_yaml_got(m).text);
			if ((index = hs_find_object(p, m)) < 0)
				return hs_unknown_object(p, m, "expect");
			for (long j = 0; j < i; ++j)
				if (e->members[c->first_member + j] == index)
					return hs_yaml_fail(&p->y, m, "object '%s' is listed twice", hs_yaml_show(m).text);
		}
		e->members[c->first_member + i] = index;
	}
	c->member_count = (int)n;
	e->member_total += (int)n;
	return true;
}

static bool parse_conserved(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	const yaml_node_t *v = value_of(f, c);
	if (hs_yaml_scalar_is(v, "momentum"))
		c->count = HS_CONSERVE_MOMENTUM;
	else if (hs_yaml_scalar_is(v, "energy"))
		c->count = HS_CONSERVE_ENERGY;
	else
		return hs_yaml_fail(&p->y, v, "'conserved' must be momentum or energy, got %s", hs_yaml_got(v).text);
	if (!read_group(p, f->value[HS_E_OBJECT], c))
		return false;
	c->object = -1;
	return true;
}

static bool parse_energy(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	if (!parse_flag(p, f, c))
		return false;
	if (!c->flag)
		return hs_yaml_fail(&p->y, value_of(f, c), "'energy_never_grows' can only be true (leave it out otherwise)");
	if (!read_group(p, f->value[HS_E_OBJECT], c))
		return false;
	c->object = -1;
	return true;
}

static bool parse_count(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	int64_t n;
	if (!hs_yaml_integer(&p->y, value_of(f, c), name_of(c), 0, INT_MAX, &n))
		return false;
	c->count = (long)n;
	return true;
}

// never_contact: one contact state, 0-3
static bool parse_contact_state(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	int64_t n;
	if (!hs_yaml_integer(&p->y, value_of(f, c), name_of(c), 0, 3, &n))
		return false;
	c->count = (long)n;
	return true;
}

// grasped: only true; "never grasped" is never_contact: 2, one way to say one thing
static bool parse_grasped(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	if (!parse_flag(p, f, c))
		return false;
	if (!c->flag)
		return hs_yaml_fail(&p->y, value_of(f, c), "'grasped' must be true; for never grasped write 'never_contact: 2'");
	c->count = HS_CONTACT_GRASP;
	return true;
}

static bool parse_value(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	return hs_yaml_number(&p->y, value_of(f, c), name_of(c), &c->value);
}

static bool parse_nonnegative(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	if (!parse_value(p, f, c))
		return false;
	if (!(c->value >= 0.0))
		return hs_yaml_fail(&p->y, value_of(f, c), "'%s' must be >= 0, got %s", name_of(c),
		                    hs_yaml_show(value_of(f, c)).text);
	return true;
}

static bool parse_positive(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	if (!parse_value(p, f, c))
		return false;
	if (!(c->value > 0.0))
		return hs_yaml_fail(&p->y, value_of(f, c), "'%s' must be > 0, got %s", name_of(c),
		                    hs_yaml_show(value_of(f, c)).text);
	return true;
}

static bool parse_time(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	return hs_yaml_time(&p->y, value_of(f, c), name_of(c), p->s->duration, &c->value);
}

static bool parse_sequence(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	const yaml_node_t *v = value_of(f, c);
	if (v->type != YAML_SEQUENCE_NODE || hs_yaml_length(v) < 1 || hs_yaml_length(v) > HS_SEQ_CAPACITY)
		return hs_yaml_fail(&p->y, v, "'contact_sequence' must be a list of 1 to %d contact states (0-3), got %s",
		                    HS_SEQ_CAPACITY, v->type == YAML_SEQUENCE_NODE ? "another count" : hs_yaml_got(v).text);
	c->seq_len = (int)hs_yaml_length(v);
	for (int i = 0; i < c->seq_len; ++i) {
		int64_t state;
		const yaml_node_t *e = hs_yaml_item(&p->y, v, i);
		if (!hs_yaml_integer(&p->y, e, name_of(c), 0, 3, &state))
			return false;
		c->seq[i] = (unsigned char)state;
		if (i > 0 && c->seq[i] == c->seq[i - 1]) // repeats are collapsed when recorded
			return hs_yaml_fail(&p->y, e, "'contact_sequence' has %ld twice in a row; repeats are collapsed, write it once",
			                    (long)state);
	}
	return true;
}

// ---------------------------------------------------------------------------------------------
// judging a check: at-based rows see the state captured at the clause's frame (k->u.at)

static bool eval_near(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	(void)s;
	static const char *const axes_text[8] = {"", "x", "y", "xy", "z", "xz", "yz", "xyz"};
	const hs_object_state *st = &k->u.at.state;
	double dx = st->position.x - c->target.x, dy = st->position.y - c->target.y, dz = st->position.z - c->target.z;
	double d2 = ((c->axes & 1) ? dx * dx : 0.0) + ((c->axes & 2) ? dy * dy : 0.0) + ((c->axes & 4) ? dz * dz : 0.0);
	double d = sqrt(d2);
	snprintf(v->what, sizeof v->what, "near [%.9g, %.9g, %.9g] within %g m%s%s %s", c->target.x, c->target.y,
	         c->target.z, c->tolerance, c->axes == 7 ? "" : " on ", c->axes == 7 ? "" : axes_text[c->axes], v->when);
	snprintf(v->measured, sizeof v->measured, "distance %.6g m (at [%.9g, %.9g, %.9g])", d, st->position.x,
	         st->position.y, st->position.z);
	return d <= c->tolerance;
}

static bool eval_resting(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	(void)s;
	snprintf(v->what, sizeof v->what, "resting %s %s", c->flag ? "true" : "false", v->when);
	snprintf(v->measured, sizeof v->measured, "resting %s", k->u.at.state.resting ? "true" : "false");
	return k->u.at.state.resting == c->flag;
}

static bool eval_floor_contacts(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	(void)s;
	snprintf(v->what, sizeof v->what, "floor_contacts %ld %s", c->count, v->when);
	snprintf(v->measured, sizeof v->measured, "floor_contacts %d", k->u.at.state.floor_contacts);
	return k->u.at.state.floor_contacts == c->count;
}

static bool eval_on_face(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	(void)s;
	snprintf(v->what, sizeof v->what, "on_face %s %s", c->flag ? "true" : "false", v->when);
	snprintf(v->measured, sizeof v->measured, "floor_contacts %d", k->u.at.state.floor_contacts);
	return (k->u.at.state.floor_contacts >= 3) == c->flag;
}

// face_down: n (a face's outward normal in the object's own frame) points straight down, within
// HS_FACE_DOWN_DEG, and the object stands on a face (at least 3 floor vertices): it rests on that face.
#define HS_FACE_DOWN_DEG 1.0
static bool eval_face_down(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	(void)s;
	const hs_object_state *st = &k->u.at.state;
	hs_vec3 n = hs_quat_rotate(st->orientation, c->target);
	double off = acos(fmax(-1.0, fmin(1.0, -n.z))) * (180.0 / HS_PI);
	snprintf(v->what, sizeof v->what, "face_down [%.6g, %.6g, %.6g] %s", c->target.x, c->target.y, c->target.z,
	         v->when);
	snprintf(v->measured, sizeof v->measured, "that normal %.3g deg from straight down, floor_contacts %d", off,
	         st->floor_contacts);
	return off <= HS_FACE_DOWN_DEG && st->floor_contacts >= 3;
}

static bool eval_height(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	(void)s;
	double z = k->u.at.state.position.z;
	snprintf(v->what, sizeof v->what, "%s %.9g m %s", name_of(c), c->value, v->when);
	snprintf(v->measured, sizeof v->measured, "z %.9g m", z);
	return strcmp(name_of(c), "below") == 0 ? z < c->value : z > c->value;
}

// The at-most rows are the same measures bounded from above: their names end in "_at_most…".
static bool at_most(const hs_clause *c) { return strstr(name_of(c), "_at_most") != NULL; }

// moved: at least this far (m) from where it started; moved_at_most: at most this far
static bool eval_moved(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	double d = hs_distance(k->u.at.state.position, s->initial[k->object].position);
	bool most = at_most(c);
	snprintf(v->what, sizeof v->what, "moved at %s %.9g m %s", most ? "most" : "least", c->value, v->when);
	snprintf(v->measured, sizeof v->measured, "moved %.6g m", d);
	return most ? d <= c->value : d >= c->value;
}

// turned_deg: turned at least this much (deg) from how it started; turned_at_most_deg: at most
static bool eval_turned(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	hs_quat rel = hs_quat_mul(k->u.at.state.orientation, hs_quat_conj(s->initial[k->object].orientation));
	double a = hs_quat_angle(rel) * (180.0 / HS_PI);
	bool most = at_most(c);
	snprintf(v->what, sizeof v->what, "turned at %s %.9g deg %s", most ? "most" : "least", c->value, v->when);
	snprintf(v->measured, sizeof v->measured, "turned %.6g deg", a);
	return most ? a <= c->value : a >= c->value;
}

// overlap_at_most: the object penetrates no other deeper than this
static bool eval_overlap(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	snprintf(v->what, sizeof v->what, "overlap at most %.9g m %s", c->value, v->when);
	if (k->u.at.overlap_with < 0)
		snprintf(v->measured, sizeof v->measured, "inside no other object");
	else
		snprintf(v->measured, sizeof v->measured, "%.6g m into '%s'", k->u.at.overlap,
		         hs_scenario_object_name(s, k->u.at.overlap_with));
	return k->u.at.overlap <= c->value;
}

static bool eval_speed_below(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	(void)s;
	double speed = hs_length(k->u.at.velocity);
	snprintf(v->what, sizeof v->what, "speed below %.9g m/s %s", c->value, v->when);
	snprintf(v->measured, sizeof v->measured, "speed %.6g m/s", speed);
	return speed < c->value;
}

static bool eval_velocity(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	(void)s;
	hs_vec3 u = k->u.at.velocity;
	double d = hs_distance(u, c->target);
	snprintf(v->what, sizeof v->what, "velocity [%.9g, %.9g, %.9g] within %g m/s %s", c->target.x, c->target.y,
	         c->target.z, c->tolerance, v->when);
	snprintf(v->measured, sizeof v->measured, "velocity [%.9g, %.9g, %.9g] m/s (difference %.6g m/s)", u.x, u.y, u.z, d);
	return d <= c->tolerance;
}

static bool eval_attached(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	snprintf(v->what, sizeof v->what, "attached %s %s", c->count ? attach_names[c->count] : c->flag ? "true" : "false",
	         v->when);
	bool on = k->u.at.holder == k->object;
	if (on)
		snprintf(v->measured, sizeof v->measured, "on the spring (%s)", attach_names[k->u.at.kind]);
	else if (k->u.at.holder >= 0)
		snprintf(v->measured, sizeof v->measured, "not on the spring (it holds '%s')", s->object_names[k->u.at.holder]);
	else
		snprintf(v->measured, sizeof v->measured, "not on the spring (it holds nothing)");
	return c->flag ? on && (c->count == HS_ATTACH_NONE || (long)k->u.at.kind == c->count) : !on;
}

static bool eval_candidate(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	snprintf(v->what, sizeof v->what, "candidate %s %s", c->flag ? "true" : "false", v->when);
	if (k->u.at.candidate >= 0)
		snprintf(v->measured, sizeof v->measured, "the candidate is '%s'", s->object_names[k->u.at.candidate]);
	else
		snprintf(v->measured, sizeof v->measured, "no candidate");
	return (k->u.at.candidate == k->object) == c->flag;
}

static bool eval_extension_ratio(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	(void)s;
	snprintf(v->what, sizeof v->what, "extension_ratio %.9g within %g %s", c->value, c->tolerance, v->when);
	if (k->u.at.holder != k->object) {
		snprintf(v->measured, sizeof v->measured, "not on the spring");
		return false;
	}
	snprintf(v->measured, sizeof v->measured, "extension / x0 = %.9g (extension %.6g m of x0 = %.6g m)", k->u.at.ratio,
	         k->u.at.extension, k->u.at.rest_length);
	return fabs(k->u.at.ratio - c->value) <= c->tolerance;
}

static bool eval_released(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	(void)s;
	snprintf(v->what, sizeof v->what, "released %s", release_names[c->count]);
	const hs_release *r = &k->u.release;
	if (r->kind == HS_RELEASE_NONE)
		snprintf(v->measured, sizeof v->measured, "never released");
	else
		snprintf(v->measured, sizeof v->measured,
		         "%s at t = %.6g s (hand speed %.6g m/s, leaving at [%.6g, %.6g, %.6g] m/s)", release_names[r->kind],
		         r->time, r->hand_speed, r->velocity.x, r->velocity.y, r->velocity.z);
	return (long)r->kind == c->count;
}

// rest_length and stiffness: the spring constants of the object, read at the end
static bool eval_spring_constant(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	hs_spring_object o;
	memset(&o, 0, sizeof o);
	hs_world_spring_object(s->world, s->ids[k->object], &o);
	bool x0 = strcmp(name_of(c), "rest_length") == 0;
	snprintf(v->what, sizeof v->what, "%s %.9g %s within %g %s", name_of(c), c->value, x0 ? "m" : "N/m", c->tolerance,
	         x0 ? "m" : "N/m");
	snprintf(v->measured, sizeof v->measured, "x0 = %.9g m, k = %.9g N/m (mass %.9g kg)", o.rest_length, o.stiffness,
	         o.mass);
	return fabs((x0 ? o.rest_length : o.stiffness) - c->value) <= c->tolerance;
}

static bool eval_energy(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	snprintf(v->what, sizeof v->what,
	         "energy per unit mass never above its value at t = %g s by more than %g J/kg, to t = %g s",
	         (double)c->frame * s->dt, c->tolerance, (double)c->last_frame * s->dt);
	if (!k->captured)
		return not_reached(s, v);
	double grew = k->u.window.peak - k->u.window.before[0];
	snprintf(v->measured, sizeof v->measured, "%.12g J/kg at first, highest %.12g J/kg at t = %g s (%+.3g)",
	         k->u.window.before[0], k->u.window.peak, (double)k->u.window.peak_frame * s->dt, grew);
	return grew <= c->tolerance;
}

static bool eval_conserved(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	bool momentum = c->count == HS_CONSERVE_MOMENTUM;
	snprintf(v->what, sizeof v->what, "conserved %s from t = %g s to t = %g s within %g (relative)",
	         momentum ? "momentum" : "energy", (double)c->frame * s->dt, (double)c->last_frame * s->dt, c->tolerance);
	if (!k->captured)
		return not_reached(s, v);
	const double *a = k->u.window.before, *b = k->u.window.after;
	double change = sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
	double size = fmax(sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]), sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
	double relative = size > 0.0 ? change / size : 0.0;
	if (momentum)
		snprintf(v->measured, sizeof v->measured, "p [%.9g, %.9g, %.9g] -> [%.9g, %.9g, %.9g] kg m/s, relative change %.3g",
		         a[0], a[1], a[2], b[0], b[1], b[2], relative);
	else
		snprintf(v->measured, sizeof v->measured, "E %.12g -> %.12g J, relative change %.3g", a[0], b[0], relative);
	return relative <= c->tolerance;
}

static bool eval_swing_below(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	snprintf(v->what, sizeof v->what, "swing below %.9g m from t = %g s to t = %g s", c->value, (double)c->frame * s->dt,
	         (double)c->last_frame * s->dt);
	if (!k->captured)
		return not_reached(s, v);
	snprintf(v->measured, sizeof v->measured, "largest horizontal offset from the stylus %.6g m (at t = %.6g s)",
	         k->u.window.peak, (double)k->u.window.peak_frame * s->dt);
	return k->u.window.peak < c->value;
}

static bool eval_lands_at(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	snprintf(v->what, sizeof v->what, "lands at t = %g s within %g s", c->value, c->tolerance);
	if (!k->u.lands.landed) {
		snprintf(v->measured, sizeof v->measured, "%s", k->u.lands.had_no_floor ? "never landed" : "never left the floor");
		return false;
	}
	double t = (double)k->u.lands.frame * s->dt;
	snprintf(v->measured, sizeof v->measured, "landed at t = %.6g s (frame %ld)", t, k->u.lands.frame);
	return fabs(t - c->value) <= c->tolerance;
}

static bool eval_still(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	double from = (double)c->frame * s->dt;
	if (c->last_frame < s->frames)
		snprintf(v->what, sizeof v->what, "still %s from t = %g s to t = %g s", c->flag ? "true" : "false", from,
		         (double)c->last_frame * s->dt);
	else
		snprintf(v->what, sizeof v->what, "still %s from t = %g s", c->flag ? "true" : "false", from);
	if (!k->captured)
		return not_reached(s, v);
	if (k->u.still.moved)
		snprintf(v->measured, sizeof v->measured, "moved at frame %ld (t = %.6g s)", k->u.still.moved_frame,
		         (double)k->u.still.moved_frame * s->dt);
	else
		snprintf(v->measured, sizeof v->measured, "unchanged");
	return k->u.still.moved != c->flag;
}

// never_contact and grasped: the first frame of [from, to] whose contact state broke the clause
static bool eval_contact_watch(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	bool never = strcmp(name_of(c), "never_contact") == 0;
	size_t w = never ? (size_t)snprintf(v->what, sizeof v->what, "never_contact %ld", c->count)
	                 : (size_t)snprintf(v->what, sizeof v->what, "grasped (contact state 2)");
	if (w < sizeof v->what)
		snprintf(v->what + w, sizeof v->what - w, " from t = %g s to t = %g s", (double)c->frame * s->dt,
		         (double)c->last_frame * s->dt);
	if (k->u.still.moved) {
		snprintf(v->measured, sizeof v->measured, "contact state %d at frame %ld (t = %.6g s)",
		         (int)k->u.still.state.contact, k->u.still.moved_frame, (double)k->u.still.moved_frame * s->dt);
		return false;
	}
	if (!k->captured)
		return not_reached(s, v);
	snprintf(v->measured, sizeof v->measured, never ? "never in state %ld" : "grasped on every frame", c->count);
	return true;
}

// "[a, b, c]" of contact states into buf
static size_t write_states(char *buf, size_t n, const unsigned char *states, int count) {
	size_t w = (size_t)snprintf(buf, n, "[");
	for (int i = 0; i < count && w < n; ++i)
		w += (size_t)snprintf(buf + w, n - w, "%s%d", i ? ", " : "", states[i]);
	return w;
}

static bool eval_sequence(const hs_scenario *s, const hs_clause *c, const hs_check *k, hs_verdict *v) {
	(void)s;
	size_t w = (size_t)snprintf(v->what, sizeof v->what, "contact_sequence ");
	w += write_states(v->what + w, sizeof v->what - w, c->seq, c->seq_len);
	if (w < sizeof v->what)
		snprintf(v->what + w, sizeof v->what - w, c->min_frames > 1 ? "] (states held %ld frames or more)" : "]",
		         c->min_frames);
	int n = k->u.seq.len;
	long overflow = k->u.seq.overflow;
	size_t m = write_states(v->measured, sizeof v->measured, k->u.seq.states, n);
	if (m < sizeof v->measured)
		snprintf(v->measured + m, sizeof v->measured - m,
		         overflow ? ", ...] (%ld more changes than the %d recorded)" : "]", overflow, HS_SEQ_CAPACITY);
	if (overflow || n != c->seq_len)
		return false;
	return memcmp(k->u.seq.states, c->seq, (size_t)n) == 0;
}

// ---------------------------------------------------------------------------------------------
// the table: one row per predicate, in the order messages list them

enum { AT = HS_PRED_AT, SPR = HS_PRED_SPRINGS, FT = HS_PRED_FROM_TO, WIN = HS_PRED_WINDOW, AX = HS_PRED_AXES,
       GRP = HS_PRED_GROUP };

// short names for the table's store column (macros: an enum constant of another type would convert)
#define S_AT HS_STORE_AT
#define S_STILL HS_STORE_STILL
#define S_WIN HS_STORE_WINDOW
#define S_LANDS HS_STORE_LANDS
#define S_SEQ HS_STORE_SEQ
#define S_REL HS_STORE_RELEASE
#define S_NONE HS_STORE_NONE

const hs_predicate hs_predicates[HS_PREDICATE_COUNT] = {
    // name, flags, tolerance unit, parse, capture, store (the hs_capture member), evaluate (a table: wider than 120)
    {"near",             AT | AX,              "m",        parse_near,        hs_capture_at,        S_AT,    eval_near},
    {"resting",          AT,                   NULL,       parse_flag,        hs_capture_at,        S_AT,    eval_resting},
    {"floor_contacts",   AT,                   NULL,       parse_count,       hs_capture_at,        S_AT,    eval_floor_contacts},
    {"on_face",          AT,                   NULL,       parse_flag,        hs_capture_at,        S_AT,    eval_on_face},
    {"face_down",        AT,                   NULL,       parse_direction,   hs_capture_at,        S_AT,    eval_face_down},
    {"below",            AT,                   NULL,       parse_value,       hs_capture_at,        S_AT,    eval_height},
    {"above",            AT,                   NULL,       parse_value,       hs_capture_at,        S_AT,    eval_height},
    {"moved",            AT,                   NULL,       parse_nonnegative, hs_capture_at,        S_AT,    eval_moved},
    {"turned_deg",       AT,                   NULL,       parse_nonnegative, hs_capture_at,        S_AT,    eval_turned},
    {"moved_at_most",    AT,                   NULL,       parse_nonnegative, hs_capture_at,        S_AT,    eval_moved},
    {"turned_at_most_deg", AT,                 NULL,       parse_nonnegative, hs_capture_at,        S_AT,    eval_turned},
    {"speed_below",      AT,                   NULL,       parse_positive,    hs_capture_at,        S_AT,    eval_speed_below},
    {"overlap_at_most",  AT,                   NULL,       parse_nonnegative, hs_capture_overlap,   S_AT,    eval_overlap},
    {"velocity",         AT,                   "m/s",      parse_vector,      hs_capture_at,        S_AT,    eval_velocity},
    {"attached",         AT | SPR,             NULL,       parse_attached,    hs_capture_at,        S_AT,    eval_attached},
    {"candidate",        AT | SPR,             NULL,       parse_flag,        hs_capture_at,        S_AT,    eval_candidate},
    {"extension_ratio",  AT | SPR,             "a ratio",  parse_value,       hs_capture_at,        S_AT,    eval_extension_ratio},
    {"lands_at",         0,                    "s",        parse_time,        hs_capture_lands,     S_LANDS, eval_lands_at},
    {"still",            FT,                   NULL,       parse_flag,        hs_capture_still,     S_STILL, eval_still},
    {"contact_sequence", HS_PRED_MIN_S,        NULL,       parse_sequence,    hs_capture_sequence,  S_SEQ,   eval_sequence},
    {"never_contact",    FT,                   NULL,       parse_contact_state, hs_capture_never_contact, S_STILL, eval_contact_watch},
    {"grasped",          FT,                   NULL,       parse_grasped,     hs_capture_grasped,   S_STILL, eval_contact_watch},
    {"released",         SPR,                  NULL,       parse_released,    hs_capture_release,   S_REL,   eval_released},
    {"rest_length",      SPR,                  "m",        parse_positive,    NULL,                 S_NONE,  eval_spring_constant},
    {"stiffness",        SPR,                  "N/m",      parse_positive,    NULL,                 S_NONE,  eval_spring_constant},
    {"conserved",        SPR | FT | WIN | GRP, "relative", parse_conserved,   hs_capture_conserved, S_WIN,   eval_conserved},
    {"swing_below",      SPR | FT | WIN,       NULL,       parse_positive,    hs_capture_swing,     S_WIN,   eval_swing_below},
    {"energy_never_grows", FT | WIN | GRP,     "J/kg",     parse_energy,      hs_capture_energy,    S_WIN,   eval_energy},
};
