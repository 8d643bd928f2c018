// state_io.h — the words of a state file: integers and doubles as 64-bit little-endian words (a
// double by its bits), so the harness's part of a state file reads back the same on any machine.
// Errors are sticky: after the first failed read or write every call does nothing and `ok` is false.
// Every byte written or read so far is hashed (FNV-1a, 64 bits), so a file can end with its checksum.
#ifndef HS_HARNESS_STATE_IO_H
#define HS_HARNESS_STATE_IO_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "handspring.h"

typedef struct hs_state_io {
	FILE *file;
	bool ok;
	uint64_t hash; // of the bytes so far: start it at HS_STATE_HASH_START
} hs_state_io;

#define HS_STATE_HASH_START 14695981039346656037ull

void hs_put_u64(hs_state_io *io, uint64_t v);
void hs_put_i64(hs_state_io *io, int64_t v);
void hs_put_f64(hs_state_io *io, double v);
void hs_put_vec3(hs_state_io *io, hs_vec3 v);
void hs_put_bytes(hs_state_io *io, const void *data, size_t size);

uint64_t hs_get_u64(hs_state_io *io);
int64_t hs_get_i64(hs_state_io *io);
double hs_get_f64(hs_state_io *io);
hs_vec3 hs_get_vec3(hs_state_io *io);
void hs_get_bytes(hs_state_io *io, void *data, size_t size);

#endif
