// scenario_state.c — saving a run part-way and resuming it (hs_scenario_save, hs_scenario_resume).
//
// A state file: a header (magic, version, the scenario's name, a checksum of the scenario file's
// bytes, the frame), the harness's own state (the step status, the numeric faults so far, the input
// noise generator, the capture queue and what every expectation check captured), then the world's
// state block (hs_world_save_state), and a checksum of all that (FNV-1a). Scripts need no
// position: they are sampled by time. Every number is a 64-bit little-endian word (state_io.h), the
// noise generator's state too (hs_noise_save), so a state file reads the same on every machine.
//
// Resuming reads at most the size a state of this scenario has (so /dev/zero or an endless file
// ends there), checks the header, the size and the checksum, then every word of the harness's part
// against its field's range and the scenario (the frame, the capture queue, the generator's words),
// then the world's block (the world checks its own), and the world's frame and fault count against
// the harness's. Only then is anything restored; a refusal names the field in one line.
#include <limits.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "expect.h"
#include "expect_table.h"
#include "noise.h"
#include "scenario_internal.h"
#include "state_io.h"

static const char MAGIC[8] = {'H', 'S', 'S', 'T', 'A', 'T', 'E', '\n'};
// version 2: the noise generator as portable words (version 1 held the bytes of GSL's state);
// version 3: a contact_sequence check keeps how long its last state has been held
enum { STATE_VERSION = 3, MAX_STATE_NAME = 4096 };

HS_PRINTF(3, 4)
static hs_status state_error(hs_error *err, hs_status status, const char *fmt, ...) {
	if (err) {
		va_list ap;
		va_start(ap, fmt);
		int n = snprintf(err->message, sizeof err->message, "state file: ");
		vsnprintf(err->message + n, sizeof err->message - (size_t)n, fmt, ap);
		va_end(ap);
	}
	return status;
}

// A block: its size, then its bytes.
static void put_block(hs_state_io *io, const void *data, size_t size) {
	hs_put_u64(io, size);
	hs_put_bytes(io, data, size);
}

static hs_store store_of(const hs_scenario *s, const hs_check *k) {
	return hs_predicates[s->expect.clauses[k->clause].pred].store;
}

// ---------------------------------------------------------------------------------------------
// save

static void put_header(hs_state_io *io, const hs_scenario *s) {
	hs_put_bytes(io, MAGIC, sizeof MAGIC);
	hs_put_u64(io, STATE_VERSION);
	put_block(io, s->name, strlen(s->name));
	hs_put_u64(io, s->source_hash);
	hs_put_i64(io, s->frame);
	hs_put_i64(io, s->frames);
}

static void put_harness(hs_state_io *io, const hs_scenario *s, const uint64_t *noise) {
	const hs_expectations *e = &s->expect;
	hs_put_i64(io, s->step_status);
	hs_put_i64(io, s->failed_frame);
	hs_put_i64(io, hs_scenario_faults(s));
	hs_put_u64(io, s->noise ? HS_NOISE_WORDS : 0);
	for (int i = 0; s->noise && i < HS_NOISE_WORDS; ++i)
		hs_put_u64(io, noise[i]);
	hs_put_i64(io, e->capture_next);
	hs_put_i64(io, e->check_count);
	for (int i = 0; i < e->check_count; ++i)
		hs_capture_put(io, store_of(s, &e->checks[i]), &e->checks[i]);
}

hs_status hs_scenario_save(const hs_scenario *s, FILE *out, hs_error *err) {
	if (!s || !out)
		return state_error(err, HS_ERR_INVALID_ARGUMENT, "no scenario or no file");
	if (s->overridden) // the header names the file's bytes, not the options: a resume could not redo them
		return state_error(err, HS_ERR_INVALID_ARGUMENT, "a run loaded with a dt or noise seed option cannot be saved");
	size_t world_size = hs_world_state_size(s->world);
	void *world = malloc(world_size ? world_size : 1);
	uint64_t noise[HS_NOISE_WORDS];
	hs_state_io io = {.file = out, .ok = true, .hash = HS_STATE_HASH_START};
	hs_status status = HS_OK;
	if (!world)
		status = state_error(err, HS_ERR_NO_MEMORY, "out of memory");
	else if ((status = hs_world_save_state(s->world, world, world_size)) != HS_OK)
		state_error(err, status, "the world cannot save its state: %s", hs_status_string(status));
	else if (s->noise && !hs_noise_save(s->noise, noise))
		status = state_error(err, HS_ERR_INVALID_ARGUMENT, "the noise generator cannot save its state");
	if (status == HS_OK) {
		put_header(&io, s);
		put_harness(&io, s, noise);
		put_block(&io, world, world_size);
		hs_put_u64(&io, io.hash); // of everything before it
		if (!io.ok || fflush(out) != 0)
			status = state_error(err, HS_ERR_INVALID_ARGUMENT, "cannot write");
	}
	free(world);
	return status;
}

