// yaml_read.h — reading YAML with libyaml's document API (so every node keeps its line): the
// document with its limits, scalars, numbers, mappings with unknown-key errors, and messages
// "PATH:LINE: what is wrong" that quote what was found.
#ifndef HS_HARNESS_YAML_READ_H
#define HS_HARNESS_YAML_READ_H

#include <stdbool.h>
#include <stdint.h>
#include <yaml.h>

#include "error.h"
#include "number.h"

// A document being read: where messages go and what they name.
typedef struct hs_yaml {
	const char *path;
	hs_error *err;
	yaml_document_t doc; // filled by hs_yaml_load
	bool loaded;
	struct hs_file_list *files; // hs_yaml_sibling_file adds each file it names here (NULL: none kept)
} hs_yaml;

// Collections nested deeper than this are refused before the document is built: the schema needs
// 6 (root, objects, an object, vertices, a vertex; or hands, a hand, keys, a key, a posture), and
// libyaml's scanner takes time quadratic in the depth of flow collections ([[[[...).
#define HS_YAML_MAX_DEPTH 8

// Parses `text` (the whole file) into `doc`: exactly one document, at most HS_YAML_MAX_DEPTH deep.
// False and y->err set on invalid YAML, too deep a nesting ("nested deeper than 8 levels" at the
// collection that goes one level too deep), a second document, or (when it has none)
// `empty_message` at line 1.
bool hs_yaml_load(hs_yaml *y, const char *text, size_t size, const char *empty_message);
// Frees what hs_yaml_load built (also after a failure).
void hs_yaml_free(hs_yaml *y);
const yaml_node_t *hs_yaml_root(const hs_yaml *y);

HS_PRINTF(3, 4) bool hs_yaml_fail(const hs_yaml *y, const yaml_node_t *node, const char *fmt, ...);
unsigned long hs_yaml_line(const yaml_node_t *node);
// a comes first in the file
bool hs_yaml_before(const yaml_node_t *a, const yaml_node_t *b);
// the 1-based line of a byte offset
unsigned long hs_yaml_line_at(const char *text, size_t size, size_t offset);

// A scalar's text for a message: at most 40 bytes, control characters shown as '?'.
typedef struct hs_shown {
	char text[64];
} hs_shown;
hs_shown hs_yaml_show(const yaml_node_t *node);
// "got ..." for a value of the wrong kind: 'text', a list, a mapping or nothing.
hs_shown hs_yaml_got(const yaml_node_t *node);

bool hs_yaml_is_scalar(const yaml_node_t *node);
const char *hs_yaml_scalar(const yaml_node_t *node);
bool hs_yaml_scalar_is(const yaml_node_t *node, const char *word);
// One of `names` (count of them) as an index, or -1.
int hs_yaml_word(const yaml_node_t *node, const char *const *names, int count);
long hs_yaml_length(const yaml_node_t *sequence);
const yaml_node_t *hs_yaml_item(const hs_yaml *y, const yaml_node_t *sequence, long i);

bool hs_yaml_number(const hs_yaml *y, const yaml_node_t *node, const char *key, double *out);
bool hs_yaml_integer(const hs_yaml *y, const yaml_node_t *node, const char *key, int64_t lo, int64_t hi,
                     int64_t *out);
bool hs_yaml_bool(const hs_yaml *y, const yaml_node_t *node, const char *key, bool *out);
// A one-line text; `out` is a new string.
bool hs_yaml_text(const hs_yaml *y, const yaml_node_t *node, const char *key, char **out);
// A file named by a text value, as a path beside the scenario file (malloc'd); NULL with the
// error set when the value is not text or memory runs out.
char *hs_yaml_sibling_file(const hs_yaml *y, const yaml_node_t *node, const char *key);
// A time in [0, duration] s.
bool hs_yaml_time(const hs_yaml *y, const yaml_node_t *node, const char *key, double duration, double *out);
// `count` numbers in a list; `elements` (optional) receives their nodes for range messages.
bool hs_yaml_numbers(const hs_yaml *y, const yaml_node_t *node, const char *key, int count, const char *what,
                     double *out, const yaml_node_t **elements);
bool hs_yaml_vec3(const hs_yaml *y, const yaml_node_t *node, const char *key, hs_vec3 *out);
// [x, y, z] with every component within [-limit, limit] (in `unit`), checked at the component's line.
bool hs_yaml_bounded_vec3(const hs_yaml *y, const yaml_node_t *node, const char *key, double limit, const char *unit,
                          hs_vec3 *out);
// An orientation: rpy_deg [roll, pitch, yaw] (fixed axes x, y, z) or quat [w, x, y, z] of norm 1.
bool hs_yaml_rpy(const hs_yaml *y, const yaml_node_t *node, const char *key, hs_quat *out);
bool hs_yaml_quat(const hs_yaml *y, const yaml_node_t *node, const char *key, hs_quat *out);

enum { HS_YAML_MAX_FIELDS = 40 }; // keys of the largest mapping (an expect clause: 33)

// A mapping's values by name index (NULL: not given) and the keys, for messages at the key.
typedef struct hs_fields {
	const yaml_node_t *key[HS_YAML_MAX_FIELDS];
	const yaml_node_t *value[HS_YAML_MAX_FIELDS];
} hs_fields;

// Checks every key of `map` against `names` (unknown and duplicate keys are errors) and collects
// the values by name index.
bool hs_yaml_mapping(const hs_yaml *y, const yaml_node_t *map, const char *const *names, int name_count,
                     const char *where, hs_fields *f);
// Fails at the later of two keys that exclude each other: "'A' and 'B' are exclusive: `why`".
bool hs_yaml_exclusive(const hs_yaml *y, const hs_fields *f, const char *const *names, int a, int b, const char *why);

#endif
