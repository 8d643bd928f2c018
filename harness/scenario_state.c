// scenario_state.c — saving a run part-way and resuming it (hs_scenario_save, hs_scenario_resume).
//
// A state file: a header (magic, version, the scenario's name, a checksum of the scenario file's
// bytes, the frame), the harness's own state (the step status, the numeric faults so far, the input
// noise generator, the capture queue and what every expectation check captured), then the world's
// state block (hs_world_save_state), and a checksum of all that (FNV-1a). Scripts need no
// position: they are sampled by time. Numbers are 64-bit little-endian words (state_io.h) and the
// world's block is portable; only the noise generator's block is the bytes of GSL's state
// (gsl_rng_state), whose size is checked.
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "expect_table.h"
#include "noise.h"
#include "scenario_internal.h"
#include "state_io.h"

static const char MAGIC[8] = {'H', 'S', 'S', 'T', 'A', 'T', 'E', '\n'};
enum { STATE_VERSION = 1, MAX_STATE_NAME = 4096 };

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

// A block of exactly `size` bytes into `data`.
static void get_block(hs_state_io *io, void *data, size_t size) {
	io->ok = io->ok && hs_get_u64(io) == size;
	hs_get_bytes(io, data, size);
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

static void put_harness(hs_state_io *io, const hs_scenario *s, const void *noise, size_t noise_size) {
	const hs_expectations *e = &s->expect;
	hs_put_i64(io, s->step_status);
	hs_put_i64(io, s->failed_frame);
	hs_put_i64(io, hs_scenario_faults(s));
	put_block(io, noise, noise_size);
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
	size_t world_size = hs_world_state_size(s->world), noise_size = hs_noise_state_size(s->noise);
	void *world = malloc(world_size ? world_size : 1), *noise = malloc(noise_size ? noise_size : 1);
	hs_state_io io = {out, true, HS_STATE_HASH_START};
	hs_status status = HS_OK;
	if (!world || !noise)
		status = state_error(err, HS_ERR_NO_MEMORY, "out of memory");
	else if ((status = hs_world_save_state(s->world, world, world_size)) != HS_OK)
		state_error(err, status, "the world cannot save its state: %s", hs_status_string(status));
	else if (s->noise && !hs_noise_save(s->noise, noise, noise_size))
		status = state_error(err, HS_ERR_INVALID_ARGUMENT, "the noise generator cannot save its state");
	if (status == HS_OK) {
		put_header(&io, s);
		put_harness(&io, s, noise, noise_size);
		put_block(&io, world, world_size);
		hs_put_u64(&io, io.hash); // of everything before it
		if (!io.ok || fflush(out) != 0)
			status = state_error(err, HS_ERR_INVALID_ARGUMENT, "cannot write");
	}
	free(world);
	free(noise);
	return status;
}

// ---------------------------------------------------------------------------------------------
// resume

// What a state file holds, read and checked in full before anything is restored.
typedef struct saved {
	int64_t frame, step_status, failed_frame, faults, capture_next;
	void *noise;
	size_t noise_size;
	hs_check *checks; // a copy of the scenario's, with the saved captures
	void *world;
	size_t world_size;
} saved;

static void saved_free(saved *v) {
	free(v->noise);
	free(v->checks);
	free(v->world);
}

static hs_status read_header(hs_state_io *io, const hs_scenario *s, saved *v, hs_error *err) {
	char magic[sizeof MAGIC], name[MAX_STATE_NAME + 1];
	hs_get_bytes(io, magic, sizeof magic);
	if (!io->ok || memcmp(magic, MAGIC, sizeof magic) != 0)
		return state_error(err, HS_ERR_STATE_MISMATCH, "not a handspring state file");
	uint64_t version = hs_get_u64(io), length = hs_get_u64(io);
	if (!io->ok || version != STATE_VERSION)
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
	if (strcmp(name, s->name) != 0)
		return state_error(err, HS_ERR_STATE_MISMATCH, "saved from scenario '%s', not '%s'", name, s->name);
	if (hash != s->source_hash)
		return state_error(err, HS_ERR_STATE_MISMATCH, "the scenario file '%s' changed since the state was saved",
		                   s->name);
	if (frames != s->frames || v->frame < 0 || v->frame > frames)
		return state_error(err, HS_ERR_STATE_MISMATCH, "frame %lld of %lld does not fit the scenario's %ld frames",
		                   (long long)v->frame, (long long)frames, s->frames);
	return HS_OK;
}

static hs_status read_harness(hs_state_io *io, const hs_scenario *s, saved *v, hs_error *err) {
	const hs_expectations *e = &s->expect;
	v->noise_size = hs_noise_state_size(s->noise);
	v->noise = malloc(v->noise_size ? v->noise_size : 1);
	v->checks = malloc(e->check_count ? (size_t)e->check_count * sizeof *v->checks : 1);
	if (!v->noise || !v->checks)
		return state_error(err, HS_ERR_NO_MEMORY, "out of memory");
	v->step_status = hs_get_i64(io);
	v->failed_frame = hs_get_i64(io);
	v->faults = hs_get_i64(io);
	get_block(io, v->noise, v->noise_size);
	v->capture_next = hs_get_i64(io);
	int64_t checks = hs_get_i64(io);
	if (!io->ok || checks != e->check_count || v->capture_next < 0 || v->capture_next > e->capture_count)
		return state_error(err, HS_ERR_STATE_MISMATCH, "the harness's state is truncated or not this scenario's");
	if (e->check_count)
		memcpy(v->checks, e->checks, (size_t)e->check_count * sizeof *v->checks);
	for (int i = 0; i < e->check_count; ++i)
		hs_capture_get(io, store_of(s, &v->checks[i]), &v->checks[i]);
	if (!io->ok)
		return state_error(err, HS_ERR_STATE_MISMATCH, "the expectations' state is truncated");
	return HS_OK;
}

static hs_status read_world(hs_state_io *io, const hs_scenario *s, saved *v, hs_error *err) {
	v->world_size = hs_world_state_size(s->world);
	v->world = malloc(v->world_size ? v->world_size : 1);
	if (!v->world)
		return state_error(err, HS_ERR_NO_MEMORY, "out of memory");
	get_block(io, v->world, v->world_size);
	if (!io->ok)
		return state_error(err, HS_ERR_STATE_MISMATCH, "the world's state is truncated or of another size");
	uint64_t hash = io->hash, saved_hash = hs_get_u64(io);
	if (!io->ok || saved_hash != hash)
		return state_error(err, HS_ERR_STATE_MISMATCH, "damaged: its checksum does not match");
	if (fgetc(io->file) != EOF)
		return state_error(err, HS_ERR_STATE_MISMATCH, "bytes after the world's state");
	return HS_OK;
}

// Everything was read and checked: the world first (it refuses a block that does not fit, and is
// then untouched), then the harness.
static hs_status restore(hs_scenario *s, const saved *v, hs_error *err) {
	hs_status status = hs_world_load_state(s->world, v->world, v->world_size);
	if (status != HS_OK)
		return state_error(err, status, "the world refused its state: %s", hs_world_state_error(s->world));
	if (s->noise && !hs_noise_load(s->noise, v->noise, v->noise_size))
		return state_error(err, HS_ERR_STATE_MISMATCH, "the noise generator refused its state");
	hs_expectations *e = &s->expect;
	if (e->check_count)
		memcpy(e->checks, v->checks, (size_t)e->check_count * sizeof *e->checks);
	e->capture_next = (int)v->capture_next;
	s->frame = (long)v->frame;
	s->step_status = (hs_status)v->step_status;
	s->failed_frame = (long)v->failed_frame;
	s->fault_offset = (long)v->faults - hs_world_get_counters(s->world).numeric_faults;
	return HS_OK;
}

hs_status hs_scenario_resume(hs_scenario *s, FILE *in, hs_error *err) {
	if (!s || !in)
		return state_error(err, HS_ERR_INVALID_ARGUMENT, "no scenario or no file");
	if (s->overridden) // a state is saved from the file as written only (hs_scenario_save)
		return state_error(err, HS_ERR_INVALID_ARGUMENT, "a run loaded with a dt or noise seed option cannot be resumed");
	saved v;
	memset(&v, 0, sizeof v);
	hs_state_io io = {in, true, HS_STATE_HASH_START};
	hs_status status = read_header(&io, s, &v, err);
	if (status == HS_OK)
		status = read_harness(&io, s, &v, err);
	if (status == HS_OK)
		status = read_world(&io, s, &v, err);
	if (status == HS_OK)
		status = restore(s, &v, err);
	saved_free(&v);
	return status;
}
