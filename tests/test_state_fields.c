// test_state_fields.c — the state's field tables (model/state/state_fields.h): a field added to a table
// is followed by all four uses of the one walker the world's state uses. For each kind of entry,
// a table with that one entry more than a base table, over the same struct: the size grows by the
// entry's words; save writes them (they change when only that field does); load restores exactly
// the saved field; check refuses a bad value of it with the reason the world's load gives, at its
// word; the hash changes when only it changes (and not under the base table); the hash's gather
// (GATHER mode, hs_state_hash_words) equals the HASH walk, field by field.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "state_fields.h"

#define SLOTS 3

typedef struct pair {
	int a;
	double force;
} pair;

// A state type: its base fields and, below, the candidates for the one field more.
typedef struct rec {
	double a;
	hs_vec3 v;
	uint8_t flag;
	int n;
	double extra_f64;
	hs_quat extra_rot;
	int extra_int;
	uint8_t extra_u8;
	bool extra_bool;
	uint32_t extra_mask;
	long extra_long;
	hs_vec3 extra_arr[3];
	bool has_extra; // a model field: the condition of extra_arr
	int slots;      // a model field: the slots of the groups below
	uint8_t *flags; // per slot, through pointers (the spring system's per-object arrays)
	double *weights;
	int live; // the counted group's live slots, the rest zero (the spring's warm-start forces)
	pair *pairs;
	uint8_t flags_store[SLOTS];
	double weights_store[SLOTS];
	pair pairs_store[SLOTS];
} rec;

static const hs_field base_fields[] = {
    {HS_ONE(rec, a, F64)},
    {HS_ONE(rec, v, VEC3)},
    {HS_ONE(rec, flag, U8), .hi = 1},
    {HS_ONE(rec, n, INT), .lo = 0, .hi = 10},
};
#define BASE_COUNT HS_FIELDS_COUNT(base_fields)

static const hs_field slot_fields[] = {
    {HS_ALL_AT(rec, flags, U8), .hi = 1},
    {HS_ALL_AT(rec, weights, F64)},
};
static const hs_field pair_fields[] = {
    {HS_EACH_AT(rec, pairs, pair, a, INT), .lo = 0, .hi = -1, HS_HI_PLUS(rec, slots)},
    {HS_EACH_AT(rec, pairs, pair, force, F64)},
};

static void init_rec(rec *r) {
	memset(r, 0, sizeof *r);
	r->a = 1.25;
	r->v = (hs_vec3){-1.0, 2.0, 0.5};
	r->flag = 1;
	r->n = 5;
	r->extra_rot = (hs_quat){1.0, 0.0, 0.0, 0.0};
	r->has_extra = true;
	r->slots = SLOTS;
	r->flags = r->flags_store;
	r->weights = r->weights_store;
	r->pairs = r->pairs_store;
	r->live = 1;
	r->pairs[0] = (pair){2, 0.75};
}

// The struct's bytes a load writes are those of its state fields: compared field by field.
static bool same_state(const rec *x, const rec *y) {
	return memcmp(&x->a, &y->a, offsetof(rec, has_extra) - offsetof(rec, a)) == 0 && x->live == y->live &&
	       memcmp(x->flags, y->flags, SLOTS) == 0 && memcmp(x->weights, y->weights, sizeof x->weights_store) == 0 &&
	       memcmp(x->pairs, y->pairs, sizeof x->pairs_store) == 0;
}

// One entry that a table may have more than the base, two values of its field, and a bad word.
typedef struct extra_case {
	const char *what;
	hs_field entry;
	void (*set)(rec *r, int variant); // variant 0 or 1: two different valid values
	int bad_word;                     // the bad word's place among the entry's words
	uint64_t bad;
	const char *reason;
	int refused_at; // the word the refusal names: the bad one, or a rotation's last (it is read whole)
} extra_case;

static uint64_t bits(double d) {
	uint64_t u;
	memcpy(&u, &d, sizeof u);
	return u;
}

