// capture.c — what the expectation checks record while the run passes, each from the current
// frame: a state at a clause's frame, a reference pose, a window's before and after, a landing,
// contact states, a release. Called through the predicate table's rows (hs_expect_capture,
// expect.c, at every step); none of it allocates.
#include <limits.h>
#include <math.h>
#include <string.h>

#include "expect.h"
#include "expect_table.h"
#include "overlap.h"
#include "scenario_internal.h"

// The object's velocity: in spring worlds the integrated one, else (P(t) − P(t − dt)) / dt.
static hs_vec3 velocity_of(const hs_scenario *s, int object, const hs_object_state *st) {
	hs_spring_object o;
	if (s->springs && hs_world_spring_object(s->world, s->ids[object], &o) == HS_OK)
		return o.velocity;
	return st->velocity;
}

// What the at-based spring predicates need: who is on the spring, how, and its stretch.
static void capture_spring(const hs_scenario *s, hs_check *k) {
	hs_spring_state ss;
	hs_spring_object o;
	if (hs_world_spring_state(s->world, &ss) != HS_OK)
		return;
	k->u.at.candidate = hs_scenario_index_of(s, ss.candidate);
	k->u.at.holder = hs_scenario_index_of(s, ss.attached);
	if (k->u.at.holder < 0)
		return;
	k->u.at.kind = ss.attach_kind;
	k->u.at.extension = ss.extension;
	if (hs_world_spring_object(s->world, ss.attached, &o) == HS_OK) {
		k->u.at.rest_length = o.rest_length;
		k->u.at.ratio = ss.extension / o.rest_length;
	}
}

void hs_capture_at(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame) {
	(void)c, (void)frame; // called once, at the clause's frame
	k->u.at.state = hs_scenario_state_of(s, k->object);
	k->u.at.velocity = velocity_of(s, k->object, &k->u.at.state);
	k->u.at.holder = k->u.at.candidate = -1;
	if (s->springs)
		capture_spring(s, k);
	k->captured = true;
}

void hs_capture_overlap(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame) {
	hs_capture_at(s, c, k, frame);
	k->u.at.overlap = hs_object_overlap(s->world, k->object, &k->u.at.overlap_with);
}

static bool same_pose(const hs_object_state *a, const hs_object_state *b) {
	double x[7] = {a->position.x,    a->position.y,    a->position.z,   a->orientation.w,
	               a->orientation.x, a->orientation.y, a->orientation.z};
	double y[7] = {b->position.x,    b->position.y,    b->position.z,   b->orientation.w,
	               b->orientation.x, b->orientation.y, b->orientation.z};
	return memcmp(x, y, sizeof x) == 0; // the exact bits: "still" means not one ulp of motion
}

void hs_capture_still(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame) {
	if (frame < c->frame || frame > c->last_frame || k->u.still.moved)
		return;
	hs_object_state st = hs_scenario_state_of(s, k->object);
	if (frame == c->frame) {
		k->u.still.state = st;
		k->captured = true;
	} else if (!same_pose(&k->u.still.state, &st)) {
		k->u.still.moved = true;
		k->u.still.moved_frame = frame;
	}
}

// conserved: the group's momentum Σ m v (kg m/s), or its energy Σ (½ m |v|² − m g·G) (J) in out[0].
static void group_quantity(const hs_scenario *s, const hs_clause *c, double out[3]) {
	out[0] = out[1] = out[2] = 0.0;
	for (int i = 0; i < c->member_count; ++i) {
		hs_spring_object o;
		hs_object_state st;
		int object = s->expect.members[c->first_member + i];
		if (hs_world_spring_object(s->world, s->ids[object], &o) != HS_OK ||
		    hs_world_object_state(s->world, s->ids[object], &st) != HS_OK)
			continue;
		if (c->count == HS_CONSERVE_MOMENTUM) {
			out[0] += o.mass * o.velocity.x;
			out[1] += o.mass * o.velocity.y;
			out[2] += o.mass * o.velocity.z;
		} else {
			out[0] += 0.5 * o.mass * hs_dot(o.velocity, o.velocity) - o.mass * hs_dot(s->gravity, st.position);
		}
	}
}

void hs_capture_conserved(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame) {
	if (frame < c->frame || frame > c->last_frame || k->captured)
		return;
	if (frame == c->frame) {
		group_quantity(s, c, k->u.window.before);
		k->u.window.began = true;
	}
	if (frame == c->last_frame) {
		group_quantity(s, c, k->u.window.after);
		k->captured = true;
	}
}

