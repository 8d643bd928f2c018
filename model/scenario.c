// scenario.c — scenario files: load and validate a YAML file (libyaml's document API, so every
// node keeps its line), build the world through the public API, step it, record what the
// `expect` clauses need, and check them. Also the catalog: every scenario file below a folder.
//
// Errors are "PATH:LINE: what is wrong", one message, the first problem found; a failed load
// frees everything it allocated. The schema is documented for users in scenarios/README.md.
#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <yaml.h>

#include "internal.h"

#if defined(__GNUC__)
#define HS_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define HS_PRINTF(f, a)
#endif

enum {
	MAX_OBJECTS = 100000,       // objects per scenario
	MAX_CHECKS = 1000000,       // expect clauses × the objects they name ("*")
	MAX_CLAUSES = 100000,
	MAX_POLY_ITEMS = 100000,    // vertices or faces of one polyhedron
	MAX_FACE_SIZE = 1000,       // vertices of one polyhedron face
	MAX_NAME = 64,              // characters of an object name
	SEQ_CAPACITY = 64,          // collapsed contact states recorded per object
	MAX_CATALOG_DEPTH = 16,     // folder nesting under the catalog root
};
static const long MAX_FRAMES = 10000000L;
static const size_t MAX_FILE_BYTES = (size_t)256 << 20; // a scenario is text; this is a runaway guard
static const double MIN_DT = 1.0 / 2000.0, MAX_DT = 1.0 / 12.0; // s: the hand paper ran at 12–17 fps
static const double MAX_LENGTH = 1000.0;                     // m: largest size accepted
static const double QUAT_NORM_TOLERANCE = 1e-6;
enum { MAX_HANDS = 64, MAX_HAND_KEYS = 100000 };

// ---------------------------------------------------------------------------------------------
// expectations

typedef enum predicate {
	PRED_NEAR,
	PRED_RESTING,
	PRED_FLOOR_CONTACTS,
	PRED_ON_FACE,
	PRED_BELOW,
	PRED_ABOVE,
	PRED_MOVED,
	PRED_TURNED, // the predicates above take `at`
	PRED_LANDS_AT,
	PRED_STILL,
	PRED_CONTACT_SEQUENCE,
	PRED_COUNT
} predicate;

static const char *const predicate_names[PRED_COUNT] = {
    "near", "resting", "floor_contacts", "on_face", "below", "above", "moved", "turned_deg",
    "lands_at", "still", "contact_sequence",
};

static bool predicate_uses_at(predicate p) { return p <= PRED_TURNED; }

// One `expect` clause as written.
typedef struct clause {
	unsigned long line;
	int object; // index, or -1 for "*"
	predicate pred;
	bool at_end;
	long frame;       // at-based: the frame whose state is checked; still: the first frame watched
	hs_vec3 target;   // near, m
	double tolerance; // near: m; lands_at: s
	unsigned axes;    // near: bit 0 x, bit 1 y, bit 2 z
	bool flag;        // resting, on_face, still
	long count;       // floor_contacts
	double value;     // below/above: m; lands_at: s
	int seq_len;      // contact_sequence
	unsigned char seq[SEQ_CAPACITY];
} clause;

// One clause applied to one object: the unit that passes or fails.
typedef struct check {
	int clause, object;
	bool captured; // at-based: `state` holds the state at the clause's frame; still: the reference pose
	bool moved;    // still: the pose changed after the reference
	long moved_frame;
	hs_object_state state;
} check;

struct hs_scenario {
	char *name, *description;
	double dt, duration; // s
	long frames;         // to run: llround(duration / dt)
	long frame;          // run so far
	hs_world *world;
	int object_count;
	char **object_names;
	hs_object_id *ids;
	int clause_count;
	clause *clauses;
	int check_count;
	check *checks;
	// at-based checks in frame order, captured as the run passes their frame
	int capture_count, capture_next;
	int *capture_order;
	int still_count;
	int *still_checks;
	// per object, allocated only when a clause needs them
	long *landed_frame;   // lands_at: first floor contact after a frame without any, or -1
	bool *had_no_floor;   // lands_at: a frame without floor contact has been seen
	unsigned char *seq;   // contact_sequence: SEQ_CAPACITY collapsed states per object
	int *seq_len;
	long *seq_overflow;   // states that did not fit
	unsigned char *seq_last; // the last state seen, recorded or not
	hs_status step_status;
	long failed_frame;
	// hands and their input scripts (1999 paper §5.1: glove + tracker), sampled every frame
	int hand_count;
	char **hand_names;
	hs_hand_id *hand_ids;
	hs_hand_script *scripts;
	hs_object_state *initial; // every object at frame 0 (moved, turned_deg)
};

// ---------------------------------------------------------------------------------------------
// errors

typedef struct name_entry {
	const char *name;
	int index;
} name_entry;

typedef struct parser {
	const char *path;
	yaml_document_t *doc;
	hs_error *err;
	hs_scenario *s;
	name_entry *sorted; // object names in strcmp order, for duplicates and expect's lookups
} parser;

static void vset_error(hs_error *err, const char *path, unsigned long line, const char *fmt, va_list ap) {
	int n = snprintf(err->message, sizeof err->message, "%s:%lu: ", path, line);
	if (n >= 0 && (size_t)n < sizeof err->message)
		vsnprintf(err->message + n, sizeof err->message - (size_t)n, fmt, ap);
}

HS_PRINTF(4, 5)
static bool set_error(hs_error *err, const char *path, unsigned long line, const char *fmt, ...) {
	va_list ap;
	va_start(ap, fmt);
	vset_error(err, path, line, fmt, ap);
	va_end(ap);
	return false;
}

HS_PRINTF(3, 4)
static bool fail(parser *p, const yaml_node_t *node, const char *fmt, ...) {
	va_list ap;
	va_start(ap, fmt);
	vset_error(p->err, p->path, node ? (unsigned long)node->start_mark.line + 1 : 1, fmt, ap);
	va_end(ap);
	return false;
}

static unsigned long line_of(const yaml_node_t *node) { return (unsigned long)node->start_mark.line + 1; }

// a comes first in the file
static bool before(const yaml_node_t *a, const yaml_node_t *b) { return a->start_mark.index < b->start_mark.index; }

// A scalar's text for a message: at most 40 bytes, control characters shown as '?'.
typedef struct shown {
	char text[64];
} shown;