static void set_f64(rec *r, int k) { r->extra_f64 = k ? -3.5 : 2.5; }
static void set_rot(rec *r, int k) { r->extra_rot = k ? (hs_quat){0.6, 0.8, 0.0, 0.0} : (hs_quat){0.0, 0.0, 0.6, 0.8}; }
static void set_int(rec *r, int k) { r->extra_int = k ? 9 : 0; }
static void set_u8(rec *r, int k) { r->extra_u8 = k ? 3 : 1; }
static void set_bool(rec *r, int k) { r->extra_bool = k != 0; }
static void set_mask(rec *r, int k) { r->extra_mask = k ? 0x11u : 0x0Au; }
static void set_long(rec *r, int k) { r->extra_long = k ? 15 : -1; } // its hi is 10 + n = 15
static void set_arr(rec *r, int k) { r->extra_arr[2].y = k ? 4.0 : -4.0; }
static void set_slots(rec *r, int k) {
	r->flags[2] = (uint8_t)k;
	r->weights[1] = k ? 0.25 : 0.5;
}
static void set_pairs(rec *r, int k) {
	r->live = 2;
	r->pairs[1] = (pair){k ? 1 : 0, k ? 8.0 : -8.0};
}

static const extra_case cases[] = {
    {"f64", {HS_ONE(rec, extra_f64, F64)}, set_f64, 0, 0x7FF8000000000000ull, "a non-finite number", 0},
    {"rotation", {HS_ONE(rec, extra_rot, ROTATION)}, set_rot, 0, 0x3FF0000000000000ull, "not a unit quaternion", 3},
    {"int in a range", {HS_ONE(rec, extra_int, INT), .lo = 0, .hi = 9}, set_int, 0, 10, "an integer out of range", 0},
    {"u8 in a range", {HS_ONE(rec, extra_u8, U8), .hi = 3}, set_u8, 0, 4, "a flag or enum out of range", 0},
    {"bool", {HS_ONE(rec, extra_bool, BOOL)}, set_bool, 0, 2, "a boolean neither 0 nor 1", 0},
    {"mask", {HS_ONE(rec, extra_mask, MASK32), .hi = 5}, set_mask, 0, 0x20, "a bit mask with bits out of range", 0},
    {"long up to a field", {HS_ONE(rec, extra_long, LONG), .lo = -1, .hi = 10, HS_HI_PLUS(rec, n)}, set_long, 0, 16,
     "an integer out of range", 0},
    {"array under a condition", {HS_ALL(rec, extra_arr, VEC3), HS_WHEN(rec, has_extra)}, set_arr, 7,
     0xFFF0000000000000ull, "a non-finite number", 7},
    {"group through pointers", {HS_GROUP("slots", slot_fields), HS_COUNT_AT(rec, slots)}, set_slots, 4, 2,
     "a flag or enum out of range", 4},
    {"counted group", {HS_GROUP("pairs", pair_fields), HS_COUNTED(rec, live), HS_COUNT_AT(rec, slots)}, set_pairs, 5, 1,
     "a slot beyond its count not zero", 5},
};

typedef struct table {
	hs_field entries[BASE_COUNT + 1];
	size_t n;
} table;

static table base_table(void) {
	table t = {.n = BASE_COUNT};
	memcpy(t.entries, base_fields, sizeof base_fields);
	return t;
}

static table more_table(const hs_field *extra) {
	table t = base_table();
	t.entries[t.n++] = *extra;
	return t;
}

static size_t size_of(const table *t, rec *r) {
	hs_state_io io = {.mode = HS_STATE_SIZE};
	hs_fields_io(&io, t->entries, t->n, r, NULL);
	return io.words;
}

static unsigned char *save(const table *t, rec *r, size_t *words) {
	*words = size_of(t, r);
	unsigned char *buffer = calloc(*words, 8);
	assert_non_null(buffer);
	hs_state_io io = {.mode = HS_STATE_SAVE, .out = buffer, .limit = *words};
	hs_fields_io(&io, t->entries, t->n, r, NULL);
	assert_false(io.overflow);
	assert_int_equal(io.words, *words);
	return buffer;
}

