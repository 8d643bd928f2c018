// state_fields.h — a state type's fields as one table, and the one walker that sizes, saves,
// checks, loads, hashes and gathers them from it (the word visitor of state_walk.h does each
// word). A field added to a table is followed by all of them; nothing else lists it.
//
// An entry says where a field is (offsetof in the walked struct, or through a pointer of it),
// its kind (how it travels as words and what CHECK accepts: state_walk.h), how many elements,
// and, when they depend on the struct, its range's bound, the condition under which it exists and
// its element count. A group walks its members element by element (older_pos[0], older_rot[0],
// older_pos[1], ...); a counted group also walks a count word first, and its slots beyond the
// count travel as zero words (CHECK refuses others, LOAD zeroes them, a hash leaves them out).
//
// The walker is inlined (HS_FORCE_INLINE) where a hash runs every frame: the tables are constant,
// every entry's loop is unrolled (the pragma), and the compiler folds each entry's kind, offset
// and mode test away: a constant table's walk compiles to what a hand-written one would be.
// Elsewhere hs_fields_io is the same walker out of line.
#ifndef HS_STATE_FIELDS_H
#define HS_STATE_FIELDS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "inline.h"
#include "state_walk.h"

typedef enum hs_field_kind {
	HS_FIELD_F64,      // double: 1 word (its bits); CHECK: finite
	HS_FIELD_VEC3,     // hs_vec3: 3 words x, y, z; CHECK: finite
	HS_FIELD_QUAT,     // hs_quat: 4 words w, x, y, z; CHECK: finite (a zero quaternion is allowed)
	HS_FIELD_ROTATION, // hs_quat: 4 words; CHECK: a unit quaternion
	HS_FIELD_U8,       // uint8_t, zero-extended; CHECK: <= hi
	HS_FIELD_BOOL,     // bool: 0 or 1; CHECK: nothing else
	HS_FIELD_INT,      // int (or an enum the size of one), sign-extended; CHECK: lo <= v <= hi
	HS_FIELD_U32,      // uint32_t read as an int (an index stored unsigned); CHECK: lo <= v <= hi
	HS_FIELD_LONG,     // long, sign-extended; CHECK: lo <= v <= hi
	HS_FIELD_MASK32,   // uint32_t bit mask, zero-extended; CHECK: no bit at or above hi
	HS_FIELD_MASK64,   // uint64_t bit mask; CHECK: no bit at or above hi
	HS_FIELD_GROUP,    // its members, element by element
} hs_field_kind;

typedef struct hs_field {
	const char *name;
	uint8_t kind;        // hs_field_kind
	bool through;        // `offset` holds a pointer to the elements (an array the struct allocates)
	uint32_t offset;     // from the walked struct: the field (its first element), or the pointer
	uint32_t inner;      // through a pointer: from each element
	uint32_t stride;     // bytes from an element to the next (a group's member: per element of the group)
	int count;           // elements (1: a plain field), unless count_at says otherwise
	uint32_t count_at;   // 1 + the offset of the walked struct's int holding the count (0: `count`)
	uint32_t when;       // 1 + the offset of its bool: the field exists only while it is true (0: always)
	int64_t lo, hi;      // the range of INT, U32, LONG; hi of U8; bits of a MASK
	uint32_t hi_at;      // 1 + the offset of the walked struct's int added to hi (0: none)
	uint8_t hi_ctx;      // 1 + the index of the walk's context value added to hi (0: none)
	uint32_t counted;    // GROUP: 1 + the offset of its count, an int in [0, count] walked first
	const struct hs_field *members; // GROUP: its members (plain fields)
	int member_count;
} hs_field;

