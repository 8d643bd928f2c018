// capture.c — what the expectation checks record while the run passes, each from the current
// frame: a state at a clause's frame, a reference pose, a window's before and after, a landing,
// contact states, a release. Called from hs_scenario_step; none of it allocates.
#include <math.h>
#include <string.h>

#include "expect_table.h"
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
void hs_capture_sequence(const hs_scenario *s, const hs_clause *c, hs_check *k, long frame) {
	(void)c, (void)frame;
	unsigned char state = (unsigned char)hs_scenario_state_of(s, k->object).contact;
	if (k->u.seq.len > 0 && k->u.seq.last == state)
		return;
	k->u.seq.last = state;
	if (k->u.seq.len < HS_SEQ_CAPACITY)
		k->u.seq.states[k->u.seq.len++] = state;
	else
		k->u.seq.overflow++;
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

void hs_expect_capture(hs_scenario *s) {
	hs_expectations *e = &s->expect;
	long f = s->frame;
	while (e->capture_next < e->capture_count) {
		hs_check *k = &e->checks[e->capture_order[e->capture_next]];
		const hs_clause *c = &e->clauses[k->clause];
		if (c->frame > f)
			break;
		hs_predicates[c->pred].capture(s, c, k, f);
		e->capture_next++;
	}
	for (int i = 0; i < e->live_count; ++i) {
		hs_check *k = &e->checks[e->live[i]];
		const hs_clause *c = &e->clauses[k->clause];
		hs_predicates[c->pred].capture(s, c, k, f);
	}
}
