// scenario_state.c — saving a run part-way and resuming it (hs_scenario_save, hs_scenario_resume).
//
// A state file: a header (magic, version, the scenario's name, a checksum of the scenario file's
// bytes, the frame), the harness's own state (the input noise generator, what the expectation
// checks captured so far, the step status and the numeric faults so far), then the world's state
// block (hs_world_save_state). Scripts need no position: they are sampled by time. Integers are
// written little-endian, 64 bits; the checks and the noise generator as the bytes of this build's
// structures (their sizes are in the file and checked), so a state file resumes on the same kind
// of build; the world's block is portable.
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "expect.h"
#include "noise.h"
#include "scenario_internal.h"

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

static bool put_u64(FILE *out, uint64_t v) {
	unsigned char b[8];
	for (int i = 0; i < 8; ++i)
		b[i] = (unsigned char)(v >> (8 * i));
	return fwrite(b, 1, 8, out) == 8;
}

static bool get_u64(FILE *in, uint64_t *v) {
	unsigned char b[8];
	if (fread(b, 1, 8, in) != 8)
		return false;
	*v = 0;
	for (int i = 0; i < 8; ++i)
		*v |= (uint64_t)b[i] << (8 * i);
	return true;
}

// A block: its size, then its bytes.
static bool put_block(FILE *out, const void *data, size_t size) {
	return put_u64(out, size) && (size == 0 || fwrite(data, 1, size, out) == size);
}

// A block of exactly `size` bytes into `data`.
static bool get_block(FILE *in, void *data, size_t size) {
	uint64_t n;
	return get_u64(in, &n) && n == size && (size == 0 || fread(data, 1, size, in) == size);
}

// ---------------------------------------------------------------------------------------------
// save

static bool put_header(FILE *out, const hs_scenario *s) {
	return fwrite(MAGIC, 1, sizeof MAGIC, out) == sizeof MAGIC && put_u64(out, STATE_VERSION) &&
	       put_block(out, s->name, strlen(s->name)) && put_u64(out, s->source_hash) &&
	       put_u64(out, (uint64_t)s->frame) && put_u64(out, (uint64_t)s->frames);
}

static bool put_harness(FILE *out, const hs_scenario *s, const void *noise, size_t noise_size) {
	const hs_expectations *e = &s->expect;
	return put_u64(out, (uint64_t)s->step_status) && put_u64(out, (uint64_t)s->failed_frame) &&
	       put_u64(out, (uint64_t)hs_scenario_faults(s)) && put_block(out, noise, noise_size) &&
	       put_u64(out, (uint64_t)e->capture_next) && put_u64(out, sizeof *e->checks) &&
	       put_block(out, e->checks, (size_t)e->check_count * sizeof *e->checks);
}

hs_status hs_scenario_save(const hs_scenario *s, FILE *out, hs_error *err) {
	if (!s || !out)
		return state_error(err, HS_ERR_INVALID_ARGUMENT, "no scenario or no file");
	size_t world_size = hs_world_state_size(s->world), noise_size = hs_noise_state_size(s->noise);
	void *world = malloc(world_size ? world_size : 1), *noise = malloc(noise_size ? noise_size : 1);
	hs_status status = HS_OK;
	if (!world || !noise)
		status = state_error(err, HS_ERR_NO_MEMORY, "out of memory");
	else if ((status = hs_world_save_state(s->world, world, world_size)) != HS_OK)
		state_error(err, status, "the world cannot save its state: %s", hs_status_string(status));
	else if (s->noise && !hs_noise_save(s->noise, noise, noise_size))
		status = state_error(err, HS_ERR_INVALID_ARGUMENT, "the noise generator cannot save its state");
	else if (!(put_header(out, s) && put_harness(out, s, noise, noise_size) && put_block(out, world, world_size) &&
	           fflush(out) == 0))
		status = state_error(err, HS_ERR_INVALID_ARGUMENT, "cannot write");
	free(world);
	free(noise);
	return status;
}

// ---------------------------------------------------------------------------------------------
// resume

// What a state file holds, read and checked in full before anything is restored.
typedef struct saved {
	uint64_t frame, step_status, failed_frame, faults, capture_next;
	void *noise;
	size_t noise_size;
	hs_check *checks;
	void *world;
	size_t world_size;
} saved;

