// collide.h — interference of posed shapes within a gap (collide.c), for the spring model's
// resting contacts: shapes that do not overlap but lie within `gap` of each other still touch.
#ifndef HS_COLLIDE_H
#define HS_COLLIDE_H

#include "handspring.h"

// hs_shapes_penetration with both shapes grown by gap / 2 (gap ≥ 0): true when they lie within
// gap of each other; *depth is the penetration less gap, so in [−gap, 0) for shapes apart but
// within the gap. With gap = 0 the bits of hs_shapes_penetration.
bool hs_shapes_within(const hs_shape *a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b, hs_vec3 pos_b,
                      hs_quat rot_b, double gap, double *depth, hs_vec3 *direction);

// hs_shapes_overlap's cheap rejection, for a caller that keeps the boxes: the world-axis box of
// part `part` of `shape` posed at (pos, rot) (the same bits as hs_shapes_overlap's), and whether
// two such boxes lie apart by its margin. When they do, hs_shapes_overlap finds those two parts
// apart (by their boxes or their bounding spheres) and runs no narrow test on them.
void hs_part_world_box(const hs_shape *shape, int part, hs_vec3 pos, hs_quat rot, hs_vec3 *centre, hs_vec3 *half);
bool hs_part_world_boxes_apart(const hs_shape *a, int part_a, hs_vec3 centre_a, hs_vec3 half_a, const hs_shape *b,
                               int part_b, hs_vec3 centre_b, hs_vec3 half_b);

#endif