static shown show_text(const char *s, size_t n) {
	shown r;
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

static shown show(const yaml_node_t *node) {
	if (node->type == YAML_SCALAR_NODE)
		return show_text((const char *)node->data.scalar.value, node->data.scalar.length);
	return show_text("", 0);
}

// "got ..." for a value of the wrong kind
static shown got(const yaml_node_t *node) {
	shown r;
	if (node->type == YAML_SEQUENCE_NODE)
		strcpy(r.text, "a list");
	else if (node->type == YAML_MAPPING_NODE)
		strcpy(r.text, "a mapping");
	else if (node->type == YAML_SCALAR_NODE && node->data.scalar.length == 0)
		strcpy(r.text, "nothing");
	else {
		shown t = show(node); // at most 43 bytes: quoting fits
		size_t n = strlen(t.text);
		r.text[0] = '\'';
		memcpy(r.text + 1, t.text, n);
		memcpy(r.text + 1 + n, "'", 2);
	}
	return r;
}

// ---------------------------------------------------------------------------------------------
// scalars

static bool is_scalar(const yaml_node_t *n) { return n->type == YAML_SCALAR_NODE; }

static const char *scalar(const yaml_node_t *n) { return (const char *)n->data.scalar.value; }

static bool scalar_is(const yaml_node_t *n, const char *word) {
	return is_scalar(n) && n->data.scalar.length == strlen(word) && memcmp(n->data.scalar.value, word, n->data.scalar.length) == 0;
}

static bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Decimal numbers only: [-+]?(d+(.d*)?|.d+)([eE][-+]?d+)? — no hex, no '_', no trailing junk.
static bool is_decimal(const char *s, size_t n) {
	size_t i = 0, digits = 0;
	if (i < n && (s[i] == '+' || s[i] == '-'))
		++i;
	for (; i < n && is_digit(s[i]); ++i)
		++digits;
	if (i < n && s[i] == '.')
		for (++i; i < n && is_digit(s[i]); ++i)
			++digits;
	if (digits == 0)
		return false;
	if (i < n && (s[i] == 'e' || s[i] == 'E')) {
		++i;
		if (i < n && (s[i] == '+' || s[i] == '-'))
			++i;
		size_t start = i;
		while (i < n && is_digit(s[i]))
			++i;
		if (i == start)
			return false;
	}
	return i == n;
}

static char lower(char c) { return (c >= 'A' && c <= 'Z') ? (char)(c - 'A' + 'a') : c; }

// YAML's .inf/.nan and strtod's inf/infinity/nan, in any case and with a sign
static bool is_non_finite_word(const char *s, size_t n) {
	size_t i = 0;
	if (i < n && (s[i] == '+' || s[i] == '-'))
		++i;
	if (i < n && s[i] == '.')
		++i;
	static const char *const words[] = {"inf", "infinity", "nan"};
	for (size_t w = 0; w < 3; ++w) {
		size_t len = strlen(words[w]);
		if (n - i != len)
			continue;
		size_t k = 0;
		while (k < len && lower(s[i + k]) == words[w][k])
			++k;
		if (k == len)
			return true;
	}
	return false;
}

typedef enum number_kind { NUMBER_OK, NUMBER_SYNTAX, NUMBER_NOT_FINITE } number_kind;

static number_kind parse_number_text(const char *s, size_t n, double *out) {
	if (is_non_finite_word(s, n))
		return NUMBER_NOT_FINITE;
	if (!is_decimal(s, n) || n > 200)
		return NUMBER_SYNTAX;
	char buf[208];
	memcpy(buf, s, n);
	buf[n] = '\0';
	double v = strtod(buf, NULL); // underflow to 0 or a subnormal is fine; ranges are checked later
	if (!isfinite(v))
		return NUMBER_NOT_FINITE;
	*out = v;
	return NUMBER_OK;
}

static bool read_number(parser *p, const yaml_node_t *node, const char *key, double *out) {
	if (!is_scalar(node))
		return fail(p, node, "'%s' must be a number, got %s", key, got(node).text);
	switch (parse_number_text(scalar(node), node->data.scalar.length, out)) {
	case NUMBER_OK:
		return true;
	case NUMBER_NOT_FINITE:
		return fail(p, node, "'%s' must be finite, got %s", key, show(node).text);
	case NUMBER_SYNTAX:
		break;
	}
	return fail(p, node, "'%s' must be a number, got %s", key, got(node).text);
}

static bool read_integer(parser *p, const yaml_node_t *node, const char *key, long lo, long hi, long *out) {
	const char *s = is_scalar(node) ? scalar(node) : "";
	size_t n = is_scalar(node) ? node->data.scalar.length : 0, i = 0;
	if (n > 0 && (s[0] == '+' || s[0] == '-'))
		++i;
	bool syntax = is_scalar(node) && i < n;
	for (size_t k = i; k < n; ++k)
		syntax = syntax && is_digit(s[k]);
	if (!syntax)
		return fail(p, node, "'%s' must be an integer, got %s", key, got(node).text);
	errno = 0;
	long v = strtol(s, NULL, 10);
	if (errno == ERANGE || v < lo || v > hi)
		return fail(p, node, "'%s' must be within [%ld, %ld], got %s", key, lo, hi, show(node).text);
	*out = v;
	return true;
}

static bool read_bool(parser *p, const yaml_node_t *node, const char *key, bool *out) {
	if (scalar_is(node, "true") || scalar_is(node, "True") || scalar_is(node, "TRUE"))
		*out = true;
	else if (scalar_is(node, "false") || scalar_is(node, "False") || scalar_is(node, "FALSE"))
		*out = false;
	else
		return fail(p, node, "'%s' must be true or false, got %s", key, got(node).text);
	return true;
}

// A one-line text. `out` is a new string.
static bool read_text(parser *p, const yaml_node_t *node, const char *key, char **out) {
	if (!is_scalar(node) || node->data.scalar.length == 0)
		return fail(p, node, "'%s' must be a text, got %s", key, got(node).text);
	for (size_t i = 0; i < node->data.scalar.length; ++i) {
		unsigned char c = node->data.scalar.value[i];
		if (c < 0x20 || c == 0x7F)
			return fail(p, node, "'%s' must be one line of text", key);
	}
	*out = malloc(node->data.scalar.length + 1);
	if (!*out)
		return fail(p, node, "out of memory");
	memcpy(*out, node->data.scalar.value, node->data.scalar.length + 1);
	return true;
}

// `count` numbers in a list; `elements` (optional) receives their nodes for range messages.
static bool read_numbers(parser *p, const yaml_node_t *node, const char *key, int count, const char *what,
                         double *out, const yaml_node_t **elements) {
	if (node->type != YAML_SEQUENCE_NODE)
		return fail(p, node, "'%s' must be a list of %d numbers%s, got %s", key, count, what, got(node).text);
	long n = node->data.sequence.items.top - node->data.sequence.items.start;
	if (n != count)
		return fail(p, node, "'%s' must be a list of %d numbers%s, got %ld", key, count, what, n);
	for (int i = 0; i < count; ++i) {
		const yaml_node_t *e = yaml_document_get_node(p->doc, node->data.sequence.items.start[i]);
		if (!read_number(p, e, key, &out[i]))
			return false;
		if (elements)
			elements[i] = e;
	}
	return true;
}

static bool read_vec3(parser *p, const yaml_node_t *node, const char *key, hs_vec3 *out) {
	double v[3];
	if (!read_numbers(p, node, key, 3, "", v, NULL))
		return false;
	*out = hs_v3(v[0], v[1], v[2]);
	return true;
}

// A length of a shape: (0, MAX_LENGTH] m.
static bool check_length(parser *p, const yaml_node_t *node, const char *key, double v) {
	if (v > 0.0 && v <= MAX_LENGTH)
		return true;
	return fail(p, node, "'%s' must be within (0, %g] m, got %s", key, MAX_LENGTH, show(node).text);
}

// A time in [0, duration] s.
static bool read_time(parser *p, const yaml_node_t *node, const char *key, double *out) {
	if (!read_number(p, node, key, out))
		return false;
	if (*out < 0.0 || *out > p->s->duration)
		return fail(p, node, "'%s' must be a time within [0, %g] s, got %s", key, p->s->duration, show(node).text);
	return true;
}

// ---------------------------------------------------------------------------------------------
// mappings

typedef struct fields {
	const yaml_node_t *key[16];
	const yaml_node_t *value[16];
} fields;

// Checks every key of `map` against `names` (unknown and duplicate keys are errors) and collects
// the values by name index.
static bool read_mapping(parser *p, const yaml_node_t *map, const char *const *names, int name_count,
                         const char *where, fields *f) {
	memset(f, 0, sizeof *f);
	for (yaml_node_pair_t *pair = map->data.mapping.pairs.start; pair < map->data.mapping.pairs.top; ++pair) {
		const yaml_node_t *k = yaml_document_get_node(p->doc, pair->key);
		const yaml_node_t *v = yaml_document_get_node(p->doc, pair->value);
		if (!k || !v)
			return fail(p, map, "malformed YAML mapping");
		if (!is_scalar(k))
			return fail(p, k, "keys must be words, got %s in %s", got(k).text, where);
		int i = 0;
		while (i < name_count && !scalar_is(k, names[i]))
			++i;
		if (i == name_count)
			return fail(p, k, "unknown key '%s' in %s", show(k).text, where);
		if (f->key[i])
			return fail(p, k, "duplicate key '%s' (first at line %lu)", names[i], line_of(f->key[i]));
		f->key[i] = k;
		f->value[i] = v;
	}
	return true;
}

static long sequence_length(const yaml_node_t *node) {
	return node->data.sequence.items.top - node->data.sequence.items.start;
}

static const yaml_node_t *sequence_item(parser *p, const yaml_node_t *node, long i) {
	return yaml_document_get_node(p->doc, node->data.sequence.items.start[i]);
}

// ---------------------------------------------------------------------------------------------
// file → document

static bool read_file(const char *path, char **text, size_t *size, hs_error *err) {
	FILE *f = fopen(path, "rb");
	if (!f)
		return set_error(err, path, 1, "cannot read: %s", strerror(errno));
	struct stat st;
	if (fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
		fclose(f);
		return set_error(err, path, 1, "cannot read: %s", strerror(EISDIR));
	}
	size_t cap = 4096, n = 0;
	char *buf = malloc(cap);
	bool ok = buf != NULL;
	while (ok) {
		if (n == cap) {
			if (cap >= MAX_FILE_BYTES) {
				ok = set_error(err, path, 1, "cannot read: larger than %zu MiB", MAX_FILE_BYTES >> 20);
				break;
			}
			char *bigger = realloc(buf, cap * 2);
			if (!bigger) {
				ok = false;
				break;
			}
			buf = bigger;
			cap *= 2;
		}
		size_t got_bytes = fread(buf + n, 1, cap - n, f);
		n += got_bytes;
		if (got_bytes == 0) {
			if (ferror(f))
				ok = set_error(err, path, 1, "cannot read: %s", strerror(errno ? errno : EIO));
			break;
		}
	}
	if (!buf || (!ok && err->message[0] == '\0'))
		set_error(err, path, 1, "cannot read: out of memory");
	fclose(f);
	if (!ok || !buf) {
		free(buf);
		return false;
	}
	*text = buf;
	*size = n;
	return true;
}

static unsigned long line_at_offset(const char *text, size_t size, size_t offset) {
	unsigned long line = 1;
	for (size_t i = 0; i < offset && i < size; ++i)
		line += text[i] == '\n';
	return line;
}

static bool yaml_failure(const yaml_parser_t *yp, const char *path, const char *text, size_t size, hs_error *err) {
	switch (yp->error) {
	case YAML_MEMORY_ERROR:
		return set_error(err, path, 1, "out of memory");
	case YAML_READER_ERROR: // reader errors carry a byte offset, not a mark
		return set_error(err, path, line_at_offset(text, size, yp->problem_offset), "not a text file: %s (byte %zu)",
		                 yp->problem ? yp->problem : "unreadable", yp->problem_offset);
	default:
		break;
	}
	const char *problem = yp->problem ? yp->problem : "unknown error";
	unsigned long line = (unsigned long)yp->problem_mark.line + 1;
	unsigned long last = line_at_offset(text, size, size > 0 && text[size - 1] == '\n' ? size - 1 : size);
	if (line > last) // libyaml ends the stream with a line break of its own
		line = last;
	if (yp->context)
		return set_error(err, path, line, "invalid YAML: %s (%s at line %lu)", problem, yp->context,
		                 (unsigned long)yp->context_mark.line + 1);
	return set_error(err, path, line, "invalid YAML: %s", problem);
}

// ---------------------------------------------------------------------------------------------
// the scenario's parts

static const char *base_name(const char *path, size_t *length) {
	const char *slash = strrchr(path, '/');
	const char *base = slash ? slash + 1 : path;
	size_t n = strlen(base);
	if (n > 5 && strcmp(base + n - 5, ".yaml") == 0)
		n -= 5;
	*length = n;
	return base;
}

static bool read_dt(parser *p, const yaml_node_t *node) {
	double dt = 0.0;
	const char *s = is_scalar(node) ? scalar(node) : "";
	const char *slash = is_scalar(node) ? memchr(s, '/', node->data.scalar.length) : NULL;
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
		number_kind ka = parse_number_text(s + a0, a1 - a0, &a), kb = parse_number_text(s + b0, b1 - b0, &b);
		if (ka == NUMBER_NOT_FINITE || kb == NUMBER_NOT_FINITE)
			return fail(p, node, "'dt' must be finite, got %s", show(node).text);
		if (ka != NUMBER_OK || kb != NUMBER_OK)
			return fail(p, node, "'dt' must be a number, got %s", got(node).text);
		if (b == 0.0)
			return fail(p, node, "'dt' divides by zero: %s", show(node).text);
		dt = a / b;
	} else if (!read_number(p, node, "dt", &dt)) {
		return false;
	}
	if (!(dt >= MIN_DT && dt <= MAX_DT))
		return fail(p, node, "'dt' must be within [1/2000, 1/12] s, got %s", show(node).text);
	p->s->dt = dt;
	return true;
}

static bool read_duration(parser *p, const yaml_node_t *node) {
	double d;
	if (!read_number(p, node, "duration", &d))
		return false;
	if (!(d > 0.0))
		return fail(p, node, "'duration' must be > 0 s, got %s", show(node).text);
	double frames = d / p->s->dt;
	if (!(frames < (double)MAX_FRAMES + 0.5))
		return fail(p, node, "'duration' is %.0f frames of dt = %g s; at most %ld are allowed", frames, p->s->dt,
		            MAX_FRAMES);
	long n = llround(frames);
	if (n < 1)
		return fail(p, node, "'duration' must be at least one frame (dt = %g s), got %s", p->s->dt, show(node).text);
	p->s->duration = d;
	p->s->frames = n;
	return true;
}

