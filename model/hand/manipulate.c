// manipulate.c — how the hand moves objects (1999 paper §3.2, Fig. 2-3) and how objects
// interfering with a moved object follow it (§4.3, paper mode).
#include <math.h>
#include <string.h>

#include "broadphase.h"
#include "collide.h"
#include "contact.h"
#include "grasp.h"
#include "hand_sweep.h"
#include "interfere.h"
#include "inline.h"
#include "manipulate.h"
#include "motion.h"
#include "push.h"
#include "stacking.h"
#include "support.h"

// Eq. 1-2: C on the surface is moved to B, the finger point now. CB = T + R with T ∥ CG:
// translate by T, turn about the axis through G along R × CG by atan(|R| / |CG|), so C moves along R.
void hs_push_at_one_point(hs_body *body, hs_vec3 c, hs_vec3 b) {
	hs_vec3 cb = hs_sub(b, c), cg = hs_sub(body->pos, c);
	double cg_len = hs_length(cg);
	if (!(cg_len > 0.0)) { // C at G: nothing to turn about
		body->pos = hs_add(body->pos, cb);
		return;
	}
	hs_vec3 cg_unit = hs_scale(cg, 1.0 / cg_len);
	hs_vec3 t = hs_scale(cg_unit, hs_dot(cb, cg_unit));
	hs_vec3 r = hs_sub(cb, t);
	body->pos = hs_add(body->pos, t);
	double r_len = hs_length(r);
	if (r_len > 0.0) { // R = 0: CB ∥ CG, translation only
		hs_vec3 axis = hs_normalize(hs_cross(r, cg));
		hs_quat q = hs_quat_from_axis_angle(axis, hs_atan(r_len / cg_len));
		body->rot = hs_quat_normalize(hs_quat_mul(q, body->rot));
	}
}

// The hand that holds a grasped object: the one already holding it while its own contacts still
// grasp, else the first hand whose own contacts grasp, else the one with the most contacts (two
// hands squeezing from either side; the lower index on a tie).
static int grasping_hand(const hs_world_model *model, const hs_body *body, const hs_contact *cs, int n) {
	double limit = model->grasp_limit;
	bool any = model->def.grasp_any_contacts;
	if (body->grasped_by > 0 && hs_contact_grasps(cs, n, (uint32_t)body->grasped_by, limit, any))
		return body->grasped_by - 1;
	for (int h = 0; h < model->hand_count; ++h)
		if (hs_contact_grasps(cs, n, (uint32_t)h + 1, limit, any))
			return h;
	int counts[64] = {0};
	for (int k = 0; k < n; ++k)
		counts[cs[k].hand.index1 - 1]++;
	int best = 0;
	for (int h = 1; h < model->hand_count; ++h)
		if (counts[h] > counts[best])
			best = h;
	return best;
}

// Adds object j to the sorted candidates of this frame's hand pass, once.
static HS_FORCE_INLINE void add_candidate(hs_world_scratch *scratch, int j) {
	int k = scratch->candidate_count;
	while (k > 0 && scratch->candidates[k - 1] > j)
		--k;
	if (k > 0 && scratch->candidates[k - 1] == j)
		return;
	for (int m = scratch->candidate_count; m > k; --m)
		scratch->candidates[m] = scratch->candidates[m - 1];
	scratch->candidates[k] = j;
	++scratch->candidate_count;
}

// The rigid motion of a hand's frame on an object: from (pos0, rot0) to (pos, rot).
typedef struct rigid_move {
	hs_vec3 from, to; // the moved object's G before and after
	hs_quat turn;     // its rotation over the move
} rigid_move;

