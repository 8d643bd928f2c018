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

// A world of this many objects or fewer is scanned whole: each caller's bounding-sphere test of
// every object costs less than hashing the cells of its query (the seed scene, 10 cubes: 233
// instructions a frame less over its three queries; 16 cubes: 930). The same bits either way.
#define HS_GRID_SCAN_MAX 16

// Whether queries read the grid once it is built: a larger world with skip_work on. Otherwise no
// moved object is filed in it (233 instructions a frame less in the seed scene); a world that
// grows past the limit files every object at its next step (grid_dirty). skip_work is fixed
// when the world is made.
static inline bool hs_grid_read(const hs_world_model *model) {
	return model->skip_work && model->object_count > HS_GRID_SCAN_MAX;
}

// A query answers by a full scan, in index order (the grid not read, or not built yet).
static inline bool hs_grid_scanned(const hs_world_model *model, const hs_world_cache *cache) {
	return !cache->grid_built || !hs_grid_read(model);
}

// Files every object (their radii from the model, their centres from the bodies) in cache->grid.
void hs_grid_build(const hs_world_model *model, const hs_body *bodies, hs_world_cache *cache);
// hs_grid_update of a world whose grid is built and read.
void hs_grid_file(const hs_body *bodies, hs_world_cache *cache, int i);

// Files object i again after it moved (the test inline: a world scanned whole files nothing).
static inline void hs_grid_update(const hs_world_model *model, const hs_body *bodies, hs_world_cache *cache, int i) {
	if (!hs_grid_scanned(model, cache))
		hs_grid_file(bodies, cache, i);
}

// Objects whose centre may lie within radius + their own bounding radius of center (in x, y), in
// index order (every object when skip_work is off). Returns how many were written to out.
int hs_grid_query(const hs_world_model *model, const hs_world_cache *cache, hs_vec3 center, double radius, int *out);
// hs_grid_near of a world whose grid is built and read: the grid's (or a neighbour list's) answer
// written to scratch->found.
int hs_grid_near_filed(const hs_broadphase *bp, hs_vec3 center, double radius);

// A world scanned whole answers with every index, listed when the world was made: nothing written.
static inline int hs_grid_every(const hs_broadphase *bp) {
	bp->scratch->near = bp->cache->every;
	return bp->model->object_count;
}

// hs_grid_query's answer in bp->scratch->near: a world scanned whole points it at the list of every
// index made with the world (nothing written per query), the grid's answer is written to `found`.
static inline int hs_grid_near(const hs_broadphase *bp, hs_vec3 center, double radius) {
	if (hs_grid_scanned(bp->model, bp->cache))
		return hs_grid_every(bp);
	return hs_grid_near_filed(bp, center, radius);
}

// hs_grid_near of the objects near either of two points (within radius plus their own).
static inline int hs_grid_near_either(const hs_broadphase *bp, hs_vec3 a, hs_vec3 b, double radius) {
	if (hs_grid_scanned(bp->model, bp->cache))
		return hs_grid_every(bp);
	return hs_grid_near_filed(bp, hs_scale(hs_add(a, b), 0.5), radius + 0.5 * hs_length(hs_sub(b, a)));
}

// hs_wake of an object not on the awake list: puts it there, in index order.
void hs_awake_insert(hs_world_cache *cache, int i);

// Marks object i awake and puts it on the awake list.
static inline void hs_wake(hs_body *bodies, hs_world_cache *cache, int i) {
	bodies[i].asleep = 0;
	if (!cache->awake_flag[i])
		hs_awake_insert(cache, i);
}
// Drops objects that fell asleep from the awake list; marks the digests of those on it stale.
void hs_awake_compact(const hs_body *bodies, hs_world_cache *cache);
// Rebuilds the awake list from the bodies' flags alone (after a load) and marks the grid dirty.
void hs_broadphase_reset(hs_world *world);

#endif