static bool read_model(parser *p, const yaml_node_t *node, hs_world_def *def) {
	static const char *const names[] = {"grasp_threshold_deg", "stacking", "floor_tolerance", "skip_work"};
	if (node->type != YAML_MAPPING_NODE)
		return fail(p, node, "'model' must be a mapping, got %s", got(node).text);
	fields f;
	if (!read_mapping(p, node, names, 4, "model", &f))
		return false;
	if (f.value[0]) {
		if (!read_number(p, f.value[0], names[0], &def->grasp_threshold_deg))
			return false;
		if (!(def->grasp_threshold_deg > 0.0 && def->grasp_threshold_deg <= 180.0))
			return fail(p, f.value[0], "'grasp_threshold_deg' must be within (0, 180] deg, got %s", show(f.value[0]).text);
	}
	if (f.value[1]) {
		if (scalar_is(f.value[1], "paper"))
			def->stacking = HS_STACKING_PAPER;
		else if (scalar_is(f.value[1], "support"))
			def->stacking = HS_STACKING_SUPPORT;
		else
			return fail(p, f.value[1], "'stacking' must be paper or support, got %s", got(f.value[1]).text);
	}
	if (f.value[2]) {
		if (!read_number(p, f.value[2], names[2], &def->floor_tolerance))
			return false;
		if (!(def->floor_tolerance > 0.0 && def->floor_tolerance <= 0.01))
			return fail(p, f.value[2], "'floor_tolerance' must be within (0, 0.01] m, got %s", show(f.value[2]).text);
	}
	if (f.value[3] && !read_bool(p, f.value[3], names[3], &def->skip_work))
		return false;
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
	O_COUNT
};
static const char *const object_keys[O_COUNT] = {
    "name", "shape", "size", "thickness", "vertices", "faces", "position", "rpy_deg", "quat", "velocity",
    "angular_velocity_deg", "density",
};

static bool is_name_char(char c) {
	return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || is_digit(c) || c == '_' || c == '-';
}

// Pass 1: every object's name (present, well formed), so later messages can name the object.
static bool read_object_name(parser *p, const yaml_node_t *node, long index, char **out) {
	if (node->type != YAML_MAPPING_NODE)
		return fail(p, node, "object %ld must be a mapping, got %s", index + 1, got(node).text);
	fields f;
	if (!read_mapping(p, node, object_keys, O_COUNT, "object", &f))
		return false;
	const yaml_node_t *v = f.value[O_NAME];
	if (!v)
		return fail(p, node, "object %ld is missing 'name'", index + 1);
	if (!is_scalar(v) || v->data.scalar.length == 0)
		return fail(p, v, "'name' must be a text, got %s", got(v).text);
	for (size_t i = 0; i < v->data.scalar.length; ++i)
		if (!is_name_char(scalar(v)[i]))
			return fail(p, v, "object name '%s' may only use letters, digits, '_' and '-'", show(v).text);
	if (v->data.scalar.length > MAX_NAME)
		return fail(p, v, "object name '%s' is longer than %d characters", show(v).text, MAX_NAME);
	return read_text(p, v, "name", out);
}

static int compare_names(const void *a, const void *b) {
	const name_entry *x = a, *y = b;
	int c = strcmp(x->name, y->name);
	return c ? c : (x->index > y->index) - (x->index < y->index);
}

static bool read_polyhedron(parser *p, const fields *f, const yaml_node_t *obj, const char *name, hs_shape **shape) {
	const yaml_node_t *vn = f->value[O_VERTICES], *fn = f->value[O_FACES];
	if (!vn)
		return fail(p, obj, "object '%s' is missing 'vertices'", name);
	if (!fn)
		return fail(p, obj, "object '%s' is missing 'faces'", name);
	if (vn->type != YAML_SEQUENCE_NODE || sequence_length(vn) < 4 || sequence_length(vn) > MAX_POLY_ITEMS)
		return fail(p, vn, "'vertices' must be a list of 4 to %d points [x, y, z], got %s", MAX_POLY_ITEMS,
		            vn->type == YAML_SEQUENCE_NODE ? "another count" : got(vn).text);
	if (fn->type != YAML_SEQUENCE_NODE || sequence_length(fn) < 4 || sequence_length(fn) > MAX_POLY_ITEMS)
		return fail(p, fn, "'faces' must be a list of 4 to %d faces [i, j, k, ...], got %s", MAX_POLY_ITEMS,
		            fn->type == YAML_SEQUENCE_NODE ? "another count" : got(fn).text);
	int vcount = (int)sequence_length(vn), fcount = (int)sequence_length(fn);
	long total = 0;
	for (int i = 0; i < fcount; ++i) {
		const yaml_node_t *face = sequence_item(p, fn, i);
		if (face->type != YAML_SEQUENCE_NODE || sequence_length(face) < 3 || sequence_length(face) > MAX_FACE_SIZE)
			return fail(p, face, "each face must be a list of 3 to %d vertex indices, got %s", MAX_FACE_SIZE,
			            face->type == YAML_SEQUENCE_NODE ? "another count" : got(face).text);
		total += sequence_length(face);
	}
	hs_vec3 *vertices = malloc((size_t)vcount * sizeof *vertices);
	int *sizes = malloc((size_t)fcount * sizeof *sizes);
	int *indices = malloc((size_t)total * sizeof *indices);
	bool ok = vertices && sizes && indices;
	if (!ok)
		fail(p, obj, "out of memory");
	for (int i = 0; ok && i < vcount; ++i)
		ok = read_vec3(p, sequence_item(p, vn, i), "vertices", &vertices[i]);
	long k = 0;
	for (int i = 0; ok && i < fcount; ++i) {
		const yaml_node_t *face = sequence_item(p, fn, i);
		sizes[i] = (int)sequence_length(face);
		for (int j = 0; ok && j < sizes[i]; ++j) {
			long index;
			const yaml_node_t *e = sequence_item(p, face, j);
			ok = read_integer(p, e, "faces", 0, vcount - 1, &index); // indices into 'vertices'
			if (ok)
				indices[k++] = (int)index;
		}
	}
	if (ok) {
		char why[256] = "";
		hs_status status = HS_OK;
		*shape = hs_shape_polyhedron(vertices, vcount, indices, sizes, fcount, why, sizeof why, &status);
		if (!*shape)
			ok = fail(p, obj, "shape is degenerate: %s", why[0] ? why : hs_status_string(status));
	}
	free(vertices);
	free(sizes);
	free(indices);
	return ok;
}

typedef enum shape_name { SH_CUBE, SH_BOX, SH_PYRAMID, SH_L_BLOCK, SH_ELLIPSOID, SH_SPHERE, SH_POLYHEDRON, SH_COUNT } shape_name;
static const char *const shape_names[SH_COUNT] = {"cube", "box", "pyramid", "l_block", "ellipsoid", "sphere", "polyhedron"};

static bool read_shape(parser *p, const fields *f, const yaml_node_t *obj, const char *name, hs_shape **shape) {
	const yaml_node_t *kind = f->value[O_SHAPE], *size = f->value[O_SIZE];
	if (!kind)
		return fail(p, obj, "object '%s' is missing 'shape'", name);
	int sh = 0;
	while (sh < SH_COUNT && !scalar_is(kind, shape_names[sh]))
		++sh;
	if (sh == SH_COUNT)
		return fail(p, kind, "unknown shape %s (expected cube, box, pyramid, l_block, ellipsoid, sphere or polyhedron)",
		            got(kind).text);
	if (sh != SH_POLYHEDRON && f->key[O_VERTICES])
		return fail(p, f->key[O_VERTICES], "'vertices' is only for shape polyhedron");
	if (sh != SH_POLYHEDRON && f->key[O_FACES])
		return fail(p, f->key[O_FACES], "'faces' is only for shape polyhedron");
	if (sh != SH_L_BLOCK && f->key[O_THICKNESS])
		return fail(p, f->key[O_THICKNESS], "'thickness' is only for shape l_block");
	if (sh == SH_POLYHEDRON) {
		if (f->key[O_SIZE])
			return fail(p, f->key[O_SIZE], "a polyhedron takes 'vertices' and 'faces', not 'size'");
		return read_polyhedron(p, f, obj, name, shape);
	}
	if (!size)
		return fail(p, obj, "object '%s' is missing 'size'", name);
	double v[3] = {0.0, 0.0, 0.0}, thickness = 0.0;
	const yaml_node_t *e[3] = {size, size, size};
	int n = sh == SH_CUBE || sh == SH_SPHERE ? 1 : sh == SH_PYRAMID ? 2 : 3;
	static const char *const what[SH_COUNT] = {" (the edge)", " [x, y, z]", " [base, height]", " [x, y, z]",
	                                           " [a, b, c] (semi-axes)", " (the radius)", ""};
	if (n == 1) {
		if (!is_scalar(size))
			return fail(p, size, "'size' of a %s must be a number%s, got %s", shape_names[sh], what[sh], got(size).text);
		if (!read_number(p, size, "size", &v[0]))
			return false;
	} else if (!read_numbers(p, size, "size", n, what[sh], v, e)) {
		return false;
	}
	for (int i = 0; i < n; ++i)
		if (!check_length(p, e[i], "size", v[i]))
			return false;
	if (sh == SH_L_BLOCK) {
		const yaml_node_t *t = f->value[O_THICKNESS];
		if (!t)
			return fail(p, obj, "object '%s' is missing 'thickness'", name);
		if (!read_number(p, t, "thickness", &thickness))
			return false;
		double limit = fmin(v[0], v[2]); // foot height and upright width stay inside the bounding box
		if (!(thickness > 0.0 && thickness < limit))
			return fail(p, t, "'thickness' must be within (0, %g) m (less than size x and z), got %s", limit, show(t).text);
	}
	hs_status status = HS_OK;
	switch ((shape_name)sh) {
	case SH_CUBE:
		*shape = hs_shape_box(hs_v3(v[0], v[0], v[0]), &status);
		break;
	case SH_BOX:
		*shape = hs_shape_box(hs_v3(v[0], v[1], v[2]), &status);
		break;
	case SH_PYRAMID:
		*shape = hs_shape_pyramid(v[0], v[1], &status);
		break;
	case SH_L_BLOCK:
		*shape = hs_shape_l_block(hs_v3(v[0], v[1], v[2]), thickness, &status);
		break;
	case SH_ELLIPSOID:
		*shape = hs_shape_ellipsoid(hs_v3(v[0], v[1], v[2]), &status);
		break;
	case SH_SPHERE:
		*shape = hs_shape_sphere(v[0], &status);
		break;
	default:
		*shape = NULL;
		break;
	}
	if (!*shape)
		return fail(p, obj, "cannot make the %s: %s", shape_names[sh], hs_status_string(status));
	return true;
}

