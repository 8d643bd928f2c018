// campaign.c — reading a campaign file (docs/campaigns.md): the base scenario, the axes whose
// product makes the cells, the trials per cell, the thrower's errors and the target. The load
// checks it whole: every cell's scenario is loaded once, so a bad option fails at its own line.
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "campaign_internal.h"
#include "scenario_internal.h"
#include "file_read.h"
#include "yaml_read.h"

enum { C_SCENARIO, C_SEED, C_TRIALS, C_JUDGE, C_AXES, C_THROW, C_TARGET, C_DESCRIPTION, C_VISITOR, C_COUNT };
static const char *const campaign_keys[C_COUNT] = {"scenario", "seed",   "trials",      "judge",         "axes",
                                                   "throw",    "target", "description", "visitor_throws"};

// A model value goes into a YAML text as it was written: numbers and words only.
static bool plain_word(const char *s) {
	if (!*s || strlen(s) >= HS_CAMPAIGN_MAX_WORD)
		return false;
	for (; *s; ++s)
		if (!strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._+-/", *s))
			return false;
	return true;
}

// A node's text when it is a scalar, else NULL (a mapping or a list has no text to read).
static const char *scalar_of(const yaml_node_t *node) {
	return node && hs_yaml_is_scalar(node) ? hs_yaml_scalar(node) : NULL;
}

// The list of an axis: 1 to HS_CAMPAIGN_MAX_VALUES scalars.
static long axis_length(const hs_yaml *y, const yaml_node_t *key, const yaml_node_t *list) {
	long n = list->type == YAML_SEQUENCE_NODE ? hs_yaml_length(list) : 0;
	if (n < 1 || n > HS_CAMPAIGN_MAX_VALUES) {
		hs_yaml_fail(y, list, "axis '%s' must be a list of 1 to %d values, got %s", hs_yaml_scalar(key),
		             HS_CAMPAIGN_MAX_VALUES, list->type == YAML_SEQUENCE_NODE ? "another count" : hs_yaml_got(list).text);
		return -1;
	}
	return n;
}

// dt, noise or throw_scale: numbers (dt as a scenario's `dt:`, "1/12" or 0.0125).
static bool read_number_axis(const hs_yaml *y, const yaml_node_t *key, const yaml_node_t *list, hs_axis *a) {
	long n = axis_length(y, key, list);
	if (n < 0)
		return false;
	for (long i = 0; i < n; ++i) {
		const yaml_node_t *item = hs_yaml_item(y, list, i);
		double v = 0.0;
		if (a->kind == HS_AXIS_DT) {
			if (!scalar_of(item) || !hs_scenario_parse_dt(scalar_of(item), &v))
				return hs_yaml_fail(y, item, "'dt' values must be frame times within [1/2000, 1/12] s, got %s",
				                    hs_yaml_got(item).text);
		} else {
			if (!hs_yaml_number(y, item, a->name, &v))
				return false;
			double most = a->kind == HS_AXIS_NOISE ? 100.0 : 10.0;
			if (!(v >= 0.0 && v <= most))
				return hs_yaml_fail(y, item, "'%s' values must be within [0, %g], got %s", a->name, most,
				                    hs_yaml_show(item).text);
		}
		a->value[i] = v;
	}
	a->count = (int)n;
	return true;
}

// `body` as the `line`-th line of a text (newlines before it), so the scenario loader's messages
// about a model override name the campaign file's line; NULL when out of memory.
static char *at_line(unsigned long line, const char *body) {
	size_t n = strlen(body);
	char *text = malloc(line + n);
	if (text) {
		memset(text, '\n', line - 1);
		memcpy(text + line - 1, body, n + 1);
	}
	return text;
}

static bool swept_noise(const hs_yaml *y, const yaml_node_t *key, const char *name) {
	if (strcmp(name, "spring") != 0 && strcmp(name, "input_noise") != 0)
		return false;
	return !hs_yaml_fail(y, key, "'%s' cannot be swept: sweep input noise with the 'noise' axis", name);
}

// model.KEY: words, each kept as the override "{KEY: VALUE}" at its line.
static bool read_model_axis(const hs_yaml *y, const yaml_node_t *key, const yaml_node_t *list, hs_axis *a) {
	long n = swept_noise(y, key, a->name) ? -1 : axis_length(y, key, list);
	for (long i = 0; i < n; ++i) {
		const yaml_node_t *item = hs_yaml_item(y, list, i);
		const char *v = scalar_of(item);
		if (!v || !plain_word(v))
			return hs_yaml_fail(y, item, "a model value must be a number or a word of at most %d characters, got %s",
			                    HS_CAMPAIGN_MAX_WORD - 1, hs_yaml_got(item).text);
		char body[2 * HS_CAMPAIGN_MAX_WORD + 8];
		snprintf(body, sizeof body, "{%s: %s}", a->name, v);
		if (!(a->model[i] = at_line(hs_yaml_line(item), body)))
			return hs_yaml_fail(y, item, "out of memory");
		snprintf(a->text[i], sizeof a->text[i], "%s", v);
		a->count = (int)i + 1; // what destroy frees
	}
	return n > 0;
}

// One value of the `model` axis: a mapping of up to HS_CAMPAIGN_MAX_OPTIONS options and its
// `name` (the column), kept as the override "{KEY: VALUE, ...}" at the mapping's line.
static bool read_model_set(const hs_yaml *y, const yaml_node_t *map, hs_axis *a, int i) {
	yaml_node_pair_t *first = map->type == YAML_MAPPING_NODE ? map->data.mapping.pairs.start : NULL;
	long pairs = first ? map->data.mapping.pairs.top - first : 0;
	if (pairs < 1 || pairs > HS_CAMPAIGN_MAX_OPTIONS + 1)
		return hs_yaml_fail(y, map, "a 'model' axis value must be a mapping of a name and 1 to %d model options, got %s",
		                    HS_CAMPAIGN_MAX_OPTIONS, hs_yaml_got(map).text);
	char body[(HS_CAMPAIGN_MAX_OPTIONS + 1) * (2 * HS_CAMPAIGN_MAX_WORD + 4) + 2] = "{";
	for (yaml_node_pair_t *q = first; q < first + pairs; ++q) {
		const yaml_node_t *key = yaml_document_get_node((yaml_document_t *)&y->doc, q->key);
		const yaml_node_t *value = yaml_document_get_node((yaml_document_t *)&y->doc, q->value);
		const char *k = scalar_of(key), *v = scalar_of(value);
		if (!k || !plain_word(k) || !v || !plain_word(v))
			return hs_yaml_fail(y, value, "a model option and its value must be words of at most %d characters, got %s",
			                    HS_CAMPAIGN_MAX_WORD - 1, hs_yaml_got(value).text);
		if (strcmp(k, "name") == 0)
			snprintf(a->text[i], sizeof a->text[i], "%s", v);
		else if (swept_noise(y, key, k))
			return false;
		else
			snprintf(body + strlen(body), sizeof body - strlen(body), "%s%s: %s", body[1] ? ", " : "", k, v);
	}
	strcat(body, "}");
	if (!a->text[i][0])
		return hs_yaml_fail(y, map, "a 'model' axis value needs a 'name' for its column");
	if (!(a->model[i] = at_line(hs_yaml_line(map), body)))
		return hs_yaml_fail(y, map, "out of memory");
	a->count = i + 1; // what destroy frees
	return true;
}

static bool read_model_sets(const hs_yaml *y, const yaml_node_t *key, const yaml_node_t *list, hs_axis *a) {
	long n = axis_length(y, key, list);
	for (long i = 0; i < n; ++i)
		if (!read_model_set(y, hs_yaml_item(y, list, i), a, (int)i))
			return false;
	return n > 0;
}

static bool read_axis(hs_campaign *c, const hs_yaml *y, const yaml_node_t *key, const yaml_node_t *list) {
	const char *name = scalar_of(key);
	if (!name || !plain_word(name))
		return hs_yaml_fail(y, key, "an axis is named by a word, got %s", hs_yaml_got(key).text);
	for (int i = 0; i < c->axis_count; ++i)
		if (strcmp(c->axes[i].name, name) == 0 || (strncmp(name, "model.", 6) == 0 && strcmp(c->axes[i].name, name + 6) == 0))
			return hs_yaml_fail(y, key, "axis '%s' is given twice", name);
	if (c->axis_count == HS_CAMPAIGN_MAX_AXES)
		return hs_yaml_fail(y, key, "at most %d axes, got more", HS_CAMPAIGN_MAX_AXES);
	hs_axis *a = &c->axes[c->axis_count++];
	if (strcmp(name, "dt") == 0 || strcmp(name, "noise") == 0 || strcmp(name, "throw_scale") == 0) {
		a->kind = name[0] == 'd' ? HS_AXIS_DT : name[0] == 'n' ? HS_AXIS_NOISE : HS_AXIS_THROW_SCALE;
		snprintf(a->name, sizeof a->name, "%s", name);
		return read_number_axis(y, key, list, a);
	}
	if (strcmp(name, "model") == 0) { // sets of options, each named
		a->kind = HS_AXIS_MODEL;
		snprintf(a->name, sizeof a->name, "model");
		return read_model_sets(y, key, list, a);
	}
	if (strncmp(name, "model.", 6) != 0 || !name[6])
		return hs_yaml_fail(y, key, "unknown axis '%s': dt, noise, throw_scale, model.OPTION or model", name);
	a->kind = HS_AXIS_MODEL;
	snprintf(a->name, sizeof a->name, "%s", name + 6);
	return read_model_axis(y, key, list, a);
}

static bool read_axes(hs_campaign *c, const hs_yaml *y, const yaml_node_t *node) {
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(y, node, "'axes' must be a mapping of axis: [values], got %s", hs_yaml_got(node).text);
	for (yaml_node_pair_t *pair = node->data.mapping.pairs.start; pair < node->data.mapping.pairs.top; ++pair)
		if (!read_axis(c, y, yaml_document_get_node((yaml_document_t *)&y->doc, pair->key),
		               yaml_document_get_node((yaml_document_t *)&y->doc, pair->value)))
			return false;
	return true;
}

// A non-negative number no larger than `most` (in the unit the message names).
static bool read_sd(const hs_yaml *y, const yaml_node_t *node, const char *key, double most, const char *unit,
                    double *out) {
	if (!node)
		return true;
	if (!hs_yaml_number(y, node, key, out))
		return false;
	if (!(*out >= 0.0 && *out <= most))
		return hs_yaml_fail(y, node, "'%s' must be within [0, %g] %s, got %s", key, most, unit, hs_yaml_show(node).text);
	return true;
}

// The index of the name `node` gives among a scenario's hands (hands) or objects, or -1 with an error.
static int find_name(const hs_yaml *y, const yaml_node_t *node, const hs_scenario *s, bool hands, const char *key) {
	const char *name = scalar_of(node);
	int n = hands ? s->hands.count : s->object_count;
	for (int i = 0; name && i < n; ++i)
		if (strcmp(name, hands ? s->hands.names[i] : s->object_names[i]) == 0)
			return i;
	hs_yaml_fail(y, node, "'%s': the scenario has no %s named %s", key, hands ? "hand" : "object", hs_yaml_got(node).text);
	return -1;
}

// When the script starts to open the hand: the last key before the first whose glove reading
// differs from the reading at `from` (`release` when none does by then). throw_underarm opens from
// its key at the release, throw_at_target from the key 10 ms before it.
static double glove_opens(const hs_hand_script *script, double from, double release) {
	uint8_t held[HS_GLOVE_SENSORS], now[HS_GLOVE_SENSORS];
	hs_vec3 wrist;
	hs_quat rot;
	hs_hand_script_sample(script, from, &wrist, &rot, held);
	for (int i = 0; i < script->key_count && script->keys[i].t <= release; ++i) {
		if (script->keys[i].t <= from)
			continue;
		hs_hand_script_sample(script, script->keys[i].t, &wrist, &rot, now);
		if (memcmp(now, held, sizeof now) != 0)
			return i > 0 && script->keys[i - 1].t > from ? script->keys[i - 1].t : from;
	}
	return release;
}

enum { T_HAND, T_FROM, T_RELEASE, T_TIMING, T_SPEED, T_DIRECTION, T_PHASE, T_COUNT };
static const char *const throw_keys[T_COUNT] = {"hand",  "from",          "release", "timing_ms",
                                                "speed", "direction_deg", "phase"};

// throw: the thrower's hand, its swing (from, release) and the SD of each error.
static bool read_throw(hs_campaign *c, const hs_yaml *y, const yaml_node_t *node, const hs_scenario *s, int index) {
	hs_fields f;
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(y, node, "'throw' must be a mapping (hand, from, release, timing_ms, speed, direction_deg, phase), got %s",
		                    hs_yaml_got(node).text);
	if (!hs_yaml_mapping(y, node, throw_keys, T_COUNT, "throw", &f))
		return false;
	for (int k = T_HAND; k <= T_RELEASE; ++k)
		if (!f.value[k])
			return hs_yaml_fail(y, node, "'throw' is missing '%s'", throw_keys[k]);
	hs_thrower_spec *t = &c->thrower;
	double ms = 0.0, deg = 0.0;
	if ((t->hand[index] = find_name(y, f.value[T_HAND], s, true, "hand")) < 0 ||
	    !hs_yaml_time(y, f.value[T_FROM], "from", s->duration, &t->from) ||
	    !hs_yaml_time(y, f.value[T_RELEASE], "release", s->duration, &t->release))
		return false;
	if (!(t->release > t->from))
		return hs_yaml_fail(y, f.value[T_RELEASE], "'release' must come after 'from' (%g s), got %s", t->from,
		                    hs_yaml_show(f.value[T_RELEASE]).text);
	if (!read_sd(y, f.value[T_TIMING], "timing_ms", 100.0, "ms", &ms) ||
	    !read_sd(y, f.value[T_SPEED], "speed", 0.2, "(relative SD)", &t->speed) ||
	    !read_sd(y, f.value[T_DIRECTION], "direction_deg", 20.0, "deg", &deg))
		return false;
	t->timing = ms * 1e-3;
	t->angle = deg * (HS_PI / 180.0);
	t->phase = true;
	if (f.value[T_PHASE] && !hs_yaml_bool(y, f.value[T_PHASE], "phase", &t->phase))
		return false;
	t->opens[index] = glove_opens(&s->hands.scripts[t->hand[index]], t->from, t->release);
	t->given = true;
	return true;
}

// The largest throw_scale (1 without the axis).
static double largest_scale(const hs_campaign *c) {
	double most = 1.0;
	for (int i = 0; i < c->axis_count; ++i)
		if (c->axes[i].kind == HS_AXIS_THROW_SCALE) {
			most = 0.0;
			for (int k = 0; k < c->axes[i].count; ++k)
				most = c->axes[i].value[k] > most ? c->axes[i].value[k] : most;
		}
	return most;
}

// Every draw is cut at HS_CAMPAIGN_TRUNCATE SD: at the largest throw_scale it must stay a throw
// (timing within 1 s, the swing not reversed, angles within 180 deg).
static bool check_thrower_range(const hs_campaign *c, const hs_yaml *y, const yaml_node_t *node) {
	double k = HS_CAMPAIGN_TRUNCATE * largest_scale(c);
	const hs_thrower_spec *t = &c->thrower;
	if (k * t->timing > 1.0 || k * t->speed >= 1.0 || k * t->angle > HS_PI)
		return hs_yaml_fail(y, node,
		                    "'throw' at %g SD times the largest throw_scale must keep timing within 1 s, speed "
		                    "above -1 and angles within 180 deg",
		                    HS_CAMPAIGN_TRUNCATE);
	return true;
}

enum { G_OBJECT, G_AT, G_RADIUS, G_COUNT };
static const char *const target_keys[G_COUNT] = {"object", "at", "radius"};

// target: an object that hits when it ends within `radius` of `at` (x, y) on the floor.
static bool read_target(hs_campaign *c, const hs_yaml *y, const yaml_node_t *node, const hs_scenario *s, int index) {
	hs_fields f;
	if (node->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(y, node, "'target' must be a mapping (object, at, radius), got %s", hs_yaml_got(node).text);
	if (!hs_yaml_mapping(y, node, target_keys, G_COUNT, "target", &f))
		return false;
	for (int k = 0; k < G_COUNT; ++k)
		if (!f.value[k])
			return hs_yaml_fail(y, node, "'target' is missing '%s'", target_keys[k]);
	hs_target *g = &c->target;
	double at[2];
	if ((g->object[index] = find_name(y, f.value[G_OBJECT], s, false, "object")) < 0 ||
	    !hs_yaml_numbers(y, f.value[G_AT], "at", 2, "[x, y] in m", at, NULL) ||
	    !hs_yaml_number(y, f.value[G_RADIUS], "radius", &g->radius))
		return false;
	if (!(g->radius > 0.0 && g->radius <= 1000.0) || !(at[0] >= -1e6 && at[0] <= 1e6 && at[1] >= -1e6 && at[1] <= 1e6))
		return hs_yaml_fail(y, node, "'target': radius within (0, 1000] m and 'at' within 1e6 m, got %s",
		                    hs_yaml_show(f.value[G_RADIUS]).text);
	g->x = at[0];
	g->y = at[1];
	g->given = true;
	return true;
}

// Every model value (with the first scenario) and the first trial of every scenario, loaded once:
// what the trials will load cannot fail later.
static bool check_cells(const hs_campaign *c, hs_error *err) {
	hs_trial t;
	hs_trial_prepare(c, 0, &t);
	for (int a = 0; a < c->axis_count; ++a)
		for (int v = 0; c->axes[a].kind == HS_AXIS_MODEL && v < c->axes[a].count; ++v) {
			const char *text = c->axes[a].model[v];
			hs_scenario_options o = {.model_count = 1, .model_texts = &text, .model_path = c->path};
			hs_scenario *s = hs_scenario_load_source(&c->source[0], &o, err);
			if (!s)
				return false;
			hs_scenario_destroy(s);
		}
	int scenarios = c->scenario ? 1 : c->axes[0].count; // a scenario axis is the first, the slowest
	for (int k = 0; k < scenarios; ++k) {
		hs_trial_prepare(c, k * (c->cells / scenarios) * c->per_cell, &t);
		hs_scenario *s = hs_scenario_load_source(&c->source[k], &t.options, err);
		hs_scenario_destroy(s);
		if (!s)
			return false;
	}
	return true;
}

// cells = the product of the axes' lengths; trials = cells × trials per cell, both bounded.
static bool count_trials(hs_campaign *c, const hs_yaml *y, const yaml_node_t *root) {
	c->cells = 1;
	for (int a = 0; a < c->axis_count; ++a) { // checked before each product: a long may be 32 bits
		if (c->cells > HS_CAMPAIGN_MAX_TRIALS / c->axes[a].count)
			return hs_yaml_fail(y, root, "the axes make more than %ld cells", HS_CAMPAIGN_MAX_TRIALS);
		c->cells *= c->axes[a].count;
	}
	if (c->cells > HS_CAMPAIGN_MAX_TRIALS / c->per_cell)
		return hs_yaml_fail(y, root, "%ld cells x %ld trials is more than %ld trials", c->cells, c->per_cell,
		                    HS_CAMPAIGN_MAX_TRIALS);
	c->trials = c->cells * c->per_cell;
	return true;
}

// `scenario:` a path, or a list of them: the first axis, named by the scenarios' names.
static bool read_scenarios(hs_campaign *c, const hs_yaml *y, const yaml_node_t *node) {
	if (node->type != YAML_SEQUENCE_NODE)
		return (c->scenario = hs_yaml_sibling_file(y, node, "scenario")) != NULL;
	long n = hs_yaml_length(node);
	if (n < 1 || n > HS_CAMPAIGN_MAX_VALUES)
		return hs_yaml_fail(y, node, "'scenario' must be a file or a list of 1 to %d files, got another count",
		                    HS_CAMPAIGN_MAX_VALUES);
	hs_axis *a = &c->axes[c->axis_count++];
	a->kind = HS_AXIS_SCENARIO;
	snprintf(a->name, sizeof a->name, "scenario");
	for (long i = 0; i < n; ++i) {
		if (!(a->model[i] = hs_yaml_sibling_file(y, hs_yaml_item(y, node, i), "scenario")))
			return false;
		a->count = (int)i + 1;
	}
	return true;
}

// Each scenario: readable (a missing one is the campaign's line, a bad one its own), its name, and
// the thrower's hand and the target's object in it.
static bool check_scenario(hs_campaign *c, const hs_yaml *y, const hs_fields *f, const yaml_node_t *where, int k) {
	const char *path = c->scenario ? c->scenario : c->axes[0].model[k];
	FILE *probe = hs_open_input(path); // a FIFO without a writer must not hold the load up
	if (!probe)
		return hs_yaml_fail(y, where, "cannot read the scenario %s: %s", hs_yaml_show(where).text, strerror(errno));
	fclose(probe);
	if (!hs_scenario_source_open(&c->source[k], path, y->err))
		return false;
	c->sources = k + 1;
	hs_scenario *s = hs_scenario_load_source(&c->source[k], NULL, y->err);
	if (!s)
		return false;
	for (int i = 0; i < hs_scenario_input_count(s); ++i)
		hs_file_list_add(&c->inputs, hs_scenario_input_path(s, i));
	c->dt[k] = s->dt;
	c->duration[k] = s->duration;
	if (!c->scenario)
		snprintf(c->axes[0].text[k], sizeof c->axes[0].text[k], "%.*s", HS_CAMPAIGN_MAX_WORD - 1, s->name);
	bool ok = (!f->value[C_THROW] || read_throw(c, y, f->value[C_THROW], s, k)) &&
	          (!f->value[C_TARGET] || read_target(c, y, f->value[C_TARGET], s, k));
	hs_scenario_destroy(s);
	return ok;
}

static bool check_scenarios(hs_campaign *c, const hs_yaml *y, const hs_fields *f) {
	const yaml_node_t *node = f->value[C_SCENARIO];
	for (int k = 0, n = c->scenario ? 1 : c->axes[0].count; k < n; ++k)
		if (!check_scenario(c, y, f, c->scenario ? node : hs_yaml_item(y, node, k), k))
			return false;
	return !f->value[C_THROW] || check_thrower_range(c, y, f->value[C_THROW]);
}

// visitor_throws: a visitor's throws, 1 to the trials of a cell; only with a thrower.
static bool read_visitor_throws(hs_campaign *c, const hs_yaml *y, const yaml_node_t *node) {
	int64_t n = HS_CAMPAIGN_VISITOR_THROWS;
	if (node && !c->thrower.given)
		return hs_yaml_fail(y, node, "'visitor_throws' needs a 'throw': a visitor is a thrower's throws");
	if (!c->thrower.given)
		return true; // no visitors
	long most = c->per_cell < HS_CAMPAIGN_MAX_VISITOR_THROWS ? c->per_cell : HS_CAMPAIGN_MAX_VISITOR_THROWS;
	if (node && !hs_yaml_integer(y, node, "visitor_throws", 1, most, &n))
		return false;
	c->visitor_throws = n > c->per_cell ? c->per_cell : (long)n; // the default, when a cell has fewer trials
	return true;
}

static bool read_campaign(hs_campaign *c, const hs_yaml *y, const yaml_node_t *root) {
	hs_fields f;
	if (root->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(y, root, "a campaign must be a mapping (scenario, trials, axes, ...), got %s", hs_yaml_got(root).text);
	if (!hs_yaml_mapping(y, root, campaign_keys, C_COUNT, "campaign", &f))
		return false;
	if (!f.value[C_SCENARIO] || !f.value[C_TRIALS])
		return hs_yaml_fail(y, root, "a campaign needs '%s'", f.value[C_SCENARIO] ? "trials" : "scenario");
	int64_t seed = 1, per_cell = 0;
	if ((f.value[C_SEED] && !hs_yaml_integer(y, f.value[C_SEED], "seed", 0, INT64_MAX, &seed)) ||
	    !hs_yaml_integer(y, f.value[C_TRIALS], "trials", 1, HS_CAMPAIGN_MAX_TRIALS, &per_cell))
		return false;
	c->seed = (uint64_t)seed;
	c->per_cell = (long)per_cell;
	if (f.value[C_JUDGE] && !hs_yaml_scalar_is(f.value[C_JUDGE], "robust") && !hs_yaml_scalar_is(f.value[C_JUDGE], "all"))
		return hs_yaml_fail(y, f.value[C_JUDGE], "'judge' must be robust or all, got %s", hs_yaml_got(f.value[C_JUDGE]).text);
	c->judge_all = f.value[C_JUDGE] && hs_yaml_scalar_is(f.value[C_JUDGE], "all");
	return read_scenarios(c, y, f.value[C_SCENARIO]) && (!f.value[C_AXES] || read_axes(c, y, f.value[C_AXES])) &&
	       count_trials(c, y, root) && check_scenarios(c, y, &f) && read_visitor_throws(c, y, f.value[C_VISITOR]) &&
	       check_cells(c, y->err);
}

hs_campaign *hs_campaign_load(const char *path, hs_error *err) {
	hs_error scratch;
	err = err ? err : &scratch;
	char *text = NULL;
	size_t size = 0;
	if (!path)
		return hs_set_error(err, "(null)", 1, "cannot read: no file given"), NULL;
	if (!hs_read_file(path, &text, &size, err))
		return NULL;
	hs_campaign *c = calloc(1, sizeof *c);
	hs_yaml y = {.path = path, .err = err};
	bool ok = c && (c->path = strdup(path)) != NULL &&
	          (c->source = calloc(HS_CAMPAIGN_MAX_VALUES, sizeof *c->source)) != NULL;
	if (!ok)
		hs_set_error(err, path, 1, "out of memory");
	else
		hs_file_list_add(&c->inputs, path);
	if (ok && memchr(text, '\0', size))
		ok = hs_set_error(err, path, hs_yaml_line_at(text, size, (size_t)((char *)memchr(text, '\0', size) - text)),
		                  "not a text file (a NUL byte)");
	ok = ok && hs_yaml_load(&y, text, size, "empty file: a campaign needs scenario and trials") &&
	     read_campaign(c, &y, hs_yaml_root(&y));
	hs_yaml_free(&y);
	free(text);
	if (!ok) {
		hs_campaign_destroy(c);
		return NULL;
	}
	return c;
}

void hs_campaign_destroy(hs_campaign *c) {
	if (!c)
		return;
	for (int a = 0; a < c->axis_count; ++a)
		for (int v = 0; v < c->axes[a].count; ++v)
			free(c->axes[a].model[v]);
	for (int k = 0; k < c->sources; ++k)
		hs_scenario_source_close(&c->source[k]);
	free(c->source);
	free(c->path);
	free(c->scenario);
	hs_file_list_free(&c->inputs);
	free(c);
}

int hs_campaign_input_count(const hs_campaign *c) { return c ? c->inputs.count : 0; }

const char *hs_campaign_input_path(const hs_campaign *c, int i) {
	return c && i >= 0 && i < c->inputs.count ? c->inputs.paths[i] : NULL;
}

long hs_campaign_trials(const hs_campaign *c) { return c ? c->trials : 0; }