// §4.3, paper mode: every object interfering with a moved object moves with it, and so on: by the
// moved object's rigid motion, its turn about its G included. Translated only, a cube on a held bar
// that the tracker's noise tilted by 0.15 deg lost its contact on one side each frame and fell onto
// the bar again; let go in such a frame, the bar no longer interfered with it and fell a frame
// (3.4 cm at 12 frames/s) before the two met again.
static void carry_along(const hs_broadphase *bp, int moved, int current, rigid_move m) {
	const hs_world_model *model = bp->model;
	hs_body *bodies = bp->bodies;
	hs_world_scratch *scratch = bp->scratch;
	hs_vec3 d = hs_sub(m.to, m.from);
	if (model->def.paper_carry) // [H] §4.3's letter: translated along with it
		m.turn = hs_quat_identity();
	bool turned = m.turn.x != 0.0 || m.turn.y != 0.0 || m.turn.z != 0.0;
	if (model->def.stacking != HS_STACKING_PAPER || !(hs_length_sq(d) > 0.0 || turned))
		return;
	hs_quat back = hs_quat_conj(m.turn);
	int head = 0, tail = 0;
	scratch->queue[tail++] = moved;
	while (head < tail) {
		int i = scratch->queue[head++];
		const hs_body *moved_body = &bodies[i];
		// where i was before this move (its inverse motion about the mover's G)
		hs_vec3 was = hs_add(m.from, hs_quat_rotate(back, hs_sub(moved_body->pos, m.to)));
		hs_quat was_rot = hs_quat_normalize(hs_quat_mul(back, moved_body->rot));
		double ra = model->shapes[moved_body->shape].radius;
		int n = hs_grid_near_either(bp, moved_body->pos, was, ra); // both are tested below
		for (int k = 0; k < n; ++k) {
			int j = scratch->near[k];
			hs_body *b = &bodies[j];
			if (j == moved || b->held || b->carried)
				continue;
			// the sphere tests the two overlap tests begin with, both at once (i does not move in this
			// loop: j is never i, which is moved or carried)
			double r = ra + model->shapes[b->shape].radius;
			if (spheres_apart(r, moved_body->pos, b) && spheres_apart(r, was, b))
				continue;
			// interfering where i is now, or where it was before this move (an object resting on a
			// held one that the hand lowers a little: under tracker noise it was left hovering)
			bool now = overlap_at_pose_in(model, bodies, bp->cache->box_memo, i, moved_body->pos, moved_body->rot, j);
			bool before = overlap_at_pose_in(model, bodies, bp->cache->box_memo, i, was, was_rot, j);
			if (!now && !before)
				continue;
			if (!before && hs_stack_pile_onto(model, bodies, j, i)) { // met from the side below its G: piled on i
				hs_wake(bodies, bp->cache, j);
				hs_grid_update(model, bodies, bp->cache, j);
				continue;
			}
			hs_vec3 at = hs_add(m.to, hs_quat_rotate(m.turn, hs_sub(b->pos, m.from)));
			b->prev = hs_add(b->prev, hs_sub(at, b->pos)); // carried, not thrown: no inertia is gained
			b->pos = at;
			if (turned) {
				b->rot = hs_quat_normalize(hs_quat_mul(m.turn, b->rot));
				b->rot_prev = hs_quat_normalize(hs_quat_mul(m.turn, b->rot_prev));
			}
			b->carried = 1;
			hs_wake(bodies, bp->cache, j);
			hs_motion_keep_above_floor(model, scratch, b);
			hs_grid_update(model, bodies, bp->cache, j);
			scratch->queue[tail++] = j;
			if (j > current) // it may have come within a hand's reach: look at it this frame
				add_candidate(scratch, j);
		}
	}
}

// How many of the hand's last frames a release's velocity is taken over: round(release_window_s /
// dt) of them (the default 50 ms: 1 at 12-17 frames/s, 3 at 60, 6 at 120), at most the wrist poses
// it has. Over one frame at 120 frames/s the tracker's noise alone (0.76 mm) made a hand opening in
// place release the object at up to 0.2 m/s and 30 deg/s: a pair let go 0.1 m up landed 3 cm off
// (docs/model.md §4 "Release").
static int release_frames(const hs_world_def *def, const hs_hand *hand) {
	int n = hs_release_window_frames(def->release_window_s, def->dt);
	int most = hand->state.older_count + 1;
	return n > most ? most : n;
}

// Where the wrist carried the object `frames` frames before this frame's end.
static hs_vec3 held_then(const hs_body *body, const hs_hand *hand, int frames) {
	hs_vec3 pos;
	hs_quat rot;
	hs_hand_past_wrist(hand, frames, &pos, &rot);
	return hs_add(pos, hs_quat_rotate(rot, body->grip_pos));
}