// The bytes of a kind's C type (a constant expression: the entry macros check fields against it).
#define HS_FIELD_BYTES(k)                                                                                   \
	((k) == HS_FIELD_F64 ? sizeof(double)                                                                \
	 : (k) == HS_FIELD_VEC3 ? sizeof(hs_vec3)                                                            \
	 : (k) == HS_FIELD_QUAT || (k) == HS_FIELD_ROTATION ? sizeof(hs_quat)                                \
	 : (k) == HS_FIELD_U8 ? sizeof(uint8_t)                                                              \
	 : (k) == HS_FIELD_BOOL ? sizeof(bool)                                                               \
	 : (k) == HS_FIELD_INT ? sizeof(int)                                                                 \
	 : (k) == HS_FIELD_U32 || (k) == HS_FIELD_MASK32 ? sizeof(uint32_t)                                  \
	 : (k) == HS_FIELD_LONG ? sizeof(long)                                                               \
	 : (k) == HS_FIELD_MASK64 ? sizeof(uint64_t)                                                         \
	                          : 0u)
// 0, or a compile error when a field's size is not its kind's (a kind that does not fit its field)
#define HS_FIELD_FITS(size, k) (0u * sizeof(char[(size) == HS_FIELD_BYTES(k) ? 1 : -1]))
#define HS_FIELD_MEMBER(T, m) (((T *)0)->m)

