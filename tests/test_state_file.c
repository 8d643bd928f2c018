// test_state_file.c — crafted state files (hs_scenario_resume): a state saved part-way through a
// noisy spring run, one word changed at a time to a value out of its field's range and the
// checksum made valid again, must be refused with one line naming the field, the scenario left as
// it was (it then runs); so must a truncated, a longer, an all-zero and a foreign file, and a
// world's block whose numbers give an object a non-finite reading.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "hs_harness.h"
#include "world_internal.h"
#include "noise.h"

#define WORD 8
#define SAVE_AT 30

static char path[] = "/tmp/hs_state_file_XXXXXX";

static const char scenario_text[] =
    "description: a noisy spring run with every kind of capture\ndt: 1/60\nduration: 2\n"
    "model: { spring: { noise_seed: 5 } }\n"
    "objects:\n  - { name: ball, shape: sphere, size: 0.05, position: [0, 0, 0.05] }\n"
    "  - { name: other, shape: sphere, size: 0.05, position: [1, 0, 0.05] }\n"
    "stylus:\n  keys:\n    - { t: 0, position: [0, 0, 0.05] }\n"
    "    - { t: 0.3, button: true }\n    - { t: 1.0, position: [0, 0, 0.4] }\n"
    "    - { t: 1.5, position: [0.3, 0, 0.4], button: false }\n"
    "expect:\n  - { object: ball, at: 0.25, attached: pick }\n"
    "  - { object: ball, at: end, above: 0 }\n"
    "  - { object: '*', contact_sequence: [0, 2, 0] }\n"
    "  - { object: other, still: true }\n";

static int setup(void **state) {
	(void)state;
	int fd = mkstemp(path);
	if (fd < 0)
		return -1;
	ssize_t n = write(fd, scenario_text, sizeof scenario_text - 1);
	return close(fd) == 0 && n == (ssize_t)(sizeof scenario_text - 1) ? 0 : -1;
}

static int teardown(void **state) {
	(void)state;
	return unlink(path);
}

static hs_scenario *load(void) {
	hs_error err;
	hs_scenario *s = hs_scenario_load(path, &err);
	if (!s)
		fail_msg("%s", err.message);
	return s;
}

// The state after SAVE_AT frames, in memory.
static unsigned char *saved_state(size_t *size) {
	hs_scenario *s = load();
	for (int f = 0; f < SAVE_AT; ++f)
		assert_true(hs_scenario_step(s));
	char *text = NULL;
	FILE *m = open_memstream(&text, size);
	assert_non_null(m);
	hs_error err;
	if (hs_scenario_save(s, m, &err) != HS_OK)
		fail_msg("%s", err.message);
	fclose(m);
	hs_scenario_destroy(s);
	return (unsigned char *)text;
}

static uint64_t get_word(const unsigned char *b) {
	uint64_t v = 0;
	for (int i = 0; i < WORD; ++i)
		v |= (uint64_t)b[i] << (8 * i);
	return v;
}

static void put_word(unsigned char *b, uint64_t v) {
	for (int i = 0; i < WORD; ++i)
		b[i] = (unsigned char)(v >> (8 * i));
}

// The FNV-1a checksum of every byte before the last word, written into it.
static void fix_checksum(unsigned char *b, size_t n) {
	uint64_t h = 14695981039346656037ull;
	for (size_t i = 0; i + WORD < n; ++i)
		h = (h ^ b[i]) * 1099511628211ull;
	put_word(b + n - WORD, h);
}

// Resumes a fresh scenario from `n` bytes: refused with a message that holds `want`, then the
// scenario runs to its end as a fresh one does (nothing was restored).
static void expect_refused(const unsigned char *b, size_t n, const char *want) {
	hs_scenario *s = load();
	FILE *f = fmemopen((void *)b, n ? n : 1, "rb");
	assert_non_null(f);
	if (n == 0)
		fgetc(f); // empty
	hs_error err;
	hs_status status = hs_scenario_resume(s, f, &err);
	fclose(f);
	assert_int_not_equal(status, HS_OK);
	if (!strstr(err.message, want))
		fail_msg("'%s' does not say '%s'", err.message, want);
	assert_null(strchr(err.message, '\n'));
	assert_int_equal(hs_world_frame(hs_scenario_world(s)), 0);
	long frames = 0;
	while (hs_scenario_step(s))
		frames++;
	assert_int_equal(frames, hs_scenario_frame_count(s));
	hs_scenario_destroy(s);
}

// The word at `at` set to `value`, the checksum made valid: refused naming `want`.
static void expect_word_refused(size_t at, uint64_t value, const char *want) {
	size_t n;
	unsigned char *b = saved_state(&n);
	assert_true(at + WORD <= n - WORD);
	put_word(b + at, value);
	fix_checksum(b, n);
	expect_refused(b, n, want);
	free(b);
}