static bool read_object(parser *p, const yaml_node_t *obj, int index) {
	hs_scenario *s = p->s;
	const char *name = s->object_names[index];
	fields f;
	if (!read_mapping(p, obj, object_keys, O_COUNT, "object", &f))
		return false;
	hs_object_def def = hs_default_object_def();
	hs_shape *shape = NULL;
	if (!read_shape(p, &f, obj, name, &shape))
		return false;
	bool ok = true;
	if (!f.value[O_POSITION])
		ok = fail(p, obj, "object '%s' is missing 'position'", name);
	else if (f.value[O_RPY] && f.value[O_QUAT])
		ok = fail(p, before(f.key[O_RPY], f.key[O_QUAT]) ? f.key[O_QUAT] : f.key[O_RPY],
		          "'rpy_deg' and 'quat' are exclusive: give one orientation");
	else
		ok = read_vec3(p, f.value[O_POSITION], "position", &def.position);
	if (ok && f.value[O_RPY]) {
		hs_vec3 rpy = {0.0, 0.0, 0.0};
		ok = read_vec3(p, f.value[O_RPY], "rpy_deg", &rpy);
		if (ok)
			def.orientation = hs_quat_from_rpy(rpy.x * (HS_PI / 180.0), rpy.y * (HS_PI / 180.0), rpy.z * (HS_PI / 180.0));
	}
	if (ok && f.value[O_QUAT]) {
		double q[4];
		ok = read_numbers(p, f.value[O_QUAT], "quat", 4, " [w, x, y, z]", q, NULL);
		double norm = ok ? sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]) : 1.0;
		if (ok && !(fabs(norm - 1.0) <= QUAT_NORM_TOLERANCE))
			ok = fail(p, f.value[O_QUAT], "'quat' must have norm 1 (within %g), got norm %.9g", QUAT_NORM_TOLERANCE, norm);
		if (ok) // exact unit length from here on, so every build starts from the same bits
			def.orientation = hs_quat_normalize(hs_q(q[0], q[1], q[2], q[3]));
	}
	if (ok && f.value[O_VELOCITY])
		ok = read_vec3(p, f.value[O_VELOCITY], "velocity", &def.velocity);
	if (ok && f.value[O_ANGULAR]) {
		hs_vec3 w = {0.0, 0.0, 0.0};
		ok = read_vec3(p, f.value[O_ANGULAR], "angular_velocity_deg", &w);
		def.angular_velocity = hs_scale(w, HS_PI / 180.0);
	}
	if (ok && f.value[O_DENSITY]) {
		ok = read_number(p, f.value[O_DENSITY], "density", &def.density);
		if (ok && !(def.density > 0.0))
			ok = fail(p, f.value[O_DENSITY], "'density' must be > 0 kg/m^3, got %s", show(f.value[O_DENSITY]).text);
	}
	hs_status status = HS_OK;
	if (ok) {
		def.shape = hs_world_add_shape(s->world, shape, &status);
		if (def.shape.index1 == 0)
			ok = fail(p, obj, "object '%s': cannot add its shape to the world: %s", name, hs_status_string(status));
	}
	hs_shape_destroy(shape);
	if (ok) {
		s->ids[index] = hs_world_add_object(s->world, &def, &status);
		if (s->ids[index].index1 == 0)
			ok = fail(p, obj, "object '%s': cannot add it to the world: %s", name, hs_status_string(status));
	}
	return ok;
}

static bool read_objects(parser *p, const yaml_node_t *node, hs_world_def def) {
	hs_scenario *s = p->s;
	if (node->type != YAML_SEQUENCE_NODE)
		return fail(p, node, "'objects' must be a list of objects, got %s", got(node).text);
	long n = sequence_length(node);
	if (n < 1 || n > MAX_OBJECTS)
		return fail(p, node, "'objects' must hold 1 to %d objects, got %ld", MAX_OBJECTS, n);
	s->object_count = (int)n;
	s->object_names = calloc((size_t)n, sizeof *s->object_names);
	s->ids = calloc((size_t)n, sizeof *s->ids);
	if (!s->object_names || !s->ids)
		return fail(p, node, "out of memory");
	for (int i = 0; i < s->object_count; ++i)
		if (!read_object_name(p, sequence_item(p, node, i), i, &s->object_names[i]))
			return false;
	// duplicate names: sort, then report the earliest object that repeats an earlier name
	name_entry *sorted = p->sorted = malloc((size_t)n * sizeof *sorted);
	if (!sorted)
		return fail(p, node, "out of memory");
	for (int i = 0; i < s->object_count; ++i)
		sorted[i] = (name_entry){s->object_names[i], i};
	qsort(sorted, (size_t)n, sizeof *sorted, compare_names);
	int dup = -1, first = -1;
	for (int i = 1; i < s->object_count; ++i)
		if (strcmp(sorted[i].name, sorted[i - 1].name) == 0 && (i < 2 || strcmp(sorted[i - 1].name, sorted[i - 2].name) != 0) &&
		    (dup < 0 || sorted[i].index < dup)) {
			dup = sorted[i].index;
			first = sorted[i - 1].index;
		}
	if (dup >= 0) {
		fields f;
		const yaml_node_t *obj = sequence_item(p, node, dup), *first_obj = sequence_item(p, node, first);
		read_mapping(p, obj, object_keys, O_COUNT, "object", &f); // succeeded in pass 1
		return fail(p, f.value[O_NAME], "duplicate object name '%s' (first at line %lu)", s->object_names[dup],
		            line_of(first_obj));
	}
	def.max_objects = s->object_count;
	def.max_shapes = s->object_count;
	hs_status status = HS_OK;
	s->world = hs_world_create(&def, &status);
	if (!s->world)
		return fail(p, node, "cannot create the world: %s", hs_status_string(status));
	for (int i = 0; i < s->object_count; ++i)
		if (!read_object(p, sequence_item(p, node, i), i))
			return false;
	return true;
}


// ---------------------------------------------------------------------------------------------
// hands: keyframes or a recorded glove + tracker file

static void drive_hands(hs_scenario *s, double t) {
	for (int h = 0; h < s->hand_count; ++h) {
		hs_vec3 wrist;
		hs_quat rot;
		uint8_t sensors[HS_GLOVE_SENSORS];
		hs_hand_script_sample(&s->scripts[h], t, &wrist, &rot, sensors);
		hs_world_set_hand(s->world, s->hand_ids[h], wrist, rot, sensors);
	}
}

static const char *const posture_names[] = {"open", "fist", "pinch", "point", "grasp"};

// posture: a word (open, fist, pinch, point) or a one-key mapping { fist: 0.5 } / { grasp: 0.05 }
static bool read_posture(parser *p, const yaml_node_t *node, const hs_hand_def *def, double out[HS_GLOVE_SENSORS]) {
	int which = -1;
	double amount = 1.0;
	const yaml_node_t *amount_node = node;
	if (is_scalar(node)) {
		for (int i = 0; i < 5; ++i)
			if (scalar_is(node, posture_names[i]))
				which = i;
		if (which == HS_POSTURE_GRASP)
			return fail(p, node, "posture 'grasp' needs the object's width: { grasp: 0.05 }");
	} else if (node->type == YAML_MAPPING_NODE && node->data.mapping.pairs.top - node->data.mapping.pairs.start == 1) {
		const yaml_node_t *k = yaml_document_get_node(p->doc, node->data.mapping.pairs.start[0].key);
		amount_node = yaml_document_get_node(p->doc, node->data.mapping.pairs.start[0].value);
		for (int i = 0; k && is_scalar(k) && i < 5; ++i)
			if (scalar_is(k, posture_names[i]))
				which = i;
		if (which >= 0 && !read_number(p, amount_node, posture_names[which], &amount))
			return false;
	}
	if (which < 0)
		return fail(p, node, "'posture' must be open, fist, pinch, point or a mapping like { grasp: 0.05 }, got %s",
		            got(node).text);
	uint8_t sensors[HS_GLOVE_SENSORS];
	if (hs_hand_posture(def, (hs_posture)which, amount, sensors) != HS_OK)
		return fail(p, amount_node, which == HS_POSTURE_GRASP ? "posture 'grasp' width must be within [0.01, 0.12] m, got %s"
		                                                      : "posture '%s' amount must be within [0, 1], got %s",
		            which == HS_POSTURE_GRASP ? show(amount_node).text : posture_names[which], show(amount_node).text);
	for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
		out[i] = sensors[i];
	return true;
}

static bool read_sensor_list(parser *p, const yaml_node_t *node, double out[HS_GLOVE_SENSORS]) {
	if (node->type != YAML_SEQUENCE_NODE)
		return fail(p, node, "'sensors' must be a list of 18 integers from 0 to 255, got %s", got(node).text);
	if (sequence_length(node) != HS_GLOVE_SENSORS)
		return fail(p, node, "'sensors' must be a list of 18 integers from 0 to 255, got %ld", sequence_length(node));
	for (int i = 0; i < HS_GLOVE_SENSORS; ++i) {
		long v;
		if (!read_integer(p, sequence_item(p, node, i), "sensors", 0, 255, &v))
			return false;
		out[i] = (double)v;
	}
	return true;
}

// 18 joint angles in degrees, in the sensor order of handspring.h
static bool read_angle_list(parser *p, const yaml_node_t *node, double out[HS_GLOVE_SENSORS]) {
	double deg[HS_GLOVE_SENSORS];
	const yaml_node_t *elements[HS_GLOVE_SENSORS];
	if (!read_numbers(p, node, "angles_deg", HS_GLOVE_SENSORS, " in the glove's sensor order", deg, elements))
		return false;
	for (int i = 0; i < HS_GLOVE_SENSORS; ++i) {
		bool wrist = i == HS_SENSOR_WRIST_PITCH || i == HS_SENSOR_WRIST_YAW;
		double lo = wrist ? -64.0 : 0.0, hi = wrist ? 63.5 : 127.5; // what 8 bits at 0.5 deg can say
		if (!(deg[i] >= lo && deg[i] <= hi))
			return fail(p, elements[i], "'angles_deg' entry %d must be within [%g, %g] deg, got %s", i + 1, lo, hi,
			            show(elements[i]).text);
		out[i] = deg[i] / 0.5 + (wrist ? 128.0 : 0.0);
	}
	return true;
}

enum { K_T, K_WRIST, K_GRIP, K_RPY, K_QUAT, K_POSTURE, K_SENSORS, K_ANGLES, K_COUNT };
static const char *const key_keys[K_COUNT] = {"t", "wrist", "grip", "rpy_deg", "quat", "posture", "sensors", "angles_deg"};