// HS_RELEASE_FIT_QUADRATIC (bench/throw_fidelity.c's "lsq"), frames ≥ 2: the least-squares
// quadratic through where the wrist carried the object j = 0 … frames frames back, its slope at
// j = 0 (the release), as a motion per frame. Fitted in the discrete orthogonal polynomials of j
// about c = frames / 2 (1, j − c, (j − c)² − s², s² their variance), whose coefficients are plain
// ratios of sums: exact for a wrist at constant acceleration, where the mean lags by a·window/2.
static hs_vec3 quadratic_slope(const hs_body *body, const hs_hand *hand, int frames) {
	double c = 0.5 * frames, s2 = frames * (frames + 2) / 12.0, n1 = 0.0, n2 = 0.0;
	hs_vec3 here = hs_grasp_held_pos(body, hand), b1 = hs_v3(0, 0, 0), b2 = b1;
	for (int j = 0; j <= frames; ++j) {
		double p1 = j - c, p2 = p1 * p1 - s2;
		n1 += p1 * p1;
		n2 += p2 * p2;
		if (j > 0) { // positions relative to the release's (y = 0 at j = 0): small sums
			hs_vec3 y = hs_sub(held_then(body, hand, j), here);
			b1 = hs_mul_add(b1, p1, y);
			b2 = hs_mul_add(b2, p2, y);
		}
	}
	// d/dj of b1 (j − c) + b2 ((j − c)² − s²) at j = 0 is b1 − 2c b2, per frame back in time
	return hs_sub(hs_scale(b2, 2.0 * c / n2), hs_scale(b1, 1.0 / n1));
}

// The wrist's mean motion per frame, where it carried the object, over `frames` frames ending
// `back` frames before this frame's end (*v_dt), and its mean turn per frame over them (*turn).
static void carried_motion(const hs_body *body, const hs_hand *hand, int back, int frames, hs_vec3 *v_dt, hs_quat *turn) {
	hs_vec3 end_pos, then_pos;
	hs_quat end_rot, then_rot;
	hs_hand_past_wrist(hand, back, &end_pos, &end_rot);
	hs_hand_past_wrist(hand, back + frames, &then_pos, &then_rot);
	hs_vec3 end = hs_add(end_pos, hs_quat_rotate(end_rot, body->grip_pos));
	hs_vec3 then = hs_add(then_pos, hs_quat_rotate(then_rot, body->grip_pos));
	*v_dt = hs_scale(hs_sub(end, then), 1.0 / frames);
	hs_quat q = hs_quat_normalize(hs_quat_mul(end_rot, hs_quat_conj(then_rot)));
	*turn = frames == 1 ? q : hs_quat_normalize(hs_quat_slerp(hs_quat_identity(), q, 1.0 / frames));
}

// A hand moving at least this fast (m/s) while it held the object can throw it (release_motion).
#define HS_RELEASE_MOVING 0.1
// cos 45°: the release frame's motion continues the held motion within this angle (release_motion).
#define HS_RELEASE_CONTINUES 0.70710678118654752

// The motion a released object leaves with (docs/model.md §4 "Release"): the wrist's over the
// window that ends with this frame, in which the hand opened (*v_dt, *turn, as carried_motion),
// when that motion continues the one the hand had while it still held the object (the same window
// a frame earlier: moving at HS_RELEASE_MOVING or more, within 45°): a throw opens the hand mid-swing,
// and at 12 frames/s the frame before the opening can be half a swing behind. Otherwise the slower
// of the two: a hand that opens and moves off sideways in the same frame, both fingertips leaving
// the object, does not throw it, and a hand that stopped and opened sets it down.
static void release_motion(const hs_world_def *def, const hs_body *body, const hs_hand *hand, hs_vec3 *v_dt, hs_quat *turn) {
	int frames = release_frames(def, hand);
	carried_motion(body, hand, 0, frames, v_dt, turn);
	if (def->release_fit == HS_RELEASE_FIT_QUADRATIC && frames >= 2) // as the bench's lsq
		*v_dt = quadratic_slope(body, hand, frames);
	int held = frames < hand->state.older_count ? frames : hand->state.older_count; // past(1 + held) must exist
	if (held < 1)
		return;
	hs_vec3 h_dt;
	hs_quat h_turn;
	carried_motion(body, hand, 1, held, &h_dt, &h_turn);
	double held_len = hs_length(h_dt), open_len = hs_length(*v_dt);
	bool moving = held_len >= HS_RELEASE_MOVING * def->dt;
	double along = hs_dot(*v_dt, h_dt);
	if (moving && along >= HS_RELEASE_CONTINUES * open_len * held_len)
		return;
	if (moving && along < 0.0) { // the hand turned back as it opened (set down, then lifted away):
		*v_dt = hs_v3(0, 0, 0); // the object left it at the turn, at rest
		*turn = hs_quat_identity();
		return;
	}
	if (held_len < open_len) {
		*v_dt = h_dt;
		*turn = h_turn;
	}
}

