// state_walk.c — the word visitor of state_walk.h: every state field as one 64-bit little-endian
// word, sized, saved, checked, loaded or hashed by the mode of the walk.
#include <limits.h>
#include <string.h>

#include "state_walk.h"

uint64_t hs_state_mix_f64(uint64_t h, double v) {
	uint64_t bits;
	memcpy(&bits, &v, sizeof bits);
	return hs_state_mix(h, bits);
}

static void put_le(unsigned char *p, uint64_t v) {
	for (int i = 0; i < 8; ++i)
		p[i] = (unsigned char)(v >> (8 * i));
}

static uint64_t get_le(const unsigned char *p) {
	uint64_t v = 0;
	for (int i = 0; i < 8; ++i)
		v |= (uint64_t)p[i] << (8 * i);
	return v;
}

// The one place a word moves: returns the word read (CHECK / LOAD) or `v` (other modes).
static uint64_t word(hs_state_io *io, uint64_t v) {
	size_t at = io->words++;
	switch (io->mode) {
	case HS_STATE_SIZE:
		return v;
	case HS_STATE_HASH:
		io->words--; // the inline hs_state_hash_word counts its own words
		hs_state_hash_word(io, v);
		return v;
	case HS_STATE_GATHER:
		io->gather[at] = v;
		return v;
	case HS_STATE_SAVE:
		if (at < io->limit)
			put_le(io->out + 8 * at, v);
		else
			io->overflow = true;
		return v;
	case HS_STATE_CHECK:
	case HS_STATE_LOAD:
		break;
	}
	if (at >= io->limit) {
		io->overflow = true;
		return v; // the value the field already has: nothing is loaded past the end
	}
	return get_le(io->in + 8 * at);
}

void hs_state_refuse(hs_state_io *io, const char *why) {
	if (io->mode == HS_STATE_CHECK && !io->error) {
		io->error = why;
		io->error_word = io->words > 0 ? io->words - 1 : 0;
	}
}

static bool loading(const hs_state_io *io) { return io->mode == HS_STATE_LOAD; }

uint64_t hs_state_hash_of(const hs_state_io *io) {
	uint64_t h = io->lane[0];
	for (int k = 1; k < 4; ++k) // rotations keep equal lanes from cancelling
		h ^= (io->lane[k] << (16 * k)) | (io->lane[k] >> (64 - 16 * k));
	h ^= (uint64_t)io->words;
	h = (h ^ (h >> 33)) * 0xFF51AFD7ED558CCDull;
	h = (h ^ (h >> 33)) * 0xC4CEB9FE1A85EC53ull;
	return h ^ (h >> 33);
}

void hs_state_hash_words(hs_state_io *io, const uint64_t *words, size_t n) {
	size_t s = io->words & 3u, i = 0; // lanes turned so that `a` takes the next word
	uint64_t a = io->lane[s], b = io->lane[(s + 1) & 3u], c = io->lane[(s + 2) & 3u], d = io->lane[(s + 3) & 3u];
	for (; i + 4 <= n; i += 4) {
		a = hs_state_mix(a, words[i]);
		b = hs_state_mix(b, words[i + 1]);
		c = hs_state_mix(c, words[i + 2]);
		d = hs_state_mix(d, words[i + 3]);
	}
	if (i < n)
		a = hs_state_mix(a, words[i++]);
	if (i < n)
		b = hs_state_mix(b, words[i++]);
	if (i < n)
		c = hs_state_mix(c, words[i++]);
	io->lane[s] = a, io->lane[(s + 1) & 3u] = b, io->lane[(s + 2) & 3u] = c, io->lane[(s + 3) & 3u] = d;
	io->words += n;
}

void hs_state_u64_io(hs_state_io *io, uint64_t *v) {
	uint64_t w = word(io, *v);
	if (loading(io))
		*v = w;
}

int hs_state_count(hs_state_io *io, int *v, int hi) {
	int64_t w = (int64_t)word(io, (uint64_t)(int64_t)*v);
	bool in_range = w >= 0 && w <= (int64_t)hi;
	if (!in_range)
		hs_state_refuse(io, "a count out of range");
	if (loading(io))
		*v = in_range ? (int)w : 0;
	return io->mode == HS_STATE_CHECK || io->mode == HS_STATE_LOAD ? (in_range ? (int)w : 0) : *v;
}

void hs_state_zero(hs_state_io *io, uint64_t *v) {
	uint64_t w = word(io, *v);
	if (w != 0u)
		hs_state_refuse(io, "a slot beyond its count not zero");
	if (loading(io))
		*v = 0u;
}

void hs_state_f64_io(hs_state_io *io, double *v) {
	uint64_t w = word(io, hs_state_bits(*v));
	double d;
	memcpy(&d, &w, sizeof d);
	if (!isfinite(d))
		hs_state_refuse(io, "a non-finite number");
	if (loading(io))
		*v = d;
}

void hs_state_long_range_io(hs_state_io *io, long *v, long lo, long hi) {
	int64_t w = (int64_t)word(io, (uint64_t)(int64_t)*v);
	if (w < (int64_t)lo || w > (int64_t)hi)
		hs_state_refuse(io, "an integer out of range");
	if (loading(io))
		*v = (long)w;
}

void hs_state_int_range_io(hs_state_io *io, int *v, int lo, int hi) {
	long l = *v;
	hs_state_long_range_io(io, &l, lo, hi);
	if (loading(io))
		*v = (int)l;
}

void hs_state_u8_range_io(hs_state_io *io, uint8_t *v, uint8_t hi) {
	uint64_t w = word(io, *v);
	if (w > hi)
		hs_state_refuse(io, "a flag or enum out of range");
	if (loading(io))
		*v = (uint8_t)w;
}

void hs_state_mask_io(hs_state_io *io, uint64_t *v, int bits) {
	uint64_t w = word(io, *v);
	if (bits < 64 && w >> bits)
		hs_state_refuse(io, "a bit mask with bits out of range");
	if (loading(io))
		*v = w;
}

void hs_state_bool_io(hs_state_io *io, bool *v) {
	uint64_t w = word(io, *v ? 1u : 0u);
	if (w > 1)
		hs_state_refuse(io, "a boolean neither 0 nor 1");
	if (loading(io))
		*v = w != 0;
}

void hs_state_rotation_io(hs_state_io *io, hs_quat *v) {
	size_t first = io->words;
	hs_quat q = *v;
	hs_state_quat(io, &q); // CHECK leaves q as it was: read the words again to test them
	if (io->mode == HS_STATE_CHECK && first + 4 <= io->limit) {
		const unsigned char *p = io->in + 8 * first;
		uint64_t w[4] = {get_le(p), get_le(p + 8), get_le(p + 16), get_le(p + 24)};
		memcpy(&q.w, &w[0], 8);
		memcpy(&q.x, &w[1], 8);
		memcpy(&q.y, &w[2], 8);
		memcpy(&q.z, &w[3], 8);
		if (!hs_quat_is_unit(q))
			hs_state_refuse(io, "an orientation that is not a unit quaternion");
	}
	if (loading(io))
		*v = q;
}

void hs_state_def(hs_state_io *io, uint64_t checksum, const char *what) {
	if (hs_state_hashing(io)) // definitions do not change while stepping
		return;
	uint64_t w = word(io, checksum);
	if (w != checksum)
		hs_state_refuse(io, what);
}