// ---------------------------------------------------------------------------------------------
// resume

// What a state file holds, read and checked in full before anything is restored.
typedef struct saved {
	int64_t frame, step_status, failed_frame, faults, capture_next;
	bool has_noise;
	uint64_t noise[HS_NOISE_WORDS];
	hs_check *checks; // a copy of the scenario's, with the saved captures
	void *world;
	size_t world_size;
} saved;

static void saved_free(saved *v) {
	free(v->checks);
	free(v->world);
}

// A refusal: the field the checked reads named, else the part that ended early.
static hs_status refused(const hs_state_io *io, hs_error *err, const char *part) {
	if (io->refused[0])
		return state_error(err, HS_ERR_STATE_MISMATCH, "%s", io->refused);
	return state_error(err, HS_ERR_STATE_MISMATCH, "%s is truncated", part);
}

// The size a state of this scenario has: its own state, saved into memory.
static hs_status expected_size(const hs_scenario *s, size_t *size, hs_error *err) {
	char *text = NULL;
	size_t n = 0;
	FILE *m = open_memstream(&text, &n);
	if (!m)
		return state_error(err, HS_ERR_NO_MEMORY, "out of memory");
	hs_status status = hs_scenario_save(s, m, err);
	fclose(m);
	free(text);
	*size = n;
	return status;
}

// The file's bytes, at most `expected` + 1: one more than a state has tells a longer file.
static hs_status read_bytes(FILE *in, size_t expected, unsigned char **buf, size_t *size, hs_error *err) {
	*buf = malloc(expected + 1);
	if (!*buf)
		return state_error(err, HS_ERR_NO_MEMORY, "out of memory");
	size_t n = 0, got;
	while (n < expected + 1 && (got = fread(*buf + n, 1, expected + 1 - n, in)) > 0)
		n += got;
	*size = n;
	if (ferror(in))
		return state_error(err, HS_ERR_STATE_MISMATCH, "cannot read it");
	return HS_OK;
}

static hs_status read_header(hs_state_io *io, const hs_scenario *s, saved *v, hs_error *err) {
	char magic[sizeof MAGIC], name[MAX_STATE_NAME + 1];
	hs_get_bytes(io, magic, sizeof magic);
	if (!io->ok || memcmp(magic, MAGIC, sizeof magic) != 0)
		return state_error(err, HS_ERR_STATE_MISMATCH, "not a handspring state file");
	uint64_t version = hs_get_u64(io), length = hs_get_u64(io);
	if (!io->ok)
		return state_error(err, HS_ERR_STATE_MISMATCH, "truncated header");
	if (version != STATE_VERSION)
		return state_error(err, HS_ERR_STATE_MISMATCH, "version %llu, this build reads version %d",
		                   (unsigned long long)version, STATE_VERSION);
	if (length > MAX_STATE_NAME)
		return state_error(err, HS_ERR_STATE_MISMATCH, "damaged header");
	hs_get_bytes(io, name, (size_t)length);
	name[length] = '\0';
	uint64_t hash = hs_get_u64(io);
	v->frame = hs_get_i64(io);
	int64_t frames = hs_get_i64(io);
	if (!io->ok)
		return state_error(err, HS_ERR_STATE_MISMATCH, "truncated header");
	if (strcmp(name, s->name) != 0) {
		for (char *c = name; *c; ++c) // the message is one line of text, whatever the file holds
			*c = *c >= ' ' && *c <= '~' ? *c : '?';
		return state_error(err, HS_ERR_STATE_MISMATCH, "saved from scenario '%.100s', not '%s'", name, s->name);
	}
	if (hash != s->source_hash)
		return state_error(err, HS_ERR_STATE_MISMATCH, "the scenario file '%s' changed since the state was saved",
		                   s->name);
	if (frames != s->frames || v->frame < 0 || v->frame > frames)
		return state_error(err, HS_ERR_STATE_MISMATCH, "frame %lld of %lld does not fit the scenario's %ld frames",
		                   (long long)v->frame, (long long)frames, s->frames);
	return HS_OK;
}