// Eq. 3 on release. A grasp that ends starts eq. 3 on the exact parabola of the release velocity
// v (docs/model.md §4 "Release"), as hs_world_add_object does for an initial velocity: P(t - dt) =
// P(t) - v dt + g dt²/2, so the flight does not depend on the frame rate. v is the hand's motion
// over its last frames (release_motion). The object's own last frame
// (the paper's letter: eq. 3 continued from its last two positions) lags the hand by a frame: at
// 12 frames/s, with the hand opened 10 ms after the end of a 0.1 s swing, its last held frame is
// mid-swing and a throw aimed 2 m away landed 1.11 m short. The spin is the wrist's mean turn over
// those frames. Any other release (a push ends, `last` its contact state) flies on with the motion
// and turn of its last frame (§4.1), unless it is left on the floor (push.c).
static void release(const hs_motion_pass *mp, const hs_hand *hands, hs_body *body, hs_contact_state last) {
	const hs_world_def *def = &mp->model->def;
	if (body->grasped_by > 0 && def->release_fit == HS_RELEASE_FIT_OBJECT) {
		// the letter: eq. 3 from its last two held positions (grasp.c left it at the last) and turn
		body->spin = hs_quat_normalize(hs_quat_mul(body->rot, hs_quat_conj(body->rot_prev)));
	} else if (body->grasped_by > 0) {
		const hs_hand *hand = &hands[body->grasped_by - 1];
		double dt = def->dt;
		hs_vec3 v_dt;
		hs_quat turn;
		release_motion(def, body, hand, &v_dt, &turn);
		// the fingers opened somewhere in this frame, which does not say where: taken as its middle,
		// the object leaves this frame where the hand carried it (this frame's step adds v dt) with
		// the velocity v + g dt / 2 it has half a frame after leaving the hand at v
		body->prev = hs_add(hs_sub(body->pos, v_dt), hs_scale(def->gravity, dt * dt));
		body->spin = turn;
	} else {
		body->spin = hs_quat_normalize(hs_quat_mul(body->rot, hs_quat_conj(body->rot_prev)));
		if (!def->paper_push_end && hs_push_release_on_floor(mp, body, last == HS_CONTACT_PUSH_MANY)) { // it stays on the floor
			body->grasped_by = 0;
			return;
		}
	}
	body->grasped_by = 0;
	body->grounded = 0;
	body->asleep = 0;
}

// An object the hand pass need not look at unless a hand reaches it: it touched nothing last frame
// and no hand holds or has let go of it (a pass over it would find no contact and change nothing).
static bool untouched(const hs_body *b) {
	return b->contact == HS_CONTACT_NONE && !b->held && !b->grasped_by && !b->released_by;
}

// The objects a hand may touch (the grid's cells near its path, then the bounding-sphere test the
// narrow tests start with), those held last frame (they may be let go) and those under a release
// rule, in index order.
static void collect_candidates(const hs_broadphase *bp, const hs_hand *hands) {
	const hs_world_model *model = bp->model;
	const hs_world_cache *cache = bp->cache;
	hs_body *bodies = bp->bodies;
	hs_world_scratch *scratch = bp->scratch;
	bool skip = model->skip_work;
	// carried or held last frame means awake: only the awake list needs looking at
	for (int k = 0, n = skip ? cache->awake_count : model->object_count; k < n; ++k)
		bodies[skip ? cache->awake[k] : k].carried = 0;
	scratch->candidate_count = 0;
	for (int h = 0; h < model->hand_count; ++h) {
		const hs_hand *hand = &hands[h];
		int n = hs_grid_near(bp, hand->cache.sweep_center, hand->cache.sweep_radius);
		for (int k = 0; k < n; ++k) {
			const hs_body *b = &bodies[scratch->near[k]];
			if (!untouched(b) || hs_contact_hand_near(model, b, hand, 0.0))
				add_candidate(scratch, scratch->near[k]);
		}
	}
	for (int k = 0; k < cache->awake_count; ++k) // a release rule lapses once its hand is clear (grasp.c)
		if (bodies[cache->awake[k]].held || bodies[cache->awake[k]].released_by)
			add_candidate(scratch, cache->awake[k]);
}