// The world's load: a CHECK pass, then (when it passed) LOAD. Returns the refusal, NULL if loaded.
static const char *load(const table *t, rec *r, const unsigned char *buffer, size_t words, size_t *at) {
	hs_state_io io = {.mode = HS_STATE_CHECK, .in = buffer, .limit = words};
	hs_fields_io(&io, t->entries, t->n, r, NULL);
	if (io.error) {
		*at = io.error_word;
		return io.error;
	}
	assert_int_equal(io.words, words);
	io = (hs_state_io){.mode = HS_STATE_LOAD, .in = buffer, .limit = words};
	hs_fields_io(&io, t->entries, t->n, r, NULL);
	return NULL;
}

// The hash as the world takes it (the walk inlined), checked against the gather's.
static uint64_t hash(const table *t, rec *r) {
	hs_state_io io = {.mode = HS_STATE_HASH, .lane = {1, 2, 3, 4}};
	hs_fields_walk(&io, t->entries, t->n, r, NULL);
	uint64_t words[64];
	hs_state_io gather = {.mode = HS_STATE_GATHER, .gather = words};
	hs_fields_walk(&gather, t->entries, t->n, r, NULL);
	assert_true(gather.words <= 64);
	hs_state_io mixed = {.mode = HS_STATE_HASH, .lane = {1, 2, 3, 4}};
	hs_state_hash_words(&mixed, words, gather.words);
	assert_int_equal(mixed.words, io.words);
	assert_true(hs_state_hash_of(&mixed) == hs_state_hash_of(&io));
	hs_state_io out_of_line = {.mode = HS_STATE_HASH, .lane = {1, 2, 3, 4}};
	hs_fields_io(&out_of_line, t->entries, t->n, r, NULL);
	assert_true(hs_state_hash_of(&out_of_line) == hs_state_hash_of(&io));
	return hs_state_hash_of(&io);
}

static void check_case(const extra_case *c) {
	table fewer = base_table(), more = more_table(&c->entry);
	rec r0, r1;
	init_rec(&r0);
	init_rec(&r1);
	c->set(&r0, 0);
	c->set(&r1, 1);
	// size: the entry's words more
	size_t base_words = size_of(&fewer, &r0), words0, words1;
	assert_true(size_of(&more, &r0) > base_words);
	// save writes them: they differ when only the field does; the base table's words are a prefix
	unsigned char *s0 = save(&more, &r0, &words0), *s1 = save(&more, &r1, &words1), *b0 = save(&fewer, &r0, &base_words);
	assert_int_equal(words0, words1);
	assert_memory_equal(s0, s1, 8 * base_words);
	assert_memory_not_equal(s0 + 8 * base_words, s1 + 8 * base_words, 8 * (words0 - base_words));
	assert_memory_equal(s0, b0, 8 * base_words);
	// load restores exactly the saved field: into a record holding the other value
	rec loaded;
	init_rec(&loaded);
	c->set(&loaded, 1);
	size_t at = 0;
	assert_null(load(&more, &loaded, s0, words0, &at));
	assert_true(same_state(&loaded, &r0));
	init_rec(&loaded); // the base table leaves it alone
	c->set(&loaded, 1);
	assert_null(load(&fewer, &loaded, b0, base_words, &at));
	assert_true(same_state(&loaded, &r1));
	// check refuses a bad value of it, at its word, and leaves the record untouched
	size_t bad_at = base_words + (size_t)c->bad_word;
	for (int k = 0; k < 8; ++k)
		s0[8 * bad_at + (size_t)k] = (unsigned char)(c->bad >> (8 * k));
	init_rec(&loaded);
	c->set(&loaded, 1);
	const char *why = load(&more, &loaded, s0, words0, &at);
	assert_non_null(why);
	if (!strstr(why, c->reason))
		fail_msg("%s: refused with '%s', expected '%s'", c->what, why, c->reason);
	assert_int_equal(at, base_words + (size_t)c->refused_at);
	assert_true(same_state(&loaded, &r1));
	// the hash changes when only it changes; the base table's does not
	assert_true(hash(&more, &r0) != hash(&more, &r1));
	assert_true(hash(&fewer, &r0) == hash(&fewer, &r1));
	free(s0);
	free(s1);
	free(b0);
}

static void test_one_entry_more_is_followed_by_all_four(void **state) {
	(void)state;
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
		print_message("  %s\n", cases[i].what);
		check_case(&cases[i]);
	}
}

