// broadphase.c — what keeps untouched objects free: a grid over the floor plane (hgrid.c, one
// level per size class) that finds the objects near a hand or a moved object, and the list of awake objects the step visits.
// (1999 paper, Experiment 3: frame time nearly flat in the number of objects not touched.)
//
// Results never depend on it: every query returns its objects in index order, the order in
// which a full scan would meet them, so a world with skip_work off gives the same bits.
#include <math.h>
#include <string.h>
#if defined(HS_SELFCHECK)
#include <stdio.h>
#include <stdlib.h>
#endif

#include "broadphase.h"
#include "inline.h"

// (HS_GRID_SCAN_MAX and the test of a world scanned whole, hs_grid_scanned: broadphase.h)

void hs_grid_file(const hs_body *bodies, hs_world_cache *cache, int i) {
	if (!cache->awake_flag[i]) // a resting object filed anew (a load, objects added, or carried):
		cache->near_lists.epoch++;   // the neighbour lists may miss it
	hs_hgrid_file(&cache->grid, i, bodies[i].pos);
}

void hs_grid_build(const hs_world_model *model, const hs_body *bodies, hs_world_cache *cache) {
	// each object at the level of its bounding radius (hgrid.c): one huge object no longer makes
	// the cell of all (the cell was twice the largest radius)
	for (int i = 0; i < model->object_count; ++i)
		cache->grid.half[i] = model->shapes[bodies[i].shape].radius;
	hs_hgrid_build(&cache->grid, model->object_count);
	cache->grid_built = true;
	for (int i = 0; i < model->object_count; ++i)
		hs_grid_update(model, bodies, cache, i);
	hs_hgrid_pack(&cache->grid); // the cells the objects occupy, read without hashing
}

static int grid_answer(const hs_world_cache *cache, hs_vec3 center, double radius, int *out) {
	hs_vec3 r = hs_v3(radius, radius, radius); // objects are filed by their centres (x, y)
	return hs_hgrid_query(&cache->grid, hs_sub(center, r), hs_add(center, r), out);
}

int hs_grid_query(const hs_world_model *model, const hs_world_cache *cache, hs_vec3 center, double radius, int *out) {
	if (!hs_grid_scanned(model, cache))
		return grid_answer(cache, center, radius, out);
	memcpy(out, cache->every, (size_t)model->object_count * sizeof *out);
	return model->object_count;
}

// The neighbour lists: a query whose box (x, y: center ± radius) lies inside a list's box is
// answered from that list's resting objects and the awake list, each object's centre tested
// against the query's box grown by its own half-extent (the grid's contract, not its cells). A
// resting object moves only through hs_grid_update, and one that comes to rest leaves the awake
// list (hs_awake_compact): either makes every list stale (near_lists.epoch). A list's box is its first
// query's grown by a skin of a typical object's width (the grid's level-0 cell), so a hand that
// moves a few mm a frame reuses it for many frames. Every answer holds all the objects the
// callers' own tests can pass, in index order: no result depends on the lists.

// Rounding allowance of the centre tests (m), far below any caller's tolerance.
static double slack(hs_vec3 c, double reach) { return 1e-9 * (1.0 + fabs(c.x) + fabs(c.y) + reach); }

static bool centre_near(const hs_broadphase *q, int i, hs_vec3 c, double r, double allow) {
	hs_vec3 p = q->bodies[i].pos;
	double reach = r + q->cache->grid.half[i];
	reach += allow * slack(c, reach);
	return fabs(p.x - c.x) <= reach && fabs(p.y - c.y) <= reach;
}

// Merges a list's objects with the awake list (both ascending; an object on both once), keeping
// those near the query.
static int list_answer(const hs_broadphase *q, const hs_near_list *l, hs_vec3 c, double r) {
	const int *awake = q->cache->awake;
	int *found = q->scratch->found;
	int n = 0, a = 0, b = 0, na = q->cache->awake_count;
	while (a < l->count || b < na) {
		int i;
		if (b == na || (a < l->count && l->index[a] < awake[b]))
			i = l->index[a++];
		else {
			i = awake[b++];
			a += a < l->count && l->index[a] == i;
		}
		if (centre_near(q, i, c, r, 1.0))
			found[n++] = i;
	}
#if defined(HS_SELFCHECK)
	// sanitizer builds: every object the contract asks for is in the answer (a stale list is not)
	for (int j = 0, k = 0; j < q->model->object_count; ++j) {
		while (k < n && found[k] < j)
			++k;
		hs_vec3 p = q->bodies[j].pos;
		if (hypot(p.x - c.x, p.y - c.y) <= r + q->cache->grid.half[j] && (k == n || found[k] != j)) {
			fprintf(stderr, "selfcheck: object %d missing from a neighbour list's answer\n", j);
			abort();
		}
	}
#endif
	return n;
}

