// broadphase.h — the grid that finds objects near a point and the list of awake objects
// (1999 paper, Experiment 3: frame time nearly flat in the number of untouched objects).
// Both are CACHES of struct hs_world: queries return objects in index order, so results never
// depend on them.
#ifndef HS_BROADPHASE_H
#define HS_BROADPHASE_H

#include "world_internal.h"

// The parts of a world a neighbour query reads and writes: the model (object count, shapes,
// skip_work), the bodies (positions; hs_wake clears asleep), the cache (the grid, its neighbour
// lists, the awake list, the list of every index, the digests, the box memo) and the scratch (a
// query's answer: found, near). The object stages that ask for neighbours take it whole.
typedef struct hs_broadphase {
	const hs_world_model *model;
	hs_body *bodies;
	hs_world_cache *cache;
	hs_world_scratch *scratch;
} hs_broadphase;

// A world's broad-phase parts.
static inline hs_broadphase hs_broadphase_of(hs_world *world) {
	return (hs_broadphase){&world->model, world->state.bodies, &world->cache, &world->scratch};
}

// Files every object (their radii from the model, their centres from the bodies) in cache->grid.
void hs_grid_build(const hs_world_model *model, const hs_body *bodies, hs_world_cache *cache);
// Files object i again after it moved.
void hs_grid_update(const hs_world_model *model, const hs_body *bodies, hs_world_cache *cache, int i);
// Objects whose centre may lie within radius + their own bounding radius of center (in x, y), in
// index order (every object when skip_work is off). Returns how many were written to out.
int hs_grid_query(const hs_world_model *model, const hs_world_cache *cache, hs_vec3 center, double radius, int *out);
// hs_grid_query's answer in bp->scratch->near: a world scanned whole points it at the list of every
// index made with the world (nothing written per query), the grid's answer is written to `found`.
int hs_grid_near(const hs_broadphase *bp, hs_vec3 center, double radius);
// hs_grid_near of the objects near either of two points (within radius plus their own).
int hs_grid_near_either(const hs_broadphase *bp, hs_vec3 a, hs_vec3 b, double radius);
// Marks object i awake and puts it on the awake list.
void hs_wake(hs_body *bodies, hs_world_cache *cache, int i);
// Drops objects that fell asleep from the awake list; marks the digests of those on it stale.
void hs_awake_compact(const hs_body *bodies, hs_world_cache *cache);
// Rebuilds the awake list from the bodies' flags alone (after a load) and marks the grid dirty.
void hs_broadphase_reset(hs_world *world);

#endif