// energy_never_grows: the group's mechanical energy per unit mass, Σ (½ |v|² − g·G) over its
// objects (J/kg: the hand model's objects have no mass), v the frame's (P(t) − P(t − dt)) / dt.
static double group_specific_energy(const hs_scenario *s, const hs_clause *c) {
	double e = 0.0;
	for (int i = 0; i < c->member_count; ++i) {
		hs_object_state st = hs_scenario_state_of(s, s->expect.members[c->first_member + i]);
		e += 0.5 * hs_dot(st.velocity, st.velocity) - hs_dot(s->gravity, st.position);
	}
	return e;
}

void hs_capture_energy(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame) {
	if (frame < c->frame || frame > c->last_frame || k->captured)
		return;
	double e = group_specific_energy(s, c);
	if (frame == c->frame) {
		k->u.window.before[0] = k->u.window.peak = e;
		k->u.window.peak_frame = frame;
		k->u.window.began = true;
	} else if (e > k->u.window.peak) {
		k->u.window.peak = e;
		k->u.window.peak_frame = frame;
	}
	if (frame == c->last_frame)
		k->captured = true;
}

// swing_below: the horizontal distance (m) from the stylus to the object's G.
static double swing_of(const hs_scenario *s, int object) {
	hs_spring_state ss;
	hs_object_state st;
	if (hs_world_spring_state(s->world, &ss) != HS_OK || hs_world_object_state(s->world, s->ids[object], &st) != HS_OK)
		return 0.0;
	double dx = st.position.x - ss.stylus.x, dy = st.position.y - ss.stylus.y;
	return sqrt(dx * dx + dy * dy);
}

void hs_capture_swing(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame) {
	if (frame < c->frame || frame > c->last_frame || k->captured)
		return;
	double d = swing_of(s, k->object);
	if (!k->u.window.began || d > k->u.window.peak) {
		k->u.window.peak = d;
		k->u.window.peak_frame = frame;
	}
	k->u.window.began = true;
	k->captured = frame == c->last_frame;
}

// lands_at: the first frame with floor contacts after a frame without any.
void hs_capture_lands(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame) {
	(void)c;
	if (k->u.lands.landed)
		return;
	hs_object_state st = hs_scenario_state_of(s, k->object);
	if (st.floor_contacts == 0) {
		k->u.lands.had_no_floor = true;
	} else if (k->u.lands.had_no_floor) {
		k->u.lands.landed = true;
		k->u.lands.frame = frame;
	}
}

// contact_sequence: the object's contact state, repeats collapsed.
// A state is recorded once it has been held for the clause's min_frames (1: at once), and only
// when it differs from the last one recorded: a briefer one is left out.
void hs_capture_sequence(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame) {
	(void)frame;
	unsigned char state = (unsigned char)hs_scenario_state_of(s, k->object).contact;
	if (k->u.seq.held > 0 && k->u.seq.last == state) {
		k->u.seq.held++;
	} else {
		k->u.seq.last = state;
		k->u.seq.held = 1;
	}
	if (k->u.seq.held != c->min_frames || (k->u.seq.len > 0 && k->u.seq.states[k->u.seq.len - 1] == state))
		return;
	if (k->u.seq.len < HS_SEQ_CAPACITY)
		k->u.seq.states[k->u.seq.len++] = state;
	else
		k->u.seq.overflow++;
}

// never: the clause breaks when the object is in the state (never_contact), else when it is not
// (grasped)
static void capture_contact(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame, bool never) {
	if (frame < c->frame || frame > c->last_frame || k->u.still.moved)
		return;
	hs_object_state st = hs_scenario_state_of(s, k->object);
	if (never ? (long)st.contact == c->count : (long)st.contact != c->count) {
		k->u.still.moved = true; // "moved" from what the clause allows: the first breaking frame
		k->u.still.moved_frame = frame;
		k->u.still.state = st;
	}
	k->captured = frame == c->last_frame;
}
void hs_capture_never_contact(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame) {
	capture_contact(s, c, k, frame, true);
}
void hs_capture_grasped(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame) {
	capture_contact(s, c, k, frame, false);
}

