// yaml_read.c — libyaml's document API wrapped for strict reading: one document, every value
// checked where it is read, every message "PATH:LINE: what is wrong" quoting what was found.
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "file_read.h"
#include "file_list.h"
#include "suggest.h"
#include "yaml_read.h"

bool hs_yaml_fail(const hs_yaml *y, const yaml_node_t *node, const char *fmt, ...) {
	va_list ap;
	va_start(ap, fmt);
	hs_vset_error(y->err, y->path, node ? (unsigned long)node->start_mark.line + 1 : 1, fmt, ap);
	va_end(ap);
	return false;
}

unsigned long hs_yaml_line(const yaml_node_t *node) { return (unsigned long)node->start_mark.line + 1; }

bool hs_yaml_before(const yaml_node_t *a, const yaml_node_t *b) { return a->start_mark.index < b->start_mark.index; }

unsigned long hs_yaml_line_at(const char *text, size_t size, size_t offset) {
	unsigned long line = 1;
	for (size_t i = 0; i < offset && i < size; ++i)
		line += text[i] == '\n';
	return line;
}

// ---------------------------------------------------------------------------------------------
// the document

static bool yaml_failure(const yaml_parser_t *yp, const hs_yaml *y, const char *text, size_t size) {
	switch (yp->error) {
	case YAML_MEMORY_ERROR:
		return hs_set_error(y->err, y->path, 1, "out of memory");
	case YAML_READER_ERROR: // reader errors carry a byte offset, not a mark
		return hs_set_error(y->err, y->path, hs_yaml_line_at(text, size, yp->problem_offset),
		                    "not a text file: %s (byte %zu)", yp->problem ? yp->problem : "unreadable",
		                    yp->problem_offset);
	default:
		break;
	}
	const char *problem = yp->problem ? yp->problem : "unknown error";
	unsigned long line = (unsigned long)yp->problem_mark.line + 1;
	unsigned long last = hs_yaml_line_at(text, size, size > 0 && text[size - 1] == '\n' ? size - 1 : size);
	if (line > last) // libyaml ends the stream with a line break of its own
		line = last;
	if (yp->context)
		return hs_set_error(y->err, y->path, line, "invalid YAML: %s (%s at line %lu)", problem, yp->context,
		                    (unsigned long)yp->context_mark.line + 1);
	return hs_set_error(y->err, y->path, line, "invalid YAML: %s", problem);
}

// A pass over the parser's events, counting how deep collections nest, that stops at the first
// one beyond the limit: the document is never built for a hostile file. Invalid YAML ends the pass
// quietly; the loader that follows reports it with its context.
static bool check_depth(const hs_yaml *y, const char *text, size_t size) {
	yaml_parser_t yp;
	if (!yaml_parser_initialize(&yp))
		return hs_set_error(y->err, y->path, 1, "out of memory");
	yaml_parser_set_input_string(&yp, (const unsigned char *)text, size);
	int depth = 0;
	bool ok = true, end = false;
	while (ok && !end) {
		yaml_event_t event;
		if (!yaml_parser_parse(&yp, &event))
			break;
		if (event.type == YAML_SEQUENCE_START_EVENT || event.type == YAML_MAPPING_START_EVENT) {
			if (++depth > HS_YAML_MAX_DEPTH)
				ok = hs_set_error(y->err, y->path, (unsigned long)event.start_mark.line + 1,
				                  "nested deeper than %d levels", HS_YAML_MAX_DEPTH);
		} else if (event.type == YAML_SEQUENCE_END_EVENT || event.type == YAML_MAPPING_END_EVENT) {
			depth--;
		}
		end = event.type == YAML_STREAM_END_EVENT;
		yaml_event_delete(&event);
	}
	yaml_parser_delete(&yp);
	return ok;
}

