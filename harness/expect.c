// expect.c — `expect` clauses: reading them (the object, the one predicate, its modifiers `at`,
// `tolerance`, `axes`, `from`, `to`, `min_s`, `robust`), preparing the checks before the run, and the report after
// it. What each predicate means is its row in the table (expect_predicates.c).
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "expect.h"
#include "expect_table.h"
#include "scenario_internal.h"

static const char *const modifier_names[] = {"object", "at", "tolerance", "axes", "from", "to", "min_s", "robust"};

// The keys of a clause: the predicates' names in table order, then the modifiers.
static void clause_keys(const char *keys[HS_E_COUNT]) {
	for (int i = 0; i < HS_PREDICATE_COUNT; ++i)
		keys[i] = hs_predicates[i].name;
	for (int i = HS_E_OBJECT; i < HS_E_COUNT; ++i)
		keys[i] = modifier_names[i - HS_E_OBJECT];
}

// "'a', 'b' and 'c'": the predicates with a flag, for "only for" messages.
static void rows_with(unsigned flag, char *buf, size_t n) {
	int count = 0, seen = 0;
	for (int i = 0; i < HS_PREDICATE_COUNT; ++i)
		count += (hs_predicates[i].flags & flag) != 0;
	size_t w = 0;
	buf[0] = '\0';
	for (int i = 0; i < HS_PREDICATE_COUNT && w < n; ++i)
		if (hs_predicates[i].flags & flag) {
			seen++;
			w += (size_t)snprintf(buf + w, n - w, "%s'%s'", seen == 1 ? "" : seen == count ? " and " : ", ",
			                      hs_predicates[i].name);
		}
}

// `object`: a name, "*" (-1), or a list (-2: a group, read by the predicates that take one).
static bool read_clause_object(hs_scenario_parser *p, const yaml_node_t *node, const hs_fields *f, hs_clause *c) {
	const yaml_node_t *obj = f->value[HS_E_OBJECT];
	if (!obj)
		return hs_yaml_fail(&p->y, node, "expect clause is missing 'object'");
	if (hs_yaml_scalar_is(obj, "*"))
		c->object = -1;
	else if (obj->type == YAML_SEQUENCE_NODE)
		c->object = -2;
	else if (!hs_yaml_is_scalar(obj))
		return hs_yaml_fail(&p->y, obj, "'object' must be an object name or \"*\", got %s", hs_yaml_got(obj).text);
	else if ((c->object = hs_find_object(p, obj)) < 0)
		return hs_unknown_object(p, obj, "expect");
	return true;
}

// Exactly one predicate per clause.
static bool read_predicate(hs_scenario_parser *p, const yaml_node_t *node, const hs_fields *f, hs_clause *c) {
	int pred = -1;
	for (int i = 0; i < HS_PREDICATE_COUNT; ++i) {
		if (!f->key[i])
			continue;
		if (pred >= 0) { // named in file order, reported at the second
			int a = hs_yaml_before(f->key[pred], f->key[i]) ? pred : i, b = a == pred ? i : pred;
			return hs_yaml_fail(&p->y, f->key[b], "expect clause has two predicates, '%s' and '%s': give one per clause",
			                    hs_predicates[a].name, hs_predicates[b].name);
		}
		pred = i;
	}
	if (pred < 0) {
		char list[512];
		size_t w = 0;
		for (int i = 0; i < HS_PREDICATE_COUNT && w < sizeof list; ++i)
			w += (size_t)snprintf(list + w, sizeof list - w, "%s%s",
			                      i == 0 ? "" : i == HS_PREDICATE_COUNT - 1 ? " or " : ", ", hs_predicates[i].name);
		return hs_yaml_fail(&p->y, node, "expect clause needs a predicate: %s", list);
	}
	c->pred = pred;
	return true;
}

