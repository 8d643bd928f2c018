// state.c — the world's state as one block (docs/model.md "The state block"; MuJoCo's mj_getState /
// mj_setState): the header that ties a buffer to a kind of world, the one walk over every state
// field (world_io), and the four uses of it: size, save, load (checked first) and hash.
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "broadphase.h"
#include "inline.h"
#include "spring_state.h"
#include "state_walk.h"
#include "world_internal.h"

#define HS_STATE_MAGIC 0x3145544154535348ull // "HSSTATE1", little-endian
#define HS_STATE_FORMAT 1                    // bump when the walk changes
#define HS_STATE_HEADER_WORDS 9
#define HS_HASH_SEED 0x6A09E667F3BCC909ull // any fixed odd start

// The library version as a word: the hash of HS_VERSION's characters.
static uint64_t library_word(void) {
	uint64_t h = HS_HASH_SEED;
	for (const char *c = HS_VERSION; *c; ++c)
		h = hs_state_mix(h, (uint64_t)(unsigned char)*c);
	return h;
}

static uint64_t mix_vec3(uint64_t h, hs_vec3 v) {
	return hs_state_mix_f64(hs_state_mix_f64(hs_state_mix_f64(h, v.x), v.y), v.z);
}

static uint64_t shape_checksum(uint64_t h, const hs_shape *s) {
	h = hs_state_mix(h, (uint64_t)s->kind);
	h = hs_state_mix(h, (uint64_t)s->part_count);
	h = hs_state_mix(h, (uint64_t)s->vertex_count);
	h = hs_state_mix(h, (uint64_t)s->face_count);
	h = hs_state_mix(h, (uint64_t)s->edge_count);
	h = hs_state_mix_f64(h, s->volume);
	h = hs_state_mix_f64(h, s->radius);
	h = hs_state_mix_f64(h, s->sphere_radius);
	for (int i = 0; i < s->vertex_count; ++i)
		h = mix_vec3(h, s->vertices[i]);
	return h;
}

static uint64_t hand_def_checksum(uint64_t h, const hs_hand_def *d) {
	h = hs_state_mix(h, d->left ? 1u : 0u);
	h = hs_state_mix_f64(h, d->finger_radius);
	h = hs_state_mix_f64(h, d->dip_per_pip);
	for (int f = 0; f < 5; ++f) {
		for (int s = 0; s < 3; ++s)
			h = hs_state_mix_f64(h, d->segment_length[f][s]);
		h = mix_vec3(h, d->base[f]);
	}
	if (d->joint_driven) // only when set: a glove hand's checksum is as it was
		h = hs_state_mix(h, 1u);
	return h;
}

// What the world was built from: a state means nothing in a world built otherwise. Left out on
// purpose: max_objects and max_shapes (room, not behaviour: the counts are in the header) and
// skip_work (it changes no result, broadphase.c), so a state moves between such worlds.
// max_hands sizes the contact list: the header carries the contact capacity.
static uint64_t definition_checksum(const hs_world *w) {
	const hs_world_def *d = &w->def;
	uint64_t h = hs_state_mix_f64(HS_HASH_SEED, d->dt);
	h = mix_vec3(h, d->gravity);
	h = hs_state_mix_f64(h, d->floor_tolerance);
	h = hs_state_mix(h, (uint64_t)d->stacking);
	h = hs_state_mix_f64(h, d->grasp_threshold_deg);
	h = hs_state_mix(h, d->grasp_any_contacts ? 1u : 0u);
	h = hs_state_mix(h, d->paper_contacts ? 1u : 0u);
	h = hs_state_mix_f64(h, d->grasp_release_mm);
	h = hs_state_mix_f64(h, d->grasp_open_mm);
	h = hs_state_mix(h, (uint64_t)d->glove_deadband);
	if (d->release_window_s != 0.05 || d->release_fit != HS_RELEASE_FIT_MEAN) { // the default keeps older checksums
		h = hs_state_mix_f64(h, d->release_window_s);
		h = hs_state_mix(h, (uint64_t)d->release_fit);
	}
	// options added later: mixed in only when not at their default, which keeps older checksums
	if (!d->grasp_opposed || d->grasp_close_mm != 10.0 || d->tracking_hold_s != 0.2 || d->paper_landing) {
		h = hs_state_mix(h, d->grasp_opposed ? 1u : 0u);
		h = hs_state_mix_f64(h, d->grasp_close_mm);
		h = hs_state_mix_f64(h, d->tracking_hold_s);
		h = hs_state_mix(h, d->paper_landing ? 1u : 0u);
	}
	for (int i = 0; i < w->shape_count; ++i)
		h = shape_checksum(h, &w->shapes[i]);
	for (int i = 0; i < w->object_count; ++i) {
		h = hs_state_mix(h, (uint64_t)w->bodies[i].shape);
		h = hs_state_mix_f64(h, w->bodies[i].mass);
		if (w->bodies[i].restitution >= 0.0) // set: a definition of its own (unset keeps older checksums)
			h = hs_state_mix_f64(h, w->bodies[i].restitution);
	}
	for (int i = 0; i < w->hand_count; ++i)
		h = hand_def_checksum(h, &w->hands[i].def);
	return h;
}