// released: the object's last release; at most one release per frame, so none is missed.
void hs_capture_release(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame) {
	(void)c, (void)frame;
	hs_release release;
	memset(&release, 0, sizeof release); // no padding byte of it may reach a state file uninitialised
	if (hs_world_spring_last_release(s->world, &release) == HS_OK && release.kind != HS_RELEASE_NONE &&
	    hs_scenario_index_of(s, release.object) == k->object)
		k->u.release = release;
}

// ---------------------------------------------------------------------------------------------
// captures in a state file: every field as a 64-bit word, so the file means the same everywhere

static void put_state(hs_state_io *io, const hs_object_state *st) {
	hs_put_vec3(io, st->position);
	hs_put_f64(io, st->orientation.w);
	hs_put_vec3(io, hs_v3(st->orientation.x, st->orientation.y, st->orientation.z));
	hs_put_vec3(io, st->velocity);
	hs_put_i64(io, st->contact);
	hs_put_i64(io, st->floor_contacts);
	hs_put_u64(io, st->resting);
}

// Every field within its range: finite numbers, a unit orientation (zero before the capture), a
// contact state of the enum.
static void get_state(hs_state_io *io, hs_object_state *st) {
	st->position = hs_get_finite3(io, "state.position");
	st->orientation.w = hs_get_finite(io, "state.orientation");
	hs_vec3 q = hs_get_finite3(io, "state.orientation");
	st->orientation.x = q.x, st->orientation.y = q.y, st->orientation.z = q.z;
	hs_quat zero = {0.0, 0.0, 0.0, 0.0}; // a check not captured yet holds a zero state
	if (io->ok && !hs_quat_is_unit(st->orientation) && memcmp(&st->orientation, &zero, sizeof zero) != 0)
		hs_state_refuse_field(io, "state.orientation", "is neither a unit quaternion nor zero (not captured)");
	st->velocity = hs_get_finite3(io, "state.velocity");
	st->contact = (hs_contact_state)hs_get_range(io, "state.contact", HS_CONTACT_NONE, HS_CONTACT_PUSH_MANY);
	st->floor_contacts = (int)hs_get_range(io, "state.floor_contacts", 0, INT_MAX);
	st->resting = hs_get_flag(io, "state.resting");
}

static void put_at(hs_state_io *io, const hs_capture *u) {
	put_state(io, &u->at.state);
	hs_put_vec3(io, u->at.velocity);
	hs_put_i64(io, u->at.holder);
	hs_put_i64(io, u->at.candidate);
	hs_put_i64(io, u->at.kind);
	hs_put_f64(io, u->at.ratio);
	hs_put_f64(io, u->at.extension);
	hs_put_f64(io, u->at.rest_length);
	hs_put_f64(io, u->at.overlap);
	hs_put_i64(io, u->at.overlap_with);
}

static void get_at(hs_state_io *io, hs_capture *u) {
	get_state(io, &u->at.state);
	u->at.velocity = hs_get_finite3(io, "at.velocity");
	u->at.holder = hs_get_object(io, "at.holder");
	u->at.candidate = hs_get_object(io, "at.candidate");
	u->at.kind = (hs_attach_kind)hs_get_range(io, "at.kind", HS_ATTACH_NONE, HS_ATTACH_MAGNET);
	u->at.ratio = hs_get_finite(io, "at.ratio");
	u->at.extension = hs_get_finite(io, "at.extension");
	u->at.rest_length = hs_get_finite(io, "at.rest_length");
	u->at.overlap = hs_get_finite(io, "at.overlap");
	u->at.overlap_with = hs_get_object(io, "at.overlap_with");
}

static void put_still(hs_state_io *io, const hs_capture *u) {
	put_state(io, &u->still.state);
	hs_put_u64(io, u->still.moved);
	hs_put_i64(io, u->still.moved_frame);
}

static void get_still(hs_state_io *io, hs_capture *u) {
	get_state(io, &u->still.state);
	u->still.moved = hs_get_flag(io, "still.moved");
	u->still.moved_frame = hs_get_frame(io, "still.moved_frame");
}

static void put_window(hs_state_io *io, const hs_capture *u) {
	hs_put_u64(io, u->window.began);
	for (int i = 0; i < 3; ++i) {
		hs_put_f64(io, u->window.before[i]);
		hs_put_f64(io, u->window.after[i]);
	}
	hs_put_f64(io, u->window.peak);
	hs_put_i64(io, u->window.peak_frame);
}