static bool exclusive(parser *p, const fields *f, int a, int b) {
	if (f->key[a] && f->key[b])
		return fail(p, before(f->key[a], f->key[b]) ? f->key[b] : f->key[a], "'%s' and '%s' are exclusive: give one",
		            key_keys[a], key_keys[b]);
	return true;
}

static bool read_key(parser *p, const yaml_node_t *node, const hs_hand_def *def, const hs_hand_key *previous,
                     hs_hand_key *key) {
	if (node->type != YAML_MAPPING_NODE)
		return fail(p, node, "a hand key must be a mapping like { t: 0, wrist: [x, y, z], posture: open }, got %s",
		            got(node).text);
	fields f;
	if (!read_mapping(p, node, key_keys, K_COUNT, "hand key", &f))
		return false;
	if (!f.value[K_T])
		return fail(p, node, "hand key is missing 't'");
	if (!read_time(p, f.value[K_T], "t", &key->t))
		return false;
	if (previous && !(key->t > previous->t))
		return fail(p, f.value[K_T], "hand keys must go forward in time: t = %s after t = %g", show(f.value[K_T]).text,
		            previous->t);
	if (!exclusive(p, &f, K_WRIST, K_GRIP) || !exclusive(p, &f, K_RPY, K_QUAT) ||
	    !exclusive(p, &f, K_POSTURE, K_SENSORS) || !exclusive(p, &f, K_POSTURE, K_ANGLES) ||
	    !exclusive(p, &f, K_SENSORS, K_ANGLES))
		return false;
	if (!previous && !f.value[K_WRIST] && !f.value[K_GRIP])
		return fail(p, node, "the first hand key needs 'wrist' or 'grip'");
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
	if (f.value[K_RPY]) {
		hs_vec3 rpy;
		if (!read_vec3(p, f.value[K_RPY], "rpy_deg", &rpy))
			return false;
		key->rot = hs_quat_from_rpy(rpy.x * (HS_PI / 180.0), rpy.y * (HS_PI / 180.0), rpy.z * (HS_PI / 180.0));
	}
	if (f.value[K_QUAT]) {
		double q[4];
		if (!read_numbers(p, f.value[K_QUAT], "quat", 4, " [w, x, y, z]", q, NULL))
			return false;
		double norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
		if (!(fabs(norm - 1.0) <= QUAT_NORM_TOLERANCE))
			return fail(p, f.value[K_QUAT], "'quat' must have norm 1 (within %g), got norm %.9g", QUAT_NORM_TOLERANCE, norm);
		key->rot = hs_quat_normalize(hs_q(q[0], q[1], q[2], q[3]));
	}
	if (f.value[K_POSTURE] && !read_posture(p, f.value[K_POSTURE], def, key->sensors))
		return false;
	if (f.value[K_SENSORS] && !read_sensor_list(p, f.value[K_SENSORS], key->sensors))
		return false;
	if (f.value[K_ANGLES] && !read_angle_list(p, f.value[K_ANGLES], key->sensors))
		return false;
	if (f.value[K_WRIST] && !read_vec3(p, f.value[K_WRIST], "wrist", &key->wrist))
		return false;
	if (f.value[K_GRIP]) { // place the wrist so the posture's grip centre lands on this point
		hs_vec3 grip, center, axis;
		if (!read_vec3(p, f.value[K_GRIP], "grip", &grip))
			return false;
		uint8_t sensors[HS_GLOVE_SENSORS];
		for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
			sensors[i] = (uint8_t)lround(key->sensors[i]);
		hs_hand_grip(def, sensors, &center, &axis);
		key->wrist = hs_sub(grip, hs_quat_rotate(key->rot, center));
	}
	return true;
}

enum { H_NAME, H_SIDE, H_FINGER_RADIUS, H_KEYS, H_RECORD, H_COUNT };
static const char *const hand_keys[H_COUNT] = {"name", "side", "finger_radius", "keys", "record"};

// The recorded file's path: relative to the scenario's folder.
static char *sibling_path(const char *scenario_path, const char *file) {
	size_t dir = 0;
	const char *slash = strrchr(scenario_path, '/');
	if (slash && file[0] != '/')
		dir = (size_t)(slash - scenario_path) + 1;
	char *out = malloc(dir + strlen(file) + 1);
	if (out) {
		memcpy(out, scenario_path, dir);
		strcpy(out + dir, file);
	}
	return out;
}

static bool read_hand(parser *p, const yaml_node_t *node, int index, const char *path) {
	hs_scenario *s = p->s;
	if (node->type != YAML_MAPPING_NODE)
		return fail(p, node, "hand %d must be a mapping, got %s", index + 1, got(node).text);
	fields f;
	if (!read_mapping(p, node, hand_keys, H_COUNT, "hand", &f))
		return false;
	if (!f.value[H_NAME])
		return fail(p, node, "hand %d is missing 'name'", index + 1);
	if (!read_text(p, f.value[H_NAME], "name", &s->hand_names[index]))
		return false;
	for (int h = 0; h < index; ++h)
		if (strcmp(s->hand_names[h], s->hand_names[index]) == 0)
			return fail(p, f.value[H_NAME], "duplicate hand name '%s'", s->hand_names[index]);
	hs_hand_def def = hs_default_hand_def();
	if (f.value[H_SIDE]) {
		if (scalar_is(f.value[H_SIDE], "left"))
			def.left = true;
		else if (!scalar_is(f.value[H_SIDE], "right"))
			return fail(p, f.value[H_SIDE], "'side' must be left or right, got %s", got(f.value[H_SIDE]).text);
	}
	if (f.value[H_FINGER_RADIUS]) {
		if (!read_number(p, f.value[H_FINGER_RADIUS], "finger_radius", &def.finger_radius))
			return false;
		if (!(def.finger_radius > 0.0 && def.finger_radius <= 0.05))
			return fail(p, f.value[H_FINGER_RADIUS], "'finger_radius' must be within (0, 0.05] m, got %s",
			            show(f.value[H_FINGER_RADIUS]).text);
	}
	if (!f.value[H_KEYS] && !f.value[H_RECORD])
		return fail(p, node, "hand '%s' needs 'keys' or 'record'", s->hand_names[index]);
	if (f.value[H_KEYS] && f.value[H_RECORD])
		return fail(p, before(f.key[H_KEYS], f.key[H_RECORD]) ? f.key[H_RECORD] : f.key[H_KEYS],
		            "'keys' and 'record' are exclusive: give one");
	hs_hand_script *script = &s->scripts[index];
	if (f.value[H_KEYS]) {
		const yaml_node_t *keys = f.value[H_KEYS];
		if (keys->type != YAML_SEQUENCE_NODE)
			return fail(p, keys, "'keys' must be a list of 1 to %d keys, got %s", MAX_HAND_KEYS, got(keys).text);
		if (sequence_length(keys) < 1 || sequence_length(keys) > MAX_HAND_KEYS)
			return fail(p, keys, "'keys' must be a list of 1 to %d keys, got %ld", MAX_HAND_KEYS, sequence_length(keys));
		script->keys = calloc((size_t)sequence_length(keys), sizeof *script->keys);
		if (!script->keys)
			return fail(p, keys, "out of memory");
		for (long k = 0; k < sequence_length(keys); ++k) {
			if (!read_key(p, sequence_item(p, keys, k), &def, k ? &script->keys[k - 1] : NULL, &script->keys[k]))
				return false;
			script->key_count = (int)k + 1;
		}
	} else {
		char *file = NULL;
		if (!read_text(p, f.value[H_RECORD], "record", &file))
			return false;
		char *full = sibling_path(path, file);
		free(file);
		if (!full)
			return fail(p, f.value[H_RECORD], "out of memory");
		bool ok = hs_record_load(full, full, script, p->err);
		free(full);
		if (!ok)
			return false;
	}
	hs_status status = HS_OK;
	s->hand_ids[index] = hs_world_add_hand(s->world, &def, &status);
	if (s->hand_ids[index].index1 == 0)
		return fail(p, node, "hand '%s': cannot add it to the world: %s", s->hand_names[index], hs_status_string(status));
	return true;
}

static bool read_hands(parser *p, const yaml_node_t *node, const char *path) {
	hs_scenario *s = p->s;
	long n = sequence_length(node);
	s->hand_names = calloc((size_t)n, sizeof *s->hand_names);
	s->hand_ids = calloc((size_t)n, sizeof *s->hand_ids);
	s->scripts = calloc((size_t)n, sizeof *s->scripts);
	if (!s->hand_names || !s->hand_ids || !s->scripts)
		return fail(p, node, "out of memory");
	s->hand_count = (int)n;
	for (int h = 0; h < s->hand_count; ++h)
		if (!read_hand(p, sequence_item(p, node, h), h, path))
			return false;
	return true;
}

