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

#include "harness_internal.h"


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
	PRED_TURNED,
	PRED_SPEED_BELOW,
	PRED_VELOCITY,
	PRED_ATTACHED,        // spring worlds
	PRED_CANDIDATE,       // spring worlds
	PRED_EXTENSION_RATIO, // spring worlds; the predicates up to here take `at`
	PRED_LANDS_AT,
	PRED_STILL,
	PRED_CONTACT_SEQUENCE,
	PRED_RELEASED,        // spring worlds from here on
	PRED_REST_LENGTH,
	PRED_STIFFNESS,
	PRED_CONSERVED,       // a window [from, to] over a group of objects
	PRED_SWING_BELOW,     // a window [from, to]
	PRED_COUNT
} predicate;

static const char *const predicate_names[PRED_COUNT] = {
    "near",        "resting",  "floor_contacts", "on_face",   "below",           "above",
    "moved",       "turned_deg", "speed_below",  "velocity",  "attached",        "candidate",
    "extension_ratio", "lands_at", "still",      "contact_sequence", "released", "rest_length",
    "stiffness",   "conserved", "swing_below",
};

static bool predicate_uses_at(predicate p) { return p <= PRED_EXTENSION_RATIO; }
// the predicates that only a spring world (a scenario with a stylus) can answer
static bool predicate_needs_springs(predicate p) {
	return p == PRED_ATTACHED || p == PRED_CANDIDATE || p == PRED_EXTENSION_RATIO || p >= PRED_RELEASED;
}
// the predicates watched over a window of frames [from, to]
static bool predicate_uses_window(predicate p) { return p == PRED_CONSERVED || p == PRED_SWING_BELOW; }

typedef enum conserved_quantity { CONSERVE_MOMENTUM, CONSERVE_ENERGY } conserved_quantity;

// One `expect` clause as written.
typedef struct clause {
	unsigned long line;
	int object; // index, or -1 for "*"
	predicate pred;
	bool at_end;
	long frame;       // at-based: the frame whose state is checked; still and windows: the first frame watched
	long last_frame;  // still and windows: the last frame watched
	hs_vec3 target;   // near: m; velocity: m/s
	double tolerance; // near, rest_length: m; lands_at: s; velocity: m/s; stiffness: N/m; extension_ratio, conserved: 1
	unsigned axes;    // near: bit 0 x, bit 1 y, bit 2 z
	bool flag;        // resting, on_face, still, attached
	long count;       // floor_contacts; attached: an hs_attach_kind (NONE: any); released: an hs_release_kind;
	                  // conserved: a conserved_quantity
	double value;     // below/above/moved/swing_below: m; turned_deg: deg; lands_at: s; speed_below: m/s; ...
	int seq_len;      // contact_sequence
	unsigned char seq[SEQ_CAPACITY];
	int first_member, member_count; // conserved: the group's objects in hs_scenario.members
	bool all_objects;                // conserved: the group is every object ("*")
} clause;

// One clause applied to one object: the unit that passes or fails.
typedef struct check {
	int clause, object; // object -1: the clause's group (conserved)
	bool captured; // at-based: `state` holds the state at the clause's frame; still: the reference pose;
	               // windows: the last frame of the window has been seen
	bool moved;    // still: the pose changed after the reference
	long moved_frame;
	hs_object_state state;
	// at-based, captured with `state`: the object's velocity (spring worlds: the integrated one) and
	// the spring (spring worlds only)
	hs_vec3 velocity;      // m/s
	int holder;            // object on the spring, -1 when none
	int candidate;         // the 'I want this one' candidate, -1 when none
	hs_attach_kind kind;   // how the holder got there
	double ratio;          // the holder's spring extension / x0
	double extension, rest_length; // m
	// windows
	bool began;              // the first frame of the window has been seen
	double before[3], after[3]; // conserved: momentum (kg m/s) or energy (J, in before[0]) at from and to
	double peak;             // swing_below: the largest horizontal stylus–G distance so far, m
	long peak_frame;
} check;

// One stylus key (keyframes) or sample (recorded file): the spring model's input (workbench §5.1).
typedef struct stylus_key {
	double t;         // s
	hs_vec3 position; // m
	hs_quat rot;
	bool button;
} stylus_key;

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
	// the stylus of a spring world (workbench paper §3–§5): keys or recorded samples, sampled every frame
	bool springs;       // the scenario has a stylus: hs_world_enable_springs was called
	hs_vec3 gravity;    // m/s²: the potential energy of `conserved: energy`
	int stylus_count;
	stylus_key *stylus; // strictly increasing t
	// expectations of spring worlds, allocated only when a clause needs them
	int member_total;
	int *members;          // conserved: the objects of every group, clause by clause
	int window_count;
	int *window_checks;    // conserved, swing_below
	hs_release *releases;  // released: per object, its last release (kind NONE: never released)
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
	hs_spring_def spring;           // model.spring, read before the world exists
	const yaml_node_t *spring_key;  // where model.spring was given (NULL: not given)
} parser;