bool hs_yaml_load(hs_yaml *y, const char *text, size_t size, const char *empty_message) {
	y->loaded = false;
	if (!check_depth(y, text, size))
		return false;
	yaml_parser_t yp;
	yaml_document_t extra;
	memset(&y->doc, 0, sizeof y->doc);
	memset(&extra, 0, sizeof extra);
	if (!yaml_parser_initialize(&yp))
		return hs_set_error(y->err, y->path, 1, "out of memory");
	yaml_parser_set_input_string(&yp, (const unsigned char *)text, size);
	bool ok = yaml_parser_load(&yp, &y->doc) != 0;
	y->loaded = ok;
	if (!ok)
		yaml_failure(&yp, y, text, size);
	if (ok && !hs_yaml_root(y))
		ok = hs_set_error(y->err, y->path, 1, "%s", empty_message);
	if (ok) { // a second document would be silently ignored: refuse it
		if (!yaml_parser_load(&yp, &extra))
			ok = yaml_failure(&yp, y, text, size);
		else if (yaml_document_get_root_node(&extra))
			ok = hs_set_error(y->err, y->path, hs_yaml_line(yaml_document_get_root_node(&extra)),
			                  "only one YAML document is allowed per scenario file");
	}
	yaml_document_delete(&extra);
	yaml_parser_delete(&yp);
	return ok;
}

void hs_yaml_free(hs_yaml *y) {
	if (y->loaded)
		yaml_document_delete(&y->doc);
	y->loaded = false;
}

const yaml_node_t *hs_yaml_root(const hs_yaml *y) {
	return y->loaded ? yaml_document_get_root_node((yaml_document_t *)&y->doc) : NULL;
}

// ---------------------------------------------------------------------------------------------
// text in messages

static hs_shown show_text(const char *s, size_t n) {
	hs_shown r;
	size_t cut = n;
	bool more = false;
	if (cut > 40) { // do not split a UTF-8 sequence
		cut = 40;
		while (cut > 0 && ((unsigned char)s[cut] & 0xC0) == 0x80)
			--cut;
		more = true;
	}
	for (size_t i = 0; i < cut; ++i) {
		unsigned char c = (unsigned char)s[i];
		r.text[i] = (c < 0x20 || c == 0x7F) ? '?' : (char)c;
	}
	strcpy(r.text + cut, more ? "..." : "");
	return r;
}

hs_shown hs_yaml_show(const yaml_node_t *node) {
	if (node->type == YAML_SCALAR_NODE)
		return show_text((const char *)node->data.scalar.value, node->data.scalar.length);
	return show_text("", 0);
}

hs_shown hs_yaml_got(const yaml_node_t *node) {
	hs_shown r;
	if (node->type == YAML_SEQUENCE_NODE)
		strcpy(r.text, "a list");
	else if (node->type == YAML_MAPPING_NODE)
		strcpy(r.text, "a mapping");
	else if (node->type == YAML_SCALAR_NODE && node->data.scalar.length == 0)
		strcpy(r.text, "nothing");
	else {
		hs_shown t = hs_yaml_show(node); // at most 43 bytes: quoting fits
		size_t n = strlen(t.text);
		r.text[0] = '\'';
		memcpy(r.text + 1, t.text, n);
		memcpy(r.text + 1 + n, "'", 2);
	}
	return r;
}

// ---------------------------------------------------------------------------------------------
// scalars and sequences

bool hs_yaml_is_scalar(const yaml_node_t *n) { return n->type == YAML_SCALAR_NODE; }

const char *hs_yaml_scalar(const yaml_node_t *n) { return (const char *)n->data.scalar.value; }

bool hs_yaml_scalar_is(const yaml_node_t *n, const char *word) {
	return hs_yaml_is_scalar(n) && n->data.scalar.length == strlen(word) &&
	       memcmp(n->data.scalar.value, word, n->data.scalar.length) == 0;
}

