// scenario.c — a scenario's life: load (file → YAML document → world, scripts and checks, each
// section read by its own file), step (inputs, the world, what the checks capture), check, and
// destroy. Orchestration only: what the sections mean lives with them.
//
// Errors are "PATH:LINE: what is wrong", one message, the first problem found; a failed load
// frees everything it allocated. The schema is documented for users in scenarios/README.md.
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expect.h"
#include "expect_table.h"
#include "file_read.h"
#include "scenario_internal.h"
#include "scenario_parser.h"
#include "scenario_warn.h"

static const char *base_name(const char *path, size_t *length) {
	const char *slash = strrchr(path, '/');
	const char *base = slash ? slash + 1 : path;
	size_t n = strlen(base);
	if (n > 5 && strcmp(base + n - 5, ".yaml") == 0)
		n -= 5;
	*length = n;
	return base;
}

enum { S_NAME, S_DESCRIPTION, S_DT, S_DURATION, S_GRAVITY, S_MODEL, S_OBJECTS, S_EXPECT, S_HANDS, S_STYLUS,
       S_ROBUST, S_COUNT };
static const char *const scenario_keys[S_COUNT] = {"name",  "description", "dt",     "duration", "gravity", "model",
                                                   "objects", "expect",    "hands", "stylus",   "robust"};

// The name is the file's; a `name` key must agree with it.
static bool read_name(hs_scenario_parser *p, const yaml_node_t *root, const yaml_node_t *node) {
	size_t base_len;
	const char *base = base_name(p->y.path, &base_len);
	if (node) {
		char *name = NULL;
		if (!hs_yaml_text(&p->y, node, "name", &name))
			return false;
		bool same = strlen(name) == base_len && memcmp(name, base, base_len) == 0;
		free(name);
		if (!same)
			return hs_yaml_fail(&p->y, node, "'name' is '%s' but the file is '%.*s.yaml': they must agree",
			                    hs_yaml_show(node).text, (int)base_len, base);
	}
	p->s->name = malloc(base_len + 1);
	if (!p->s->name)
		return hs_yaml_fail(&p->y, root, "out of memory");
	memcpy(p->s->name, base, base_len);
	p->s->name[base_len] = '\0';
	return true;
}

// name, description, dt, duration: what every scenario has
static bool read_header(hs_scenario_parser *p, const yaml_node_t *root, const hs_fields *f) {
	if (!read_name(p, root, f->value[S_NAME]))
		return false;
	for (int i = S_DESCRIPTION; i <= S_DURATION; ++i)
		if (!f->value[i])
			return hs_yaml_fail(&p->y, root, "scenario is missing '%s'", scenario_keys[i]);
	if (!f->value[S_OBJECTS])
		return hs_yaml_fail(&p->y, root, "scenario is missing 'objects'");
	return hs_yaml_text(&p->y, f->value[S_DESCRIPTION], "description", &p->s->description) &&
	       hs_read_dt(p, f->value[S_DT]) && hs_read_duration(p, f->value[S_DURATION]);
}

// The noise a load option turns on: a real glove's and tracker's on hands (the robust block's levels,
// else model.input_noise's, else the paper's: glove ±4 units, the Fastrak's 0.03 inch and 0.15°), the
// tracker's on a stylus.
static void realistic_noise(hs_scenario_parser *p, bool hands) {
	p->seeded = true;
	p->seed = p->options->noise_seed;
	if (!hands) {
		p->noise.stylus = true;
	} else if (p->s->robust.has_levels) {
		p->noise = p->s->robust.levels;
	} else if (!p->input_noise_key) {
		p->noise.glove_units = 4;
		p->noise.wrist = HS_STYLUS_NOISE_POSITION;
		p->noise.wrist_rotation = HS_STYLUS_NOISE_ROTATION;
		p->noise.joint = HS_JOINT_NOISE;
	}
	double k = p->options->noise_scale;
	if (k > 0.0) { // a campaign's noise axis: the levels times k
		p->noise.glove_units = (int)lround(p->noise.glove_units * k);
		p->noise.wrist *= k;
		p->noise.wrist_rotation *= k;
		p->noise.joint *= k;
		p->stylus_scale = k;
	}
}

// The caller's model options (a campaign's axes), each read as the file's `model:` is, after it.
static bool read_model_overrides(hs_scenario_parser *p, hs_world_def *def) {
	const hs_scenario_options *o = p->options;
	for (int i = 0; o && i < o->model_count; ++i) {
		const char *text = o->model_texts[i];
		hs_yaml file = p->y;
		p->y = (hs_yaml){.path = o->model_path ? o->model_path : "(model options)", .err = file.err};
		bool ok = hs_yaml_load(&p->y, text, strlen(text), "empty model options") &&
		          hs_read_model(p, hs_yaml_root(&p->y), def);
		if (ok && (p->spring_key || p->input_noise_key)) // their nodes would outlive this document
			ok = hs_yaml_fail(&p->y, p->spring_key ? p->spring_key : p->input_noise_key,
			                  "'spring' and 'input_noise' cannot be overridden");
		hs_yaml_free(&p->y);
		p->y = file;
		if (!ok)
			return false;
	}
	return true;
}

