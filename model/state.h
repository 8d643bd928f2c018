// state.h — one walk over a world's whole state, used four ways: to size it, save it, load it
// and hash it, so the four can never disagree on what the state is. Every field travels as one
// 64-bit little-endian word (doubles by their bits, integers sign-extended), so a saved state and
// its hash are the same on every machine, whatever its struct layout or padding.
#ifndef HS_STATE_H
#define HS_STATE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "hs_math.h"

typedef enum hs_state_mode { HS_STATE_SIZE, HS_STATE_SAVE, HS_STATE_LOAD, HS_STATE_HASH } hs_state_mode;

typedef struct hs_state_io {
	hs_state_mode mode;
	unsigned char *out;     // SAVE: next byte to write
	const unsigned char *in; // LOAD: next byte to read
	size_t words;           // words visited so far
	size_t limit;           // SAVE / LOAD: words the buffer holds
	bool overflow;          // SAVE / LOAD ran past limit
	bool invalid;           // LOAD read a value out of range (a bad index, enum or number)
	const char *why;        // LOAD: what the first invalid value was (static text)
	uint64_t hash;          // HASH: running hash of the words
} hs_state_io;

void hs_state_u64(hs_state_io *io, uint64_t *v);
void hs_state_f64(hs_state_io *io, double *v);
void hs_state_i64(hs_state_io *io, int64_t *v);
void hs_state_int(hs_state_io *io, int *v);
void hs_state_long(hs_state_io *io, long *v);
void hs_state_u8(hs_state_io *io, uint8_t *v);
void hs_state_bool(hs_state_io *io, bool *v);
void hs_state_vec3(hs_state_io *io, hs_vec3 *v);
void hs_state_quat(hs_state_io *io, hs_quat *v);

#endif