int hs_yaml_word(const yaml_node_t *node, const char *const *names, int count) {
	for (int i = 0; i < count; ++i)
		if (hs_yaml_scalar_is(node, names[i]))
			return i;
	return -1;
}

long hs_yaml_length(const yaml_node_t *node) { return node->data.sequence.items.top - node->data.sequence.items.start; }

const yaml_node_t *hs_yaml_item(const hs_yaml *y, const yaml_node_t *node, long i) {
	return yaml_document_get_node((yaml_document_t *)&y->doc, node->data.sequence.items.start[i]);
}

bool hs_yaml_number(const hs_yaml *y, const yaml_node_t *node, const char *key, double *out) {
	if (!hs_yaml_is_scalar(node))
		return hs_yaml_fail(y, node, "'%s' must be a number, got %s", key, hs_yaml_got(node).text);
	switch (hs_parse_number(hs_yaml_scalar(node), node->data.scalar.length, out)) {
	case HS_NUMBER_OK:
		return true;
	case HS_NUMBER_NOT_FINITE:
		return hs_yaml_fail(y, node, "'%s' must be finite, got %s", key, hs_yaml_show(node).text);
	case HS_NUMBER_SYNTAX:
		break;
	}
	char point[64];
	if (hs_comma_decimal(hs_yaml_scalar(node), node->data.scalar.length, point, sizeof point))
		return hs_yaml_fail(y, node, "'%s' must be a number, got %s: write decimals with a point (%s)", key,
		                    hs_yaml_got(node).text, point);
	return hs_yaml_fail(y, node, "'%s' must be a number, got %s", key, hs_yaml_got(node).text);
}

// A number with a decimal comma in a flow collection ([0, 1,5, 2] or { size: 1,5 }) is read as two
// plain scalars, the comma between them and no space after it: true with the hint in `hint`.
static bool split_decimal(const yaml_node_t *a, const yaml_node_t *b, char *hint, size_t size) {
	if (!a || !b || !hs_yaml_is_scalar(a) || !hs_yaml_is_scalar(b) || a->data.scalar.style != YAML_PLAIN_SCALAR_STYLE ||
	    b->data.scalar.style != YAML_PLAIN_SCALAR_STYLE || b->start_mark.index != a->end_mark.index + 1)
		return false;
	size_t na = a->data.scalar.length, nb = b->data.scalar.length;
	char joined[64], point[64];
	if (na + nb + 2 > sizeof joined)
		return false;
	memcpy(joined, hs_yaml_scalar(a), na);
	joined[na] = ',';
	memcpy(joined + na + 1, hs_yaml_scalar(b), nb);
	joined[na + nb + 1] = '\0';
	if (!hs_comma_decimal(joined, na + nb + 1, point, sizeof point))
		return false;
	snprintf(hint, size, ": write decimals with a point ('%s' is read as two numbers; write %s)", joined, point);
	return true;
}

bool hs_yaml_integer(const hs_yaml *y, const yaml_node_t *node, const char *key, int64_t lo, int64_t hi, int64_t *out) {
	hs_integer_kind kind = HS_INTEGER_SYNTAX;
	int64_t v = 0;
	if (hs_yaml_is_scalar(node))
		kind = hs_parse_integer(hs_yaml_scalar(node), node->data.scalar.length, &v);
	if (kind == HS_INTEGER_SYNTAX)
		return hs_yaml_fail(y, node, "'%s' must be an integer, got %s", key, hs_yaml_got(node).text);
	if (kind == HS_INTEGER_RANGE || v < lo || v > hi) // %lld: int64_t's own format macro differs by target
		return hs_yaml_fail(y, node, "'%s' must be within [%lld, %lld], got %s", key, (long long)lo, (long long)hi,
		                    hs_yaml_show(node).text);
	*out = v;
	return true;
}