// The header words this world writes and accepts, in order, with the reason a mismatch gives.
static int header_of(const hs_world *w, uint64_t out[HS_STATE_HEADER_WORDS], const char *why[HS_STATE_HEADER_WORDS]) {
	const uint64_t words[HS_STATE_HEADER_WORDS] = {
	    HS_STATE_MAGIC,          HS_STATE_FORMAT,        library_word(),
	    w->spring ? 1u : 0u,     (uint64_t)w->object_count, (uint64_t)w->hand_count,
	    (uint64_t)w->shape_count, (uint64_t)w->contact_capacity, definition_checksum(w)};
	static const char *const reasons[HS_STATE_HEADER_WORDS] = {
	    "not a handspring state (wrong magic)",
	    "another state format version",
	    "saved by another library version",
	    "another kind of world (hand model / spring model)",
	    "another object count",
	    "another hand count",
	    "another shape count",
	    "another contact capacity (max_hands)",
	    "another world definition (dt, gravity, tolerance, stacking, grasp rule, release, shapes, masses or hand definitions)"};
	for (int i = 0; i < HS_STATE_HEADER_WORDS; ++i) {
		out[i] = words[i];
		why[i] = reasons[i];
	}
	return HS_STATE_HEADER_WORDS;
}

// The walks below are inlined into each use (HS_FORCE_INLINE): where the mode is a constant (the
// hash, every frame), the mode tests and the calls for other modes fold away, and the word count
// stays in a register.

// One object: 39 words. The model fields (shape, mass) are in the definition checksum instead.
static HS_FORCE_INLINE void body_io(hs_state_io *io, const hs_world *w, hs_body *b) {
	hs_state_vec3(io, &b->pos);
	hs_state_vec3(io, &b->prev);
	hs_state_rotation(io, &b->rot);
	hs_state_rotation(io, &b->rot_prev);
	hs_state_rotation(io, &b->spin);
	hs_state_vec3(io, &b->vel);
	hs_state_u8_range(io, &b->contact, HS_CONTACT_PUSH_MANY);
	hs_state_int_range(io, &b->floor_contacts, 0, w->shapes[b->shape].vertex_count);
	hs_state_u8_range(io, &b->grounded, 1);
	hs_state_u8_range(io, &b->asleep, 1);
	hs_state_u8_range(io, &b->held, 1);
	hs_state_u8_range(io, &b->carried, 1);
	hs_state_int_range(io, &b->grasped_by, 0, w->hand_count);
	hs_state_vec3(io, &b->grip_pos);
	hs_state_quat(io, &b->grip_rot); // zero until a grasp begins
	hs_state_f64(io, &b->grip_spread);
	hs_state_f64(io, &b->grip_reach);
	hs_state_u8_range(io, &b->grip_fingers, 31);
	hs_state_int_range(io, &b->released_by, 0, w->hand_count);
}