static void saved_free(saved *v) {
	free(v->noise);
	free(v->checks);
	free(v->world);
}

static hs_status read_header(FILE *in, const hs_scenario *s, saved *v, hs_error *err) {
	char magic[sizeof MAGIC], name[MAX_STATE_NAME + 1];
	uint64_t version = 0, length, hash, frames; // every block's size is the one this scenario needs: none is
	                                            // allocated from a number in the file
	if (fread(magic, 1, sizeof magic, in) != sizeof magic || memcmp(magic, MAGIC, sizeof magic) != 0)
		return state_error(err, HS_ERR_STATE_MISMATCH, "not a handspring state file");
	if (!get_u64(in, &version) || version != STATE_VERSION)
		return state_error(err, HS_ERR_STATE_MISMATCH, "version %llu, this build reads version %d",
		                   (unsigned long long)version, STATE_VERSION);
	if (!get_u64(in, &length) || length > MAX_STATE_NAME || fread(name, 1, (size_t)length, in) != length)
		return state_error(err, HS_ERR_STATE_MISMATCH, "truncated header");
	name[length] = '\0';
	if (strcmp(name, s->name) != 0)
		return state_error(err, HS_ERR_STATE_MISMATCH, "saved from scenario '%s', not '%s'", name, s->name);
	if (!get_u64(in, &hash) || !get_u64(in, &v->frame) || !get_u64(in, &frames))
		return state_error(err, HS_ERR_STATE_MISMATCH, "truncated header");
	if (hash != s->source_hash)
		return state_error(err, HS_ERR_STATE_MISMATCH, "the scenario file '%s' changed since the state was saved",
		                   s->name);
	if (frames != (uint64_t)s->frames || v->frame > frames)
		return state_error(err, HS_ERR_STATE_MISMATCH, "frame %llu of %llu does not fit the scenario's %ld frames",
		                   (unsigned long long)v->frame, (unsigned long long)frames, s->frames);
	return HS_OK;
}

// A block of `size` bytes, allocated into *data.
static bool get_new_block(FILE *in, void **data, size_t size) {
	*data = malloc(size ? size : 1);
	return *data && get_block(in, *data, size);
}

static hs_status read_harness(FILE *in, const hs_scenario *s, saved *v, hs_error *err) {
	const hs_expectations *e = &s->expect;
	uint64_t check_size;
	v->noise_size = hs_noise_state_size(s->noise);
	if (!get_u64(in, &v->step_status) || !get_u64(in, &v->failed_frame) || !get_u64(in, &v->faults) ||
	    !get_new_block(in, &v->noise, v->noise_size) || !get_u64(in, &v->capture_next) || !get_u64(in, &check_size))
		return state_error(err, HS_ERR_STATE_MISMATCH, "the harness's state is truncated or not this scenario's");
	if (check_size != sizeof *e->checks || v->capture_next > (uint64_t)e->capture_count)
		return state_error(err, HS_ERR_STATE_MISMATCH, "the expectations' state is from another build or scenario");
	void *checks;
	if (!get_new_block(in, &checks, (size_t)e->check_count * sizeof *e->checks)) {
		free(checks);
		return state_error(err, HS_ERR_STATE_MISMATCH, "the expectations' state is truncated");
	}
	v->checks = checks;
	for (int i = 0; i < e->check_count; ++i)
		if (v->checks[i].clause != e->checks[i].clause || v->checks[i].object != e->checks[i].object)
			return state_error(err, HS_ERR_STATE_MISMATCH, "the expectations' state is not this scenario's");
	return HS_OK;
}

static hs_status read_world(FILE *in, const hs_scenario *s, saved *v, hs_error *err) {
	v->world_size = hs_world_state_size(s->world);
	if (!get_new_block(in, &v->world, v->world_size))
		return state_error(err, HS_ERR_STATE_MISMATCH, "the world's state is truncated or of another size");
	if (fgetc(in) != EOF)
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
	saved v;
	memset(&v, 0, sizeof v);
	hs_status status = read_header(in, s, &v, err);
	if (status == HS_OK)
		status = read_harness(in, s, &v, err);
	if (status == HS_OK)
		status = read_world(in, s, &v, err);
	if (status == HS_OK)
		status = restore(s, &v, err);
	saved_free(&v);
	return status;
}
