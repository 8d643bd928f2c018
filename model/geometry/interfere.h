// interfere.h — interference between objects (1999 paper §4.3): whether two objects' shapes
// overlap at given poses, with the bounding-sphere and world-box tests first. The pose tests are
// inline so that the hand pass (manipulate.c) keeps them in its loop; interfere.c answers the
// stages that ask of an object as it stands (fall_group.c, support.c, the hand step).
#ifndef HS_INTERFERE_H
#define HS_INTERFERE_H

#include <stdbool.h>
#include <string.h>

#include "broadphase.h"
#include "collide.h"
#include "inline.h"
#include "world_internal.h"

// Object i's world box at (pos, rot), from its memo when it was made at that pose's bits.
static HS_FORCE_INLINE int memo_box(const hs_world_model *model, const hs_body *bodies, hs_box_memo *box_memo, int i,
                                    hs_vec3 pos, hs_quat rot) {
	return hs_box_memo_find(&box_memo[i], &model->shapes[bodies[i].shape], pos, rot);
}

// The bounding spheres (radii summing to r) of an object at pos and object b lie apart: no overlap.
static HS_FORCE_INLINE bool spheres_apart(double r, hs_vec3 pos, const hs_body *b) {
	return hs_length_sq(hs_sub(pos, b->pos)) > r * r;
}

// Objects i, posed at (pos, rot), and j overlap (libccd; bounding spheres first). Two single-part
// objects (no exact spheres) whose world boxes lie apart are not handed to hs_shapes_overlap: it
// would find them apart by the same boxes (hs_part_world_boxes_apart), after making them again.
// Reads the model (shapes, skip_work) and the bodies; refreshes the box memo (the cache's).
static HS_FORCE_INLINE bool overlap_at_pose_in(const hs_world_model *model, const hs_body *bodies, hs_box_memo *box_memo,
                                               int i, hs_vec3 pos, hs_quat rot, int j) {
	const hs_body *b = &bodies[j];
	const hs_shape *sa = &model->shapes[bodies[i].shape], *sb = &model->shapes[b->shape];
	if (spheres_apart(sa->radius + sb->radius, pos, b))
		return false; // no narrow test
	if (model->skip_work && sa->part_count == 1 && sb->part_count == 1 && sa->kind != HS_SHAPE_SPHERE &&
	    sb->kind != HS_SHAPE_SPHERE) {
		int ka = memo_box(model, bodies, box_memo, i, pos, rot), kb = memo_box(model, bodies, box_memo, j, b->pos, b->rot);
		const hs_box_memo *ma = &box_memo[i], *mb = &box_memo[j];
		if (hs_part_world_boxes_apart(sa, 0, ma->centre[ka], ma->half[ka], sb, 0, mb->centre[kb], mb->half[kb]))
			return false;
	}
	return hs_shapes_overlap(sa, pos, rot, sb, b->pos, b->rot);
}

// overlap_at_pose_in over a world's parts (the hand pass holds the world).
static HS_FORCE_INLINE bool overlap_at_pose(const hs_world *world, int i, hs_vec3 pos, hs_quat rot, int j) {
	return overlap_at_pose_in(&world->model, world->state.bodies, world->cache.box_memo, i, pos, rot, j);
}

static HS_FORCE_INLINE bool bodies_overlap(const hs_world *world, int i, int j) {
	return overlap_at_pose(world, i, world->state.bodies[i].pos, world->state.bodies[i].rot, j);
}

// §4.3: true when an untouched free object interferes with another and so ignores gravity.
bool hs_object_interferes(const hs_broadphase *bp, int object);
// Objects i and j (not the same) overlap: interference of §4.3. Refreshes their box memos.
bool hs_objects_interfere(const hs_world_model *model, const hs_body *bodies, hs_box_memo *box_memo, int i, int j);

#endif