// The modifiers a predicate does not take are errors at their key.
static bool check_modifiers(hs_scenario_parser *p, const hs_fields *f, const hs_clause *c) {
	const hs_predicate *row = &hs_predicates[c->pred];
	const yaml_node_t *obj = f->value[HS_E_OBJECT];
	char list[256];
	if ((row->flags & HS_PRED_SPRINGS) && !p->s->springs)
		return hs_yaml_fail(&p->y, f->key[c->pred], "'%s' needs a spring world: give the scenario a 'stylus'", row->name);
	if (c->object == -2 && !(row->flags & HS_PRED_GROUP)) {
		rows_with(HS_PRED_GROUP, list, sizeof list);
		return hs_yaml_fail(&p->y, obj, "'object' may list several objects only for %s", list);
	}
	if (f->key[HS_E_AT] && !(row->flags & HS_PRED_AT))
		return hs_yaml_fail(&p->y, f->key[HS_E_AT], "'at' is not used by '%s'", row->name);
	if (f->key[HS_E_TOLERANCE] && !row->tolerance_unit)
		return hs_yaml_fail(&p->y, f->key[HS_E_TOLERANCE], "'tolerance' is not used by '%s'", row->name);
	if (f->key[HS_E_AXES] && !(row->flags & HS_PRED_AXES)) {
		rows_with(HS_PRED_AXES, list, sizeof list);
		return hs_yaml_fail(&p->y, f->key[HS_E_AXES], "'axes' is only for %s", list);
	}
	if (f->key[HS_E_MIN_S] && !(row->flags & HS_PRED_MIN_S)) {
		rows_with(HS_PRED_MIN_S, list, sizeof list);
		return hs_yaml_fail(&p->y, f->key[HS_E_MIN_S], "'min_s' is only for %s", list);
	}
	for (int m = HS_E_FROM; m <= HS_E_TO; ++m)
		if (f->key[m] && !(row->flags & HS_PRED_FROM_TO)) {
			rows_with(HS_PRED_FROM_TO, list, sizeof list);
			return hs_yaml_fail(&p->y, f->key[m], "'%s' is only for %s", modifier_names[m - HS_E_OBJECT], list);
		}
	return true;
}

// `at`: end or a time in s, as the frame whose state is checked.
static bool read_at(hs_scenario_parser *p, const yaml_node_t *node, const hs_fields *f, hs_clause *c) {
	const hs_scenario *s = p->s;
	const yaml_node_t *at = f->value[HS_E_AT];
	if (!at)
		return hs_yaml_fail(&p->y, node, "expect clause '%s' is missing 'at' (end or a time in s)",
		                    hs_predicates[c->pred].name);
	double t = 0.0;
	if (hs_yaml_scalar_is(at, "end")) {
		c->at_end = true;
		c->frame = s->frames;
	} else if (!hs_yaml_is_scalar(at) || hs_parse_number(hs_yaml_scalar(at), at->data.scalar.length, &t) != HS_NUMBER_OK) {
		return hs_yaml_fail(&p->y, at, "'at' must be 'end' or a time in s, got %s", hs_yaml_got(at).text);
	} else if (t < 0.0 || t > s->duration) {
		return hs_yaml_fail(&p->y, at, "'at' must be 'end' or a time within [0, %g] s, got %s", s->duration,
		                    hs_yaml_show(at).text);
	} else {
		c->frame = (long)llround(t / s->dt); // t <= duration: within MAX_FRAMES
	}
	return true;
}

static bool read_tolerance(hs_scenario_parser *p, const yaml_node_t *node, const hs_fields *f, hs_clause *c) {
	const char *unit = hs_predicates[c->pred].tolerance_unit;
	const yaml_node_t *tol = f->value[HS_E_TOLERANCE];
	if (!tol)
		return hs_yaml_fail(&p->y, node, "expect clause '%s' is missing 'tolerance' (%s)", hs_predicates[c->pred].name,
		                    unit);
	if (!hs_yaml_number(&p->y, tol, "tolerance", &c->tolerance))
		return false;
	if (!(c->tolerance > 0.0))
		return hs_yaml_fail(&p->y, tol, "'tolerance' must be > 0, got %s", hs_yaml_show(tol).text);
	return true;
}

