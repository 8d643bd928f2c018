// step_hand.c — one frame of a hand world (the 1999 paper's model): the step's stages in order,
// each a function below that names its section (docs/model.md follows the same order). A stage
// takes the parts of struct hs_world (world_internal.h) it reads and writes: the hands alone
// (age_hands); the model, bodies and cache (file_objects); the object stages the model, bodies,
// cache, scratch (and counters, fault words), from which they make the broad phase's context
// (broadphase.h) and free motion's (motion.h) where they step an object; track_hands the model,
// hands, bodies and cache; the hand pass (hs_manipulate) the world, from which it makes the broad
// phase's, the contact tests' (contact_pass.h) and free motion's contexts once. Stages call the
// concepts below them and none calls back up here. They are forced inline: the
// step's cost is read from what hs_step_hand calls (tool/bench_cmd.c's stage table), as it was
// from hs_world_step's.
#include "broadphase.h"
#include "fall_group.h"
#include "grasp.h"
#include "inline.h"
#include "interfere.h"
#include "manipulate.h"
#include "motion.h"
#include "stacking.h"
#include "step.h"
#include "support.h"
#include "tracking.h"
#include "world_internal.h"

static bool body_is_finite(const hs_body *body) {
	return hs_vec3_is_finite(body->pos) && hs_vec3_is_finite(body->prev) && hs_quat_is_finite(body->rot) &&
	       hs_quat_is_finite(body->spin);
}

static bool in_list(const int *list, int n, int i) {
	for (int k = 0; k < n; ++k)
		if (list[k] == i)
			return true;
	return false;
}

// Paper mode, an awake object that interferes with others: if nothing holds it up, it falls with
// what rests on it (fall_group.c), whose indices go to bp->scratch->queue from *fallen (support
// mode's list there is never used in paper mode).
static bool paper_group_falls(const hs_broadphase *bp, int i, int *fallen) {
	int n = hs_fall_group(bp, i, bp->scratch->queue + *fallen, bp->model->object_count - *fallen);
	*fallen += n;
	return n > 0;
}

// One unheld object's frame: §4.3 in paper mode (interfering and untouched: no gravity, no
// inertia, but rectified out of the objects under it as out of the floor, Fig. 11), else eq. 3 and
// the floor (§4.2), the fall swept over the objects under it, and in support mode its supports.
// The broad phase's parts (bp) and free motion's (motion) are of one world.
static void step_object(const hs_broadphase *bp, const hs_motion_pass *motion, int i, bool interferes) {
	const hs_world_model *model = bp->model;
	hs_body *body = &bp->bodies[i];
	hs_vec3 from = body->pos;
	if (interferes) {
		hs_stack_rectify(bp, i);
		hs_motion_keep_above_floor(model, bp->scratch, body);
		body->grounded = body->floor_contacts > 0; // it may rest above the floor (carried up)
		body->prev = body->pos;
		body->spin = hs_quat_identity();
		body->asleep = 1;
		return;
	}
	body->rot_prev = body->rot;
	hs_motion_step(motion, body);
	if (hs_stack_sweep(bp, i, from)) {
		hs_motion_keep_above_floor(model, bp->scratch, body); // its floor contacts where it landed
		// Gm of eq. 4-5 as on the floor (motion.c): the rectified motion and this frame's gravity
		double dt = model->def.dt;
		body->prev = hs_mul_add(from, -dt * dt, model->def.gravity);
		if (model->def.stacking == HS_STACKING_PAPER) { // §4.1: stops at the interference, no rebound
			body->prev = body->pos;
			body->asleep = 1;
		}
	}
	if (model->def.stacking == HS_STACKING_SUPPORT && !body->asleep) {
		hs_support_step(bp, motion->counters, i);
		hs_stack_rectify(bp, i); // a turn about a support's edge stops at the floor only (eq. 7)
	}
}

// Experiment 3 (the broad phase): objects added, or a state loaded, since the grid was built are
// filed again. In: the model's shapes, the bodies. Out: cache->grid.
static HS_FORCE_INLINE void file_objects(const hs_world_model *model, const hs_body *bodies, hs_world_cache *cache) {
	if (cache->grid_dirty || !cache->grid_built) {
		hs_grid_build(model, bodies, cache);
		cache->grid_dirty = false;
	}
}

// docs/model.md §3 "Tracking loss": hands lost past tracking_hold_s let their grasps go. In: each
// hand's tracked flag, the hold in frames, dt. Out: the hand's lost-frame count and placement; the
// bodies it let go, woken, their digests stale (cache).
static HS_FORCE_INLINE void track_hands(const hs_world_model *model, hs_hand *hands, hs_body *bodies, hs_world_cache *cache) {
	for (int h = 0; h < model->hand_count; ++h)
		if (hs_tracking_update(&hands[h], model->hold_frames, model->def.dt))
			hs_grasp_let_go_in_place(model, bodies, cache, &hands[h], h);
}

// §3.2 (Fig. 2-3, eq. 1-2): the hands' contacts, grasps and pushes move what they touch, and
// (§4.3) what interferes with it. In: hands, bodies. Out: bodies moved, held or carried, contacts.
// Takes the world: hs_manipulate makes its steps' contexts (docs/architecture.md, its step table).
static HS_FORCE_INLINE void hands_move_objects(hs_world *world) {
	if (world->model.hand_count > 0)
		hs_manipulate(world);
}

