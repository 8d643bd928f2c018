// world_hands.c — a world's hands as its user sees them: added, set from a glove reading or from
// joint positions, marked tracked or lost, and read back (the points, the rectified points, the
// last step's contacts). The hand pass of the step (manipulate.c) moves objects by them.
#include <string.h>

#include "contact.h"
#include "grasp.h"
#include "world_internal.h"

hs_hand_id hs_world_add_hand(hs_world *world, const hs_hand_def *def, hs_status *status) {
	hs_hand_id none = {0};
	if (!world || !def || !(def->finger_radius > 0.0) || !isfinite(def->finger_radius) ||
	    !(def->dip_per_pip >= 0.0) || !isfinite(def->dip_per_pip)) {
		hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
		return none;
	}
	for (int f = 0; f < 5; ++f) {
		if (!hs_vec3_is_finite(def->base[f])) {
			hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
			return none;
		}
		for (int s = 0; s < 3; ++s)
			if (!(def->segment_length[f][s] > 0.0) || !isfinite(def->segment_length[f][s])) {
				hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
				return none;
			}
	}
	if (world->model.hand_count >= world->model.def.max_hands) {
		hs_set_status(status, HS_ERR_CAPACITY);
		return none;
	}
	hs_hand *hand = &world->state.hands[world->model.hand_count];
	memset(hand, 0, sizeof *hand);
	hs_hand_init_buffers(hand);
	hand->model.def = *def;
	hs_glove_table_build(&hand->model.def, &hand->model.glove);
	hand->state.wrist_rot = hand->state.prev_wrist_rot = hs_quat_identity();
	hand->model.older_capacity = hs_hand_older_capacity(world->model.def.release_window_s, world->model.def.dt);
	for (int k = 0; k < HS_HAND_OLDER_MAX; ++k) // not yet reached: a unit rotation, as a state file must hold
		hand->state.older_rot[k] = hs_quat_identity();
	hand->cache.lines_ready = hand->cache.prev_lines_ready = hand->cache.local_ready = HS_HAND_ALL_SEGMENTS; // all zero until set
	hs_hand_update_bounds(hand); // touches nothing until it is set
	hs_set_status(status, HS_OK);
	int index = world->model.hand_count++;
	return hs_hand_handle(&world->model, index);
}

hs_hand_id hs_world_hand_at(const hs_world *world, int i) {
	hs_hand_id none = {0, 0, 0};
	return world ? hs_hand_handle(&world->model, i) : none;
}

static hs_hand *hand_of(const hs_world *world, hs_hand_id id) {
	int h = hs_hand_index(world, id);
	return h >= 0 ? &world->state.hands[h] : NULL;
}

// The hand placed from its new reading (its shape made): the first placement moves nothing.
static hs_status place_hand(hs_hand *hand) {
	hs_hand_place_points(hand);
	bool first = !hand->state.placed;
	hand->state.placed = true;
	hs_hand_update_bounds(hand);
	if (first) { // no motion before the first pose, no closing either
		hs_hand_keep_previous(hand);
		hs_grasp_reset_pairs(hand);
	}
	return HS_OK;
}

hs_status hs_world_set_hand(hs_world *world, hs_hand_id id, hs_vec3 wrist_position, hs_quat wrist_orientation,
                            const uint8_t reading[HS_GLOVE_SENSORS]) {
	hs_hand *hand = hand_of(world, id);
	if (!hand || hand->model.def.joint_driven || !reading || !hs_within(wrist_position, HS_MAX_COORDINATE) ||
	    !hs_quat_is_unit(wrist_orientation))
		return HS_ERR_INVALID_ARGUMENT;
	hand->state.wrist_pos = wrist_position;
	hand->state.wrist_rot = hs_quat_normalize(wrist_orientation);
	// The glove's deadband (docs/model.md §1). Without it a glove's per-frame noise (±4 units, ±2°,
	// is ±6 mm at a fingertip from the wrist sensors alone) moves a still hand every frame:
	// fingertips on a face drag and turn what they touch, and the drags add up frame after frame (a
	// two-fingertip push drifted 2 cm sideways). A still reading keeps the hand's bits; a moving one
	// lags by the band. The first reading is used as it is.
	uint8_t sensors[HS_GLOVE_SENSORS];
	hs_glove_deadband(hand->state.placed ? hand->state.sensors : reading, world->model.def.glove_deadband, reading, sensors);
	if (!hand->state.placed || memcmp(hand->state.sensors, sensors, sizeof hand->state.sensors) != 0) {
		memcpy(hand->state.sensors, sensors, sizeof hand->state.sensors); // the glove moved: a new hand shape
		hs_hand_update_shape(hand);
	}
	return place_hand(hand);
}

hs_status hs_world_set_hand_joints(hs_world *world, hs_hand_id id, hs_vec3 wrist_position, hs_quat wrist_orientation,
                                   const hs_vec3 points[HS_HAND_POINTS]) {
	hs_hand *hand = hand_of(world, id);
	if (!hand || !hand->model.def.joint_driven || !points || !hs_within(wrist_position, HS_MAX_COORDINATE) ||
	    !hs_quat_is_unit(wrist_orientation))
		return HS_ERR_INVALID_ARGUMENT;
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		if (!hs_within(points[i], HS_MAX_COORDINATE))
			return HS_ERR_INVALID_ARGUMENT;
	hand->state.wrist_pos = wrist_position;
	hand->state.wrist_rot = hs_quat_normalize(wrist_orientation);
	if (!hand->state.placed || memcmp(hand->state.joints, points, sizeof hand->state.joints) != 0) {
		memcpy(hand->state.joints, points, sizeof hand->state.joints); // a new hand shape
		hs_hand_update_shape(hand);
	}
	return place_hand(hand);
}

hs_status hs_world_set_hand_tracked(hs_world *world, hs_hand_id id, bool tracked) {
	hs_hand *hand = hand_of(world, id);
	if (!hand)
		return HS_ERR_INVALID_ARGUMENT;
	hand->state.untracked = !tracked;
	return HS_OK;
}

hs_status hs_world_hand_points(const hs_world *world, hs_hand_id id, hs_vec3 points[HS_HAND_POINTS]) {
	const hs_hand *hand = hand_of(world, id);
	if (!hand || !points)
		return HS_ERR_INVALID_ARGUMENT;
	memcpy(points, hand->cache.points, HS_HAND_POINTS * sizeof hand->cache.points[0]);
	return HS_OK;
}

hs_status hs_world_hand_rectified_points(const hs_world *world, hs_hand_id id, hs_vec3 points[HS_HAND_POINTS],
                                         uint32_t *touching) {
	const hs_hand *hand = hand_of(world, id);
	if (!hand || !points)
		return HS_ERR_INVALID_ARGUMENT;
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		points[i] = hand->state.touch_points >> i & 1u ? hs_contact_rectify(&world->model, world->state.bodies, hand->cache.points[i])
		                                              : hand->cache.points[i];
	if (touching)
		*touching = hand->state.touch_points;
	return HS_OK;
}

int hs_world_contacts(const hs_world *world, hs_contact *out, int max) {
	if (!world)
		return 0;
	int n = world->out.contact_count;
	for (int i = 0; i < n && i < max && out; ++i)
		out[i] = world->out.contacts[i];
	return n;
}