// One hand: 68 words and 7 for each of its older_capacity older wrist poses (117 at the default
// release window: HS_HAND_OLDER of them), the two readings its check points now and a frame ago
// come from (the points and lines are rebuilt from them after a load), its tracking state and its
// fingertip pairs' recent peaks, the wrist poses before those (a release's velocity), its two
// touch masks and its two embedded masks. Its definition is
// in the checksum; older_capacity follows from the world's (dt, release_window_s).
static HS_FORCE_INLINE void hand_io(hs_state_io *io, hs_hand *h) {
	hs_state_vec3(io, &h->wrist_pos);
	hs_state_rotation(io, &h->wrist_rot);
	for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
		hs_state_u8(io, &h->sensors[i]);
	hs_state_vec3(io, &h->prev_wrist_pos);
	hs_state_rotation(io, &h->prev_wrist_rot);
	for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
		hs_state_u8(io, &h->prev_sensors[i]);
	for (int i = 0; h->def.joint_driven && i < HS_HAND_POINTS; ++i)
		hs_state_vec3(io, &h->joints[i]);
	for (int i = 0; h->def.joint_driven && i < HS_HAND_POINTS; ++i)
		hs_state_vec3(io, &h->prev_joints[i]);
	hs_state_bool(io, &h->placed);
	hs_state_bool(io, &h->untracked);
	hs_state_int_range(io, &h->lost_frames, 0, INT_MAX);
	for (int k = 0; k < HS_FINGER_PAIRS; ++k)
		hs_state_f64(io, &h->pair_open[k]);
	hs_state_int_range(io, &h->older_count, 0, h->older_capacity);
	for (int i = 0; i < h->older_capacity; ++i) { // all of them (those not yet reached are zero): a fixed size
		hs_state_vec3(io, &h->older_pos[i]);
		hs_state_rotation(io, &h->older_rot[i]);
	}
	uint64_t points = h->touch_points;
	hs_state_mask(io, &points, HS_HAND_POINTS);
	h->touch_points = (uint32_t)points;
	hs_state_mask(io, &h->touch_lines, HS_HAND_LINES);
	uint64_t embedded = h->embed_points;
	hs_state_mask(io, &embedded, HS_HAND_POINTS);
	h->embed_points = (uint32_t)embedded;
	hs_state_mask(io, &h->embed_lines, HS_HAND_LINES);
}

#define HS_HASH_LANES {HS_HASH_SEED, ~HS_HASH_SEED, HS_HASH_SEED >> 1, 1}

// A hand's words in HASH mode, as hand_io visits them (every frame: 117 at the default window),
// gathered to be mixed four lanes at a time. HS_HASH_SELFCHECK builds compare with hand_io's walk.
#define HAND_WORDS_MAX (68 + 6 * HS_HAND_POINTS + 7 * HS_HAND_OLDER_MAX) // joint-driven: its joints twice
static size_t put_vec3(uint64_t *w, size_t n, hs_vec3 v) {
	w[n] = hs_state_bits(v.x), w[n + 1] = hs_state_bits(v.y), w[n + 2] = hs_state_bits(v.z);
	return n + 3;
}
static size_t put_quat(uint64_t *w, size_t n, hs_quat q) { // w, x, y, z as hs_state_quat
	w[n] = hs_state_bits(q.w), w[n + 1] = hs_state_bits(q.x);
	w[n + 2] = hs_state_bits(q.y), w[n + 3] = hs_state_bits(q.z);
	return n + 4;
}
// A reading's sensors, a word each (zero-extended); with SSE2 the first 16 by unpacking with zeros.
static size_t put_sensors(uint64_t *w, size_t n, const uint8_t v[HS_GLOVE_SENSORS]) {
	int i = 0;
#if defined(__SSE2__)
	const __m128i zero = _mm_setzero_si128();
	__m128i b = _mm_loadu_si128((const __m128i *)(const void *)v);
	__m128i h[2] = {_mm_unpacklo_epi8(b, zero), _mm_unpackhi_epi8(b, zero)}; // 16 bits
	for (size_t k = 0; k < 2; ++k) {
		__m128i d[2] = {_mm_unpacklo_epi16(h[k], zero), _mm_unpackhi_epi16(h[k], zero)}; // 32 bits
		for (size_t m = 0; m < 2; ++m) {
			_mm_storeu_si128((__m128i *)(void *)&w[n + 8 * k + 4 * m], _mm_unpacklo_epi32(d[m], zero));
			_mm_storeu_si128((__m128i *)(void *)&w[n + 8 * k + 4 * m + 2], _mm_unpackhi_epi32(d[m], zero));
		}
	}
	i = 16;
	_Static_assert(HS_GLOVE_SENSORS >= 16, "16 sensors unpacked at once");
#endif
	for (; i < HS_GLOVE_SENSORS; ++i)
		w[n + (size_t)i] = v[i];
	return n + HS_GLOVE_SENSORS;
}