static bool pose_changed(const hs_body *body, hs_pose was) {
	return body->pos.x != was.pos.x || body->pos.y != was.pos.y || body->pos.z != was.pos.z || body->rot.w != was.rot.w ||
	       body->rot.x != was.rot.x || body->rot.y != was.rot.y || body->rot.z != was.rot.z;
}

// §3.2: a grasped object follows the grasping wrist, one contact pushes by eq. 1-2 (on the floor
// without lifting or sinking it, push.c), several contacts translate it by the mean of the parts'
// motions while touching (3; the paper: their mean displacement over the frame, which also counts
// the motion before a part reached the surface and shoves the object off the fingers).
// A grasp that continues (grasp.c) has already moved the object with its wrist.
static void move_by_contacts(const hs_motion_pass *mp, const hs_hand *hands, hs_body *body, hs_contact_state state,
                             const hs_contact *cs, int n, bool continues) {
	if (state == HS_CONTACT_GRASP) {
		if (continues)
			return;
		int h = grasping_hand(mp->model, body, cs, n);
		hs_grasp_begin(body, &hands[h], h, cs, n); // fix the pose in the wrist frame (§3.2 (2))
		hs_grasp_follow_wrist(body, &hands[h]);
	} else if (state == HS_CONTACT_PUSH_ONE) {
		body->grasped_by = 0;
		if (mp->model->def.paper_floor_push || !hs_push_on_floor(mp, body, cs[0].point, cs[0].finger)) // on the floor: model.md §4
			hs_push_at_one_point(body, cs[0].point, cs[0].finger);
	} else {
		body->grasped_by = 0;
		hs_vec3 sum = hs_v3(0, 0, 0);
		for (int k = 0; k < n; ++k) // each part's motion while touching (B - C: rectified, contact.c)
			sum = hs_add(sum, hs_sub(cs[k].finger, cs[k].point));
		hs_push_many(mp, body, hs_scale(sum, 1.0 / n));
	}
}

// The pose a frame ago that eq. 3 continues from if the contact ends (release: P(t) - P(t - dt)
// is the velocity times dt, rot · rot_prev⁻¹ the spin). A push at one point that began in the
// frame moved the object only over the part after the finger reached it (a fraction `after` of
// the frame, hs_contact.t): its velocity is that motion over that time, so the motion and the turn
// are remembered scaled by 1 / after (at most HS_PUSH_SPEEDUP). Without it a flick's spin and
// velocity depended on where the frames fell: the same 2 cm push over the last 46 % of a 1/30 s
// frame and over the last 92 % of a 1/60 s frame left the pyramid half as fast at 30 frames/s.
// The cap bounds what noise on a touch in a frame's last tenth can launch (at 4, a flick a
// 12-30 frames/s tracker saw reach the face in the last quarter of a frame flew on too slowly to
// tip the pyramid over).
#define HS_PUSH_SPEEDUP 10.0
static void remember_motion(hs_body *body, hs_vec3 old_pos, hs_quat old_rot, double after) {
	body->prev = old_pos;
	body->rot_prev = old_rot;
	if (!(after < 1.0))
		return;
	double s = after > 1.0 / HS_PUSH_SPEEDUP ? 1.0 / after : HS_PUSH_SPEEDUP;
	body->prev = hs_mul_add(body->pos, -s, hs_sub(body->pos, old_pos));
	hs_quat q = hs_quat_normalize(hs_quat_mul(body->rot, hs_quat_conj(old_rot))); // this frame's turn
	hs_vec3 v = hs_v3(q.x, q.y, q.z);
	double sin_half = hs_length(v);
	if (!(sin_half > 0.0))
		return;
	double angle = 2.0 * hs_atan2(sin_half, q.w);
	hs_quat scaled = hs_quat_from_axis_angle(hs_scale(v, 1.0 / sin_half), angle * s);
	body->rot_prev = hs_quat_normalize(hs_quat_mul(hs_quat_conj(scaled), body->rot));
}

