// broadphase.c — what keeps untouched objects free: a grid over the floor plane (hgrid.c, one
// level per size class) that finds the objects near a hand or a moved object, and the list of awake objects the step visits.
// (1999 paper, Experiment 3: frame time nearly flat in the number of objects not touched.)
//
// Results never depend on it: every query returns its objects in index order, the order in
// which a full scan would meet them, so a world with skip_work off gives the same bits.
#include <string.h>

#include "broadphase.h"

// A world of this many objects or fewer is scanned whole: each caller's bounding-sphere test of
// every object costs less than hashing the cells of its query (the seed scene, 10 cubes: 233
// instructions a frame less over its three queries; 16 cubes: 930). The same bits either way.
#define HS_GRID_SCAN_MAX 16

// Whether queries read the grid once it is built: a larger world with skip_work on. Otherwise no
// moved object is filed in it (233 instructions a frame less in the seed scene); a world that
// grows past the limit files every object at its next step (grid_dirty). skip_work is fixed
// when the world is made.
static bool grid_read(const hs_world *world) {
	return world->def.skip_work && world->object_count > HS_GRID_SCAN_MAX;
}

void hs_grid_update(hs_world *world, int i) {
	if (!world->grid_built || !grid_read(world))
		return; // not built yet (the first step builds it), or not read
	hs_hgrid_file(&world->grid, i, world->bodies[i].pos);
}

void hs_grid_build(hs_world *world) {
	// each object at the level of its bounding radius (hgrid.c): one huge object no longer makes
	// the cell of all (the cell was twice the largest radius)
	for (int i = 0; i < world->object_count; ++i)
		world->grid.half[i] = world->shapes[world->bodies[i].shape].radius;
	hs_hgrid_build(&world->grid, world->object_count);
	world->grid_built = true;
	for (int i = 0; i < world->object_count; ++i)
		hs_grid_update(world, i);
	hs_hgrid_pack(&world->grid); // the cells the objects occupy, read without hashing
}

// A query answers by a full scan, in index order (the grid not read, or not built yet).
static bool scanned(const hs_world *world) { return !world->grid_built || !grid_read(world); }

static int grid_answer(const hs_world *world, hs_vec3 center, double radius, int *out) {
	hs_vec3 r = hs_v3(radius, radius, radius); // objects are filed by their centres (x, y)
	return hs_hgrid_query(&world->grid, hs_sub(center, r), hs_add(center, r), out);
}

int hs_grid_query(const hs_world *world, hs_vec3 center, double radius, int *out) {
	if (!scanned(world))
		return grid_answer(world, center, radius, out);
	memcpy(out, world->every, (size_t)world->object_count * sizeof *out);
	return world->object_count;
}

int hs_grid_near(hs_world *world, hs_vec3 center, double radius) {
	if (scanned(world)) { // every index, listed when the world was made: nothing written
		world->near = world->every;
		return world->object_count;
	}
	world->near = world->found;
	return grid_answer(world, center, radius, world->found);
}

static void insert_sorted(int *list, int *count, int value) {
	int k = *count;
	while (k > 0 && list[k - 1] > value) {
		list[k] = list[k - 1];
		--k;
	}
	list[k] = value;
	++*count;
}

void hs_wake(hs_world *world, int i) {
	world->bodies[i].asleep = 0;
	if (!world->awake_flag[i]) {
		world->awake_flag[i] = 1;
		insert_sorted(world->awake, &world->awake_count, i);
	}
}

void hs_awake_compact(hs_world *world) {
	int kept = 0;
	for (int k = 0; k < world->awake_count; ++k) {
		int i = world->awake[k];
		const hs_body *b = &world->bodies[i];
		hs_digest_stale(world, i); // the step changes no other object (skip_work changes no result)
		if (b->asleep && !b->held && !b->carried)
			world->awake_flag[i] = 0;
		else
			world->awake[kept++] = i;
	}
	world->awake_count = kept;
}

void hs_broadphase_reset(hs_world *world) {
	// between steps the awake list holds exactly the objects not asleep, held or carried
	// (hs_awake_compact ends every step; hs_wake keeps it for objects added since), in index order
	world->awake_count = 0;
	for (int i = 0; i < world->object_count; ++i) {
		const hs_body *b = &world->bodies[i];
		bool awake = !b->asleep || b->held || b->carried;
		world->awake_flag[i] = (uint8_t)awake;
		if (awake)
			world->awake[world->awake_count++] = i;
	}
	world->grid_dirty = true; // filed again at the next step
	hs_digest_all_stale(world);
}