// The size (a state of this scenario has exactly one) and the checksum, before any field is read.
static hs_status check_whole(const unsigned char *buf, size_t n, size_t expected, hs_error *err) {
	if (n > expected)
		return state_error(err, HS_ERR_STATE_MISMATCH, "longer than the %zu bytes a state of this scenario has",
		                   expected);
	if (n < expected)
		return state_error(err, HS_ERR_STATE_MISMATCH, "truncated: %zu bytes, a state of this scenario has %zu", n,
		                   expected);
	uint64_t sum = 0;
	for (int i = 0; i < 8; ++i)
		sum |= (uint64_t)buf[n - 8 + (size_t)i] << (8 * i);
	if (sum != hs_state_checksum(buf, n - 8))
		return state_error(err, HS_ERR_STATE_MISMATCH, "damaged: its checksum does not match");
	return HS_OK;
}

// The checks whose frame has passed: what hs_expect_capture has taken at `frame` (in frame order).
static int64_t captures_due(const hs_expectations *e, int64_t frame) {
	int64_t n = 0;
	while (n < e->capture_count && e->clauses[e->checks[e->capture_order[n]].clause].frame <= frame)
		++n;
	return n;
}

// The generator's 624 words and its position, each within its range (hs_noise_check).
static void read_noise(hs_state_io *io, const hs_scenario *s, saved *v) {
	int64_t words = s->noise ? HS_NOISE_WORDS : 0;
	v->has_noise = hs_get_range(io, "noise.words", words, words) != 0;
	if (!v->has_noise)
		return;
	for (int i = 0; i < HS_NOISE_WORDS - 1; ++i)
		v->noise[i] = hs_get_u64(io);
	v->noise[HS_NOISE_WORDS - 1] = (uint64_t)hs_get_range(io, "noise.position", 0, HS_NOISE_WORDS - 1);
	int field;
	const char *why = io->ok ? hs_noise_check(v->noise, &field) : NULL;
	if (why) {
		char name[32];
		snprintf(name, sizeof name, "noise.word[%d]", field);
		hs_state_refuse_field(io, name, why);
	}
}

static hs_status read_harness(hs_state_io *io, const hs_scenario *s, saved *v, hs_error *err) {
	const hs_expectations *e = &s->expect;
	io->frame = (long)v->frame;
	io->objects = s->object_count;
	v->step_status = hs_get_range(io, "step_status", HS_OK, HS_ERR_STATE_MISMATCH);
	int64_t failed = v->step_status == HS_OK ? 0 : v->frame + 1; // the frame a failed step was to make
	v->failed_frame = hs_get_range(io, "failed_frame", failed, failed);
	v->faults = hs_get_range(io, "faults", 0, LONG_MAX);
	read_noise(io, s, v);
	int64_t due = captures_due(e, v->frame);
	v->capture_next = hs_get_range(io, "capture_next", due, due);
	hs_get_range(io, "checks", e->check_count, e->check_count);
	if (!io->ok)
		return refused(io, err, "the harness's state");
	v->checks = malloc(e->check_count ? (size_t)e->check_count * sizeof *v->checks : 1);
	if (!v->checks)
		return state_error(err, HS_ERR_NO_MEMORY, "out of memory");
	if (e->check_count)
		memcpy(v->checks, e->checks, (size_t)e->check_count * sizeof *v->checks);
	char where[96];
	io->where = where;
	for (int i = 0; io->ok && i < e->check_count; ++i) {
		snprintf(where, sizeof where, "check %d (line %lu) ", i + 1, e->clauses[v->checks[i].clause].line);
		hs_capture_get(io, store_of(s, &v->checks[i]), &v->checks[i]);
	}
	io->where = NULL;
	return io->ok ? HS_OK : refused(io, err, "the expectations' state");
}

static hs_status read_world(hs_state_io *io, const hs_scenario *s, saved *v, hs_error *err) {
	v->world_size = hs_world_state_size(s->world);
	v->world = malloc(v->world_size ? v->world_size : 1);
	if (!v->world)
		return state_error(err, HS_ERR_NO_MEMORY, "out of memory");
	hs_get_range(io, "world.size", (int64_t)v->world_size, (int64_t)v->world_size);
	hs_get_bytes(io, v->world, v->world_size);
	return io->ok ? HS_OK : refused(io, err, "the world's state");
}

