// state_walk.h — one walk over a world's whole state, used four ways (five with the load's dry run):
// to size it, save it, check a buffer, load it and hash it, so they can never disagree on what the
// state is. Every field travels as one 64-bit little-endian word (doubles by their bits, integers
// sign-extended), so a saved state and its hash are the same on every machine, whatever its
// struct layout or padding. The word visitor below is state_walk.c's; the walks are driven by
// each state type's field table (state_fields.h: state.c's body, hand and world tables,
// spring_state.c's spring table), which the walker turns into these calls.
//
// Contract for a walk (world_io in state.c, hs_spring_state_io for the spring system):
//  - visit every STATE field once, in a fixed order that depends only on the model (counts,
//    capacities), never on the values (the size must not change while stepping); one exception,
//    in HASH (and GATHER) mode only: slots beyond a count (hs_state_count) that must be zero
//    (hs_state_zero: CHECK refuses others) may be left out (the spring's warm-start forces);
//  - pass each field through the hs_state_* call of its type; give ranged calls the range a
//    valid state obeys (enums, indices, flags): CHECK refuses a buffer that breaks it;
//  - in CHECK mode nothing is written (the calls only read and validate); in LOAD mode every field
//    is written and the walk may also reset its caches (io->mode == HS_STATE_LOAD);
//  - GATHER writes the words HASH would mix, in order, to `gather` (a hash's fast path mixes
//    them four lanes at a time: hs_state_hash_words);
//  - definitions are not state: a walk may carry a checksum of its own definition with
//    hs_state_def, which SAVE writes, CHECK requires equal and HASH and GATHER skip.
#ifndef HS_STATE_WALK_H
#define HS_STATE_WALK_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <limits.h>
#include <string.h>

#include "hs_math.h"

typedef enum hs_state_mode {
	HS_STATE_SIZE,  // count the words
	HS_STATE_SAVE,  // write them to `out`
	HS_STATE_CHECK, // read them from `in` and validate, writing nothing (load's first pass)
	HS_STATE_LOAD,  // read them from `in` into the fields (after a CHECK pass that passed)
	HS_STATE_HASH,  // mix them into `hash`
	HS_STATE_GATHER, // write them to `gather` as they would be hashed (a hash's fast path: HASH's words, in order)
} hs_state_mode;

typedef struct hs_state_io {
	hs_state_mode mode;
	unsigned char *out;      // SAVE: the buffer's first byte
	const unsigned char *in; // CHECK / LOAD: the buffer's first byte
	size_t words;            // words visited so far
	size_t limit;            // SAVE / CHECK / LOAD: words the buffer holds
	bool overflow;           // SAVE / CHECK / LOAD ran past limit (nothing read or written there)
	uint64_t lane[4];        // HASH: word k is mixed into lane k mod 4 (four independent chains)
	uint64_t *gather;        // GATHER: the words, in host order (room for all of them)
	int objects;             // the world's object count, for walks over per-object arrays
	const char *error;       // CHECK: why the buffer is refused (first refusal), NULL while valid
	size_t error_word;       // CHECK: the word where it was refused
} hs_state_io;

// HASH and GATHER: the words a hash takes (slots a hash leaves out are left out of both).
static inline bool hs_state_hashing(const hs_state_io *io) {
	return io->mode == HS_STATE_HASH || io->mode == HS_STATE_GATHER;
}

// Mixes one 64-bit word into a running hash (multiply, xor-shift: a bijection of the running
// value for every word, so a change in any single word changes the result).
static inline uint64_t hs_state_mix(uint64_t h, uint64_t word) {
	h = (h ^ word) * 0x9E3779B97F4A7C15ull;
	return h ^ (h >> 29);
}
uint64_t hs_state_mix_f64(uint64_t h, double v);
// Mixes words[0..n) into a HASH walk, as n calls of hs_state_hash_word would: the four lanes in
// registers, each word's mix independent of the three before it.
void hs_state_hash_words(hs_state_io *io, const uint64_t *words, size_t n);
// The hash of a HASH walk: its four lanes and word count folded and avalanched (fmix64).
uint64_t hs_state_hash_of(const hs_state_io *io);

// HASH runs every frame: each call below does it inline (one mix into the lane of the word),
// and calls the out-of-line *_io function of state_walk.c for the other modes.
static inline void hs_state_hash_word(hs_state_io *io, uint64_t word) {
	size_t k = io->words++ & 3u;
	io->lane[k] = hs_state_mix(io->lane[k], word);
}
static inline uint64_t hs_state_bits(double v) {
	uint64_t bits;
	memcpy(&bits, &v, sizeof bits);
	return bits;
}