static bool read_scenario(hs_scenario_parser *p, const yaml_node_t *root) {
	hs_scenario *s = p->s;
	if (root->type != YAML_MAPPING_NODE)
		return hs_yaml_fail(&p->y, root,
		                    "a scenario must be a mapping of keys (description, dt, duration, objects, ...), got %s",
		                    hs_yaml_got(root).text);
	hs_fields f;
	if (!hs_yaml_mapping(&p->y, root, scenario_keys, S_COUNT, "scenario", &f) || !read_header(p, root, &f))
		return false;
	if (!hs_yaml_exclusive(&p->y, &f, scenario_keys, S_HANDS, S_STYLUS,
	                       "a world runs the hand model or the spring model")) // one world runs one model
		return false;
	hs_world_def def = hs_default_world_def();
	def.dt = s->dt;
	if (p->options && p->options->phase != 0.0) {
		if (!(p->options->phase > 0.0 && p->options->phase < 1.0))
			return hs_set_error(p->y.err, p->y.path, 0, "the phase must be within [0, 1) of a frame, got %g",
			                    p->options->phase);
		s->phase = p->options->phase;
	}
	if (f.value[S_GRAVITY] && !hs_read_gravity(p, f.value[S_GRAVITY], &def))
		return false;
	s->gravity = def.gravity;
	p->spring = hs_default_spring_def();
	if (f.value[S_MODEL] && !hs_read_model(p, f.value[S_MODEL], &def))
		return false;
	const yaml_node_t *spring_key = p->spring_key, *noise_key = p->input_noise_key;
	p->spring_key = p->input_noise_key = NULL;
	if (!read_model_overrides(p, &def))
		return false;
	p->spring_key = spring_key;
	p->input_noise_key = noise_key;
	if (p->spring_key && !f.value[S_STYLUS])
		return hs_yaml_fail(&p->y, p->spring_key, "'spring' options need a 'stylus': only spring worlds use them");
	if (p->input_noise_key && !f.value[S_HANDS])
		return hs_yaml_fail(&p->y, p->input_noise_key, "'input_noise' needs 'hands': only hand worlds use it");
	if (f.value[S_ROBUST] && !hs_read_robust(p, f.value[S_ROBUST], f.value[S_HANDS] != NULL))
		return false;
	if (p->options && p->options->noise)
		realistic_noise(p, f.value[S_HANDS] != NULL);
	if (p->seeded && !(s->noise = hs_noise_create(p->seed)))
		return hs_yaml_fail(&p->y, root, "out of memory");
	if (s->noise && p->stylus_scale > 0.0)
		hs_noise_set_stylus_scale(s->noise, p->stylus_scale);
	s->noise_options = p->noise;
	if (f.value[S_HANDS] && !hs_count_hands(p, f.value[S_HANDS], &def))
		return false;
	if (f.value[S_STYLUS]) { // a stylus makes a spring world: its kind is fixed when it is made
		def.kind = HS_WORLD_SPRING;
		def.spring = p->spring;
	}
	if (!hs_read_objects(p, f.value[S_OBJECTS], def))
		return false;
	if (f.value[S_HANDS] && !hs_read_hands(p, f.value[S_HANDS]))
		return false;
	if (p->options && p->options->throw_error && !hs_throw_error_set(p, root, p->options->throw_error))
		return false;
	if (f.value[S_STYLUS] && !hs_read_stylus(p, f.value[S_STYLUS]))
		return false;
	if (f.value[S_EXPECT] && !hs_read_expect(p, f.value[S_EXPECT]))
		return false;
	hs_warn_start(p, f.value[S_OBJECTS], f.value[S_HANDS], def.floor_tolerance);
	return hs_prepare_checks(p, root);
}

// FNV-1a, 64 bits: a state file and the scenario file it continues must match byte for byte.
static uint64_t fnv1a(const char *text, size_t size) {
	uint64_t h = 14695981039346656037ull;
	for (size_t i = 0; i < size; ++i)
		h = (h ^ (unsigned char)text[i]) * 1099511628211ull;
	return h;
}

// The file's text: read whole, NUL bytes refused (libyaml would stop or complain at one).
static bool read_text_file(const char *path, char **text, size_t *size, hs_error *err) {
	if (!hs_read_file(path, text, size, err))
		return false;
	const char *nul = memchr(*text, '\0', *size);
	if (!nul)
		return true;
	hs_set_error(err, path, hs_yaml_line_at(*text, *size, (size_t)(nul - *text)),
	             "not a text file (NUL byte at byte %zu)", (size_t)(nul - *text));
	free(*text);
	return false;
}

// The run's start: inputs at t = 0 (no motion before frame 1), initial states, frame 0 captured.
static bool start(hs_scenario *s, const char *path, hs_error *err) {
	hs_hands_drive(s->world, &s->hands, 0.0, s->noise, &s->noise_options);
	hs_stylus_drive(s->world, &s->stylus, 0.0, s->noise_options.stylus ? s->noise : NULL);
	s->initial = calloc((size_t)s->object_count, sizeof *s->initial);
	if (!s->initial)
		return hs_set_error(err, path, 1, "out of memory");
	for (int i = 0; i < s->object_count; ++i)
		s->initial[i] = hs_scenario_state_of(s, i);
	hs_expect_capture(s);
	return true;
}

