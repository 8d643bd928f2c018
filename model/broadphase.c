// broadphase.c — what keeps untouched objects free: a uniform grid over the floor plane that
// finds the objects near a hand or a moved object, and the list of awake objects the step visits.
// (1999 paper, Experiment 3: frame time nearly flat in the number of objects not touched.)
//
// Results never depend on it: every query returns its objects in index order, the order in
// which a full scan would meet them, so a world with skip_work off gives the same bits.
#include <string.h>

#include "broadphase.h"

static long cell_coord(double v, double cell) { return (long)floor(v / cell); }

static int bucket_of(const hs_world *world, long ix, long iy) {
	// a multiplicative hash of the cell; any fixed mix is deterministic
	unsigned long h = (unsigned long)ix * 73856093ul ^ (unsigned long)iy * 19349663ul;
	return (int)(h & (unsigned long)(world->grid_buckets - 1));
}

static void unlink_object(hs_world *world, int i) {
	int b = world->grid_bucket[i];
	if (b < 0)
		return;
	int *link = &world->grid_head[b];
	while (*link != i)
		link = &world->grid_next[*link];
	*link = world->grid_next[i];
	world->grid_bucket[i] = -1;
}

void hs_grid_update(hs_world *world, int i) {
	if (world->grid_cell <= 0.0)
		return; // not built yet: the first step builds it
	const hs_body *body = &world->bodies[i];
	long ix = cell_coord(body->pos.x, world->grid_cell), iy = cell_coord(body->pos.y, world->grid_cell);
	if (world->grid_bucket[i] >= 0 && world->grid_ix[i] == ix && world->grid_iy[i] == iy)
		return;
	unlink_object(world, i);
	int b = bucket_of(world, ix, iy);
	world->grid_next[i] = world->grid_head[b];
	world->grid_head[b] = i;
	world->grid_bucket[i] = b;
	world->grid_ix[i] = ix;
	world->grid_iy[i] = iy;
}

void hs_grid_build(hs_world *world) {
	double largest = 0.0;
	for (int i = 0; i < world->object_count; ++i) {
		double r = world->shapes[world->bodies[i].shape].radius;
		largest = r > largest ? r : largest;
	}
	world->grid_radius = largest;
	world->grid_cell = largest > 0.0 ? 2.0 * largest : 1.0;
	for (int b = 0; b < world->grid_buckets; ++b)
		world->grid_head[b] = -1;
	for (int i = 0; i < world->object_count; ++i) {
		world->grid_bucket[i] = -1;
		hs_grid_update(world, i);
	}
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

int hs_grid_query(const hs_world *world, hs_vec3 center, double radius, int *out) {
	int n = 0;
	if (!world->def.skip_work || world->grid_cell <= 0.0) { // the full scan, in index order
		for (int i = 0; i < world->object_count; ++i)
			out[n++] = i;
		return n;
	}
	double reach = radius + world->grid_radius; // objects are filed by their centres
	double cell = world->grid_cell;
	long x0 = cell_coord(center.x - reach, cell), x1 = cell_coord(center.x + reach, cell);
	long y0 = cell_coord(center.y - reach, cell), y1 = cell_coord(center.y + reach, cell);
	if ((x1 - x0 + 1) * (y1 - y0 + 1) > world->grid_buckets) { // larger than the grid: scan
		for (int i = 0; i < world->object_count; ++i)
			out[n++] = i;
		return n;
	}
	for (long ix = x0; ix <= x1; ++ix)
		for (long iy = y0; iy <= y1; ++iy)
			for (int i = world->grid_head[bucket_of(world, ix, iy)]; i >= 0; i = world->grid_next[i])
				if (world->grid_ix[i] == ix && world->grid_iy[i] == iy) // not a hash neighbour
					insert_sorted(out, &n, i);
	return n;
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
}
