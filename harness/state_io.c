// state_io.c — 64-bit little-endian words for state files (see state_io.h).
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "state_io.h"

static void hash_bytes(hs_state_io *io, const unsigned char *b, size_t n) {
	for (size_t i = 0; i < n; ++i)
		io->hash = (io->hash ^ b[i]) * 1099511628211ull;
}

uint64_t hs_state_checksum(const void *data, size_t size) {
	hs_state_io io = {.hash = HS_STATE_HASH_START};
	hash_bytes(&io, data, size);
	return io.hash;
}

void hs_put_u64(hs_state_io *io, uint64_t v) {
	unsigned char b[8];
	for (int i = 0; i < 8; ++i)
		b[i] = (unsigned char)(v >> (8 * i));
	io->ok = io->ok && fwrite(b, 1, 8, io->file) == 8;
	hash_bytes(io, b, 8);
}

void hs_put_i64(hs_state_io *io, int64_t v) { hs_put_u64(io, (uint64_t)v); }

void hs_put_f64(hs_state_io *io, double v) {
	uint64_t bits;
	memcpy(&bits, &v, sizeof bits); // the exact bits: a resumed run continues bit for bit
	hs_put_u64(io, bits);
}

void hs_put_vec3(hs_state_io *io, hs_vec3 v) {
	hs_put_f64(io, v.x);
	hs_put_f64(io, v.y);
	hs_put_f64(io, v.z);
}

void hs_put_bytes(hs_state_io *io, const void *data, size_t size) {
	io->ok = io->ok && (size == 0 || fwrite(data, 1, size, io->file) == size);
	hash_bytes(io, data, size);
}

uint64_t hs_get_u64(hs_state_io *io) {
	unsigned char b[8];
	io->ok = io->ok && fread(b, 1, 8, io->file) == 8;
	if (io->ok)
		hash_bytes(io, b, 8);
	uint64_t v = 0;
	for (int i = 0; io->ok && i < 8; ++i)
		v |= (uint64_t)b[i] << (8 * i);
	return v;
}

int64_t hs_get_i64(hs_state_io *io) {
	uint64_t u = hs_get_u64(io);
	int64_t v;
	memcpy(&v, &u, sizeof v); // two's complement on every target: no implementation-defined conversion
	return v;
}

double hs_get_f64(hs_state_io *io) {
	uint64_t bits = hs_get_u64(io);
	double v;
	memcpy(&v, &bits, sizeof v);
	return v;
}

hs_vec3 hs_get_vec3(hs_state_io *io) {
	double x = hs_get_f64(io), y = hs_get_f64(io), z = hs_get_f64(io);
	return hs_v3(x, y, z);
}

void hs_get_bytes(hs_state_io *io, void *data, size_t size) {
	io->ok = io->ok && (size == 0 || fread(data, 1, size, io->file) == size);
	if (io->ok)
		hash_bytes(io, data, size);
}

// ---------------------------------------------------------------------------------------------
// checked reads: every word of the harness's part is tested against its field's range

void hs_state_refuse_field(hs_state_io *io, const char *field, const char *why) {
	if (io->refused[0] == '\0')
		snprintf(io->refused, sizeof io->refused, "%s%s %s", io->where ? io->where : "", field, why);
	io->ok = false;
}

int64_t hs_get_range(hs_state_io *io, const char *field, int64_t lo, int64_t hi) {
	int64_t v = hs_get_i64(io);
	if (!io->ok)
		return lo;
	if (v < lo || v > hi) {
		char why[120];
		snprintf(why, sizeof why, "is %lld, not within [%lld, %lld]", (long long)v, (long long)lo, (long long)hi);
		hs_state_refuse_field(io, field, why);
		return lo;
	}
	return v;
}

bool hs_get_flag(hs_state_io *io, const char *field) { return hs_get_range(io, field, 0, 1) != 0; }

double hs_get_finite(hs_state_io *io, const char *field) {
	double v = hs_get_f64(io);
	if (!io->ok)
		return 0.0;
	if (!isfinite(v)) {
		hs_state_refuse_field(io, field, "is not a finite number");
		return 0.0;
	}
	return v;
}

hs_vec3 hs_get_finite3(hs_state_io *io, const char *field) {
	double x = hs_get_finite(io, field), y = hs_get_finite(io, field), z = hs_get_finite(io, field);
	return hs_v3(x, y, z);
}

long hs_get_frame(hs_state_io *io, const char *field) { return (long)hs_get_range(io, field, 0, io->frame); }

int hs_get_object(hs_state_io *io, const char *field) { return (int)hs_get_range(io, field, -1, io->objects - 1); }