// Where the harness's part starts: after the magic, the version, the name's block, the source
// hash, the frame and the frame count.
static size_t harness_at(const unsigned char *b) { return 3 * WORD + (size_t)get_word(b + 2 * WORD) + 3 * WORD; }

static void test_unchanged_state_resumes(void **state) {
	(void)state;
	size_t n;
	unsigned char *b = saved_state(&n);
	hs_scenario *s = load();
	FILE *f = fmemopen(b, n, "rb");
	hs_error err;
	if (hs_scenario_resume(s, f, &err) != HS_OK)
		fail_msg("%s", err.message);
	fclose(f);
	assert_int_equal(hs_world_frame(hs_scenario_world(s)), SAVE_AT);
	hs_scenario_destroy(s);
	free(b);
}

static void test_header_fields(void **state) {
	(void)state;
	size_t n;
	unsigned char *b = saved_state(&n);
	size_t h = harness_at(b), frame_at = h - 2 * WORD;
	assert_int_equal(get_word(b + frame_at), SAVE_AT);
	free(b);
	expect_word_refused(frame_at, 1000000, "frame 1000000 of 120 does not fit");
	expect_word_refused(frame_at, (uint64_t)-1, "frame -1 of 120 does not fit");
	expect_word_refused(frame_at, SAVE_AT + 1, "frame is 31, the world's state is at frame 30");
	expect_word_refused(frame_at + WORD, 121, "does not fit the scenario's 120 frames");
	expect_word_refused(WORD, 1, "version 1, this build reads version 3");
}

static void test_harness_fields(void **state) {
	(void)state;
	size_t n;
	unsigned char *b = saved_state(&n);
	size_t h = harness_at(b), words = h + 4 * WORD, position = words + (HS_NOISE_WORDS - 1) * WORD;
	assert_int_equal(get_word(b + h + 3 * WORD), HS_NOISE_WORDS);
	size_t queue = position + WORD;
	free(b);
	expect_word_refused(h, 77, "step_status is 77, not within [0, 5]");
	expect_word_refused(h + WORD, 12, "failed_frame is 12, not within [0, 0]");
	expect_word_refused(h + 2 * WORD, (uint64_t)-1, "faults is -1, not within [0, ");
	expect_word_refused(h + 2 * WORD, 3, "faults is 3, the world's state counts 0");
	expect_word_refused(h + 3 * WORD, 624, "noise.words is 624, not within [625, 625]");
	expect_word_refused(position, (uint64_t)-100000000, "noise.position is -100000000, not within [0, 624]");
	expect_word_refused(position, 625, "noise.position is 625, not within [0, 624]");
	expect_word_refused(words + 3 * WORD, 0xFFFFFFFF00000001ull, "noise.word[3] is not a 32-bit word");
	expect_word_refused(queue, 0, "capture_next is 0, not within [1, 1]");
	expect_word_refused(queue + WORD, 9, "checks is 9, not within [");
	expect_word_refused(queue + 2 * WORD, 2, "check 1 (line 15) captured is 2, not within [0, 1]");
}

// An all-zero generator draws zeros for ever: refused though each word is within its range.
static void test_noise_all_zero(void **state) {
	(void)state;
	size_t n;
	unsigned char *b = saved_state(&n);
	size_t words = harness_at(b) + 4 * WORD;
	memset(b + words, 0, (HS_NOISE_WORDS - 1) * WORD);
	fix_checksum(b, n);
	expect_refused(b, n, "noise.word[0] is all zero");
	free(b);
}

// The captures: the first check (at 0.25 s, frame 15: captured) holds an object state first.
static void test_capture_fields(void **state) {
	(void)state;
	size_t n;
	unsigned char *b = saved_state(&n);
	size_t first = harness_at(b) + (4 + HS_NOISE_WORDS + 2) * WORD + WORD; // after `captured`
	assert_int_equal(get_word(b + first - WORD), 1);
	free(b);
	uint64_t nan = 0x7FF8000000000000ull, two = 0x4000000000000000ull;
	expect_word_refused(first, nan, "check 1 (line 15) state.position is not a finite number");
	expect_word_refused(first + 3 * WORD, two, "check 1 (line 15) state.orientation is neither a unit quaternion");
	expect_word_refused(first + 10 * WORD, 4, "check 1 (line 15) state.contact is 4, not within [0, 3]");
	expect_word_refused(first + 11 * WORD, (uint64_t)-2, "state.floor_contacts is -2");
	expect_word_refused(first + 12 * WORD, 7, "state.resting is 7");
	expect_word_refused(first + 16 * WORD, 2, "check 1 (line 15) at.holder is 2, not within [-1, 1]");
	expect_word_refused(first + 17 * WORD, (uint64_t)-2, "at.candidate is -2, not within [-1, 1]");
	expect_word_refused(first + 18 * WORD, 7, "at.kind is 7, not within [0, 6]"); // HS_ATTACH_MAGNET (6) is the last kind
}