static void vset_error(hs_error *err, const char *path, unsigned long line, const char *fmt, va_list ap) {
	char shown[HS_SHOWN_PATH + 4];
	int n = snprintf(err->message, sizeof err->message, "%s:%lu: ", hs_shown_path(path, shown), line);
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

hs_number_kind hs_parse_number(const char *s, size_t n, double *out) {
	if (is_non_finite_word(s, n))
		return HS_NUMBER_NOT_FINITE;
	if (!is_decimal(s, n) || n > 200)
		return HS_NUMBER_SYNTAX;
	char buf[208];
	memcpy(buf, s, n);
	buf[n] = '\0';
	double v = strtod(buf, NULL); // underflow to 0 or a subnormal is fine; ranges are checked later
	if (!isfinite(v))
		return HS_NUMBER_NOT_FINITE;
	*out = v;
	return HS_NUMBER_OK;
}

static bool read_number(parser *p, const yaml_node_t *node, const char *key, double *out) {
	if (!is_scalar(node))
		return fail(p, node, "'%s' must be a number, got %s", key, got(node).text);
	switch (hs_parse_number(scalar(node), node->data.scalar.length, out)) {
	case HS_NUMBER_OK:
		return true;
	case HS_NUMBER_NOT_FINITE:
		return fail(p, node, "'%s' must be finite, got %s", key, show(node).text);
	case HS_NUMBER_SYNTAX:
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

// A point in the world: every coordinate within ±MAX_LENGTH m, so nothing downstream overflows.
static bool read_point(parser *p, const yaml_node_t *node, const char *key, hs_vec3 *out) {
	double v[3];
	const yaml_node_t *e[3];
	if (!read_numbers(p, node, key, 3, "", v, e))
		return false;
	for (int i = 0; i < 3; ++i)
		if (!(fabs(v[i]) <= MAX_LENGTH))
			return fail(p, e[i], "'%s' must be within [-%g, %g] m, got %s", key, MAX_LENGTH, MAX_LENGTH, show(e[i]).text);
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

enum { MAX_FIELDS = 32 }; // keys of the largest mapping (an expect clause)

typedef struct fields {
	const yaml_node_t *key[MAX_FIELDS];
	const yaml_node_t *value[MAX_FIELDS];
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
		hs_number_kind ka = hs_parse_number(s + a0, a1 - a0, &a), kb = hs_parse_number(s + b0, b1 - b0, &b);
		if (ka == HS_NUMBER_NOT_FINITE || kb == HS_NUMBER_NOT_FINITE)
			return fail(p, node, "'dt' must be finite, got %s", show(node).text);
		if (ka != HS_NUMBER_OK || kb != HS_NUMBER_OK)
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
		return fail(p, node, frames < 1e15 ? "'duration' is %.0f frames of dt = %g s; at most %ld are allowed"
		                                   : "'duration' is %.6g frames of dt = %g s; at most %ld are allowed",
		            frames, p->s->dt,
		            MAX_FRAMES);
	long n = llround(frames);
	if (n < 1)
		return fail(p, node, "'duration' must be at least one frame (dt = %g s), got %s", p->s->dt, show(node).text);
	p->s->duration = d;
	p->s->frames = n;
	return true;
}

// ---------------------------------------------------------------------------------------------
// model.spring: the options of the spring model (workbench paper §4); read into p->spring

enum { SP_INTEGRATOR, SP_FRICTION, SP_SLIDING, SP_RESTITUTION, SP_WALLS, SP_NOISE_SEED, SP_COUNT };
static const char *const spring_keys[SP_COUNT] = {"integrator", "friction", "sliding_friction",
                                                  "restitution", "walls",    "noise_seed"};
static const char *const integrator_names[] = {"exact", "implicit_euler", "semi_implicit_euler", "rk4"};

// A coefficient in [0, hi] (hi < 0: no upper bound).
static bool read_coefficient(parser *p, const yaml_node_t *node, const char *key, double hi, double *out) {
	if (!read_number(p, node, key, out))
		return false;
	if (hi >= 0.0 && !(*out >= 0.0 && *out <= hi))
		return fail(p, node, "'%s' must be within [0, %g], got %s", key, hi, show(node).text);
	if (hi < 0.0 && !(*out >= 0.0))
		return fail(p, node, "'%s' must be >= 0, got %s", key, show(node).text);
	return true;
}

static bool read_spring(parser *p, const yaml_node_t *node) {
	hs_spring_def *d = &p->spring;
	if (node->type != YAML_MAPPING_NODE)
		return fail(p, node, "'spring' must be a mapping, got %s", got(node).text);
	fields f;
	if (!read_mapping(p, node, spring_keys, SP_COUNT, "model.spring", &f))
		return false;
	if (f.value[SP_INTEGRATOR]) {
		const yaml_node_t *v = f.value[SP_INTEGRATOR];
		int i = 0;
		while (i < 4 && !scalar_is(v, integrator_names[i]))
			++i;
		if (i == 4)
			return fail(p, v, "'integrator' must be exact, implicit_euler, semi_implicit_euler or rk4, got %s",
			            got(v).text);
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
			return fail(p, f.value[SP_SLIDING], "'sliding_friction' must not exceed 'friction' (%g), got %s",
			            d->friction_static, show(f.value[SP_SLIDING]).text);
	}
	if (f.value[SP_RESTITUTION] && !read_coefficient(p, f.value[SP_RESTITUTION], "restitution", 1.0, &d->restitution))
		return false;
	if (f.value[SP_WALLS]) {
		double w[4];
		const yaml_node_t *e[4];
		if (!read_numbers(p, f.value[SP_WALLS], "walls", 4, " [x_min, x_max, y_min, y_max]", w, e))
			return false;
		for (int i = 0; i < 4; ++i)
			if (!(fabs(w[i]) <= MAX_LENGTH))
				return fail(p, e[i], "'walls' must be within [-%g, %g] m, got %s", MAX_LENGTH, MAX_LENGTH, show(e[i]).text);
		if (!(w[0] < w[1]))
			return fail(p, e[1], "'walls' x_max must be greater than x_min (%g), got %s", w[0], show(e[1]).text);
		if (!(w[2] < w[3]))
			return fail(p, e[3], "'walls' y_max must be greater than y_min (%g), got %s", w[2], show(e[3]).text);
		d->walls.enabled = true;
		d->walls.x_min = w[0];
		d->walls.x_max = w[1];
		d->walls.y_min = w[2];
		d->walls.y_max = w[3];
	}
	if (f.value[SP_NOISE_SEED]) { // the Fastrak's static accuracy (§5.1), from a seeded generator
		long seed;
		if (!read_integer(p, f.value[SP_NOISE_SEED], "noise_seed", 0, 4294967295L, &seed))
			return false;
	}
	return true;
}

static bool read_model(parser *p, const yaml_node_t *node, hs_world_def *def) {
	static const char *const names[] = {"grasp_threshold_deg", "stacking", "floor_tolerance", "skip_work", "spring"};
	if (node->type != YAML_MAPPING_NODE)
		return fail(p, node, "'model' must be a mapping, got %s", got(node).text);
	fields f;
	if (!read_mapping(p, node, names, 5, "model", &f))
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
	if (f.value[4]) {
		p->spring_key = f.key[4];
		if (!read_spring(p, f.value[4]))
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
		ok = read_point(p, f.value[O_POSITION], "position", &def.position);
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
	if (f.value[K_WRIST] && !read_point(p, f.value[K_WRIST], "wrist", &key->wrist))
		return false;
	if (f.value[K_GRIP]) { // place the wrist so the posture's grip centre lands on this point
		hs_vec3 grip, center, axis;
		if (!read_point(p, f.value[K_GRIP], "grip", &grip))
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
		bool ok = hs_record_load(full, script, p->err);
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

// ---------------------------------------------------------------------------------------------
// stylus: the spring model's input (workbench paper §3–§5): keyframes or a recorded tracker file
//
// Every frame the stylus is sampled at the frame's end time and given to hs_world_set_stylus before
// hs_world_step (the library moves it linearly within the frame). Positions are linear between
// keys, orientations slerped, and the button is a step: a key's button holds from the key's time
// on. A frame whose end lies within STYLUS_TIME_SLOP of a key's time counts as reaching it, so a
// key at t = 1.2 s takes effect at the end of frame 72 of dt = 1/60 s whatever the rounding of 72 dt.

static const double STYLUS_TIME_SLOP = 1e-9; // s
static const long MAX_STYLUS_KEYS = 10000000L;
static const char *const STYLUS_HEADER = "t,x,y,z,qw,qx,qy,qz,button";

// The last key with t_k <= t, or -1.
static int stylus_key_at(const stylus_key *keys, int n, double t) {
	if (n == 0 || keys[0].t > t)
		return -1;
	int lo = 0, hi = n; // keys[lo].t <= t; keys[hi].t > t (hi = n: none)
	while (hi - lo > 1) {
		int mid = lo + (hi - lo) / 2;
		if (keys[mid].t <= t)
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

static void stylus_sample(const hs_scenario *s, double t, hs_vec3 *position, hs_quat *rot, bool *button) {
	const stylus_key *keys = s->stylus;
	int n = s->stylus_count;
	int a = stylus_key_at(keys, n, t);
	if (a < 0) { // before the first key: it holds
		*position = keys[0].position;
		*rot = keys[0].rot;
	} else if (a == n - 1) { // after the last: it holds
		*position = keys[a].position;
		*rot = keys[a].rot;
	} else {
		double u = (t - keys[a].t) / (keys[a + 1].t - keys[a].t);
		*position = hs_lerp(keys[a].position, keys[a + 1].position, u);
		*rot = u > 0.0 ? hs_quat_slerp(keys[a].rot, keys[a + 1].rot, u) : keys[a].rot;
	}
	int b = stylus_key_at(keys, n, t + STYLUS_TIME_SLOP);
	*button = keys[b < 0 ? 0 : b].button;
}

// Sets the stylus for the frame that ends at time t. Never allocates.
static void drive_stylus(hs_scenario *s, double t) {
	if (s->stylus_count == 0)
		return;
	hs_vec3 position;
	hs_quat rot;
	bool button;
	stylus_sample(s, t, &position, &rot, &button);
	hs_world_set_stylus(s->world, position, rot, button); // the keys were validated: finite, unit
}

enum { SK_T, SK_POSITION, SK_RPY, SK_QUAT, SK_BUTTON, SK_COUNT };
static const char *const stylus_key_keys[SK_COUNT] = {"t", "position", "rpy_deg", "quat", "button"};

// What a key leaves out it keeps from the key before (the first: identity orientation, button up).
static bool read_stylus_key(parser *p, const yaml_node_t *node, const stylus_key *previous, stylus_key *key) {
	if (node->type != YAML_MAPPING_NODE)
		return fail(p, node, "a stylus key must be a mapping like { t: 0, position: [x, y, z], button: false }, got %s",
		            got(node).text);
	fields f;
	if (!read_mapping(p, node, stylus_key_keys, SK_COUNT, "stylus key", &f))
		return false;
	if (!f.value[SK_T])
		return fail(p, node, "stylus key is missing 't'");
	if (!read_time(p, f.value[SK_T], "t", &key->t))
		return false;
	if (previous && !(key->t > previous->t))
		return fail(p, f.value[SK_T], "stylus keys must go forward in time: t = %s after t = %g", show(f.value[SK_T]).text,
		            previous->t);
	if (f.key[SK_RPY] && f.key[SK_QUAT])
		return fail(p, before(f.key[SK_RPY], f.key[SK_QUAT]) ? f.key[SK_QUAT] : f.key[SK_RPY],
		            "'rpy_deg' and 'quat' are exclusive: give one");
	if (!previous && !f.value[SK_POSITION])
		return fail(p, node, "the first stylus key needs 'position'");
	key->position = previous ? previous->position : hs_v3(0.0, 0.0, 0.0);
	key->rot = previous ? previous->rot : hs_quat_identity();
	key->button = previous ? previous->button : false;
	if (f.value[SK_POSITION] && !read_point(p, f.value[SK_POSITION], "position", &key->position))
		return false;
	if (f.value[SK_RPY]) {
		hs_vec3 rpy;
		if (!read_vec3(p, f.value[SK_RPY], "rpy_deg", &rpy))
			return false;
		key->rot = hs_quat_from_rpy(rpy.x * (HS_PI / 180.0), rpy.y * (HS_PI / 180.0), rpy.z * (HS_PI / 180.0));
	}
	if (f.value[SK_QUAT]) {
		double q[4];
		if (!read_numbers(p, f.value[SK_QUAT], "quat", 4, " [w, x, y, z]", q, NULL))
			return false;
		double norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
		if (!(fabs(norm - 1.0) <= QUAT_NORM_TOLERANCE))
			return fail(p, f.value[SK_QUAT], "'quat' must have norm 1 (within %g), got norm %.9g", QUAT_NORM_TOLERANCE, norm);
		key->rot = hs_quat_normalize(hs_q(q[0], q[1], q[2], q[3]));
	}
	if (f.value[SK_BUTTON] && !read_bool(p, f.value[SK_BUTTON], "button", &key->button))
		return false;
	return true;
}

HS_PRINTF(4, 5)
static bool record_fail(hs_error *err, const char *path, long line, const char *fmt, ...) {
	va_list ap;
	va_start(ap, fmt);
	vset_error(err, path, (unsigned long)line, fmt, ap);
	va_end(ap);
	return false;
}

// Reads a recorded tracker file: the header t,x,y,z,qw,qx,qy,qz,button, then one sample per line
// at any rate (strictly increasing t, s; position m; a unit quaternion within 1e-3, renormalised;
// button 0 or 1). Blank lines and lines starting with '#' are skipped. Errors are "PATH:LINE: ...".
static bool read_stylus_record(const char *path, hs_scenario *s, hs_error *err) {
	hs_record_rows rows;
	if (!hs_record_read(path, "recorded stylus input", STYLUS_HEADER, STYLUS_HEADER, 9, MAX_STYLUS_KEYS, &rows, err))
		return false;
	s->stylus = calloc((size_t)rows.count, sizeof *s->stylus);
	bool ok = s->stylus != NULL || record_fail(err, path, 1, "out of memory");
	for (long r = 0; ok && r < rows.count; ++r) {
		const double *v = &rows.values[r * 9];
		if (v[8] != 0.0 && v[8] != 1.0) {
			ok = record_fail(err, path, rows.lines[r], "button must be 0 or 1, got %.17g", v[8]);
			break;
		}
		stylus_key *key = &s->stylus[s->stylus_count++];
		key->t = v[0];
		key->position = hs_v3(v[1], v[2], v[3]);
		key->rot = hs_quat_normalize(hs_q(v[4], v[5], v[6], v[7]));
		key->button = v[8] == 1.0;
	}
	hs_record_rows_free(&rows);
	return ok;
}

enum { ST_KEYS, ST_RECORD, ST_COUNT };
static const char *const stylus_keys[ST_COUNT] = {"keys", "record"};

// The stylus: switches the world to the spring model (with model.spring's options) and reads its script.
static bool read_stylus(parser *p, const yaml_node_t *node, const char *path) {
	hs_scenario *s = p->s;
	if (node->type != YAML_MAPPING_NODE)
		return fail(p, node, "'stylus' must be a mapping with 'keys' or 'record', got %s", got(node).text);
	fields f;
	if (!read_mapping(p, node, stylus_keys, ST_COUNT, "stylus", &f))
		return false;
	if (!f.value[ST_KEYS] && !f.value[ST_RECORD])
		return fail(p, node, "'stylus' needs 'keys' or 'record'");
	if (f.value[ST_KEYS] && f.value[ST_RECORD])
		return fail(p, before(f.key[ST_KEYS], f.key[ST_RECORD]) ? f.key[ST_RECORD] : f.key[ST_KEYS],
		            "'keys' and 'record' are exclusive: give one");
	hs_status status = hs_world_enable_springs(s->world, &p->spring);
	if (status != HS_OK)
		return fail(p, p->spring_key ? p->spring_key : node, "cannot enable the spring model: %s", hs_status_string(status));
	s->springs = true;
	if (f.value[ST_KEYS]) {
		const yaml_node_t *keys = f.value[ST_KEYS];
		if (keys->type != YAML_SEQUENCE_NODE)
			return fail(p, keys, "'keys' must be a list of 1 to %ld keys, got %s", MAX_STYLUS_KEYS, got(keys).text);
		long n = sequence_length(keys);
		if (n < 1 || n > MAX_STYLUS_KEYS)
			return fail(p, keys, "'keys' must be a list of 1 to %ld keys, got %ld", MAX_STYLUS_KEYS, n);
		s->stylus = calloc((size_t)n, sizeof *s->stylus);
		if (!s->stylus)
			return fail(p, keys, "out of memory");
		for (long k = 0; k < n; ++k) {
			if (!read_stylus_key(p, sequence_item(p, keys, k), k ? &s->stylus[k - 1] : NULL, &s->stylus[k]))
				return false;
			s->stylus_count = (int)k + 1;
		}
		return true;
	}
	char *file = NULL;
	if (!read_text(p, f.value[ST_RECORD], "record", &file))
		return false;
	char *full = sibling_path(path, file);
	free(file);
	if (!full)
		return fail(p, f.value[ST_RECORD], "out of memory");
	bool ok = read_stylus_record(full, s, p->err);
	free(full);
	return ok;
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

enum { E_OBJECT = PRED_COUNT, E_AT, E_TOLERANCE, E_AXES, E_FROM, E_TO, E_COUNT };
static const char *const expect_keys[E_COUNT] = { // the predicates in their order, then the modifiers
    "near",        "resting",  "floor_contacts", "on_face",   "below",           "above",
    "moved",       "turned_deg", "speed_below",  "velocity",  "attached",        "candidate",
    "extension_ratio", "lands_at", "still",      "contact_sequence", "released", "rest_length",
    "stiffness",   "conserved", "swing_below",
    "object",      "at",       "tolerance",      "axes",      "from",            "to",
};

// The unit of a predicate's tolerance, or NULL when it takes none.
static const char *tolerance_unit(predicate p) {
	switch (p) {
	case PRED_NEAR:
	case PRED_REST_LENGTH:
		return "m";
	case PRED_LANDS_AT:
		return "s";
	case PRED_VELOCITY:
		return "m/s";
	case PRED_STIFFNESS:
		return "N/m";
	case PRED_EXTENSION_RATIO:
		return "a ratio";
	case PRED_CONSERVED:
		return "relative";
	default:
		return NULL;
	}
}

static const char *const attach_names[] = {"none", "pick", "catch", "select", "api"};
static const char *const release_names[] = {"none", "drop", "throw"};

// conserved: the clause's group — every object ("*"), a list of names, or one name.
static bool read_group(parser *p, const yaml_node_t *obj, clause *c) {
	hs_scenario *s = p->s;
	long n = obj->type == YAML_SEQUENCE_NODE ? sequence_length(obj) : 1;
	if (scalar_is(obj, "*")) {
		c->all_objects = true;
		n = s->object_count;
	} else if (obj->type == YAML_SEQUENCE_NODE && n < 1) { // more names than objects repeat one: caught below
		return fail(p, obj, "'object' must list at least one object name");
	}
	c->first_member = s->member_total;
	int *grown = realloc(s->members, (size_t)(s->member_total + n) * sizeof *grown);
	if (!grown)
		return fail(p, obj, "out of memory");
	s->members = grown;
	for (long i = 0; i < n; ++i) {
		int index = (int)i;
		if (!c->all_objects) {
			const yaml_node_t *e = obj->type == YAML_SEQUENCE_NODE ? sequence_item(p, obj, i) : obj;
			if (!is_scalar(e))
				return fail(p, e, "'object' must be an object name, a list of names or \"*\", got %s", got(e).text);
			if ((index = find_object(p, e)) < 0)
				return fail(p, e, "unknown object '%s' in expect", show(e).text);
			for (long j = 0; j < i; ++j)
				if (s->members[c->first_member + j] == index)
					return fail(p, e, "object '%s' is listed twice", show(e).text);
		}
		s->members[c->first_member + i] = index;
	}
	c->member_count = (int)n;
	s->member_total += (int)n;
	return true;
}

// One of `names` (count of them) as an index, or -1.
static int word_index(const yaml_node_t *node, const char *const *names, int count) {
	for (int i = 0; i < count; ++i)
		if (scalar_is(node, names[i]))
			return i;
	return -1;
}

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
	else if (obj->type == YAML_SEQUENCE_NODE)
		c->object = -2; // a group: only for 'conserved', read below
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
	if (pred < 0) {
		char list[512];
		size_t w = 0;
		for (int i = 0; i < PRED_COUNT && w < sizeof list; ++i)
			w += (size_t)snprintf(list + w, sizeof list - w, "%s%s", i == 0 ? "" : i == PRED_COUNT - 1 ? " or " : ", ",
			                      predicate_names[i]);
		return fail(p, node, "expect clause needs a predicate: %s", list);
	}
	c->pred = (predicate)pred;
	const char *pn = predicate_names[pred];
	const yaml_node_t *v = f.value[pred];
	if (predicate_needs_springs(c->pred) && !s->springs)
		return fail(p, f.key[pred], "'%s' needs a spring world: give the scenario a 'stylus'", pn);
	if (c->object == -2 && c->pred != PRED_CONSERVED)
		return fail(p, obj, "'object' may list several objects only for 'conserved'");
	// modifiers belong to particular predicates
	if (f.key[E_AT] && !predicate_uses_at(c->pred))
		return fail(p, f.key[E_AT], "'at' is not used by '%s'", pn);
	if (f.key[E_TOLERANCE] && !tolerance_unit(c->pred))
		return fail(p, f.key[E_TOLERANCE], "'tolerance' is not used by '%s'", pn);
	if (f.key[E_AXES] && c->pred != PRED_NEAR)
		return fail(p, f.key[E_AXES], "'axes' is only for 'near'");
	if (f.key[E_FROM] && c->pred != PRED_STILL && !predicate_uses_window(c->pred))
		return fail(p, f.key[E_FROM], "'from' is only for 'still', 'conserved' and 'swing_below'");
	if (f.key[E_TO] && c->pred != PRED_STILL && !predicate_uses_window(c->pred))
		return fail(p, f.key[E_TO], "'to' is only for 'still', 'conserved' and 'swing_below'");
	if (predicate_uses_at(c->pred)) {
		const yaml_node_t *at = f.value[E_AT];
		if (!at)
			return fail(p, node, "expect clause '%s' is missing 'at' (end or a time in s)", pn);
		double t = 0.0;
		if (scalar_is(at, "end")) {
			c->at_end = true;
			c->frame = s->frames;
		} else if (!is_scalar(at) || hs_parse_number(scalar(at), at->data.scalar.length, &t) != HS_NUMBER_OK) {
			return fail(p, at, "'at' must be 'end' or a time in s, got %s", got(at).text);
		} else if (t < 0.0 || t > s->duration) {
			return fail(p, at, "'at' must be 'end' or a time within [0, %g] s, got %s", s->duration, show(at).text);
		} else {
			c->frame = llround(t / s->dt);
		}
	}
	const char *unit = tolerance_unit(c->pred);
	if (unit) {
		const yaml_node_t *tol = f.value[E_TOLERANCE];
		if (!tol)
			return fail(p, node, "expect clause '%s' is missing 'tolerance' (%s)", pn, unit);
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
	case PRED_VELOCITY:
		if (!read_vec3(p, v, pn, &c->target))
			return false;
		break;
	case PRED_RESTING:
	case PRED_ON_FACE:
	case PRED_STILL:
	case PRED_CANDIDATE:
		if (!read_bool(p, v, pn, &c->flag))
			return false;
		break;
	case PRED_ATTACHED: { // true, false, or how it got there
		int kind = word_index(v, attach_names, 4);
		if (kind > HS_ATTACH_NONE) {
			c->flag = true;
			c->count = kind;
		} else if (!(is_scalar(v) && read_bool(p, v, pn, &c->flag))) {
			return fail(p, v, "'attached' must be true, false, pick, catch or select, got %s", got(v).text);
		}
		break;
	}
	case PRED_RELEASED: {
		int kind = word_index(v, release_names, 3);
		if (kind < 0)
			return fail(p, v, "'released' must be drop, throw or none, got %s", got(v).text);
		c->count = kind;
		break;
	}
	case PRED_CONSERVED: {
		if (scalar_is(v, "momentum"))
			c->count = CONSERVE_MOMENTUM;
		else if (scalar_is(v, "energy"))
			c->count = CONSERVE_ENERGY;
		else
			return fail(p, v, "'conserved' must be momentum or energy, got %s", got(v).text);
		if (!read_group(p, obj, c))
			return false;
		c->object = -1;
		break;
	}
	case PRED_FLOOR_CONTACTS:
		if (!read_integer(p, v, pn, 0, INT_MAX, &c->count))
			return false;
		break;
	case PRED_BELOW:
	case PRED_ABOVE:
	case PRED_EXTENSION_RATIO:
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
	case PRED_SPEED_BELOW:
	case PRED_REST_LENGTH:
	case PRED_STIFFNESS:
	case PRED_SWING_BELOW:
		if (!read_number(p, v, pn, &c->value))
			return false;
		if (!(c->value > 0.0))
			return fail(p, v, "'%s' must be > 0, got %s", pn, show(v).text);
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
	if ((c->pred == PRED_STILL || predicate_uses_window(c->pred)) && f.value[E_FROM]) {
		double from;
		if (!read_time(p, f.value[E_FROM], "from", &from))
			return false;
		c->frame = llround(from / s->dt);
	}
	if (c->pred == PRED_STILL || predicate_uses_window(c->pred)) {
		c->last_frame = s->frames;
		if (f.value[E_TO]) {
			double to;
			if (!read_time(p, f.value[E_TO], "to", &to))
				return false;
			c->last_frame = llround(to / s->dt);
		}
		if (!(c->last_frame > c->frame) && (f.value[E_TO] || c->pred != PRED_STILL)) // still: from = end is fine
			return fail(p, f.value[E_TO] ? f.value[E_TO] : node,
			            "'to' must come at least one frame after 'from' (frames %ld and %ld of dt = %g s)", c->frame,
			            c->last_frame, s->dt);
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
		if (ok) // the work the checks will take: a group counts its members
			checks += s->clauses[i].pred == PRED_CONSERVED ? s->clauses[i].member_count
			                                                : s->clauses[i].object < 0 ? s->object_count : 1;
		if (ok && checks > MAX_CHECKS)
			ok = fail(p, item, "expect clauses check more than %d object states in all", MAX_CHECKS);
	}
	return ok;
}

// Allocates everything the run records, so that hs_scenario_step never allocates.
static bool prepare_records(parser *p, const yaml_node_t *root) {
	hs_scenario *s = p->s;
	long checks = 0;
	bool landing = false, sequences = false, releases = false;
	for (int i = 0; i < s->clause_count; ++i) {
		const clause *c = &s->clauses[i];
		checks += c->pred == PRED_CONSERVED || c->object >= 0 ? 1 : s->object_count;
		landing = landing || c->pred == PRED_LANDS_AT;
		sequences = sequences || c->pred == PRED_CONTACT_SEQUENCE;
		releases = releases || c->pred == PRED_RELEASED;
	}
	size_t n = (size_t)s->object_count, nc = (size_t)checks;
	if (checks > 0) {
		s->checks = calloc(nc, sizeof *s->checks);
		s->capture_order = malloc(nc * sizeof *s->capture_order);
		s->still_checks = malloc(nc * sizeof *s->still_checks);
		s->window_checks = malloc(nc * sizeof *s->window_checks);
		if (!s->checks || !s->capture_order || !s->still_checks || !s->window_checks)
			return fail(p, root, "out of memory");
	}
	if (releases) {
		s->releases = calloc(n, sizeof *s->releases);
		if (!s->releases)
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
		if (c->pred == PRED_CONSERVED) // one check for the whole group
			first = last = -1;
		for (int o = first; o <= last; ++o) {
			int k = s->check_count++;
			s->checks[k].clause = i;
			s->checks[k].object = o;
			s->checks[k].moved_frame = -1;
			s->checks[k].peak_frame = -1;
			s->checks[k].holder = -1;
			s->checks[k].candidate = -1;
			if (predicate_uses_at(c->pred))
				s->capture_order[s->capture_count++] = k;
			else if (c->pred == PRED_STILL)
				s->still_checks[s->still_count++] = k;
			else if (predicate_uses_window(c->pred))
				s->window_checks[s->window_count++] = k;
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

// The object's velocity: in spring worlds the integrated one, else (P(t) − P(t − dt)) / dt.
static hs_vec3 velocity_of(const hs_scenario *s, int object, const hs_object_state *st) {
	hs_spring_object o;
	if (s->springs && hs_world_spring_object(s->world, s->ids[object], &o) == HS_OK)
		return o.velocity;
	return st->velocity;
}

// What the at-based spring predicates need: who is on the spring, how, and its stretch.
static void capture_spring(const hs_scenario *s, check *c) {
	hs_spring_state ss;
	hs_spring_object o;
	if (hs_world_spring_state(s->world, &ss) != HS_OK)
		return;
	c->candidate = (int)ss.candidate.index1 - 1; // objects were added in the file's order
	if (ss.attached.index1 == 0)
		return; // holder stays -1
	c->holder = (int)ss.attached.index1 - 1; // objects were added in the file's order
	c->kind = ss.attach_kind;
	c->extension = ss.extension;
	if (hs_world_spring_object(s->world, ss.attached, &o) == HS_OK) {
		c->rest_length = o.rest_length;
		c->ratio = ss.extension / o.rest_length;
	}
}

// conserved: the group's momentum Σ m v (kg m/s), or its energy Σ (½ m |v|² − m g·G) (J) in out[0].
static void group_quantity(const hs_scenario *s, const clause *c, double out[3]) {
	out[0] = out[1] = out[2] = 0.0;
	for (int i = 0; i < c->member_count; ++i) {
		hs_spring_object o;
		hs_object_state st;
		int object = s->members[c->first_member + i];
		if (hs_world_spring_object(s->world, s->ids[object], &o) != HS_OK ||
		    hs_world_object_state(s->world, s->ids[object], &st) != HS_OK)
			continue;
		if (c->count == CONSERVE_MOMENTUM) {
			out[0] += o.mass * o.velocity.x;
			out[1] += o.mass * o.velocity.y;
			out[2] += o.mass * o.velocity.z;
		} else {
			out[0] += 0.5 * o.mass * hs_dot(o.velocity, o.velocity) - o.mass * hs_dot(s->gravity, st.position);
		}
	}
}

// swing_below: the horizontal distance (m) from the stylus to the object's G.
static double swing_of(const hs_scenario *s, int object) {
	hs_spring_state ss;
	hs_object_state st;
	if (hs_world_spring_state(s->world, &ss) != HS_OK || hs_world_object_state(s->world, s->ids[object], &st) != HS_OK)
		return 0.0;
	double dx = st.position.x - ss.stylus.x, dy = st.position.y - ss.stylus.y;
	return sqrt(dx * dx + dy * dy);
}

// Records what the expectations need from the current frame. Never allocates.
static void record(hs_scenario *s) {
	long f = s->frame;
	while (s->capture_next < s->capture_count) {
		check *c = &s->checks[s->capture_order[s->capture_next]];
		if (s->clauses[c->clause].frame > f)
			break;
		c->state = state_of(s, c->object);
		c->velocity = velocity_of(s, c->object, &c->state);
		if (s->springs)
			capture_spring(s, c);
		c->captured = true;
		s->capture_next++;
	}
	for (int i = 0; i < s->window_count; ++i) {
		check *k = &s->checks[s->window_checks[i]];
		const clause *c = &s->clauses[k->clause];
		if (f < c->frame || f > c->last_frame || k->captured)
			continue;
		if (c->pred == PRED_CONSERVED) {
			if (f == c->frame) {
				group_quantity(s, c, k->before);
				k->began = true;
			}
			if (f == c->last_frame) {
				group_quantity(s, c, k->after);
				k->captured = true;
			}
		} else { // swing_below
			double d = swing_of(s, k->object);
			if (!k->began || d > k->peak) {
				k->peak = d;
				k->peak_frame = f;
			}
			k->began = true;
			k->captured = f == c->last_frame;
		}
	}
	hs_release release;
	if (s->releases && hs_world_spring_last_release(s->world, &release) == HS_OK && release.kind != HS_RELEASE_NONE &&
	    release.object.index1 >= 1 && release.object.index1 <= (uint32_t)s->object_count)
		s->releases[release.object.index1 - 1] = release; // at most one release per frame: none is missed
	for (int i = 0; i < s->still_count; ++i) {
		check *c = &s->checks[s->still_checks[i]];
		long from = s->clauses[c->clause].frame;
		if (f < from || f > s->clauses[c->clause].last_frame || c->moved)
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
	static const char *const keys[] = {"name",  "description", "dt",     "duration", "gravity",
	                                   "model", "objects",     "expect", "hands",    "stylus"};
	hs_scenario *s = p->s;
	if (root->type != YAML_MAPPING_NODE)
		return fail(p, root, "a scenario must be a mapping of keys (description, dt, duration, objects, ...), got %s",
		            got(root).text);
	fields f;
	if (!read_mapping(p, root, keys, 10, "scenario", &f))
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
	if (f.key[8] && f.key[9]) // one world runs one model
		return fail(p, before(f.key[8], f.key[9]) ? f.key[9] : f.key[8],
		            "'hands' and 'stylus' are exclusive: a world runs the hand model or the spring model");
	hs_world_def def = hs_default_world_def();
	def.dt = s->dt;
	if (f.value[4] && !read_vec3(p, f.value[4], "gravity", &def.gravity))
		return false;
	s->gravity = def.gravity;
	p->spring = hs_default_spring_def();
	if (f.value[5] && !read_model(p, f.value[5], &def))
		return false;
	if (p->spring_key && !f.value[9])
		return fail(p, p->spring_key, "'spring' options need a 'stylus': only spring worlds use them");
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
	if (f.value[9] && !read_stylus(p, f.value[9], path))
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
		parser p = {.path = path, .doc = &doc, .err = err, .s = s};
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
	drive_stylus(s, 0.0); // likewise the stylus
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
	free(s->stylus);
	free(s->members);
	free(s->window_checks);
	free(s->releases);
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
	drive_stylus(s, (double)(s->frame + 1) * s->dt);
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
	case PRED_SPEED_BELOW: {
		double v = hs_length(k->velocity);
		snprintf(what, wn, "speed below %.9g m/s %s", c->value, when);
		snprintf(measured, mn, "speed %.6g m/s", v);
		return v < c->value;
	}
	case PRED_VELOCITY: {
		double d = hs_distance(k->velocity, c->target);
		snprintf(what, wn, "velocity [%.9g, %.9g, %.9g] within %g m/s %s", c->target.x, c->target.y, c->target.z,
		         c->tolerance, when);
		snprintf(measured, mn, "velocity [%.9g, %.9g, %.9g] m/s (difference %.6g m/s)", k->velocity.x, k->velocity.y,
		         k->velocity.z, d);
		return d <= c->tolerance;
	}
	case PRED_ATTACHED: {
		snprintf(what, wn, "attached %s %s", c->count ? attach_names[c->count] : c->flag ? "true" : "false", when);
		bool on = k->holder == k->object;
		if (on)
			snprintf(measured, mn, "on the spring (%s)", attach_names[k->kind]);
		else if (k->holder >= 0)
			snprintf(measured, mn, "not on the spring (it holds '%s')", s->object_names[k->holder]);
		else
			snprintf(measured, mn, "not on the spring (it holds nothing)");
		return c->flag ? on && (c->count == HS_ATTACH_NONE || (long)k->kind == c->count) : !on;
	}
	case PRED_CANDIDATE: {
		snprintf(what, wn, "candidate %s %s", c->flag ? "true" : "false", when);
		bool is = k->candidate == k->object;
		if (k->candidate >= 0)
			snprintf(measured, mn, "the candidate is '%s'", s->object_names[k->candidate]);
		else
			snprintf(measured, mn, "no candidate");
		return is == c->flag;
	}
	case PRED_EXTENSION_RATIO: {
		snprintf(what, wn, "extension_ratio %.9g within %g %s", c->value, c->tolerance, when);
		if (k->holder != k->object) {
			snprintf(measured, mn, "not on the spring");
			return false;
		}
		snprintf(measured, mn, "extension / x0 = %.9g (extension %.6g m of x0 = %.6g m)", k->ratio, k->extension,
		         k->rest_length);
		return fabs(k->ratio - c->value) <= c->tolerance;
	}
	case PRED_RELEASED: {
		snprintf(what, wn, "released %s", release_names[c->count]);
		const hs_release *r = &s->releases[k->object];
		if (r->kind == HS_RELEASE_NONE)
			snprintf(measured, mn, "never released");
		else
			snprintf(measured, mn, "%s at t = %.6g s (hand speed %.6g m/s, leaving at [%.6g, %.6g, %.6g] m/s)",
			         release_names[r->kind], r->time, r->hand_speed, r->velocity.x, r->velocity.y, r->velocity.z);
		return (long)r->kind == c->count;
	}
	case PRED_REST_LENGTH:
	case PRED_STIFFNESS: {
		hs_spring_object o;
		memset(&o, 0, sizeof o);
		hs_world_spring_object(s->world, s->ids[k->object], &o);
		bool x0 = c->pred == PRED_REST_LENGTH;
		snprintf(what, wn, "%s %.9g %s within %g %s", predicate_names[c->pred], c->value, x0 ? "m" : "N/m", c->tolerance,
		         x0 ? "m" : "N/m");
		snprintf(measured, mn, "x0 = %.9g m, k = %.9g N/m (mass %.9g kg)", o.rest_length, o.stiffness, o.mass);
		return fabs((x0 ? o.rest_length : o.stiffness) - c->value) <= c->tolerance;
	}
	case PRED_CONSERVED: {
		bool momentum = c->count == CONSERVE_MOMENTUM;
		snprintf(what, wn, "conserved %s from t = %g s to t = %g s within %g (relative)", momentum ? "momentum" : "energy",
		         (double)c->frame * s->dt, (double)c->last_frame * s->dt, c->tolerance);
		if (!k->captured) {
			snprintf(measured, mn, "not reached: the run stopped at frame %ld of %ld", s->frame, s->frames);
			return false;
		}
		const double *a = k->before, *b = k->after;
		double change = sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
		double size = fmax(sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]), sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
		double relative = size > 0.0 ? change / size : 0.0;
		if (momentum)
			snprintf(measured, mn, "p [%.9g, %.9g, %.9g] -> [%.9g, %.9g, %.9g] kg m/s, relative change %.3g", a[0], a[1],
			         a[2], b[0], b[1], b[2], relative);
		else
			snprintf(measured, mn, "E %.12g -> %.12g J, relative change %.3g", a[0], b[0], relative);
		return relative <= c->tolerance;
	}
	case PRED_SWING_BELOW: {
		snprintf(what, wn, "swing below %.9g m from t = %g s to t = %g s", c->value, (double)c->frame * s->dt,
		         (double)c->last_frame * s->dt);
		if (!k->captured) {
			snprintf(measured, mn, "not reached: the run stopped at frame %ld of %ld", s->frame, s->frames);
			return false;
		}
		snprintf(measured, mn, "largest horizontal offset from the stylus %.6g m (at t = %.6g s)", k->peak,
		         (double)k->peak_frame * s->dt);
		return k->peak < c->value;
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
		if (c->last_frame < s->frames)
			snprintf(what, wn, "still %s from t = %g s to t = %g s", c->flag ? "true" : "false", from,
			         (double)c->last_frame * s->dt);
		else
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

// The object a check names, or its group: "all objects" or the names joined by '+'.
typedef struct label {
	char text[256];
} label;

static label check_label(const hs_scenario *s, const check *k) {
	label l;
	const clause *c = &s->clauses[k->clause];
	if (k->object >= 0) {
		snprintf(l.text, sizeof l.text, "%s", s->object_names[k->object]);
	} else if (c->all_objects) {
		snprintf(l.text, sizeof l.text, "all objects");
	} else {
		size_t w = 0;
		l.text[0] = '\0';
		for (int i = 0; i < c->member_count && w < sizeof l.text; ++i)
			w += (size_t)snprintf(l.text + w, sizeof l.text - w, "%s%s", i ? "+" : "",
			                      s->object_names[s->members[c->first_member + i]]);
	}
	return l;
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
			        check_label(s, k).text, what, measured);
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
