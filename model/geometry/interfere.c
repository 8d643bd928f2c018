// interfere.c — interference between objects as they stand (1999 paper §4.3): the tests the
// stacking stages ask (fall_group.c, support.c, the hand step's paper mode).
#include "interfere.h"

static HS_FORCE_INLINE bool overlap_now(const hs_world_model *model, const hs_body *bodies, hs_box_memo *box_memo, int i, int j) {
	return overlap_at_pose_in(model, bodies, box_memo, i, bodies[i].pos, bodies[i].rot, j);
}

bool hs_objects_interfere(const hs_world_model *model, const hs_body *bodies, hs_box_memo *box_memo, int i, int j) {
	return i != j && overlap_now(model, bodies, box_memo, i, j);
}

bool hs_object_interferes(const hs_broadphase *bp, int object) {
	const hs_body *body = &bp->bodies[object];
	int n = hs_grid_near(bp, body->pos, bp->model->shapes[body->shape].radius);
	for (int k = 0; k < n; ++k)
		if (bp->scratch->near[k] != object && overlap_now(bp->model, bp->bodies, bp->cache->box_memo, object, bp->scratch->near[k]))
			return true;
	return false;
}