bool hs_yaml_bool(const hs_yaml *y, const yaml_node_t *node, const char *key, bool *out) {
	static const char *const words[] = {"true", "True", "TRUE", "false", "False", "FALSE"};
	int w = hs_yaml_word(node, words, 6);
	if (w < 0)
		return hs_yaml_fail(y, node, "'%s' must be true or false, got %s", key, hs_yaml_got(node).text);
	*out = w < 3;
	return true;
}

bool hs_yaml_text(const hs_yaml *y, const yaml_node_t *node, const char *key, char **out) {
	if (!hs_yaml_is_scalar(node) || node->data.scalar.length == 0)
		return hs_yaml_fail(y, node, "'%s' must be a text, got %s", key, hs_yaml_got(node).text);
	for (size_t i = 0; i < node->data.scalar.length; ++i) {
		unsigned char c = node->data.scalar.value[i];
		if (c < 0x20 || c == 0x7F)
			return hs_yaml_fail(y, node, "'%s' must be one line of text", key);
	}
	*out = malloc(node->data.scalar.length + 1);
	if (!*out)
		return hs_yaml_fail(y, node, "out of memory");
	memcpy(*out, node->data.scalar.value, node->data.scalar.length + 1);
	return true;
}

bool hs_yaml_time(const hs_yaml *y, const yaml_node_t *node, const char *key, double duration, double *out) {
	if (!hs_yaml_number(y, node, key, out))
		return false;
	if (*out < 0.0 || *out > duration)
		return hs_yaml_fail(y, node, "'%s' must be a time within [0, %g] s, got %s", key, duration,
		                    hs_yaml_show(node).text);
	return true;
}

bool hs_yaml_numbers(const hs_yaml *y, const yaml_node_t *node, const char *key, int count, const char *what,
                     double *out, const yaml_node_t **elements) {
	if (node->type != YAML_SEQUENCE_NODE)
		return hs_yaml_fail(y, node, "'%s' must be a list of %d numbers%s, got %s", key, count, what,
		                    hs_yaml_got(node).text);
	long n = hs_yaml_length(node);
	char hint[200] = "";
	for (long i = 0; n != count && i + 1 < n && !hint[0]; ++i)
		split_decimal(hs_yaml_item(y, node, i), hs_yaml_item(y, node, i + 1), hint, sizeof hint);
	if (n != count)
		return hs_yaml_fail(y, node, "'%s' must be a list of %d numbers%s, got %ld%s", key, count, what, n, hint);
	for (int i = 0; i < count; ++i) {
		const yaml_node_t *e = hs_yaml_item(y, node, i);
		if (!hs_yaml_number(y, e, key, &out[i]))
			return false;
		if (elements)
			elements[i] = e;
	}
	return true;
}

bool hs_yaml_vec3(const hs_yaml *y, const yaml_node_t *node, const char *key, hs_vec3 *out) {
	double v[3];
	if (!hs_yaml_numbers(y, node, key, 3, "", v, NULL))
		return false;
	*out = hs_v3(v[0], v[1], v[2]);
	return true;
}

bool hs_yaml_bounded_vec3(const hs_yaml *y, const yaml_node_t *node, const char *key, double limit, const char *unit,
                          hs_vec3 *out) {
	double v[3];
	const yaml_node_t *e[3];
	if (!hs_yaml_numbers(y, node, key, 3, "", v, e))
		return false;
	for (int i = 0; i < 3; ++i)
		if (!(fabs(v[i]) <= limit))
			return hs_yaml_fail(y, e[i], "'%s' must be within [-%g, %g] %s, got %s", key, limit, limit, unit,
			                    hs_yaml_show(e[i]).text);
	*out = hs_v3(v[0], v[1], v[2]);
	return true;
}

bool hs_yaml_rpy(const hs_yaml *y, const yaml_node_t *node, const char *key, hs_quat *out) {
	hs_vec3 rpy;
	if (!hs_yaml_vec3(y, node, key, &rpy))
		return false;
	*out = hs_quat_from_rpy(rpy.x * (HS_PI / 180.0), rpy.y * (HS_PI / 180.0), rpy.z * (HS_PI / 180.0));
	return true;
}