static void get_window(hs_state_io *io, hs_capture *u) {
	u->window.began = hs_get_flag(io, "window.began");
	for (int i = 0; i < 3; ++i) {
		u->window.before[i] = hs_get_finite(io, "window.before");
		u->window.after[i] = hs_get_finite(io, "window.after");
	}
	u->window.peak = hs_get_finite(io, "window.peak");
	u->window.peak_frame = hs_get_frame(io, "window.peak_frame");
}

static void put_lands(hs_state_io *io, const hs_capture *u) {
	hs_put_u64(io, u->lands.had_no_floor);
	hs_put_u64(io, u->lands.landed);
	hs_put_i64(io, u->lands.frame);
}

static void get_lands(hs_state_io *io, hs_capture *u) {
	u->lands.had_no_floor = hs_get_flag(io, "lands.had_no_floor");
	u->lands.landed = hs_get_flag(io, "lands.landed");
	u->lands.frame = hs_get_frame(io, "lands.frame");
}

static void put_seq(hs_state_io *io, const hs_capture *u) {
	hs_put_bytes(io, u->seq.states, HS_SEQ_CAPACITY);
	hs_put_i64(io, u->seq.len);
	hs_put_i64(io, u->seq.overflow);
	hs_put_u64(io, u->seq.last);
	hs_put_i64(io, u->seq.held);
}

// The states recorded are contact states, those beyond `len` zero (never written); at most one
// change a frame overflows.
static void get_seq(hs_state_io *io, hs_capture *u) {
	hs_get_bytes(io, u->seq.states, HS_SEQ_CAPACITY);
	u->seq.len = (int)hs_get_range(io, "contact_sequence.len", 0, HS_SEQ_CAPACITY);
	u->seq.overflow = (long)hs_get_range(io, "contact_sequence.overflow", 0, io->frame + 1);
	u->seq.last = (unsigned char)hs_get_range(io, "contact_sequence.last", HS_CONTACT_NONE, HS_CONTACT_PUSH_MANY);
	u->seq.held = (long)hs_get_range(io, "contact_sequence.held", 0, io->frame + 1);
	for (int i = 0; io->ok && i < HS_SEQ_CAPACITY; ++i)
		if (u->seq.states[i] > (i < u->seq.len ? HS_CONTACT_PUSH_MANY : 0))
			hs_state_refuse_field(io, "contact_sequence.states",
			                      i < u->seq.len ? "holds a value that is no contact state" : "is not zero beyond its length");
}

static void put_release(hs_state_io *io, const hs_capture *u) {
	hs_put_i64(io, u->release.kind);
	hs_put_u64(io, u->release.object.index1);
	hs_put_f64(io, u->release.time);
	hs_put_vec3(io, u->release.velocity);
	hs_put_f64(io, u->release.hand_speed);
}

static void get_release(hs_state_io *io, hs_capture *u) {
	u->release.kind = (hs_release_kind)hs_get_range(io, "released.kind", HS_RELEASE_NONE, HS_RELEASE_RETURN);
	u->release.object.index1 = (uint32_t)hs_get_range(io, "released.object", 0, io->objects); // index + 1, 0: none
	u->release.time = hs_get_finite(io, "released.time");
	u->release.velocity = hs_get_finite3(io, "released.velocity");
	u->release.hand_speed = hs_get_finite(io, "released.hand_speed");
}

static const struct {
	void (*put)(hs_state_io *io, const hs_capture *u);
	void (*get)(hs_state_io *io, hs_capture *u);
} stores[] = {
    [HS_STORE_NONE] = {NULL, NULL},          [HS_STORE_AT] = {put_at, get_at},
    [HS_STORE_STILL] = {put_still, get_still}, [HS_STORE_WINDOW] = {put_window, get_window},
    [HS_STORE_LANDS] = {put_lands, get_lands}, [HS_STORE_SEQ] = {put_seq, get_seq},
    [HS_STORE_RELEASE] = {put_release, get_release},
};

void hs_capture_put(hs_state_io *io, hs_store store, const hs_check *k) {
	hs_put_u64(io, k->captured);
	if (stores[store].put)
		stores[store].put(io, &k->u);
}

void hs_capture_get(hs_state_io *io, hs_store store, hs_check *k) {
	k->captured = hs_get_flag(io, "captured");
	if (stores[store].get)
		stores[store].get(io, &k->u);
}