static hs_near_list *list_holding(hs_near_lists *lists, hs_vec3 c, double r) {
	for (int k = 0; k < HS_NEAR_BOXES; ++k) {
		hs_near_list *l = &lists->list[k];
		if (l->epoch == lists->epoch && c.x - r >= l->lo[0] && c.x + r <= l->hi[0] && c.y - r >= l->lo[1] &&
		    c.y + r <= l->hi[1])
			return l;
	}
	return NULL;
}

// Lists the resting objects near the query's box grown by the skin, in place of the least recently
// used list; or, when more than a list holds, answers from the grid's answer alone (found).
static int list_and_answer(const hs_broadphase *q, hs_vec3 c, double r) {
	hs_world_cache *cache = q->cache;
	int *found = q->scratch->found;
	double grown = r + cache->grid.cell0;
	int n = grid_answer(cache, c, grown, found);
	hs_near_list *l = &cache->near_lists.list[0];
	for (int k = 1; k < HS_NEAR_BOXES; ++k)
		l = cache->near_lists.list[k].used < l->used ? &cache->near_lists.list[k] : l;
	l->epoch = 0;
	l->count = 0;
	for (int k = 0; k < n; ++k) {
		int i = found[k];
		if (cache->awake_flag[i] || !centre_near(q, i, c, grown, 4.0))
			continue;
		if (l->count == HS_NEAR_LISTED) { // a crowd: the grid's answer, kept where near the query
			int kept = 0;
			for (int j = 0; j < n; ++j)
				if (centre_near(q, found[j], c, r, 1.0))
					found[kept++] = found[j];
			return kept;
		}
		l->index[l->count++] = i;
	}
	l->lo[0] = c.x - grown;
	l->hi[0] = c.x + grown;
	l->lo[1] = c.y - grown;
	l->hi[1] = c.y + grown;
	l->epoch = cache->near_lists.epoch;
	l->used = ++cache->near_lists.clock;
	return list_answer(q, l, c, r);
}

// (out of line: a world scanned whole pays no more than its test, inline in broadphase.h)
int hs_grid_near_filed(const hs_broadphase *q, hs_vec3 center, double radius) {
	hs_world_cache *cache = q->cache;
	hs_world_scratch *scratch = q->scratch;
	scratch->near = scratch->found;
	if (cache->awake_count > HS_NEAR_AWAKE_MAX) // many in motion: the lists would hold few
		return grid_answer(cache, center, radius, scratch->found);
	hs_near_list *l = list_holding(&cache->near_lists, center, radius);
	if (!l)
		return list_and_answer(q, center, radius);
	l->used = ++cache->near_lists.clock;
	cache->near_lists.hits++;
	return list_answer(q, l, center, radius);
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

void hs_awake_insert(hs_world_cache *cache, int i) {
	cache->awake_flag[i] = 1;
	insert_sorted(cache->awake, &cache->awake_count, i);
}

void hs_awake_compact(const hs_body *bodies, hs_world_cache *cache) {
	int kept = 0;
	for (int k = 0; k < cache->awake_count; ++k) {
		int i = cache->awake[k];
		const hs_body *b = &bodies[i];
		hs_digest_stale(cache, i); // the step changes no other object (skip_work changes no result)
		if (b->asleep && !b->held && !b->carried) {
			cache->awake_flag[i] = 0;
			cache->near_lists.epoch++; // at rest where no neighbour list looked for it
		}
		else
			cache->awake[kept++] = i;
	}
	cache->awake_count = kept;
}

void hs_broadphase_reset(hs_world *world) {
	// between steps the awake list holds exactly the objects not asleep, held or carried
	// (hs_awake_compact ends every step; hs_wake keeps it for objects added since), in index order
	world->cache.awake_count = 0;
	for (int i = 0; i < world->model.object_count; ++i) {
		const hs_body *b = &world->state.bodies[i];
		bool awake = !b->asleep || b->held || b->carried;
		world->cache.awake_flag[i] = (uint8_t)awake;
		if (awake)
			world->cache.awake[world->cache.awake_count++] = i;
	}
	world->cache.grid_dirty = true; // filed again at the next step (the neighbour lists made stale)
	hs_digest_all_stale(&world->cache);
}
