// state.c — the world's state as one block (docs/model.md "The state block"; MuJoCo's mj_getState /
// mj_setState): the header that ties a buffer to a kind of world, the field tables of the object,
// the hand and the world's own words (state_fields.h), the one walk over every state field they
// drive (world_io), and the four uses of it: size, save, load (checked first) and hash.
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "broadphase.h"
#include "inline.h"
#include "spring_state.h"
#include "state_fields.h"
#include "state_walk.h"
#include "world_internal.h"

#define HS_STATE_MAGIC 0x3145544154535348ull // "HSSTATE1", little-endian
#define HS_STATE_FORMAT 1                    // bump when the walk (a table's fields or order) changes
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
	const hs_world_def *d = &w->model.def;
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
	if (d->paper_grasp_end || d->paper_floor_push || d->paper_push_end || d->paper_tipping || d->paper_carry) {
		unsigned rules = (d->paper_grasp_end ? 1u : 0u) | (d->paper_floor_push ? 2u : 0u) | (d->paper_push_end ? 4u : 0u) |
		                 (d->paper_tipping ? 8u : 0u) | (d->paper_carry ? 16u : 0u);
		h = hs_state_mix(h, 0x6c6574746572u ^ rules); // "letter"
	}
	for (int i = 0; i < w->model.shape_count; ++i)
		h = shape_checksum(h, &w->model.shapes[i]);
	for (int i = 0; i < w->model.object_count; ++i) {
		h = hs_state_mix(h, (uint64_t)w->state.bodies[i].shape);
		h = hs_state_mix_f64(h, w->state.bodies[i].mass);
		if (w->state.bodies[i].restitution >= 0.0) // set: a definition of its own (unset keeps older checksums)
			h = hs_state_mix_f64(h, w->state.bodies[i].restitution);
	}
	for (int i = 0; i < w->model.hand_count; ++i)
		h = hand_def_checksum(h, &w->state.hands[i].model.def);
	return h;
}