// A push at one point whose part drives nothing (B = C: a sunk part leaving or sliding along the
// face, contact.c's friction) on an object that moved last frame neither moves it nor takes its
// motion away: eq. 3 goes on from the motion it had when the contact ends (as a part off the
// surface within the margin, contact.c: a finger drawn back after a push does not stop what it
// pushed). The flicked pyramid was held on its edge for 2-3 frames at 120 frames/s while the
// lifting fingertip left it, its motion remembered as none, and fell back onto its base.
static bool push_drives_nothing(hs_contact_state state, const hs_contact *cs, int n, bool at_rest) {
	if (at_rest || state != HS_CONTACT_PUSH_ONE)
		return false;
	for (int k = 0; k < n; ++k)
		if (cs[k].finger.x != cs[k].point.x || cs[k].finger.y != cs[k].point.y || cs[k].finger.z != cs[k].point.z)
			return false;
	return true;
}

// An object's own motion beats a finger's push by this factor (outruns); it must be turning over
// (rolling or tipping: about an axis within 30 deg of horizontal) by at least 2 deg a frame
// (HS_OUTRUN_SIN_HALF = sin(1 deg), the sine of half that turn).
#define HS_OUTRUN 1.25
#define HS_OUTRUN_SIN_HALF 0.0174524064372835

// True when an object that rolls or tips over outruns the one part pushing it (docs/model.md §4
// "Pushes that end"): eq. 3 would carry the contact point C further along the part's drive CB than
// the part drives it (by HS_OUTRUN). A finger pushes and never pulls, so it cannot slow an object
// that turns away from it: in a flick's last frame the stroke ends and the finger lifts; that
// frame's smaller push put its motion in place of the pyramid's own, and whether the pyramid
// tipped over depended on where the frames fell on the stroke. An object pushed along the floor
// (turning about the vertical at most) keeps no motion of its own (§4.1: no sliding): a finger
// pushing it drives it every frame, however its speed varies under noise.
static bool outruns(const hs_body *body, const hs_contact *c) {
	hs_quat spin = hs_quat_normalize(hs_quat_mul(body->rot, hs_quat_conj(body->rot_prev)));
	hs_vec3 axis = hs_v3(spin.x, spin.y, spin.z);
	double sin_half = hs_length(axis); // sin(angle / 2), for q and -q alike
	if (!(sin_half >= HS_OUTRUN_SIN_HALF) || fabs(axis.z) > 0.5 * sin_half)
		return false; // not turning over
	hs_vec3 drive = hs_sub(c->finger, c->point);
	double len = hs_length(drive);
	if (!(len > 0.0))
		return false;
	hs_vec3 arm = hs_sub(c->point, body->pos);
	hs_vec3 moved = hs_add(hs_sub(body->pos, body->prev), hs_sub(hs_quat_rotate(spin, arm), arm));
	return hs_dot(moved, drive) >= HS_OUTRUN * len * len;
}

// Which finger parts of each hand touch an object at the end of the frame: next frame a part found
// inside an object it did not reach then is in contact only if it touches now (contact.c). A check
// point that touched and has come off by less than grasp_release_mm still touches (near_points).
static void note_touching(hs_hand *hands, int hand_count, const hs_contact *contacts, int contact_count) {
	for (int h = 0; h < hand_count; ++h) {
		hands[h].state.touch_points = hands[h].scratch.near_points;
		hands[h].state.touch_lines = 0;
		hands[h].state.embed_points = hands[h].scratch.embed_points_next;
		hands[h].state.embed_lines = hands[h].scratch.embed_lines_next;
	}
	for (int k = 0; k < contact_count; ++k) {
		const hs_contact *c = &contacts[k];
		hs_hand *hand = &hands[c->hand.index1 - 1];
		if (c->part < HS_HAND_POINTS)
			hand->state.touch_points |= 1u << c->part;
		else
			hand->state.touch_lines |= (uint64_t)1 << (c->part - HS_HAND_POINTS);
	}
}

