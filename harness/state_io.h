// state_io.h — the words of a state file: integers and doubles as 64-bit little-endian words (a
// double by its bits), so the harness's part of a state file reads back the same on any machine.
// Errors are sticky: after the first failed read or write every call does nothing and `ok` is false.
// Every byte written or read so far is hashed (FNV-1a, 64 bits), so a file can end with its checksum.
// The checked reads (hs_get_range and after) also refuse a word out of its field's range: `ok`
// turns false and `refused` names the field, its value and its range, for a one-line message.
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
	// checked reads: the ranges they test against, the field's place, the first field refused
	long frame;        // the saved frame: a frame a capture records lies within [0, frame]
	int objects;       // an object index lies within [-1, objects - 1]
	const char *where; // prefixed to a field's name in `refused` ("" or NULL: none)
	char refused[240]; // empty while every field read so far was within its range
} hs_state_io;

#define HS_STATE_HASH_START 14695981039346656037ull
// The hash of `size` bytes from the start: what a file's last word holds for the bytes before it.
uint64_t hs_state_checksum(const void *data, size_t size);

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

// A whole number within [lo, hi]; lo when it is not (io->ok then false, io->refused set).
int64_t hs_get_range(hs_state_io *io, const char *field, int64_t lo, int64_t hi);
// 0 or 1.
bool hs_get_flag(hs_state_io *io, const char *field);
// A finite double; 0 when it is not.
double hs_get_finite(hs_state_io *io, const char *field);
hs_vec3 hs_get_finite3(hs_state_io *io, const char *field);
// A frame a capture recorded: within [0, io->frame].
long hs_get_frame(hs_state_io *io, const char *field);
// An object index, or -1 for none: within [-1, io->objects - 1].
int hs_get_object(hs_state_io *io, const char *field);
// Refuses the field with a reason of the caller's (when no field was refused before).
void hs_state_refuse_field(hs_state_io *io, const char *field, const char *why);

#endif
