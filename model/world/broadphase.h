// broadphase.h — the grid that finds objects near a point and the list of awake objects
// (1999 paper, Experiment 3: frame time nearly flat in the number of untouched objects).
// Both are CACHES of struct hs_world: queries return objects in index order, so results never
// depend on them.
#ifndef HS_BROADPHASE_H
#define HS_BROADPHASE_H

#include "world_internal.h"

void hs_grid_build(hs_world *world);
// Files object i again after it moved.
void hs_grid_update(hs_world *world, int i);
// Objects whose centre may lie within radius + their own bounding radius of center (in x, y), in
// index order (every object when skip_work is off). Returns how many were written to out.
int hs_grid_query(const hs_world *world, hs_vec3 center, double radius, int *out);
// hs_grid_query's answer in world->scratch.near: a world scanned whole points it at the list of every
// index made with the world (nothing written per query), the grid's answer is written to `found`.
int hs_grid_near(hs_world *world, hs_vec3 center, double radius);
// hs_grid_near of the objects near either of two points (within radius plus their own).
int hs_grid_near_either(hs_world *world, hs_vec3 a, hs_vec3 b, double radius);
// Marks object i awake and puts it on the awake list.
void hs_wake(hs_world *world, int i);
// Drops objects that fell asleep from the awake list.
void hs_awake_compact(hs_world *world);
// Rebuilds the awake list from the bodies' flags alone (after a load) and marks the grid dirty.
void hs_broadphase_reset(hs_world *world);

#endif