bool hs_yaml_quat(const hs_yaml *y, const yaml_node_t *node, const char *key, hs_quat *out) {
	double q[4], norm;
	if (!hs_yaml_numbers(y, node, key, 4, " [w, x, y, z]", q, NULL))
		return false;
	if (!hs_unit_quat(q, &norm, out))
		return hs_yaml_fail(y, node, "'%s' must have norm 1 (within %g), got norm %.9g", key, HS_QUAT_NORM_TOLERANCE,
		                    norm);
	return true;
}

// ---------------------------------------------------------------------------------------------
// mappings

// "unknown key 'K' in WHERE", with the nearest key and the list of keys when it is short, or the
// decimal comma that split a number into a value and this key.
static bool unknown_key(const hs_yaml *y, const yaml_node_t *map, const yaml_node_pair_t *pair,
                        const char *const *names, int name_count, const char *where) {
	const yaml_node_t *k = yaml_document_get_node((yaml_document_t *)&y->doc, pair->key);
	const yaml_node_t *before = pair > map->data.mapping.pairs.start
	                                ? yaml_document_get_node((yaml_document_t *)&y->doc, pair[-1].value)
	                                : NULL;
	char why[HS_ERROR_TEXT];
	snprintf(why, sizeof why, "unknown key '%s' in %s", hs_yaml_show(k).text, where);
	char hint[200];
	if (split_decimal(before, k, hint, sizeof hint))
		strncat(why, hint, sizeof why - strlen(why) - 1);
	else
		hs_suggest_append(why, sizeof why, hs_yaml_scalar(k), k->data.scalar.length, names, name_count, 1);
	return hs_yaml_fail(y, k, "%s", why);
}

bool hs_yaml_mapping(const hs_yaml *y, const yaml_node_t *map, const char *const *names, int name_count,
                     const char *where, hs_fields *f) {
	memset(f, 0, sizeof *f);
	for (yaml_node_pair_t *pair = map->data.mapping.pairs.start; pair < map->data.mapping.pairs.top; ++pair) {
		const yaml_node_t *k = yaml_document_get_node((yaml_document_t *)&y->doc, pair->key);
		const yaml_node_t *v = yaml_document_get_node((yaml_document_t *)&y->doc, pair->value);
		if (!k || !v)
			return hs_yaml_fail(y, map, "malformed YAML mapping");
		if (!hs_yaml_is_scalar(k))
			return hs_yaml_fail(y, k, "keys must be words, got %s in %s", hs_yaml_got(k).text, where);
		int i = hs_yaml_word(k, names, name_count);
		if (i < 0)
			return unknown_key(y, map, pair, names, name_count, where);
		if (f->key[i])
			return hs_yaml_fail(y, k, "duplicate key '%s' (first at line %lu)", names[i], hs_yaml_line(f->key[i]));
		f->key[i] = k;
		f->value[i] = v;
	}
	return true;
}

bool hs_yaml_exclusive(const hs_yaml *y, const hs_fields *f, const char *const *names, int a, int b, const char *why) {
	if (f->key[a] && f->key[b])
		return hs_yaml_fail(y, hs_yaml_before(f->key[a], f->key[b]) ? f->key[b] : f->key[a],
		                    "'%s' and '%s' are exclusive: %s", names[a], names[b], why);
	return true;
}

char *hs_yaml_sibling_file(const hs_yaml *y, const yaml_node_t *node, const char *key) {
	char *file = NULL;
	if (!hs_yaml_text(y, node, key, &file))
		return NULL;
	char *full = hs_sibling_path(y->path, file);
	free(file);
	if (!full)
		hs_yaml_fail(y, node, "out of memory");
	hs_file_list_add(y->files, full); // an input: a writer must not overwrite it (hs_scenario_input_path)
	return full;
}