// `from` and `to`: the frames watched (default: from frame 0 to the end).
static bool read_from_to(hs_scenario_parser *p, const yaml_node_t *node, const hs_fields *f, hs_clause *c) {
	const hs_scenario *s = p->s;
	double t;
	if (f->value[HS_E_FROM]) {
		if (!hs_yaml_time(&p->y, f->value[HS_E_FROM], "from", s->duration, &t))
			return false;
		c->frame = (long)llround(t / s->dt); // t <= duration: within MAX_FRAMES
	}
	c->last_frame = s->frames;
	if (f->value[HS_E_TO]) {
		if (!hs_yaml_time(&p->y, f->value[HS_E_TO], "to", s->duration, &t))
			return false;
		c->last_frame = (long)llround(t / s->dt);
	}
	bool window = hs_predicates[c->pred].flags & HS_PRED_WINDOW; // still: from = end is fine
	if (!(c->last_frame > c->frame) && (f->value[HS_E_TO] || window))
		return hs_yaml_fail(&p->y, f->value[HS_E_TO] ? f->value[HS_E_TO] : node,
		                    "'to' must come at least one frame after 'from' (frames %ld and %ld of dt = %g s)", c->frame,
		                    c->last_frame, s->dt);
	return true;
}

// `min_s`: the shortest time a contact state must be held to count, as frames of this dt (a state
// held for n frames lasts n dt); default one frame, every state counts.
static bool read_min_s(hs_scenario_parser *p, const hs_fields *f, hs_clause *c) {
	c->min_frames = 1;
	if (!f->value[HS_E_MIN_S])
		return true;
	double t;
	if (!hs_yaml_time(&p->y, f->value[HS_E_MIN_S], "min_s", p->s->duration, &t))
		return false;
	long n = (long)ceil(t / p->s->dt - 1e-9); // t <= duration: within MAX_FRAMES
	c->min_frames = n > 1 ? n : 1;
	return true;
}

static bool read_clause(hs_scenario_parser *p, const yaml_node_t *node, hs_clause *c) {
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(&p->y, node, "each expect clause must be a mapping, got %s", hs_yaml_got(node).text);
	const char *keys[HS_E_COUNT];
	clause_keys(keys);
	hs_fields f;
	if (!hs_yaml_mapping(&p->y, node, keys, HS_E_COUNT, "expect clause", &f))
		return false;
	memset(c, 0, sizeof *c);
	c->line = hs_yaml_line(node);
	if (!read_clause_object(p, node, &f, c) || !read_predicate(p, node, &f, c) || !check_modifiers(p, &f, c))
		return false;
	const hs_predicate *row = &hs_predicates[c->pred];
	if ((row->flags & HS_PRED_AT) && !read_at(p, node, &f, c))
		return false;
	if (row->tolerance_unit && !read_tolerance(p, node, &f, c))
		return false;
	if (!row->parse(p, &f, c))
		return false;
	if (!read_min_s(p, &f, c))
		return false;
	if (f.value[HS_E_ROBUST] && !hs_yaml_bool(&p->y, f.value[HS_E_ROBUST], "robust", &c->robust))
		return false;
	return !(row->flags & HS_PRED_FROM_TO) || read_from_to(p, node, &f, c);
}