// What the loaded world reports of each object must be finite: the world checks each number of
// its block, not what they give together (a previous position of -4.5e306 m is finite, the
// velocity read from it is not).
static hs_status check_readings(const hs_scenario *s, hs_error *err) {
	for (int i = 0; i < s->object_count; ++i) {
		hs_object_state st;
		if (hs_world_object_state(s->world, s->ids[i], &st) != HS_OK || !hs_vec3_is_finite(st.position) ||
		    !hs_quat_is_finite(st.orientation) || !hs_vec3_is_finite(st.velocity))
			return state_error(err, HS_ERR_STATE_MISMATCH, "the world's state gives object '%s' a non-finite position, "
			                   "orientation or velocity", s->object_names[i]);
	}
	return HS_OK;
}

// The world's block loaded, then its frame and fault count held against the harness's; on any
// refusal the world is put back as it was.
static hs_status load_world(hs_scenario *s, const saved *v, hs_error *err) {
	size_t size = hs_world_state_size(s->world);
	void *before = malloc(size ? size : 1);
	if (!before || hs_world_save_state(s->world, before, size) != HS_OK) {
		free(before);
		return state_error(err, HS_ERR_NO_MEMORY, "out of memory");
	}
	hs_status status = hs_world_load_state(s->world, v->world, v->world_size);
	if (status != HS_OK) {
		free(before);
		return state_error(err, status, "the world refused its state: %s", hs_world_state_error(s->world));
	}
	long frame = hs_world_frame(s->world), faults = hs_world_get_counters(s->world).numeric_faults;
	if (frame != v->frame)
		status = state_error(err, HS_ERR_STATE_MISMATCH, "frame is %lld, the world's state is at frame %ld",
		                     (long long)v->frame, frame);
	else if (faults != v->faults)
		status = state_error(err, HS_ERR_STATE_MISMATCH, "faults is %lld, the world's state counts %ld",
		                     (long long)v->faults, faults);
	else if ((status = check_readings(s, err)) != HS_OK)
		;
	else if (s->noise && !hs_noise_load(s->noise, v->noise))
		status = state_error(err, HS_ERR_STATE_MISMATCH, "the noise generator refused its state");
	if (status != HS_OK)
		hs_world_load_state(s->world, before, size);
	free(before);
	return status;
}

// Everything was read and checked: the world first (it refuses a block that does not fit, and is
// then untouched), then the harness.
static hs_status restore(hs_scenario *s, const saved *v, hs_error *err) {
	hs_status status = load_world(s, v, err);
	if (status != HS_OK)
		return status;
	hs_expectations *e = &s->expect;
	if (e->check_count)
		memcpy(e->checks, v->checks, (size_t)e->check_count * sizeof *e->checks);
	e->capture_next = (int)v->capture_next;
	s->frame = (long)v->frame;
	s->step_status = (hs_status)v->step_status;
	s->failed_frame = (long)v->failed_frame;
	s->fault_offset = 0; // the world's counters hold every fault (load_world checked they are the saved count)
	return HS_OK;
}

// The parts read in order from the file's bytes (size and checksum checked after the header).
static hs_status read_parts(const unsigned char *buf, size_t n, size_t expected, hs_scenario *s, saved *v,
                            hs_error *err) {
	if (n < sizeof MAGIC)
		return state_error(err, HS_ERR_STATE_MISMATCH, "not a handspring state file");
	FILE *m = fmemopen((void *)buf, n, "rb");
	if (!m)
		return state_error(err, HS_ERR_NO_MEMORY, "out of memory");
	hs_state_io io = {.file = m, .ok = true, .hash = HS_STATE_HASH_START};
	hs_status status = read_header(&io, s, v, err);
	if (status == HS_OK)
		status = check_whole(buf, n, expected, err);
	if (status == HS_OK)
		status = read_harness(&io, s, v, err);
	if (status == HS_OK)
		status = read_world(&io, s, v, err);
	fclose(m);
	return status;
}

hs_status hs_scenario_resume(hs_scenario *s, FILE *in, hs_error *err) {
	if (!s || !in)
		return state_error(err, HS_ERR_INVALID_ARGUMENT, "no scenario or no file");
	if (s->overridden) // a state is saved from the file as written only (hs_scenario_save)
		return state_error(err, HS_ERR_INVALID_ARGUMENT, "a run loaded with a dt or noise seed option cannot be resumed");
	saved v;
	memset(&v, 0, sizeof v);
	unsigned char *buf = NULL;
	size_t expected = 0, n = 0;
	hs_status status = expected_size(s, &expected, err);
	if (status == HS_OK)
		status = read_bytes(in, expected, &buf, &n, err);
	if (status == HS_OK)
		status = read_parts(buf, n, expected, s, &v, err);
	if (status == HS_OK)
		status = restore(s, &v, err);
	free(buf);
	saved_free(&v);
	return status;
}