void hs_state_u64_io(hs_state_io *io, uint64_t *v);
void hs_state_f64_io(hs_state_io *io, double *v);
void hs_state_long_range_io(hs_state_io *io, long *v, long lo, long hi);
void hs_state_int_range_io(hs_state_io *io, int *v, int lo, int hi);
void hs_state_u8_range_io(hs_state_io *io, uint8_t *v, uint8_t hi);
void hs_state_bool_io(hs_state_io *io, bool *v);
void hs_state_mask_io(hs_state_io *io, uint64_t *v, int bits);
void hs_state_rotation_io(hs_state_io *io, hs_quat *v);
// A count of slots in [0, hi] (an int word); returns the count the rest of the walk follows: the
// buffer's in CHECK and LOAD (0 when out of range: refused anyway), *v otherwise.
int hs_state_count(hs_state_io *io, int *v, int hi);
// A word that must be zero (a slot beyond its count); CHECK refuses any other.
void hs_state_zero(hs_state_io *io, uint64_t *v);

static inline void hs_state_u64(hs_state_io *io, uint64_t *v) {
	if (io->mode == HS_STATE_HASH)
		hs_state_hash_word(io, *v);
	else
		hs_state_u64_io(io, v);
}
static inline void hs_state_i64(hs_state_io *io, int64_t *v) {
	uint64_t w = (uint64_t)*v;
	hs_state_u64(io, &w);
	if (io->mode == HS_STATE_LOAD)
		*v = (int64_t)w;
}
// CHECK: finite
static inline void hs_state_f64(hs_state_io *io, double *v) {
	if (io->mode == HS_STATE_HASH)
		hs_state_hash_word(io, hs_state_bits(*v));
	else
		hs_state_f64_io(io, v);
}
// CHECK: lo <= v <= hi
static inline void hs_state_long_range(hs_state_io *io, long *v, long lo, long hi) {
	if (io->mode == HS_STATE_HASH)
		hs_state_hash_word(io, (uint64_t)(int64_t)*v);
	else
		hs_state_long_range_io(io, v, lo, hi);
}
static inline void hs_state_long(hs_state_io *io, long *v) { hs_state_long_range(io, v, LONG_MIN, LONG_MAX); }
static inline void hs_state_int_range(hs_state_io *io, int *v, int lo, int hi) {
	if (io->mode == HS_STATE_HASH)
		hs_state_hash_word(io, (uint64_t)(int64_t)*v);
	else
		hs_state_int_range_io(io, v, lo, hi);
}
static inline void hs_state_int(hs_state_io *io, int *v) { hs_state_int_range(io, v, INT_MIN, INT_MAX); }
// CHECK: v <= hi
static inline void hs_state_u8_range(hs_state_io *io, uint8_t *v, uint8_t hi) {
	if (io->mode == HS_STATE_HASH)
		hs_state_hash_word(io, *v);
	else
		hs_state_u8_range_io(io, v, hi);
}
static inline void hs_state_u8(hs_state_io *io, uint8_t *v) { hs_state_u8_range(io, v, UINT8_MAX); }
// CHECK: 0 or 1
static inline void hs_state_bool(hs_state_io *io, bool *v) {
	if (io->mode == HS_STATE_HASH)
		hs_state_hash_word(io, *v ? 1u : 0u);
	else
		hs_state_bool_io(io, v);
}
// CHECK: no bit at or above `bits`
static inline void hs_state_mask(hs_state_io *io, uint64_t *v, int bits) {
	if (io->mode == HS_STATE_HASH)
		hs_state_hash_word(io, *v);
	else
		hs_state_mask_io(io, v, bits);
}
// 3 words
static inline void hs_state_vec3(hs_state_io *io, hs_vec3 *v) {
	hs_state_f64(io, &v->x);
	hs_state_f64(io, &v->y);
	hs_state_f64(io, &v->z);
}
// 4 words (w, x, y, z); CHECK: finite only (zero quaternions are allowed)
static inline void hs_state_quat(hs_state_io *io, hs_quat *v) {
	hs_state_f64(io, &v->w);
	hs_state_f64(io, &v->x);
	hs_state_f64(io, &v->y);
	hs_state_f64(io, &v->z);
}
// 4 words; CHECK: a unit quaternion (hs_quat_is_unit)
static inline void hs_state_rotation(hs_state_io *io, hs_quat *v) {
	if (io->mode == HS_STATE_HASH)
		hs_state_quat(io, v);
	else
		hs_state_rotation_io(io, v);
}
static inline void hs_state_vec3_array(hs_state_io *io, hs_vec3 *v, int count) {
	for (int i = 0; i < count; ++i)
		hs_state_vec3(io, &v[i]);
}
// A definition checksum: SAVE writes it, CHECK refuses a buffer whose word differs (`what`
// names the definition in the reason), LOAD skips it, HASH and GATHER ignore it.
void hs_state_def(hs_state_io *io, uint64_t checksum, const char *what);
// CHECK: refuses the buffer with `why` (a static string) at the current word.
void hs_state_refuse(hs_state_io *io, const char *why);

#endif
