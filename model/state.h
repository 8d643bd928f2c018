// state.h — one walk over a world's whole state, used four ways (five with the load's dry run):
// to size it, save it, check a buffer, load it and hash it, so they can never disagree on what the
// state is. Every field travels as one 64-bit little-endian word (doubles by their bits, integers
// sign-extended), so a saved state and its hash are the same on every machine, whatever its
// struct layout or padding.
//
// Contract for a walk (world_io in state.c, hs_spring_state_io for the spring system):
//  - visit every STATE field once, in a fixed order that depends only on the model (counts,
//    capacities), never on the values (the size must not change while stepping);
//  - pass each field through the hs_state_* call of its type; give ranged calls the range a
//    valid state obeys (enums, indices, flags): CHECK refuses a buffer that breaks it;
//  - in CHECK mode nothing is written (the calls only read and validate); in LOAD mode every field
//    is written and the walk may also reset its caches (io->mode == HS_STATE_LOAD);
//  - definitions are not state: a walk may carry a checksum of its own definition with
//    hs_state_def, which SAVE writes, CHECK requires equal and HASH skips.
#ifndef HS_STATE_H
#define HS_STATE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "hs_math.h"

typedef enum hs_state_mode {
	HS_STATE_SIZE,  // count the words
	HS_STATE_SAVE,  // write them to `out`
	HS_STATE_CHECK, // read them from `in` and validate, writing nothing (load's first pass)
	HS_STATE_LOAD,  // read them from `in` into the fields (after a CHECK pass that passed)
	HS_STATE_HASH,  // mix them into `hash`
} hs_state_mode;

typedef struct hs_state_io {
	hs_state_mode mode;
	unsigned char *out;      // SAVE: the buffer's first byte
	const unsigned char *in; // CHECK / LOAD: the buffer's first byte
	size_t words;            // words visited so far
	size_t limit;            // SAVE / CHECK / LOAD: words the buffer holds
	bool overflow;           // SAVE / CHECK / LOAD ran past limit (nothing read or written there)
	uint64_t hash;           // HASH: running hash of the words
	int objects;             // the world's object count, for walks over per-object arrays
	const char *error;       // CHECK: why the buffer is refused (first refusal), NULL while valid
	size_t error_word;       // CHECK: the word where it was refused
} hs_state_io;

// Mixes one 64-bit word into a running hash (multiply, xor-shift: a bijection of the running
// value for every word, so a change in any single word changes the result).
static inline uint64_t hs_state_mix(uint64_t h, uint64_t word) {
	h = (h ^ word) * 0x9E3779B97F4A7C15ull;
	return h ^ (h >> 29);
}
uint64_t hs_state_mix_f64(uint64_t h, double v);

void hs_state_u64(hs_state_io *io, uint64_t *v);
void hs_state_f64(hs_state_io *io, double *v);   // CHECK: finite
void hs_state_i64(hs_state_io *io, int64_t *v);
void hs_state_int(hs_state_io *io, int *v);      // CHECK: fits an int
void hs_state_long(hs_state_io *io, long *v);    // CHECK: fits a long (32 bits on i386)
void hs_state_u8(hs_state_io *io, uint8_t *v);   // CHECK: 0..255
void hs_state_bool(hs_state_io *io, bool *v);    // CHECK: 0 or 1
void hs_state_vec3(hs_state_io *io, hs_vec3 *v); // 3 words
void hs_state_quat(hs_state_io *io, hs_quat *v); // 4 words (w, x, y, z); CHECK: finite only
// Ranged and array forms.
void hs_state_int_range(hs_state_io *io, int *v, int lo, int hi);      // CHECK: lo <= v <= hi
void hs_state_long_range(hs_state_io *io, long *v, long lo, long hi);  // CHECK: lo <= v <= hi
void hs_state_u8_range(hs_state_io *io, uint8_t *v, uint8_t hi);       // CHECK: v <= hi
void hs_state_rotation(hs_state_io *io, hs_quat *v);                   // CHECK: a unit quaternion
void hs_state_vec3_array(hs_state_io *io, hs_vec3 *v, int count);
// A definition checksum: SAVE writes it, CHECK refuses a buffer whose word differs (`what`
// names the definition in the reason), LOAD skips it, HASH ignores it.
void hs_state_def(hs_state_io *io, uint64_t checksum, const char *what);
// CHECK: refuses the buffer with `why` (a static string) at the current word.
void hs_state_refuse(hs_state_io *io, const char *why);

#endif