// The start of the hand pass: each hand's parts' paths through the frame (swept detection;
// `chords_only`: hs_world_def.paper_contacts) and its pass scratch emptied.
static void begin_hand_pass(hs_hand *hands, int hand_count, bool chords_only) {
	for (int h = 0; h < hand_count; ++h) {
		hs_hand_sweep(&hands[h], chords_only);
		hands[h].scratch.near_points = hands[h].scratch.embed_points_next = 0;
		hands[h].scratch.embed_lines_next = 0;
	}
}

void hs_manipulate(hs_world *world) {
	world->out.contact_count = 0;
	begin_hand_pass(world->state.hands, world->model.hand_count, world->model.def.paper_contacts);
	// the contexts of the hand pass's concepts, made once: the broad phase's (the candidates, what a
	// moved object carries along or wakes), the contact tests' and free motion's (a push)
	hs_broadphase bp = hs_broadphase_of(world);
	hs_contact_pass cp = hs_contact_pass_of(world);
	hs_motion_pass mp = hs_motion_pass_of(world);
	collect_candidates(&bp, world->state.hands);
	// candidate_count may grow in the loop: carry_along adds objects it moved within reach
	for (int c = 0; c < world->scratch.candidate_count; ++c) {
		int i = world->scratch.candidates[c];
		hs_body *body = &world->state.bodies[i];
		int first = world->out.contact_count, n = 0;
		hs_vec3 old_pos = body->pos;
		hs_quat old_rot = body->rot;
		bool continues = false;
		bool at_rest = body->prev.x == old_pos.x && body->prev.y == old_pos.y && body->prev.z == old_pos.z;
		hs_contact_state state = hs_grasp_detect(&cp, &world->cache, body, i, first, &n, &continues);
		if (state == HS_CONTACT_PUSH_ONE && !at_rest && !body->grasped_by && !world->model.def.paper_push_end &&
		    outruns(body, &world->out.contacts[first])) {
			state = HS_CONTACT_NONE; // it turns on by its own motion (eq. 3), the finger left behind
			world->out.contact_count = first;
		}
		bool was_held = body->held != 0;
		hs_contact_state last = (hs_contact_state)body->contact;
		if (state != last) // changed, even if it sleeps on (an object moved is woken, hs_wake)
			hs_digest_stale(&world->cache, i);
		body->contact = (uint8_t)state;
		body->held = 0;
		if (state == HS_CONTACT_NONE) {
			if (was_held)
				release(&mp, world->state.hands, body, last);
			continue;
		}
		move_by_contacts(&mp, world->state.hands, body, state, &world->out.contacts[first], n, continues);
		hs_pose carried_to = {body->pos, body->rot};
		hs_motion_keep_above_floor(&world->model, &world->scratch, body); // §4.2 for a pushed object; the trajectory shows its floor contacts
		if (state == HS_CONTACT_GRASP && pose_changed(body, carried_to)) // pressed into the floor: it slid in the grip
			hs_grasp_slip(body, &world->state.hands[body->grasped_by - 1]);
		bool letter = world->model.def.paper_push_end; // eq. 3 from its last two positions, as they fall
		double after = state == HS_CONTACT_PUSH_ONE && at_rest && !letter ? 1.0 - world->out.contacts[first].t : 1.0;
		if (letter || !push_drives_nothing(state, &world->out.contacts[first], n, at_rest)) // else its motion is kept
			remember_motion(body, old_pos, old_rot, after);
		body->held = 1;
		hs_wake(world->state.bodies, &world->cache, i);
		body->grounded = 0;
		hs_grid_update(&world->model, world->state.bodies, &world->cache, i);
		if (world->model.def.stacking == HS_STACKING_SUPPORT) // what rested on it or against it looks again
			hs_support_wake_neighbours(&bp, i, body->prev);
		else
			carry_along(&bp, i, i,
			            (rigid_move){old_pos, body->pos, hs_quat_normalize(hs_quat_mul(body->rot, hs_quat_conj(old_rot)))});
	}
	note_touching(world->state.hands, world->model.hand_count, world->out.contacts, world->out.contact_count);
}