// §4.2-§4.3 (docs/model.md §5-§6): every awake object the hands leave free, through its own frame
// (step_object). In: the model, the awake list (cache). Out: bodies; the grid; support mode's
// moved objects in scratch->queue and moved_from (the count returned); paper mode's fallen groups
// in scratch->queue (*fallen); the counters; a numeric fault's frame and object in the state's
// first-fault words (`faults`). All parts of one world.
static HS_FORCE_INLINE int move_free_objects(const hs_world_model *model, hs_body *bodies, hs_world_cache *cache,
                                             hs_world_scratch *scratch, hs_world_counters *counters,
                                             hs_world_state *faults, int *fallen) {
	bool skip = model->skip_work;
	int visits = skip ? cache->awake_count : model->object_count;
	if (skip) // the sleeping objects cost nothing (the awake list holds the others, in index order)
		counters->sleeping_skips += model->object_count - cache->awake_count;
	int moved = 0; // support mode: objects that moved, to wake what rested on them (after the loop)
	for (int k = 0; k < visits; ++k) {
		int i = skip ? cache->awake[k] : k;
		hs_body *body = &bodies[i];
		if (body->held || body->carried || in_list(scratch->queue, *fallen, i))
			continue;
		// asleep: stays as it is until woken — on the floor, on a support (support mode), where it
		// stopped at an interference (paper mode, §4.3) — with skip_work off too (the same bits:
		// its pose and its last turn, rot_prev, kept); one that fell asleep this frame leaves the
		// awake list below
		if (body->asleep)
			continue;
		// the broad phase's and free motion's parts, made here rather than each frame: most frames
		// step no free object
		hs_broadphase bp = {model, bodies, cache, scratch};
		bool interferes = model->def.stacking == HS_STACKING_PAPER && hs_object_interferes(&bp, i);
		if (interferes && paper_group_falls(&bp, i, fallen))
			continue;
		hs_body saved = *body;
		hs_motion_pass motion = {model, bodies, scratch, counters};
		step_object(&bp, &motion, i, interferes);
		if (!body_is_finite(body)) { // never let a NaN spread: freeze the object and count it
			*body = saved;
			hs_world_note_fault(counters, faults, i);
		}
		// support mode: what moved by more than the floor's tolerance wakes what rests on it (a
		// settling stack's rounding-size moves woke each other for good)
		if (model->def.stacking == HS_STACKING_SUPPORT && hs_length(hs_sub(body->pos, saved.pos)) > model->def.floor_tolerance) {
			scratch->moved_from[moved] = saved.pos;
			scratch->queue[moved++] = i;
		}
		hs_grid_update(model, bodies, cache, i);
	}
	return moved;
}

// §4.3 and docs/model.md §6: what rested on a moved object, and a fallen group, wake and look
// again; the awake list drops what fell asleep. In: the queue from move_free_objects. Out: the
// awake list, the stale digests. The broad phase's parts: hs_broadphase (broadphase.h).
static HS_FORCE_INLINE void wake_neighbours(const hs_world_model *model, hs_body *bodies, hs_world_cache *cache,
                                           hs_world_scratch *scratch, int moved, int fallen) {
	for (int k = 0; k < moved; ++k) { // the awake list may grow only once the loop is over
		hs_broadphase bp = {model, bodies, cache, scratch};
		hs_support_wake_neighbours(&bp, scratch->queue[k], scratch->moved_from[k]);
	}
	for (int k = 0; k < fallen; ++k)
		hs_wake(bodies, cache, scratch->queue[k]);
	hs_awake_compact(bodies, cache);
	if (!model->skip_work) // every object was looked at (the awake list does not bound what may have changed)
		hs_digest_all_stale(cache);
}

// docs/model.md §4 "Release": each hand's wrist history ages by a frame and its points become the
// previous ones; a hand not set again stays where it is. In and out: the hands.
static HS_FORCE_INLINE void age_hands(hs_hand *hands, int hand_count) {
	for (int h = 0; h < hand_count; ++h) {
		hs_hand_age_wrist(&hands[h]);
		hs_hand_keep_previous(&hands[h]);
	}
}

void hs_step_hand(hs_world *world) {
	const hs_world_model *model = &world->model;
	hs_body *bodies = world->state.bodies;
	hs_world_cache *cache = &world->cache;
	hs_world_scratch *scratch = &world->scratch;
	file_objects(model, bodies, cache);                   // Experiment 3: the broad phase
	track_hands(model, world->state.hands, bodies, cache); // docs/model.md §3: tracking loss
	hands_move_objects(world);                            // §3.2: contacts, grasps, pushes
	int fallen = 0;                                       // paper mode: objects moved with a falling group
	// §4.2-§4.3: free motion, floor, stacking
	int moved = move_free_objects(model, bodies, cache, scratch, &world->counters, &world->state, &fallen);
	wake_neighbours(model, bodies, cache, scratch, moved, fallen); // §4.3: what rested on a moved object looks again
	age_hands(world->state.hands, model->hand_count);              // docs/model.md §4: the hands' history
	world->state.frame++;
}