// Entries are designated initializers: {HS_ONE(hs_hand, placed, BOOL)}, with the options below.
// One field m of T (m may name a field of a field, a.b, or one element, a[2]).
#define HS_ONE(T, m, K)                                                                                     \
	.name = #m, .kind = HS_FIELD_##K, .count = 1, .stride = (uint32_t)sizeof(HS_FIELD_MEMBER(T, m)),       \
	.offset = (uint32_t)(offsetof(T, m) + HS_FIELD_FITS(sizeof(HS_FIELD_MEMBER(T, m)), HS_FIELD_##K))
// Every element of the array m of T (as a group's member: its element g).
#define HS_ALL(T, m, K)                                                                                     \
	.name = #m, .kind = HS_FIELD_##K, .stride = (uint32_t)sizeof(HS_FIELD_MEMBER(T, m)[0]),                 \
	.count = (int)(sizeof(HS_FIELD_MEMBER(T, m)) / sizeof(HS_FIELD_MEMBER(T, m)[0])),                      \
	.offset = (uint32_t)(offsetof(T, m) + HS_FIELD_FITS(sizeof(HS_FIELD_MEMBER(T, m)[0]), HS_FIELD_##K))
// A group's member: field m of the array a's element g.
#define HS_EACH(T, a, m, K)                                                                                 \
	.name = #a "." #m, .kind = HS_FIELD_##K, .count = 1, .stride = (uint32_t)sizeof(HS_FIELD_MEMBER(T, a)[0]), \
	.offset = (uint32_t)(offsetof(T, a[0].m) + HS_FIELD_FITS(sizeof(HS_FIELD_MEMBER(T, a)[0].m), HS_FIELD_##K))
// A group's member: element g of the array T's pointer p points to.
#define HS_ALL_AT(T, p, K)                                                                                  \
	.name = #p, .kind = HS_FIELD_##K, .count = 1, .through = true, .offset = (uint32_t)offsetof(T, p),     \
	.stride = (uint32_t)(sizeof(*HS_FIELD_MEMBER(T, p)) + HS_FIELD_FITS(sizeof(*HS_FIELD_MEMBER(T, p)), HS_FIELD_##K))
// A group's member: field m of element g (of type E) of the array T's pointer p points to.
#define HS_EACH_AT(T, p, E, m, K)                                                                           \
	.name = #p "->" #m, .kind = HS_FIELD_##K, .count = 1, .through = true, .offset = (uint32_t)offsetof(T, p), \
	.stride = (uint32_t)sizeof(E), .inner = (uint32_t)(offsetof(E, m) + HS_FIELD_FITS(sizeof(((E *)0)->m), HS_FIELD_##K))
// A group of the entries of the array `table` (count: `.count = N` or HS_COUNT_AT).
#define HS_GROUP(name_, table)                                                                              \
	.name = name_, .kind = HS_FIELD_GROUP, .members = table, .member_count = (int)(sizeof(table) / sizeof((table)[0]))

// Options. The count is T's int m (an array's or a group's).
#define HS_COUNT_AT(T, m) .count_at = (uint32_t)(offsetof(T, m) + 1u + HS_FIELD_FITS(sizeof(HS_FIELD_MEMBER(T, m)), HS_FIELD_INT))
// A group's live slots: T's int m, in [0, count], walked before them; the rest travel as zeros.
#define HS_COUNTED(T, m) .counted = (uint32_t)(offsetof(T, m) + 1u + HS_FIELD_FITS(sizeof(HS_FIELD_MEMBER(T, m)), HS_FIELD_INT))
// The field exists only while T's bool m is true (m: a model field, fixed while stepping).
#define HS_WHEN(T, m) .when = (uint32_t)(offsetof(T, m) + 1u + HS_FIELD_FITS(sizeof(HS_FIELD_MEMBER(T, m)), HS_FIELD_BOOL))
// The range's hi is .hi plus T's int m, or plus the walk's context value k.
#define HS_HI_PLUS(T, m) .hi_at = (uint32_t)(offsetof(T, m) + 1u + HS_FIELD_FITS(sizeof(HS_FIELD_MEMBER(T, m)), HS_FIELD_INT))
#define HS_HI_PLUS_CTX(k) .hi_ctx = (uint8_t)((k) + 1)

#define HS_FIELDS_COUNT(table) (sizeof(table) / sizeof((table)[0]))

// Walks the n entries of `table` over the struct at `root` in io's mode (state_walk.h);
// `ctx`: the context values the entries' HS_HI_PLUS_CTX name (may be NULL when none does).
void hs_fields_io(hs_state_io *io, const hs_field *table, size_t n, void *root, const int64_t *ctx);

// ---- the walker (inline: see the top of the file) ----

// Unrolls the loop that follows completely where its count is a constant (up to n). GCC only:
// clang warns of every loop it cannot unroll (a table not known at compile time, as in the tests)
// and unrolls constant ones by its own measure.
#if defined(__GNUC__) && !defined(__clang__)
#define HS_FIELD_PRAGMA(x) _Pragma(#x)
#define HS_FIELD_UNROLL(n) HS_FIELD_PRAGMA(GCC unroll n)
#else
#define HS_FIELD_UNROLL(n)
#endif

static inline int hs_field_int_at(const unsigned char *root, uint32_t at1) {
	int v;
	memcpy(&v, root + at1 - 1u, sizeof v);
	return v;
}

// Where element 0 of a field is.
static HS_FORCE_INLINE unsigned char *hs_field_base(const hs_field *f, unsigned char *root) {
	unsigned char *base = root + f->offset;
	if (f->through) { // the struct's pointer to the elements
		void *elements;
		memcpy(&elements, base, sizeof elements);
		base = elements;
	}
	return base + f->inner;
}

static HS_FORCE_INLINE int hs_field_words(uint8_t kind) {
	return kind == HS_FIELD_VEC3 ? 3 : kind == HS_FIELD_QUAT || kind == HS_FIELD_ROTATION ? 4 : 1;
}

static HS_FORCE_INLINE int64_t hs_field_hi(const hs_field *f, const unsigned char *root, const int64_t *ctx) {
	int64_t hi = f->hi;
	if (f->hi_at)
		hi += hs_field_int_at(root, f->hi_at);
	if (f->hi_ctx)
		hi += ctx[f->hi_ctx - 1];
	return hi;
}

// Word k of an element of `kind` at p, as a hash takes it (and state_walk.h's calls save it).
static HS_FORCE_INLINE uint64_t hs_field_word(uint8_t kind, const unsigned char *p, int k) {
	switch ((hs_field_kind)kind) {
	case HS_FIELD_F64:
	case HS_FIELD_VEC3:
	case HS_FIELD_QUAT:
	case HS_FIELD_ROTATION:
	case HS_FIELD_MASK64: {
		uint64_t w; // a double's word is its bits
		memcpy(&w, p + 8 * k, sizeof w);
		return w;
	}
	case HS_FIELD_U8:
		return *p;
	case HS_FIELD_BOOL: {
		bool b;
		memcpy(&b, p, sizeof b);
		return b ? 1u : 0u;
	}
	case HS_FIELD_INT:
		return (uint64_t)(int64_t)hs_field_int_at(p, 1u);
	case HS_FIELD_U32:
	case HS_FIELD_MASK32: {
		uint32_t u;
		memcpy(&u, p, sizeof u);
		return kind == HS_FIELD_U32 ? (uint64_t)(int64_t)(int)u : u;
	}
	case HS_FIELD_LONG: {
		long l;
		memcpy(&l, p, sizeof l);
		return (uint64_t)(int64_t)l;
	}
	case HS_FIELD_GROUP:
		break;
	}
	return 0;
}

// HASH: an element's words mixed in; GATHER: stored (the same words, in the same order).
static HS_FORCE_INLINE void hs_field_hash(hs_state_io *io, hs_state_mode mode, uint8_t kind, const unsigned char *p) {
	HS_FIELD_UNROLL(4)
	for (int k = 0; k < hs_field_words(kind); ++k) {
		uint64_t w = hs_field_word(kind, p, k);
		if (mode == HS_STATE_GATHER)
			io->gather[io->words++] = w;
		else
			hs_state_hash_word(io, w);
	}
}

// GATHER: n bytes, a word each (zero-extended); with SSE2 16 at a time, by unpacking with zeros.
static HS_FORCE_INLINE void hs_field_gather_u8(hs_state_io *io, const uint8_t *v, int n) {
	uint64_t *w = io->gather + io->words;
	int i = 0;
#if defined(__SSE2__)
	const __m128i zero = _mm_setzero_si128();
	for (; i + 16 <= n; i += 16) {
		__m128i b = _mm_loadu_si128((const __m128i *)(const void *)(v + i));
		__m128i h[2] = {_mm_unpacklo_epi8(b, zero), _mm_unpackhi_epi8(b, zero)}; // 16 bits
		for (int k = 0; k < 2; ++k) {
			__m128i d[2] = {_mm_unpacklo_epi16(h[k], zero), _mm_unpackhi_epi16(h[k], zero)}; // 32 bits
			for (int m = 0; m < 2; ++m) {
				_mm_storeu_si128((__m128i *)(void *)&w[i + 8 * k + 4 * m], _mm_unpacklo_epi32(d[m], zero));
				_mm_storeu_si128((__m128i *)(void *)&w[i + 8 * k + 4 * m + 2], _mm_unpackhi_epi32(d[m], zero));
			}
		}
	}
#endif
	for (; i < n; ++i)
		w[i] = v[i];
	io->words += (size_t)n;
}

// One element at p, in `mode` (io's, passed as a value so that a constant one folds). The range
// is read only where CHECK may use it.
static HS_FORCE_INLINE void hs_field_element(hs_state_io *io, hs_state_mode mode, const hs_field *f, unsigned char *p,
                                             const unsigned char *root, const int64_t *ctx) {
	if (mode == HS_STATE_HASH || mode == HS_STATE_GATHER) {
		hs_field_hash(io, mode, f->kind, p);
		return;
	}
	bool load = mode == HS_STATE_LOAD;
	switch ((hs_field_kind)f->kind) {
	case HS_FIELD_F64:
		hs_state_f64_io(io, (double *)(void *)p);
		break;
	case HS_FIELD_VEC3:
		hs_state_vec3(io, (hs_vec3 *)(void *)p);
		break;
	case HS_FIELD_QUAT:
		hs_state_quat(io, (hs_quat *)(void *)p);
		break;
	case HS_FIELD_ROTATION:
		hs_state_rotation_io(io, (hs_quat *)(void *)p);
		break;
	case HS_FIELD_U8:
		hs_state_u8_range_io(io, p, (uint8_t)hs_field_hi(f, root, ctx));
		break;
	case HS_FIELD_BOOL:
		hs_state_bool_io(io, (bool *)(void *)p);
		break;
	case HS_FIELD_INT:
		hs_state_int_range_io(io, (int *)(void *)p, (int)f->lo, (int)hs_field_hi(f, root, ctx));
		break;
	case HS_FIELD_U32: {
		uint32_t *u = (uint32_t *)(void *)p;
		int v = (int)*u;
		hs_state_int_range_io(io, &v, (int)f->lo, (int)hs_field_hi(f, root, ctx));
		if (load)
			*u = (uint32_t)v;
	} break;
	case HS_FIELD_LONG:
		hs_state_long_range_io(io, (long *)(void *)p, (long)f->lo, (long)hs_field_hi(f, root, ctx));
		break;
	case HS_FIELD_MASK32: {
		uint32_t *u = (uint32_t *)(void *)p;
		uint64_t v = *u;
		hs_state_mask_io(io, &v, (int)f->hi);
		if (load)
			*u = (uint32_t)v;
	} break;
	case HS_FIELD_MASK64:
		hs_state_mask_io(io, (uint64_t *)(void *)p, (int)f->hi);
		break;
	case HS_FIELD_GROUP:
		break;
	}
}

// A counted group's slot beyond its count: zero words (CHECK refuses others); LOAD zeroes it.
static inline void hs_field_zero(hs_state_io *io, const hs_field *f, unsigned char *p) {
	for (int k = 0; k < hs_field_words(f->kind); ++k) {
		uint64_t zero = 0;
		hs_state_zero(io, &zero);
	}
	if (io->mode == HS_STATE_LOAD)
		memset(p, 0, HS_FIELD_BYTES(f->kind));
}

static HS_FORCE_INLINE void hs_field_group(hs_state_io *io, hs_state_mode mode, const hs_field *f, unsigned char *root,
                                           const int64_t *ctx, int count) {
	int live = f->counted ? hs_state_count(io, (int *)(void *)(root + f->counted - 1u), count) : count;
	for (int g = 0; g < live; ++g) {
		HS_FIELD_UNROLL(8)
		for (int m = 0; m < f->member_count; ++m) {
			const hs_field *e = &f->members[m];
			hs_field_element(io, mode, e, hs_field_base(e, root) + (size_t)g * e->stride, root, ctx);
		}
	}
	if (!f->counted || mode == HS_STATE_HASH || mode == HS_STATE_GATHER) // a hash leaves the zero slots out
		return;
	for (int g = live; g < count; ++g)
		for (int m = 0; m < f->member_count; ++m) {
			const hs_field *e = &f->members[m];
			hs_field_zero(io, e, hs_field_base(e, root) + (size_t)g * e->stride);
		}
}

// One entry: its elements, or its group's.
static HS_FORCE_INLINE void hs_field_walk(hs_state_io *io, hs_state_mode mode, const hs_field *f, unsigned char *root,
                                          const int64_t *ctx) {
	if (f->when) {
		bool exists;
		memcpy(&exists, root + f->when - 1u, sizeof exists);
		if (!exists)
			return;
	}
	int count = f->count_at ? hs_field_int_at(root, f->count_at) : f->count;
	if (f->kind == HS_FIELD_GROUP) {
		hs_field_group(io, mode, f, root, ctx, count);
		return;
	}
	unsigned char *base = hs_field_base(f, root);
	if (mode == HS_STATE_GATHER && f->kind == HS_FIELD_U8 && f->stride == 1u) {
		hs_field_gather_u8(io, base, count);
		return;
	}
	for (int i = 0; i < count; ++i)
		hs_field_element(io, mode, f, base + (size_t)i * f->stride, root, ctx);
}

// The table, unrolled: with a constant table (and mode) each entry's walk is specialized.
static HS_FORCE_INLINE void hs_fields_walk(hs_state_io *io, const hs_field *table, size_t n, void *root,
                                           const int64_t *ctx) {
	hs_state_mode mode = io->mode;
	HS_FIELD_UNROLL(64)
	for (size_t i = 0; i < n; ++i)
		hs_field_walk(io, mode, &table[i], (unsigned char *)root, ctx);
}

#endif