static size_t hand_words(const hs_hand *h, uint64_t *w) {
	size_t n = put_sensors(w, put_quat(w, put_vec3(w, 0, h->wrist_pos), h->wrist_rot), h->sensors);
	n = put_sensors(w, put_quat(w, put_vec3(w, n, h->prev_wrist_pos), h->prev_wrist_rot), h->prev_sensors);
	for (int i = 0; h->def.joint_driven && i < HS_HAND_POINTS; ++i)
		n = put_vec3(w, n, h->joints[i]);
	for (int i = 0; h->def.joint_driven && i < HS_HAND_POINTS; ++i)
		n = put_vec3(w, n, h->prev_joints[i]);
	w[n++] = h->placed ? 1u : 0u;
	w[n++] = h->untracked ? 1u : 0u;
	w[n++] = (uint64_t)(int64_t)h->lost_frames;
	for (int k = 0; k < HS_FINGER_PAIRS; ++k)
		w[n++] = hs_state_bits(h->pair_open[k]);
	w[n++] = (uint64_t)(int64_t)h->older_count;
	for (int i = 0; i < h->older_capacity; ++i)
		n = put_quat(w, put_vec3(w, n, h->older_pos[i]), h->older_rot[i]);
	w[n++] = h->touch_points;
	w[n++] = h->touch_lines;
	w[n++] = h->embed_points;
	w[n++] = h->embed_lines;
	return n;
}

static void hand_hash(hs_state_io *io, hs_hand *h) {
	uint64_t words[HAND_WORDS_MAX];
#if defined(HS_HASH_SELFCHECK)
	hs_state_io walked = *io;
	hand_io(&walked, h);
#endif
	hs_state_hash_words(io, words, hand_words(h, words));
#if defined(HS_HASH_SELFCHECK)
	if (walked.words != io->words || memcmp(walked.lane, io->lane, sizeof io->lane) != 0) {
		fprintf(stderr, "handspring: a hand's gathered words differ from its walk\n");
		abort();
	}
#endif
}

// Object i's digest: its index and its walk, hashed alone. Objects enter the world's hash as the
// sum of their digests, so an object that did not change costs nothing to hash again (its digest
// is kept), and the sum still changes with any single field of any object (each digest is a
// bijection of each field, the sum of each digest) and with their order (the index).
static uint64_t body_digest(const hs_world *w, int i) {
	hs_state_io io = {.mode = HS_STATE_HASH, .lane = HS_HASH_LANES};
	uint64_t index = (uint64_t)i;
	hs_state_u64(&io, &index);
	body_io(&io, w, &w->bodies[i]); // HASH mode only reads the fields
	return hs_state_hash_of(&io);
}

#if defined(HS_HASH_SELFCHECK)
// Sanitizer builds: every hash checks the kept digests against a walk over every object, so a
// change the stale list missed fails the first test that hashes after it.
static void check_digests(const hs_world *w) {
	uint64_t sum = 0;
	for (int i = 0; i < w->object_count; ++i) {
		uint64_t d = body_digest(w, i);
		if (d != w->digest[i]) {
			fprintf(stderr, "handspring: object %d changed at frame %ld but was not marked stale\n", i, w->frame);
			abort();
		}
		sum += d;
	}
	if (sum != w->digest_sum) {
		fprintf(stderr, "handspring: digest sum wrong at frame %ld\n", w->frame);
		abort();
	}
}
#endif

// The sum of every object's digest, after digesting again those that may have changed. The
// digests are a cache of the hash (not state): refreshing them changes no result.
static uint64_t objects_digest(hs_world *w) {
	if (w->all_stale) {
		w->digest_sum = 0;
		for (int i = 0; i < w->object_count; ++i) {
			w->digest[i] = body_digest(w, i);
			w->digest_sum += w->digest[i];
		}
		memset(w->stale_flag, 0, (size_t)w->object_count);
		w->stale_count = 0;
		w->all_stale = false;
	}
	for (int k = 0; k < w->stale_count; ++k) {
		int i = w->stale[k];
		uint64_t d = body_digest(w, i);
		w->digest_sum += d - w->digest[i]; // unsigned: wraps, as the sum does
		w->digest[i] = d;
		w->stale_flag[i] = 0;
	}
	w->stale_count = 0;
#if defined(HS_HASH_SELFCHECK)
	check_digests(w);
#endif
	return w->digest_sum;
}

// The whole state after the header: the single list of what a step reads from the last one. The
// hash takes the objects as the sum of their digests (above); the other modes walk them in order.
static HS_FORCE_INLINE void world_io(hs_state_io *io, hs_world *w) {
	io->objects = w->object_count;
	hs_state_long_range(io, &w->frame, 0, LONG_MAX);
	hs_state_long_range(io, &w->counters.numeric_faults, 0, LONG_MAX);
	hs_state_long_range(io, &w->first_fault_frame, -1, LONG_MAX);
	hs_state_int_range(io, &w->first_fault_object, -1, w->object_count - 1);
	if (io->mode == HS_STATE_HASH) {
		uint64_t objects = objects_digest(w);
		hs_state_u64(io, &objects);
	} else {
		for (int i = 0; i < w->object_count; ++i)
			body_io(io, w, &w->bodies[i]);
	}
	for (int h = 0; h < w->hand_count; ++h)
		if (io->mode == HS_STATE_HASH)
			hand_hash(io, &w->hands[h]);
		else
			hand_io(io, &w->hands[h]);
	if (w->spring)
		hs_spring_state_io(w->spring, io);
}