// The world's own frame counter, the first word after its header: it must be the harness's.
static void test_world_frame(void **state) {
	(void)state;
	size_t n;
	unsigned char *b = saved_state(&n);
	hs_scenario *s = load();
	size_t world = hs_world_state_size(hs_scenario_world(s));
	hs_scenario_destroy(s);
	size_t frame_at = n - WORD - world + 9 * WORD;
	assert_int_equal(get_word(b + frame_at), SAVE_AT);
	free(b);
	expect_word_refused(frame_at, 0x7FFFFFFFFFFFFFFFull, "frame is 30, the world's state is at frame 9223372036854775807");
	expect_word_refused(frame_at + WORD, 4, "faults is 0, the world's state counts 4");
	expect_word_refused(n - WORD - world - WORD, 8, "world.size is 8, not within");
}

static void test_whole_file(void **state) {
	(void)state;
	size_t n;
	unsigned char *b = saved_state(&n);
	b[n / 2] ^= 1;
	expect_refused(b, n, "damaged: its checksum does not match");
	b[n / 2] ^= 1;
	expect_refused(b, n - 1, "truncated: ");
	expect_refused(b, 12, "truncated header");
	expect_refused(b, 0, "not a handspring state file");
	unsigned char *longer = calloc(n + 100, 1);
	assert_non_null(longer);
	memcpy(longer, b, n);
	expect_refused(longer, n + 100, "longer than the ");
	memset(longer, 0, n + 100); // /dev/zero: read no further than a state's size
	expect_refused(longer, n + 100, "not a handspring state file");
	free(longer);
	free(b);
}

// The bytes of a state of tests/fuzz/state/hand.yaml saved after `frames` frames, with object
// 'block''s previous position x set to `x` (its three words found by their bits) and the checksum
// made valid: the state fuzz_state found, made again for this library's layout. Written to
// tests/fuzz/state/hand_prev_position.state when HS_WRITE_SEED names that file.
static unsigned char *hand_state_with_prev_x(hs_scenario *s, long frames, double x, size_t *n) {
	for (long k = 0; k < frames; ++k)
		assert_true(hs_scenario_step(s));
	char *buf = NULL;
	FILE *f = open_memstream(&buf, n);
	assert_non_null(f);
	hs_error err;
	assert_int_equal(hs_scenario_save(s, f, &err), HS_OK);
	fclose(f);
	const hs_body *b = &hs_scenario_world(s)->state.bodies[0];
	unsigned char want[3 * WORD];
	memcpy(want, &b->prev, sizeof want); // little-endian words, as the state writes them
	unsigned char *at = NULL;
	for (size_t i = 0; i + sizeof want <= *n && !at; ++i)
		if (memcmp(buf + i, want, sizeof want) == 0)
			at = (unsigned char *)buf + i;
	assert_non_null(at);
	memcpy(at, &x, sizeof x);
	fix_checksum((unsigned char *)buf, *n);
	return (unsigned char *)buf;
}

// A world's block whose every number is in range but whose previous position (-4.5e306 m, found by
// fuzz_state) gives an infinite velocity: refused, naming the object.
static void test_world_readings(void **state) {
	(void)state;
	hs_error err;
	hs_scenario *s = hs_scenario_load("tests/fuzz/state/hand.yaml", &err);
	if (!s)
		fail_msg("%s (the tests run from the repository's top folder)", err.message);
	size_t n;
	unsigned char *bytes = hand_state_with_prev_x(s, 30, -4.49423283715579e306, &n);
	hs_scenario_destroy(s);
	const char *seed = getenv("HS_WRITE_SEED");
	if (seed) {
		FILE *out = fopen(seed, "wb");
		assert_non_null(out);
		assert_int_equal(fwrite(bytes, 1, n, out), n);
		fclose(out);
	}
	s = hs_scenario_load("tests/fuzz/state/hand.yaml", &err);
	assert_non_null(s);
	FILE *f = fmemopen(bytes, n, "rb");
	assert_non_null(f);
	assert_int_equal(hs_scenario_resume(s, f, &err), HS_ERR_STATE_MISMATCH);
	fclose(f);
	assert_string_equal(err.message, "state file: the world's state gives object 'block' a non-finite position, "
	                                 "orientation or velocity");
	assert_int_equal(hs_world_frame(hs_scenario_world(s)), 0);
	hs_scenario_destroy(s);
	free(bytes);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_unchanged_state_resumes), cmocka_unit_test(test_header_fields),
	    cmocka_unit_test(test_harness_fields),          cmocka_unit_test(test_noise_all_zero),
	    cmocka_unit_test(test_capture_fields),          cmocka_unit_test(test_world_frame),
	    cmocka_unit_test(test_whole_file),              cmocka_unit_test(test_world_readings),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