bool hs_read_expect(hs_scenario_parser *p, const yaml_node_t *node) {
	hs_scenario *s = p->s;
	hs_expectations *e = &s->expect;
	if (node->type != YAML_SEQUENCE_NODE)
		return hs_yaml_fail(&p->y, node, "'expect' must be a list of clauses, got %s", hs_yaml_got(node).text);
	long n = hs_yaml_length(node);
	if (n > HS_MAX_CLAUSES)
		return hs_yaml_fail(&p->y, node, "'expect' has %ld clauses; at most %d are allowed", n, HS_MAX_CLAUSES);
	if (n == 0)
		return true;
	e->clauses = calloc((size_t)n, sizeof *e->clauses);
	if (!e->clauses)
		return hs_yaml_fail(&p->y, node, "out of memory");
	long checks = 0;
	bool ok = true;
	for (long i = 0; ok && i < n; ++i) {
		const yaml_node_t *item = hs_yaml_item(&p->y, node, i);
		ok = read_clause(p, item, &e->clauses[i]);
		e->clause_count = (int)i + (ok ? 1 : 0);
		if (ok) // the work the checks will take: a group counts its members
			checks += (hs_predicates[e->clauses[i].pred].flags & HS_PRED_GROUP) ? e->clauses[i].member_count
			          : e->clauses[i].object < 0                              ? s->object_count
			                                                                  : 1;
		if (ok && checks > HS_MAX_CHECKS)
			ok = hs_yaml_fail(&p->y, item, "expect clauses check more than %d object states in all", HS_MAX_CHECKS);
	}
	return ok;
}

static int compare_capture(int x, int y, const hs_expectations *e) {
	long fx = e->clauses[e->checks[x].clause].frame, fy = e->clauses[e->checks[y].clause].frame;
	if (fx != fy)
		return fx < fy ? -1 : 1;
	return (x > y) - (x < y);
}

// C11's qsort takes no context to reach the clauses: a small merge sort by (frame, check index)
static void sort_captures(int *a, int *tmp, int n, const hs_expectations *e) {
	if (n < 2)
		return;
	int h = n / 2;
	sort_captures(a, tmp, h, e);
	sort_captures(a + h, tmp, n - h, e);
	int i = 0, j = h, k = 0;
	while (i < h && j < n)
		tmp[k++] = compare_capture(a[j], a[i], e) < 0 ? a[j++] : a[i++];
	while (i < h)
		tmp[k++] = a[i++];
	while (j < n)
		tmp[k++] = a[j++];
	memcpy(a, tmp, (size_t)n * sizeof *a);
}

// One check per clause and object it names (a group: one for the group); at-based ones queued in
// frame order, the others captured every frame.
static void make_checks(hs_scenario *s) {
	hs_expectations *e = &s->expect;
	for (int i = 0; i < e->clause_count; ++i) {
		const hs_clause *c = &e->clauses[i];
		const hs_predicate *row = &hs_predicates[c->pred];
		int first = c->object < 0 ? 0 : c->object, last = c->object < 0 ? s->object_count - 1 : c->object;
		if (row->flags & HS_PRED_GROUP)
			first = last = -1;
		for (int o = first; o <= last; ++o) {
			int k = e->check_count++;
			e->checks[k].clause = i;
			e->checks[k].object = o;
			if (row->flags & HS_PRED_AT)
				e->capture_order[e->capture_count++] = k;
			else if (row->capture)
				e->live[e->live_count++] = k;
		}
	}
}

bool hs_prepare_checks(hs_scenario_parser *p, const yaml_node_t *root) {
	hs_scenario *s = p->s;
	hs_expectations *e = &s->expect;
	long checks = 0;
	for (int i = 0; i < e->clause_count; ++i) {
		const hs_clause *c = &e->clauses[i];
		checks += (hs_predicates[c->pred].flags & HS_PRED_GROUP) || c->object >= 0 ? 1 : s->object_count;
	}
	if (checks == 0)
		return true;
	size_t nc = (size_t)checks;
	e->checks = calloc(nc, sizeof *e->checks);
	e->capture_order = malloc(nc * sizeof *e->capture_order);
	e->live = malloc(nc * sizeof *e->live);
	if (!e->checks || !e->capture_order || !e->live)
		return hs_yaml_fail(&p->y, root, "out of memory");
	make_checks(s);
	if (e->capture_count > 1) {
		int *tmp = malloc((size_t)e->capture_count * sizeof *tmp);
		if (!tmp)
			return hs_yaml_fail(&p->y, root, "out of memory");
		sort_captures(e->capture_order, tmp, e->capture_count, e);
		free(tmp);
	}
	return true;
}