static size_t state_words(const hs_world *w) {
	hs_state_io io = {.mode = HS_STATE_SIZE};
	world_io(&io, (hs_world *)w); // SIZE mode reads nothing and writes nothing
	return HS_STATE_HEADER_WORDS + io.words;
}

size_t hs_world_state_size(const hs_world *world) { return world ? 8 * state_words(world) : 0; }

hs_status hs_world_save_state(const hs_world *world, void *buffer, size_t size) {
	if (!world || !buffer)
		return HS_ERR_INVALID_ARGUMENT;
	size_t words = state_words(world);
	if (size < 8 * words)
		return HS_ERR_INVALID_ARGUMENT;
	hs_state_io io = {.mode = HS_STATE_SAVE, .out = buffer, .limit = words};
	uint64_t header[HS_STATE_HEADER_WORDS];
	const char *why[HS_STATE_HEADER_WORDS];
	for (int i = 0, n = header_of(world, header, why); i < n; ++i)
		hs_state_u64(&io, &header[i]);
	world_io(&io, (hs_world *)world); // SAVE mode only reads the fields
	return io.overflow ? HS_ERR_INVALID_ARGUMENT : HS_OK;
}

uint64_t hs_world_hash(const hs_world *world) {
	hs_state_io io = {.mode = HS_STATE_HASH, .lane = HS_HASH_LANES};
	if (world)
		world_io(&io, (hs_world *)world); // HASH mode reads the state and refreshes the digest cache
	return hs_state_hash_of(&io);
}

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static hs_status refuse(hs_world *w, const char *format, ...) {
	va_list args;
	va_start(args, format);
	vsnprintf(w->state_error, sizeof w->state_error, format, args);
	va_end(args);
	return HS_ERR_STATE_MISMATCH;
}

// The header first: a buffer of another kind of world is named as such, not as a wrong size.
static hs_status check_header(hs_world *w, const void *buffer, size_t size) {
	if (size < 8 * HS_STATE_HEADER_WORDS)
		return refuse(w, "%zu bytes: too short for a state header", size);
	uint64_t expected[HS_STATE_HEADER_WORDS], found[HS_STATE_HEADER_WORDS];
	const char *why[HS_STATE_HEADER_WORDS];
	int n = header_of(w, expected, why);
	hs_state_io io = {.mode = HS_STATE_LOAD, .in = buffer, .limit = HS_STATE_HEADER_WORDS};
	for (int i = 0; i < n; ++i) {
		found[i] = 0;
		hs_state_u64(&io, &found[i]);
		if (found[i] != expected[i])
			return refuse(w, "%s (header word %d)", why[i], i);
	}
	size_t words = state_words(w);
	if (size != 8 * words)
		return refuse(w, "%zu bytes where this world's state is %zu", size, 8 * words);
	return HS_OK;
}

hs_status hs_world_load_state(hs_world *world, const void *buffer, size_t size) {
	if (!world || !buffer)
		return HS_ERR_INVALID_ARGUMENT;
	world->state_error[0] = '\0';
	hs_status status = check_header(world, buffer, size);
	if (status != HS_OK)
		return status;
	size_t words = size / 8;
	// first pass: read and validate every word, writing nothing
	hs_state_io io = {.mode = HS_STATE_CHECK, .in = buffer, .limit = words, .words = HS_STATE_HEADER_WORDS};
	world_io(&io, world);
	if (io.error)
		return refuse(world, "%s at word %zu", io.error, io.error_word);
	if (io.overflow || io.words != words)
		return refuse(world, "the walk read %zu words of %zu", io.words, words);
	// second pass: the same walk, now writing; then the caches follow the state
	io = (hs_state_io){.mode = HS_STATE_LOAD, .in = buffer, .limit = words, .words = HS_STATE_HEADER_WORDS};
	world_io(&io, world);
	for (int h = 0; h < world->hand_count; ++h)
		hs_hand_refresh(&world->hands[h]);
	hs_broadphase_reset(world);
	world->contact_count = 0; // the last step's contacts are output, not state
	return HS_OK;
}

const char *hs_world_state_error(const hs_world *world) { return world ? world->state_error : "no world"; }