// The header words this world writes and accepts, in order, with the reason a mismatch gives.
static int header_of(const hs_world *w, uint64_t out[HS_STATE_HEADER_WORDS], const char *why[HS_STATE_HEADER_WORDS]) {
	const uint64_t words[HS_STATE_HEADER_WORDS] = {
	    HS_STATE_MAGIC,          HS_STATE_FORMAT,        library_word(),
	    w->state.spring ? 1u : 0u,     (uint64_t)w->model.object_count, (uint64_t)w->model.hand_count,
	    (uint64_t)w->model.shape_count, (uint64_t)w->out.contact_capacity, definition_checksum(w)};
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

// ---- the state's field tables (state_fields.h): each is the one list of its type's STATE fields,
// in walk order; size, save, check, load, hash and the hash's gather all walk it ----

// Context values of a body's walk (HS_HI_PLUS_CTX): bounds that come from the world.
enum { BODY_VERTICES, BODY_HANDS, BODY_CONTEXT };

// One object: 39 words. The model fields (shape, mass) are in the definition checksum instead.
static const hs_field body_fields[] = {
    {HS_ONE(hs_body, pos, VEC3)},
    {HS_ONE(hs_body, prev, VEC3)},
    {HS_ONE(hs_body, rot, ROTATION)},
    {HS_ONE(hs_body, rot_prev, ROTATION)},
    {HS_ONE(hs_body, spin, ROTATION)},
    {HS_ONE(hs_body, vel, VEC3)},
    {HS_ONE(hs_body, contact, U8), .hi = HS_CONTACT_PUSH_MANY},
    {HS_ONE(hs_body, floor_contacts, INT), .lo = 0, HS_HI_PLUS_CTX(BODY_VERTICES)}, // its shape's vertices
    {HS_ONE(hs_body, grounded, U8), .hi = 1},
    {HS_ONE(hs_body, asleep, U8), .hi = 1},
    {HS_ONE(hs_body, held, U8), .hi = 1},
    {HS_ONE(hs_body, carried, U8), .hi = 1},
    {HS_ONE(hs_body, grasped_by, INT), .lo = 0, HS_HI_PLUS_CTX(BODY_HANDS)},
    {HS_ONE(hs_body, grip_pos, VEC3)},
    {HS_ONE(hs_body, grip_rot, QUAT)}, // zero until a grasp begins
    {HS_ONE(hs_body, grip_spread, F64)},
    {HS_ONE(hs_body, grip_reach, F64)},
    {HS_ONE(hs_body, grip_fingers, U8), .hi = 31},
    {HS_ONE(hs_body, released_by, INT), .lo = 0, HS_HI_PLUS_CTX(BODY_HANDS)},
};

// A hand's older wrist poses, element by element (older_pos[0], older_rot[0], older_pos[1], ...).
static const hs_field hand_older_fields[] = {
    {HS_ALL(hs_hand, state.older_pos, VEC3)},
    {HS_ALL(hs_hand, state.older_rot, ROTATION)},
};

// One hand: 68 words and 7 for each of its older_capacity older wrist poses (117 at the default
// release window: HS_HAND_OLDER of them), the two readings its check points now and a frame ago
// come from (the points and lines are rebuilt from them after a load), its tracking state and its
// fingertip pairs' closing references, the wrist poses before those (a release's velocity), its two
// touch masks and its two embedded masks; a joint-driven hand's joints too (120 words). Its
// definition is in the checksum; older_capacity follows from the world's (dt, release_window_s).
static const hs_field hand_fields[] = {
    {HS_ONE(hs_hand, state.wrist_pos, VEC3)},
    {HS_ONE(hs_hand, state.wrist_rot, ROTATION)},
    {HS_ALL(hs_hand, state.sensors, U8), .hi = UINT8_MAX},
    {HS_ONE(hs_hand, state.prev_wrist_pos, VEC3)},
    {HS_ONE(hs_hand, state.prev_wrist_rot, ROTATION)},
    {HS_ALL(hs_hand, state.prev_sensors, U8), .hi = UINT8_MAX},
    {HS_ALL(hs_hand, state.joints, VEC3), HS_WHEN(hs_hand, model.def.joint_driven)},
    {HS_ALL(hs_hand, state.prev_joints, VEC3), HS_WHEN(hs_hand, model.def.joint_driven)},
    {HS_ONE(hs_hand, state.placed, BOOL)},
    {HS_ONE(hs_hand, state.untracked, BOOL)},
    {HS_ONE(hs_hand, state.lost_frames, INT), .lo = 0, .hi = INT_MAX},
    {HS_ALL(hs_hand, state.pair_open, F64)},
    {HS_ONE(hs_hand, state.older_count, INT), .lo = 0, HS_HI_PLUS(hs_hand, model.older_capacity)},
    // all of them (those not yet reached are zero): a fixed size
    {HS_GROUP("older poses", hand_older_fields), HS_COUNT_AT(hs_hand, model.older_capacity)},
    {HS_ONE(hs_hand, state.touch_points, MASK32), .hi = HS_HAND_POINTS},
    {HS_ONE(hs_hand, state.touch_lines, MASK64), .hi = HS_HAND_LINES},
    {HS_ONE(hs_hand, state.embed_points, MASK32), .hi = HS_HAND_POINTS},
    {HS_ONE(hs_hand, state.embed_lines, MASK64), .hi = HS_HAND_LINES},
};

// The world's own words, before its objects, hands and spring system.
static const hs_field world_fields[] = {
    {HS_ONE(hs_world, state.frame, LONG), .lo = 0, .hi = LONG_MAX},
    {HS_ONE(hs_world, counters.numeric_faults, LONG), .lo = 0, .hi = LONG_MAX},
    {HS_ONE(hs_world, state.first_fault_frame, LONG), .lo = -1, .hi = LONG_MAX},
    {HS_ONE(hs_world, state.first_fault_object, INT), .lo = -1, .hi = -1, HS_HI_PLUS(hs_world, model.object_count)},
};

// A body's walk, in any mode: inlined where the mode is a constant (the digests, every frame).
static HS_FORCE_INLINE void body_walk(hs_state_io *io, const hs_world *w, hs_body *b, bool inline_walk) {
	const int64_t ctx[BODY_CONTEXT] = {[BODY_VERTICES] = w->model.shapes[b->shape].vertex_count, [BODY_HANDS] = w->model.hand_count};
	if (inline_walk)
		hs_fields_walk(io, body_fields, HS_FIELDS_COUNT(body_fields), b, ctx);
	else
		hs_fields_io(io, body_fields, HS_FIELDS_COUNT(body_fields), b, ctx);
}

static void hand_walk(hs_state_io *io, hs_hand *h) { hs_fields_io(io, hand_fields, HS_FIELDS_COUNT(hand_fields), h, NULL); }

#define HS_HASH_LANES {HS_HASH_SEED, ~HS_HASH_SEED, HS_HASH_SEED >> 1, 1}

// A hand's words in HASH mode, as its walk visits them (every frame: 117 at the default window),
// gathered (the walk in GATHER mode, inlined over its constant table) to be mixed four lanes at a
// time. HS_HASH_SELFCHECK builds compare with the walk.
#define HAND_WORDS_MAX (68 + 6 * HS_HAND_POINTS + 7 * HS_HAND_OLDER_MAX) // joint-driven: its joints twice
static size_t hand_words(hs_hand *h, uint64_t *w) {
	hs_state_io gather = {.mode = HS_STATE_GATHER, .gather = w};
	hs_fields_walk(&gather, hand_fields, HS_FIELDS_COUNT(hand_fields), h, NULL);
	return gather.words;
}

static void hand_hash(hs_state_io *io, hs_hand *h) {
	uint64_t words[HAND_WORDS_MAX];
#if defined(HS_HASH_SELFCHECK)
	hs_state_io walked = *io;
	hand_walk(&walked, h);
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
	body_walk(&io, w, &w->state.bodies[i], true); // HASH mode only reads the fields
	return hs_state_hash_of(&io);
}

#if defined(HS_HASH_SELFCHECK)
// Sanitizer builds: every hash checks the kept digests against a walk over every object, so a
// change the stale list missed fails the first test that hashes after it.
static void check_digests(const hs_world *w) {
	uint64_t sum = 0;
	for (int i = 0; i < w->model.object_count; ++i) {
		uint64_t d = body_digest(w, i);
		if (d != w->cache.digest[i]) {
			fprintf(stderr, "handspring: object %d changed at frame %ld but was not marked stale\n", i, w->state.frame);
			abort();
		}
		sum += d;
	}
	if (sum != w->cache.digest_sum) {
		fprintf(stderr, "handspring: digest sum wrong at frame %ld\n", w->state.frame);
		abort();
	}
}
#endif

// The sum of every object's digest, after digesting again those that may have changed. The
// digests are a cache of the hash (not state): refreshing them changes no result.
static uint64_t objects_digest(hs_world *w) {
	if (w->cache.all_stale) {
		w->cache.digest_sum = 0;
		for (int i = 0; i < w->model.object_count; ++i) {
			w->cache.digest[i] = body_digest(w, i);
			w->cache.digest_sum += w->cache.digest[i];
		}
		memset(w->cache.stale_flag, 0, (size_t)w->model.object_count);
		w->cache.stale_count = 0;
		w->cache.all_stale = false;
	}
	for (int k = 0; k < w->cache.stale_count; ++k) {
		int i = w->cache.stale[k];
		uint64_t d = body_digest(w, i);
		w->cache.digest_sum += d - w->cache.digest[i]; // unsigned: wraps, as the sum does
		w->cache.digest[i] = d;
		w->cache.stale_flag[i] = 0;
	}
	w->cache.stale_count = 0;
#if defined(HS_HASH_SELFCHECK)
	check_digests(w);
#endif
	return w->cache.digest_sum;
}

// The whole state after the header: the single list of what a step reads from the last one. The
// hash takes the objects as the sum of their digests (above); the other modes walk them in order.
static HS_FORCE_INLINE void world_io(hs_state_io *io, hs_world *w) {
	io->objects = w->model.object_count;
	if (io->mode == HS_STATE_HASH)
		hs_fields_walk(io, world_fields, HS_FIELDS_COUNT(world_fields), w, NULL);
	else
		hs_fields_io(io, world_fields, HS_FIELDS_COUNT(world_fields), w, NULL);
	if (io->mode == HS_STATE_HASH) {
		uint64_t objects = objects_digest(w);
		hs_state_u64(io, &objects);
	} else {
		for (int i = 0; i < w->model.object_count; ++i)
			body_walk(io, w, &w->state.bodies[i], false);
	}
	for (int h = 0; h < w->model.hand_count; ++h)
		if (io->mode == HS_STATE_HASH)
			hand_hash(io, &w->state.hands[h]);
		else
			hand_walk(io, &w->state.hands[h]);
	if (w->state.spring)
		hs_spring_state_io(w->state.spring, io);
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
	vsnprintf(w->out.state_error, sizeof w->out.state_error, format, args);
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
	world->out.state_error[0] = '\0';
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
	for (int h = 0; h < world->model.hand_count; ++h)
		hs_hand_refresh(&world->state.hands[h]);
	hs_broadphase_reset(world);
	world->out.contact_count = 0; // the last step's contacts are output, not state
	return HS_OK;
}

const char *hs_world_state_error(const hs_world *world) { return world ? world->out.state_error : "no world"; }