// Index of the object named by a scalar, or -1.
static int find_object(const parser *p, const yaml_node_t *node) {
	size_t n = node->data.scalar.length;
	if (n > MAX_NAME || memchr(scalar(node), '\0', n))
		return -1;
	name_entry key = {scalar(node), -1};
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

enum { E_OBJECT = PRED_COUNT, E_AT, E_TOLERANCE, E_AXES, E_FROM, E_COUNT };
static const char *const expect_keys[E_COUNT] = {
    "near", "resting", "floor_contacts", "on_face", "below", "above", "moved", "turned_deg",
    "lands_at", "still", "contact_sequence", "object", "at", "tolerance", "axes", "from",
};

static bool read_clause(parser *p, const yaml_node_t *node, clause *c) {
	hs_scenario *s = p->s;
	if (node->type != YAML_MAPPING_NODE)
		return fail(p, node, "each expect clause must be a mapping, got %s", got(node).text);
	fields f;
	if (!read_mapping(p, node, expect_keys, E_COUNT, "expect clause", &f))
		return false;
	memset(c, 0, sizeof *c);
	c->line = line_of(node);
	const yaml_node_t *obj = f.value[E_OBJECT];
	if (!obj)
		return fail(p, node, "expect clause is missing 'object'");
	if (scalar_is(obj, "*"))
		c->object = -1;
	else if (!is_scalar(obj))
		return fail(p, obj, "'object' must be an object name or \"*\", got %s", got(obj).text);
	else if ((c->object = find_object(p, obj)) < 0)
		return fail(p, obj, "unknown object '%s' in expect", show(obj).text);
	int pred = -1;
	for (int i = 0; i < PRED_COUNT; ++i) {
		if (!f.key[i])
			continue;
		if (pred >= 0) { // named in file order, reported at the second
			int a = before(f.key[pred], f.key[i]) ? pred : i, b = a == pred ? i : pred;
			return fail(p, f.key[b], "expect clause has two predicates, '%s' and '%s': give one per clause",
			            predicate_names[a], predicate_names[b]);
		}
		pred = i;
	}
	if (pred < 0)
		return fail(p, node,
		            "expect clause needs a predicate: near, resting, floor_contacts, on_face, below, above, moved, "
		            "turned_deg, lands_at, still or contact_sequence");
	c->pred = (predicate)pred;
	const char *pn = predicate_names[pred];
	const yaml_node_t *v = f.value[pred];
	// modifiers belong to particular predicates
	if (f.key[E_AT] && !predicate_uses_at(c->pred))
		return fail(p, f.key[E_AT], "'at' is not used by '%s'", pn);
	if (f.key[E_TOLERANCE] && c->pred != PRED_NEAR && c->pred != PRED_LANDS_AT)
		return fail(p, f.key[E_TOLERANCE], "'tolerance' is not used by '%s'", pn);
	if (f.key[E_AXES] && c->pred != PRED_NEAR)
		return fail(p, f.key[E_AXES], "'axes' is only for 'near'");
	if (f.key[E_FROM] && c->pred != PRED_STILL)
		return fail(p, f.key[E_FROM], "'from' is only for 'still'");
	if (predicate_uses_at(c->pred)) {
		const yaml_node_t *at = f.value[E_AT];
		if (!at)
			return fail(p, node, "expect clause '%s' is missing 'at' (end or a time in s)", pn);
		double t = 0.0;
		if (scalar_is(at, "end")) {
			c->at_end = true;
			c->frame = s->frames;
		} else if (!is_scalar(at) || parse_number_text(scalar(at), at->data.scalar.length, &t) != NUMBER_OK) {
			return fail(p, at, "'at' must be 'end' or a time in s, got %s", got(at).text);
		} else if (t < 0.0 || t > s->duration) {
			return fail(p, at, "'at' must be 'end' or a time within [0, %g] s, got %s", s->duration, show(at).text);
		} else {
			c->frame = llround(t / s->dt);
		}
	}
	if (c->pred == PRED_NEAR || c->pred == PRED_LANDS_AT) {
		const yaml_node_t *tol = f.value[E_TOLERANCE];
		if (!tol)
			return fail(p, node, "expect clause '%s' is missing 'tolerance' (%s)", pn, c->pred == PRED_NEAR ? "m" : "s");
		if (!read_number(p, tol, "tolerance", &c->tolerance))
			return false;
		if (!(c->tolerance > 0.0))
			return fail(p, tol, "'tolerance' must be > 0, got %s", show(tol).text);
	}
	switch (c->pred) {
	case PRED_NEAR: {
		if (!read_vec3(p, v, "near", &c->target))
			return false;
		c->axes = 7;
		const yaml_node_t *axes = f.value[E_AXES];
		if (axes) {
			c->axes = 0;
			bool ok = is_scalar(axes) && axes->data.scalar.length > 0 && axes->data.scalar.length <= 3;
			for (size_t i = 0; ok && i < axes->data.scalar.length; ++i) {
				char a = scalar(axes)[i];
				unsigned bit = a == 'x' ? 1u : a == 'y' ? 2u : a == 'z' ? 4u : 0u;
				ok = bit != 0 && !(c->axes & bit);
				c->axes |= bit;
			}
			if (!ok)
				return fail(p, axes, "'axes' must be distinct letters from \"xyz\", got %s", got(axes).text);
		}
		break;
	}
	case PRED_RESTING:
	case PRED_ON_FACE:
	case PRED_STILL:
		if (!read_bool(p, v, pn, &c->flag))
			return false;
		break;
	case PRED_FLOOR_CONTACTS:
		if (!read_integer(p, v, pn, 0, INT_MAX, &c->count))
			return false;
		break;
	case PRED_BELOW:
	case PRED_ABOVE:
		if (!read_number(p, v, pn, &c->value))
			return false;
		break;
	case PRED_MOVED:
	case PRED_TURNED:
		if (!read_number(p, v, pn, &c->value))
			return false;
		if (!(c->value >= 0.0))
			return fail(p, v, "'%s' must be >= 0, got %s", pn, show(v).text);
		break;
	case PRED_LANDS_AT:
		if (!read_time(p, v, pn, &c->value))
			return false;
		break;
	case PRED_CONTACT_SEQUENCE: {
		if (v->type != YAML_SEQUENCE_NODE || sequence_length(v) < 1 || sequence_length(v) > SEQ_CAPACITY)
			return fail(p, v, "'contact_sequence' must be a list of 1 to %d contact states (0-3), got %s", SEQ_CAPACITY,
			            v->type == YAML_SEQUENCE_NODE ? "another count" : got(v).text);
		c->seq_len = (int)sequence_length(v);
		for (int i = 0; i < c->seq_len; ++i) {
			long state;
			const yaml_node_t *e = sequence_item(p, v, i);
			if (!read_integer(p, e, pn, 0, 3, &state))
				return false;
			c->seq[i] = (unsigned char)state;
			if (i > 0 && c->seq[i] == c->seq[i - 1]) // repeats are collapsed when recorded
				return fail(p, e, "'contact_sequence' has %ld twice in a row; repeats are collapsed, write it once", state);
		}
		break;
	}
	default:
		break;
	}
	if (c->pred == PRED_STILL && f.value[E_FROM]) {
		double from;
		if (!read_time(p, f.value[E_FROM], "from", &from))
			return false;
		c->frame = llround(from / s->dt);
	}
	return true;
}

static int compare_capture(const void *a, const void *b, const hs_scenario *s) {
	int x = *(const int *)a, y = *(const int *)b;
	long fx = s->clauses[s->checks[x].clause].frame, fy = s->clauses[s->checks[y].clause].frame;
	if (fx != fy)
		return fx < fy ? -1 : 1;
	return (x > y) - (x < y);
}

// C11's qsort takes no context to reach the clauses: a small merge sort by (frame, check index)
static void sort_captures(int *a, int *tmp, int n, const hs_scenario *s) {
	if (n < 2)
		return;
	int h = n / 2;
	sort_captures(a, tmp, h, s);
	sort_captures(a + h, tmp, n - h, s);
	int i = 0, j = h, k = 0;
	while (i < h && j < n)
		tmp[k++] = compare_capture(&a[j], &a[i], s) < 0 ? a[j++] : a[i++];
	while (i < h)
		tmp[k++] = a[i++];
	while (j < n)
		tmp[k++] = a[j++];
	memcpy(a, tmp, (size_t)n * sizeof *a);
}

static bool read_expect(parser *p, const yaml_node_t *node) {
	hs_scenario *s = p->s;
	if (node->type != YAML_SEQUENCE_NODE)
		return fail(p, node, "'expect' must be a list of clauses, got %s", got(node).text);
	long n = sequence_length(node);
	if (n > MAX_CLAUSES)
		return fail(p, node, "'expect' has %ld clauses; at most %d are allowed", n, MAX_CLAUSES);
	if (n == 0)
		return true;
	s->clauses = calloc((size_t)n, sizeof *s->clauses);
	if (!s->clauses)
		return fail(p, node, "out of memory");
	long checks = 0;
	bool ok = true;
	for (long i = 0; ok && i < n; ++i) {
		const yaml_node_t *item = sequence_item(p, node, i);
		ok = read_clause(p, item, &s->clauses[i]);
		s->clause_count = (int)i + (ok ? 1 : 0);
		if (ok)
			checks += s->clauses[i].object < 0 ? s->object_count : 1;
		if (ok && checks > MAX_CHECKS)
			ok = fail(p, item, "expect clauses check more than %d object states in all", MAX_CHECKS);
	}
	return ok;
}

// Allocates everything the run records, so that hs_scenario_step never allocates.
static bool prepare_records(parser *p, const yaml_node_t *root) {
	hs_scenario *s = p->s;
	long checks = 0;
	bool landing = false, sequences = false;
	for (int i = 0; i < s->clause_count; ++i) {
		checks += s->clauses[i].object < 0 ? s->object_count : 1;
		landing = landing || s->clauses[i].pred == PRED_LANDS_AT;
		sequences = sequences || s->clauses[i].pred == PRED_CONTACT_SEQUENCE;
	}
	size_t n = (size_t)s->object_count, nc = (size_t)checks;
	if (checks > 0) {
		s->checks = calloc(nc, sizeof *s->checks);
		s->capture_order = malloc(nc * sizeof *s->capture_order);
		s->still_checks = malloc(nc * sizeof *s->still_checks);
		if (!s->checks || !s->capture_order || !s->still_checks)
			return fail(p, root, "out of memory");
	}
	if (landing) {
		s->landed_frame = malloc(n * sizeof *s->landed_frame);
		s->had_no_floor = calloc(n, sizeof *s->had_no_floor);
		if (!s->landed_frame || !s->had_no_floor)
			return fail(p, root, "out of memory");
		for (size_t i = 0; i < n; ++i)
			s->landed_frame[i] = -1;
	}
	if (sequences) {
		s->seq = calloc(n * SEQ_CAPACITY, 1);
		s->seq_len = calloc(n, sizeof *s->seq_len);
		s->seq_overflow = calloc(n, sizeof *s->seq_overflow);
		s->seq_last = calloc(n, 1);
		if (!s->seq || !s->seq_len || !s->seq_overflow || !s->seq_last)
			return fail(p, root, "out of memory");
	}
	for (int i = 0; i < s->clause_count; ++i) {
		const clause *c = &s->clauses[i];
		int first = c->object < 0 ? 0 : c->object, last = c->object < 0 ? s->object_count - 1 : c->object;
		for (int o = first; o <= last; ++o) {
			int k = s->check_count++;
			s->checks[k].clause = i;
			s->checks[k].object = o;
			s->checks[k].moved_frame = -1;
			if (predicate_uses_at(c->pred))
				s->capture_order[s->capture_count++] = k;
			else if (c->pred == PRED_STILL)
				s->still_checks[s->still_count++] = k;
		}
	}
	if (s->capture_count > 1) {
		int *tmp = malloc((size_t)s->capture_count * sizeof *tmp);
		if (!tmp)
			return fail(p, root, "out of memory");
		sort_captures(s->capture_order, tmp, s->capture_count, s);
		free(tmp);
	}
	return true;
}

static bool same_pose(const hs_object_state *a, const hs_object_state *b) {
	double x[7] = {a->position.x, a->position.y, a->position.z, a->orientation.w, a->orientation.x, a->orientation.y, a->orientation.z};
	double y[7] = {b->position.x, b->position.y, b->position.z, b->orientation.w, b->orientation.x, b->orientation.y, b->orientation.z};
	return memcmp(x, y, sizeof x) == 0; // the exact bits: "still" means not one ulp of motion
}

static hs_object_state state_of(const hs_scenario *s, int object) {
	hs_object_state st;
	memset(&st, 0, sizeof st);
	hs_world_object_state(s->world, s->ids[object], &st);
	return st;
}

// Records what the expectations need from the current frame. Never allocates.
static void record(hs_scenario *s) {
	long f = s->frame;
	while (s->capture_next < s->capture_count) {
		check *c = &s->checks[s->capture_order[s->capture_next]];
		if (s->clauses[c->clause].frame > f)
			break;
		c->state = state_of(s, c->object);
		c->captured = true;
		s->capture_next++;
	}
	for (int i = 0; i < s->still_count; ++i) {
		check *c = &s->checks[s->still_checks[i]];
		long from = s->clauses[c->clause].frame;
		if (f < from || c->moved)
			continue;
		hs_object_state st = state_of(s, c->object);
		if (f == from) {
			c->state = st;
			c->captured = true;
		} else if (!same_pose(&c->state, &st)) {
			c->moved = true;
			c->moved_frame = f;
		}
	}
	if (!s->landed_frame && !s->seq)
		return;
	for (int o = 0; o < s->object_count; ++o) {
		hs_object_state st = state_of(s, o);
		if (s->landed_frame && s->landed_frame[o] < 0) {
			if (st.floor_contacts == 0)
				s->had_no_floor[o] = true;
			else if (s->had_no_floor[o])
				s->landed_frame[o] = f;
		}
		if (s->seq) {
			unsigned char state = (unsigned char)st.contact;
			if (s->seq_len[o] > 0 && s->seq_last[o] == state)
				continue;
			s->seq_last[o] = state;
			if (s->seq_len[o] < SEQ_CAPACITY)
				s->seq[(size_t)o * SEQ_CAPACITY + (size_t)s->seq_len[o]++] = state;
			else
				s->seq_overflow[o]++;
		}
	}
}

// ---------------------------------------------------------------------------------------------
// public: load, destroy, step

static bool read_scenario(parser *p, const yaml_node_t *root, const char *path) {
	static const char *const keys[] = {"name",    "description", "dt",     "duration", "gravity",
	                                   "model",   "objects",     "expect", "hands"};
	hs_scenario *s = p->s;
	if (root->type != YAML_MAPPING_NODE)
		return fail(p, root, "a scenario must be a mapping of keys (description, dt, duration, objects, ...), got %s",
		            got(root).text);
	fields f;
	if (!read_mapping(p, root, keys, 9, "scenario", &f))
		return false;
	size_t base_len;
	const char *base = base_name(path, &base_len);
	if (f.value[0]) {
		char *name = NULL;
		if (!read_text(p, f.value[0], "name", &name))
			return false;
		bool same = strlen(name) == base_len && memcmp(name, base, base_len) == 0;
		free(name);
		if (!same)
			return fail(p, f.value[0], "'name' is '%s' but the file is '%.*s.yaml': they must agree", show(f.value[0]).text,
			            (int)base_len, base);
	}
	s->name = malloc(base_len + 1);
	if (!s->name)
		return fail(p, root, "out of memory");
	memcpy(s->name, base, base_len);
	s->name[base_len] = '\0';
	for (int i = 1; i <= 3; ++i)
		if (!f.value[i])
			return fail(p, root, "scenario is missing '%s'", keys[i]);
	if (!f.value[6])
		return fail(p, root, "scenario is missing 'objects'");
	if (!read_text(p, f.value[1], "description", &s->description) || !read_dt(p, f.value[2]) ||
	    !read_duration(p, f.value[3]))
		return false;
	hs_world_def def = hs_default_world_def();
	def.dt = s->dt;
	if (f.value[4] && !read_vec3(p, f.value[4], "gravity", &def.gravity))
		return false;
	if (f.value[5] && !read_model(p, f.value[5], &def))
		return false;
	if (f.value[8]) {
		if (f.value[8]->type != YAML_SEQUENCE_NODE)
			return fail(p, f.value[8], "'hands' must be a list of 1 to %d hands, got %s", MAX_HANDS, got(f.value[8]).text);
		if (sequence_length(f.value[8]) < 1 || sequence_length(f.value[8]) > MAX_HANDS)
			return fail(p, f.value[8], "'hands' must be a list of 1 to %d hands, got %ld", MAX_HANDS,
			            sequence_length(f.value[8]));
		def.max_hands = (int)sequence_length(f.value[8]);
	}
	if (!read_objects(p, f.value[6], def))
		return false;
	if (f.value[8] && !read_hands(p, f.value[8], path))
		return false;
	if (f.value[7] && !read_expect(p, f.value[7]))
		return false;
	return prepare_records(p, root);
}

hs_scenario *hs_scenario_load(const char *path, hs_error *err) {
	hs_error scratch;
	if (!err)
		err = &scratch;
	err->message[0] = '\0';
	if (!path) {
		set_error(err, "(null)", 1, "cannot read: no file given");
		return NULL;
	}
	char *text = NULL;
	size_t size = 0;
	if (!read_file(path, &text, &size, err))
		return NULL;
	const char *nul = memchr(text, '\0', size);
	if (nul) { // libyaml would stop or complain at a NUL; say plainly what is wrong
		set_error(err, path, line_at_offset(text, size, (size_t)(nul - text)), "not a text file (NUL byte at byte %zu)",
		          (size_t)(nul - text));
		free(text);
		return NULL;
	}
	yaml_parser_t yp;
	yaml_document_t doc, extra;
	memset(&doc, 0, sizeof doc);
	memset(&extra, 0, sizeof extra);
	if (!yaml_parser_initialize(&yp)) {
		set_error(err, path, 1, "out of memory");
		free(text);
		return NULL;
	}
	yaml_parser_set_input_string(&yp, (const unsigned char *)text, size);
	hs_scenario *s = NULL;
	bool ok = yaml_parser_load(&yp, &doc) != 0;
	if (!ok)
		yaml_failure(&yp, path, text, size, err);
	const yaml_node_t *root = ok ? yaml_document_get_root_node(&doc) : NULL;
	if (ok && !root)
		ok = set_error(err, path, 1, "empty file: a scenario needs description, dt, duration and objects");
	if (ok) { // a second document would be silently ignored: refuse it
		if (!yaml_parser_load(&yp, &extra))
			ok = yaml_failure(&yp, path, text, size, err);
		else if (yaml_document_get_root_node(&extra))
			ok = set_error(err, path, line_of(yaml_document_get_root_node(&extra)),
			               "only one YAML document is allowed per scenario file");
	}
	if (ok) {
		s = calloc(1, sizeof *s);
		if (!s)
			ok = set_error(err, path, 1, "out of memory");
	}
	if (ok) {
		parser p = {path, &doc, err, s, NULL};
		ok = read_scenario(&p, root, path);
		free(p.sorted);
	}
	yaml_document_delete(&extra);
	yaml_document_delete(&doc);
	yaml_parser_delete(&yp);
	free(text);
	if (!ok) {
		hs_scenario_destroy(s);
		return NULL;
	}
	drive_hands(s, 0.0); // the hands' first pose: no motion before frame 1
	s->initial = calloc((size_t)s->object_count, sizeof *s->initial);
	if (!s->initial) {
		set_error(err, path, 1, "out of memory");
		hs_scenario_destroy(s);
		return NULL;
	}
	for (int i = 0; i < s->object_count; ++i)
		s->initial[i] = state_of(s, i);
	record(s); // frame 0: the initial state
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
	free(s->clauses);
	free(s->checks);
	free(s->capture_order);
	free(s->still_checks);
	free(s->landed_frame);
	free(s->had_no_floor);
	free(s->seq);
	free(s->seq_len);
	free(s->seq_overflow);
	free(s->seq_last);
	for (int h = 0; h < s->hand_count; ++h) {
		free(s->hand_names ? s->hand_names[h] : NULL);
		free(s->scripts ? s->scripts[h].keys : NULL);
	}
	free(s->initial);
	free(s->hand_names);
	free(s->hand_ids);
	free(s->scripts);
	free(s);
}

const char *hs_scenario_name(const hs_scenario *s) { return s ? s->name : NULL; }
const char *hs_scenario_description(const hs_scenario *s) { return s ? s->description : NULL; }
hs_world *hs_scenario_world(hs_scenario *s) { return s ? s->world : NULL; }
long hs_scenario_frame_count(const hs_scenario *s) { return s ? s->frames : 0; }
double hs_scenario_dt(const hs_scenario *s) { return s ? s->dt : 0.0; }
int hs_scenario_object_count(const hs_scenario *s) { return s ? s->object_count : 0; }

const char *hs_scenario_object_name(const hs_scenario *s, int i) {
	return s && i >= 0 && i < s->object_count ? s->object_names[i] : NULL;
}

int hs_scenario_expectation_count(const hs_scenario *s) {
	return s ? s->check_count + (s->step_status != HS_OK) : 0;
}

bool hs_scenario_step(hs_scenario *s) {
	if (!s || s->frame >= s->frames || s->step_status != HS_OK)
		return false;
	drive_hands(s, (double)(s->frame + 1) * s->dt);
	hs_status status = hs_world_step(s->world);
	if (status != HS_OK) { // reported by hs_scenario_check as a failure
		s->step_status = status;
		s->failed_frame = s->frame + 1;
		return false;
	}
	s->frame++;
	record(s);
	return true;
}

// ---------------------------------------------------------------------------------------------
// check

static void describe_time(char *buf, size_t n, const hs_scenario *s, const clause *c) {
	if (c->at_end)
		snprintf(buf, n, "at end (t = %g s)", (double)s->frames * s->dt);
	else
		snprintf(buf, n, "at t = %g s", (double)c->frame * s->dt);
}

// Evaluates one check; writes what was expected into `what` and what was measured into `measured`.
static bool evaluate(const hs_scenario *s, const check *k, char *what, size_t wn, char *measured, size_t mn) {
	const clause *c = &s->clauses[k->clause];
	const hs_object_state *st = &k->state;
	char when[64] = "";
	if (predicate_uses_at(c->pred)) {
		describe_time(when, sizeof when, s, c);
		if (!k->captured) {
			snprintf(what, wn, "%s %s", predicate_names[c->pred], when);
			snprintf(measured, mn, "not reached: the run stopped at frame %ld of %ld", s->frame, s->frames);
			return false;
		}
	}
	switch (c->pred) {
	case PRED_NEAR: {
		static const char *const axes_text[8] = {"", "x", "y", "xy", "z", "xz", "yz", "xyz"};
		double dx = st->position.x - c->target.x, dy = st->position.y - c->target.y, dz = st->position.z - c->target.z;
		double d2 = ((c->axes & 1) ? dx * dx : 0.0) + ((c->axes & 2) ? dy * dy : 0.0) + ((c->axes & 4) ? dz * dz : 0.0);
		double d = sqrt(d2);
		snprintf(what, wn, "near [%.9g, %.9g, %.9g] within %g m%s%s %s", c->target.x, c->target.y, c->target.z, c->tolerance,
		         c->axes == 7 ? "" : " on ", c->axes == 7 ? "" : axes_text[c->axes], when);
		snprintf(measured, mn, "distance %.6g m (at [%.9g, %.9g, %.9g])", d, st->position.x, st->position.y, st->position.z);
		return d <= c->tolerance;
	}
	case PRED_RESTING:
		snprintf(what, wn, "resting %s %s", c->flag ? "true" : "false", when);
		snprintf(measured, mn, "resting %s", st->resting ? "true" : "false");
		return st->resting == c->flag;
	case PRED_FLOOR_CONTACTS:
		snprintf(what, wn, "floor_contacts %ld %s", c->count, when);
		snprintf(measured, mn, "floor_contacts %d", st->floor_contacts);
		return st->floor_contacts == c->count;
	case PRED_ON_FACE:
		snprintf(what, wn, "on_face %s %s", c->flag ? "true" : "false", when);
		snprintf(measured, mn, "floor_contacts %d", st->floor_contacts);
		return (st->floor_contacts >= 3) == c->flag;
	case PRED_BELOW:
	case PRED_ABOVE:
		snprintf(what, wn, "%s %.9g m %s", predicate_names[c->pred], c->value, when);
		snprintf(measured, mn, "z %.9g m", st->position.z);
		return c->pred == PRED_BELOW ? st->position.z < c->value : st->position.z > c->value;
	case PRED_MOVED: { // at least this far (m) from where it started
		double d = hs_distance(st->position, s->initial[k->object].position);
		snprintf(what, wn, "moved at least %.9g m %s", c->value, when);
		snprintf(measured, mn, "moved %.6g m", d);
		return d >= c->value;
	}
	case PRED_TURNED: { // turned at least this much (deg) from how it started
		hs_quat rel = hs_quat_mul(st->orientation, hs_quat_conj(s->initial[k->object].orientation));
		double a = hs_quat_angle(rel) * (180.0 / HS_PI);
		snprintf(what, wn, "turned at least %.9g deg %s", c->value, when);
		snprintf(measured, mn, "turned %.6g deg", a);
		return a >= c->value;
	}
	case PRED_LANDS_AT: {
		snprintf(what, wn, "lands at t = %g s within %g s", c->value, c->tolerance);
		long f = s->landed_frame[k->object];
		if (f < 0) {
			snprintf(measured, mn, "%s", s->had_no_floor[k->object] ? "never landed" : "never left the floor");
			return false;
		}
		double t = (double)f * s->dt;
		snprintf(measured, mn, "landed at t = %.6g s (frame %ld)", t, f);
		return fabs(t - c->value) <= c->tolerance;
	}
	case PRED_STILL: {
		double from = (double)c->frame * s->dt;
		snprintf(what, wn, "still %s from t = %g s", c->flag ? "true" : "false", from);
		if (!k->captured) {
			snprintf(measured, mn, "not reached: the run stopped at frame %ld of %ld", s->frame, s->frames);
			return false;
		}
		if (k->moved)
			snprintf(measured, mn, "moved at frame %ld (t = %.6g s)", k->moved_frame, (double)k->moved_frame * s->dt);
		else
			snprintf(measured, mn, "unchanged");
		return k->moved != c->flag;
	}
	case PRED_CONTACT_SEQUENCE: {
		size_t w = (size_t)snprintf(what, wn, "contact_sequence [");
		for (int i = 0; i < c->seq_len && w < wn; ++i)
			w += (size_t)snprintf(what + w, wn - w, "%s%d", i ? ", " : "", c->seq[i]);
		if (w < wn)
			snprintf(what + w, wn - w, "]");
		const unsigned char *q = s->seq + (size_t)k->object * SEQ_CAPACITY;
		int n = s->seq_len[k->object];
		long overflow = s->seq_overflow[k->object];
		size_t m = (size_t)snprintf(measured, mn, "[");
		for (int i = 0; i < n && m < mn; ++i)
			m += (size_t)snprintf(measured + m, mn - m, "%s%d", i ? ", " : "", q[i]);
		if (m < mn)
			snprintf(measured + m, mn - m, overflow ? ", ...] (%ld more changes than the %d recorded)" : "]", overflow,
			         SEQ_CAPACITY);
		if (overflow || n != c->seq_len)
			return false;
		return memcmp(q, c->seq, (size_t)n) == 0;
	}
	default:
		break;
	}
	return false;
}

int hs_scenario_check(const hs_scenario *s, FILE *report) {
	if (!s)
		return 0;
	int failed = 0;
	for (int i = 0; i < s->check_count; ++i) {
		const check *k = &s->checks[i];
		char what[640], measured[640];
		bool pass = evaluate(s, k, what, sizeof what, measured, sizeof measured);
		failed += !pass;
		if (report)
			fprintf(report, "%s  line %lu: %s %s: %s\n", pass ? "PASS" : "FAIL", s->clauses[k->clause].line,
			        s->object_names[k->object], what, measured);
	}
	if (s->step_status != HS_OK) {
		failed++;
		if (report)
			fprintf(report, "FAIL  the world failed to step at frame %ld: %s\n", s->failed_frame,
			        hs_status_string(s->step_status));
	}
	return failed;
}

// ---------------------------------------------------------------------------------------------
// catalog

typedef struct catalog_entry {
	char *name, *path;
} catalog_entry;

typedef struct catalog_builder {
	catalog_entry *entries;
	int count, capacity;
	hs_error *err;
} catalog_builder;

static char *join(const char *a, const char *b) {
	size_t na = strlen(a), nb = strlen(b);
	size_t slash = na > 0 && a[na - 1] != '/';
	char *r = malloc(na + slash + nb + 1);
	if (r) {
		memcpy(r, a, na);
		if (slash)
			r[na] = '/';
		memcpy(r + na + slash, b, nb + 1);
	}
	return r;
}

static bool catalog_add(catalog_builder *b, const char *rel, const char *path) {
	if (b->count == b->capacity) {
		int cap = b->capacity ? b->capacity * 2 : 16;
		catalog_entry *bigger = realloc(b->entries, (size_t)cap * sizeof *bigger);
		if (!bigger)
			return false;
		b->entries = bigger;
		b->capacity = cap;
	}
	size_t n = strlen(rel) - 5; // without ".yaml"
	char *name = malloc(n + 1), *copy = malloc(strlen(path) + 1);
	if (!name || !copy) {
		free(name);
		free(copy);
		return false;
	}
	memcpy(name, rel, n);
	name[n] = '\0';
	strcpy(copy, path);
	b->entries[b->count++] = (catalog_entry){name, copy};
	return true;
}

static bool catalog_walk(catalog_builder *b, const char *dir, const char *rel, int depth) {
	DIR *d = opendir(dir);
	if (!d) {
		snprintf(b->err->message, sizeof b->err->message, "%s: cannot read: %s", dir, strerror(errno));
		return false;
	}
	bool ok = true;
	struct dirent *e;
	while (ok && (e = readdir(d)) != NULL) {
		if (e->d_name[0] == '.') // hidden files, editors' files, "." and ".."
			continue;
		char *path = join(dir, e->d_name);
		char *sub = join(rel, e->d_name);
		struct stat st;
		if (!path || !sub) {
			snprintf(b->err->message, sizeof b->err->message, "%s: out of memory", dir);
			ok = false;
		} else if (stat(path, &st) != 0) {
			snprintf(b->err->message, sizeof b->err->message, "%s: cannot read: %s", path, strerror(errno));
			ok = false;
		} else if (S_ISDIR(st.st_mode)) {
			if (depth >= MAX_CATALOG_DEPTH) { // also stops a symbolic link loop
				snprintf(b->err->message, sizeof b->err->message, "%s: folders nested deeper than %d", path,
				         MAX_CATALOG_DEPTH);
				ok = false;
			} else {
				ok = catalog_walk(b, path, sub, depth + 1);
			}
		} else if (S_ISREG(st.st_mode)) {
			size_t n = strlen(e->d_name);
			if (n > 5 && strcmp(e->d_name + n - 5, ".yaml") == 0 && !catalog_add(b, sub, path)) {
				snprintf(b->err->message, sizeof b->err->message, "%s: out of memory", dir);
				ok = false;
			}
		}
		free(path);
		free(sub);
	}
	closedir(d);
	return ok;
}

static int compare_entries(const void *a, const void *b) {
	return strcmp(((const catalog_entry *)a)->name, ((const catalog_entry *)b)->name);
}

bool hs_catalog_load(const char *dir, hs_catalog *out, hs_error *err) {
	hs_error scratch;
	if (!err)
		err = &scratch;
	err->message[0] = '\0';
	if (!out)
		return false;
	memset(out, 0, sizeof *out);
	if (!dir) {
		snprintf(err->message, sizeof err->message, "(null): cannot read: no folder given");
		return false;
	}
	catalog_builder b = {NULL, 0, 0, err};
	bool ok = catalog_walk(&b, dir, "", 0);
	// readdir's order is the file system's: sort by name
	if (ok && b.count > 0) {
		qsort(b.entries, (size_t)b.count, sizeof *b.entries, compare_entries);
		out->names = malloc((size_t)b.count * sizeof *out->names);
		out->paths = malloc((size_t)b.count * sizeof *out->paths);
		ok = out->names && out->paths;
		if (!ok)
			snprintf(err->message, sizeof err->message, "%s: out of memory", dir);
	}
	for (int i = 0; i < b.count; ++i) {
		if (ok) {
			out->names[i] = b.entries[i].name;
			out->paths[i] = b.entries[i].path;
		} else {
			free(b.entries[i].name);
			free(b.entries[i].path);
		}
	}
	free(b.entries);
	if (!ok) {
		free(out->names);
		free(out->paths);
		memset(out, 0, sizeof *out);
		return false;
	}
	out->count = b.count;
	return true;
}

void hs_catalog_free(hs_catalog *catalog) {
	if (!catalog)
		return;
	for (int i = 0; i < catalog->count; ++i) {
		free(catalog->names[i]);
		free(catalog->paths[i]);
	}
	free(catalog->names);
	free(catalog->paths);
	memset(catalog, 0, sizeof *catalog);
}