hs_scenario *hs_scenario_load(const char *path, hs_error *err) { return hs_scenario_load_with(path, NULL, err); }

bool hs_scenario_source_open(hs_scenario_source *src, const char *path, hs_error *err) {
	memset(src, 0, sizeof *src);
	if (!path)
		return hs_set_error(err, "(null)", 1, "cannot read: no file given");
	char *text = NULL;
	size_t size = 0;
	if (!read_text_file(path, &text, &size, err))
		return false;
	src->y = (hs_yaml){.path = path, .err = err};
	src->hash = fnv1a(text, size);
	bool ok = hs_yaml_load(&src->y, text, size, "empty file: a scenario needs description, dt, duration and objects");
	free(text);
	if (!ok)
		hs_yaml_free(&src->y);
	return ok;
}

void hs_scenario_source_close(hs_scenario_source *src) { hs_yaml_free(&src->y); }

hs_scenario *hs_scenario_load_source(const hs_scenario_source *src, const hs_scenario_options *options, hs_error *err) {
	hs_error scratch;
	if (!err)
		err = &scratch;
	err->message[0] = '\0';
	const char *path = src->y.path;
	hs_scenario_parser p = {.y = src->y, .options = options};
	p.y.err = err; // the document is only read: every load builds its own scenario from it
	p.s = calloc(1, sizeof *p.s);
	if (p.s) {
		hs_file_list_add(&p.s->inputs, path);
		p.y.files = &p.s->inputs;
	}
	bool ok = p.s ? read_scenario(&p, hs_yaml_root(&p.y)) : hs_set_error(err, path, 1, "out of memory");
	if (ok) {
		p.s->source_hash = src->hash;
		p.s->overridden = options && (options->dt > 0.0 || options->noise || options->model_count > 0 ||
		                              options->throw_error || options->phase > 0.0);
	}
	free(p.sorted);
	if (!ok || !start(p.s, path, err)) {
		hs_scenario_destroy(p.s);
		return NULL;
	}
	return p.s;
}

hs_scenario *hs_scenario_load_with(const char *path, const hs_scenario_options *options, hs_error *err) {
	hs_error scratch;
	if (!err)
		err = &scratch;
	err->message[0] = '\0';
	hs_scenario_source src;
	if (!hs_scenario_source_open(&src, path, err))
		return NULL;
	hs_scenario *s = hs_scenario_load_source(&src, options, err);
	hs_scenario_source_close(&src);
	return s;
}

void hs_scenario_destroy(hs_scenario *s) {
	if (!s)
		return;
	hs_world_destroy(s->world);
	if (s->object_names)
		for (int i = 0; i < s->object_count; ++i)
			free(s->object_names[i]);
	free(s->object_names);
	free(s->ids);
	free(s->name);
	free(s->description);
	free(s->initial);
	hs_hands_free(&s->hands);
	free(s->stylus.keys);
	hs_expectations_free(&s->expect);
	hs_noise_destroy(s->noise);
	free(s->warnings);
	hs_file_list_free(&s->inputs);
	free(s);
}

bool hs_scenario_step(hs_scenario *s) {
	if (!s || s->frame >= s->frames || s->step_status != HS_OK)
		return false;
	// inputs are given for the end of the coming frame, on the scripts' clock (phase × dt late)
	double t = ((double)(s->frame + 1) - s->phase) * s->dt;
	hs_hands_drive(s->world, &s->hands, t, s->noise, &s->noise_options);
	hs_stylus_drive(s->world, &s->stylus, t, s->noise_options.stylus ? s->noise : NULL);
	hs_status status = hs_world_step(s->world);
	if (status != HS_OK) { // reported by hs_scenario_check as a failure
		s->step_status = status;
		s->failed_frame = s->frame + 1;
		return false;
	}
	s->frame++;
	hs_expect_capture(s);
	return true;
}

int hs_scenario_check(const hs_scenario *s, FILE *report) {
	if (!s)
		return 0;
	int failed = hs_expect_report(s, report);
	if (s->step_status != HS_OK) {
		failed++;
		if (report)
			fprintf(report, "FAIL  the world failed to step at frame %ld: %s\n", s->failed_frame,
			        hs_status_string(s->step_status));
	}
	long faults = hs_scenario_faults(s);
	if (faults > 0) {
		failed++;
		long frame = -1;
		hs_object_id object = {0, 0, 0};
		hs_world_first_fault(s->world, &frame, &object);
		int i = (int)object.index1 - 1;
		if (report && frame >= 0 && i >= 0 && i < s->object_count)
			fprintf(report, "FAIL  numeric fault at frame %ld in object '%s' (%ld in all): non-finite values, the object frozen\n",
			        frame, hs_scenario_object_name(s, i), faults);
		else if (report)
			fprintf(report, "FAIL  the world caught %ld numeric fault%s: non-finite values, the objects frozen\n", faults,
			        faults == 1 ? "" : "s");
	}
	return failed;
}