// ---------------------------------------------------------------------------------------------
// the report

// The object a check names, or its group: "all objects" or the names joined by '+'.
typedef struct label {
	char text[256];
} label;

static label check_label(const hs_scenario *s, const hs_check *k) {
	label l;
	const hs_clause *c = &s->expect.clauses[k->clause];
	if (k->object >= 0) {
		snprintf(l.text, sizeof l.text, "%s", s->object_names[k->object]);
	} else if (c->all_objects) {
		snprintf(l.text, sizeof l.text, "all objects");
	} else {
		size_t w = 0;
		l.text[0] = '\0';
		for (int i = 0; i < c->member_count && w < sizeof l.text; ++i)
			w += (size_t)snprintf(l.text + w, sizeof l.text - w, "%s%s", i ? "+" : "",
			                      s->object_names[s->expect.members[c->first_member + i]]);
	}
	return l;
}

static bool judge(const hs_scenario *s, const hs_check *k, hs_verdict *v) {
	const hs_clause *c = &s->expect.clauses[k->clause];
	const hs_predicate *row = &hs_predicates[c->pred];
	v->when[0] = '\0';
	if (row->flags & HS_PRED_AT) {
		if (c->at_end)
			snprintf(v->when, sizeof v->when, "at end (t = %g s)", (double)s->frames * s->dt);
		else
			snprintf(v->when, sizeof v->when, "at t = %g s", (double)c->frame * s->dt);
		if (!k->captured) {
			snprintf(v->what, sizeof v->what, "%s %s", row->name, v->when);
			snprintf(v->measured, sizeof v->measured, "not reached: the run stopped at frame %ld of %ld", s->frame,
			         s->frames);
			return false;
		}
	}
	return row->evaluate(s, c, k, v);
}

int hs_expect_report(const hs_scenario *s, FILE *report) {
	int failed = 0;
	for (int i = 0; i < s->expect.check_count; ++i) {
		const hs_check *k = &s->expect.checks[i];
		hs_verdict v;
		bool pass = judge(s, k, &v);
		failed += !pass;
		if (report)
			fprintf(report, "%s  line %lu: %s %s: %s\n", pass ? "PASS" : "FAIL", s->expect.clauses[k->clause].line,
			        check_label(s, k).text, v.what, v.measured);
	}
	return failed;
}

unsigned long hs_expect_first_failure(const hs_scenario *s, bool robust_only) {
	for (int i = 0; i < s->expect.check_count; ++i) {
		const hs_check *k = &s->expect.checks[i];
		const hs_clause *c = &s->expect.clauses[k->clause];
		hs_verdict v;
		if ((!robust_only || c->robust) && !judge(s, k, &v))
			return c->line;
	}
	return 0;
}

void hs_expectations_free(hs_expectations *e) {
	free(e->clauses);
	free(e->checks);
	free(e->capture_order);
	free(e->live);
	free(e->members);
	memset(e, 0, sizeof *e);
}

// What the checks record from the frame just stepped: the at-based ones due by now (in frame
// order), then every watching one (capture.c, through the table's rows).
void hs_expect_capture(hs_scenario *s) {
	hs_expectations *e = &s->expect;
	long f = s->frame;
	while (e->capture_next < e->capture_count) {
		hs_check *k = &e->checks[e->capture_order[e->capture_next]];
		const hs_clause *c = &e->clauses[k->clause];
		if (c->frame > f)
			break;
		hs_predicates[c->pred].capture(s, c, k, f);
		e->capture_next++;
	}
	for (int i = 0; i < e->live_count; ++i) {
		hs_check *k = &e->checks[e->live[i]];
		const hs_clause *c = &e->clauses[k->clause];
		hs_predicates[c->pred].capture(s, c, k, f);
	}
}
