// spring_near.h — the spring model's broad phase (docs/model.md §8): which objects may meet one
// object, through the hierarchical grid (hgrid.c) and a neighbour list that spares most queries.
#ifndef HS_SPRING_NEAR_H
#define HS_SPRING_NEAR_H

#include "spring_system.h"
#include "world_internal.h"

// m added around each bounding box at G = p in the box tests: far above rounding and libccd's
// touch margins, so it only ever lets through pairs the exact test then rejects.
static inline double hs_spring_margin(const hs_spring_geom *g, hs_vec3 p) {
	return 1e-6 + 1e-9 * (fabs(p.x) + fabs(p.y) + fabs(p.z) + g->hi.x - g->lo.x + g->hi.y - g->lo.y + g->hi.z - g->lo.z);
}

// Files every object by its bounding box's centre (the levels again when objects were added or the
// geometry was rebuilt) and keeps the neighbour lists while no object moved beyond their skin.
void hs_spring_file_all(hs_world *world, hs_spring_system *sys);
// Files object i again after it moved within the frame.
void hs_spring_refile(hs_world *world, hs_spring_system *sys, int i);
// Objects whose bounds may meet object i's box (its margin included), or its path through the
// frame grown by `reach` (the farthest any object moved: where another's path may cross it), in
// index order, i among them; more may come than meet. *out points to them; returns how many.
int hs_spring_near(const hs_world *world, hs_spring_system *sys, int i, double reach, const int **out);
// As hs_spring_near for object i's box where it is now, grown by `grow` (m) on every side.
int hs_spring_near_grown(const hs_world *world, hs_spring_system *sys, int i, double grow, const int **out);

#endif
