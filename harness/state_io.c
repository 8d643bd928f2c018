// state_io.c — 64-bit little-endian words for state files (see state_io.h).
#include <string.h>

#include "state_io.h"

static void hash_bytes(hs_state_io *io, const unsigned char *b, size_t n) {
	for (size_t i = 0; i < n; ++i)
		io->hash = (io->hash ^ b[i]) * 1099511628211ull;
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
