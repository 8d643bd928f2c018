// collide.h — collide.c's entries beside the public ones: interference of posed shapes within a
// gap, for the spring model's resting contacts (shapes that do not overlap but lie within `gap` of
// each other still touch); libccd's overlap test and the box test before it; the world boxes.
#ifndef HS_COLLIDE_H
#define HS_COLLIDE_H

#include "handspring.h"

// hs_shapes_penetration with both shapes grown by gap / 2 (gap ≥ 0): true when they lie within
// gap of each other; *depth is the penetration less gap, so in [−gap, 0) for shapes apart but
// within the gap. With gap = 0 the bits of hs_shapes_penetration.
bool hs_shapes_within(const hs_shape *a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b, hs_vec3 pos_b,
                      hs_quat rot_b, double gap, double *depth, hs_vec3 *direction);

// hs_shapes_overlap without its separating-axis test for two boxes: libccd's GJK on every part pair
// the bounding spheres and world boxes leave. The rule the box test stands for: hs_shapes_overlap
// returns the same for every pair (tests/test_collide.c compares them; self-check builds, each call).
bool hs_shapes_overlap_gjk(const hs_shape *a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b, hs_vec3 pos_b,
                           hs_quat rot_b);

// The separating-axis test hs_shapes_overlap puts a pair of box parts to before libccd, whatever
// their bounding spheres and world boxes say: HS_BOXES_OVERLAP or HS_BOXES_APART when the answer is
// clear of touching by its slack (libccd's answer then), HS_BOXES_CLOSE when libccd must decide
// (touching within the slack, or a part that is not exactly a box). For tests.
typedef enum hs_box_verdict { HS_BOXES_OVERLAP, HS_BOXES_APART, HS_BOXES_CLOSE } hs_box_verdict;
hs_box_verdict hs_box_parts_verdict(const hs_shape *a, int part_a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b,
                                    int part_b, hs_vec3 pos_b, hs_quat rot_b);

// hs_shapes_overlap's cheap rejection, for a caller that keeps the boxes: the world-axis box of
// part `part` of `shape` posed at (pos, rot) (the same bits as hs_shapes_overlap's), and whether
// two such boxes lie apart by its margin. When they do, hs_shapes_overlap finds those two parts
// apart (by their boxes or their bounding spheres) and runs no narrow test on them.
void hs_part_world_box(const hs_shape *shape, int part, hs_vec3 pos, hs_quat rot, hs_vec3 *centre, hs_vec3 *half);
bool hs_part_world_boxes_apart(const hs_shape *a, int part_a, hs_vec3 centre_a, hs_vec3 half_a, const hs_shape *b,
                               int part_b, hs_vec3 centre_b, hs_vec3 half_b);

#endif