// A field under a condition exists only while it holds: no words, nothing loaded or hashed.
static void test_condition_off_means_no_field(void **state) {
	(void)state;
	table fewer = base_table(), more = more_table(&cases[7].entry);
	rec r0, r1;
	init_rec(&r0);
	init_rec(&r1);
	r0.has_extra = r1.has_extra = false;
	set_arr(&r0, 0);
	set_arr(&r1, 1);
	assert_int_equal(size_of(&more, &r0), size_of(&fewer, &r0));
	assert_true(hash(&more, &r0) == hash(&more, &r1));
	r0.has_extra = true;
	assert_int_equal(size_of(&more, &r0), size_of(&fewer, &r0) + 9);
}

// A counted group: its count is checked, its slots beyond the count travel as zeros (loaded as
// zeros) and a hash leaves them out: the hash depends on the live slots only.
static void test_counted_group(void **state) {
	(void)state;
	table more = more_table(&cases[9].entry);
	rec r;
	init_rec(&r);
	size_t words;
	unsigned char *s = save(&more, &r, &words);
	assert_int_equal(words, 6 + 1 + 2 * SLOTS); // a, v (3), flag, n; the count; 2 words a slot
	rec loaded;
	init_rec(&loaded);
	loaded.live = 3;
	loaded.pairs[2] = (pair){1, 9.0}; // beyond the saved count: zeroed by the load
	size_t at = 0;
	assert_null(load(&more, &loaded, s, words, &at));
	assert_int_equal(loaded.live, 1);
	assert_int_equal(loaded.pairs[2].a, 0);
	assert_true(loaded.pairs[2].force == 0.0);
	assert_true(same_state(&loaded, &r));
	s[8 * 6] = SLOTS + 1; // the count word, after the base's 6
	const char *why = load(&more, &loaded, s, words, &at);
	assert_non_null(why);
	assert_string_equal(why, "a count out of range");
	rec other;
	init_rec(&other);
	other.pairs[2] = (pair){1, 1.0}; // a hash leaves out what is beyond the count
	assert_true(hash(&more, &r) == hash(&more, &other));
	other.live = 3;
	assert_true(hash(&more, &r) != hash(&more, &other));
	free(s);
}

// Every kind's words are those of state_walk.h's calls: a table walk saves what the calls save.
static void test_words_are_the_visitors(void **state) {
	(void)state;
	rec r;
	init_rec(&r);
	r.extra_long = -7;
	r.extra_mask = 0x1Fu;
	const hs_field entries[] = {{HS_ONE(rec, extra_long, LONG), .lo = LONG_MIN, .hi = LONG_MAX},
	                            {HS_ONE(rec, extra_mask, MASK32), .hi = 5},
	                            {HS_ONE(rec, v, VEC3)},
	                            {HS_ONE(rec, extra_rot, ROTATION)}};
	unsigned char a[12 * 8] = {0}, b[12 * 8] = {0};
	hs_state_io io = {.mode = HS_STATE_SAVE, .out = a, .limit = 12};
	hs_fields_io(&io, entries, 4, &r, NULL);
	assert_int_equal(io.words, 9);
	hs_state_io calls = {.mode = HS_STATE_SAVE, .out = b, .limit = 12};
	hs_state_long(&calls, &r.extra_long);
	uint64_t mask = r.extra_mask;
	hs_state_mask(&calls, &mask, 5);
	hs_state_vec3(&calls, &r.v);
	hs_state_rotation(&calls, &r.extra_rot);
	assert_int_equal(calls.words, 9);
	assert_memory_equal(a, b, sizeof a);
	assert_true(bits(r.v.x) == ((uint64_t)a[16] | (uint64_t)a[17] << 8 | (uint64_t)a[18] << 16 | (uint64_t)a[19] << 24 |
	                            (uint64_t)a[20] << 32 | (uint64_t)a[21] << 40 | (uint64_t)a[22] << 48 |
	                            (uint64_t)a[23] << 56));
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_one_entry_more_is_followed_by_all_four),
	    cmocka_unit_test(test_condition_off_means_no_field),
	    cmocka_unit_test(test_counted_group),
	    cmocka_unit_test(test_words_are_the_visitors),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
