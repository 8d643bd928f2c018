// hgrid.h — a hierarchical hashed grid: finds the objects whose bounds may meet a box, in O(1)
// per object for any mix of sizes. Used by the hand model's broad phase (broadphase.c, over the
// floor plane) and the spring model's collisions (spring_collide.c, in 3D).
//
// Each object is filed by its centre in one cell of the level its size fits: level 0's cell is
// twice the median half-extent (a typical object's width, as the old single cell was for equal
// objects, whatever one huge object does), each level above doubles it. A query visits, per level, the cells its box widened by that
// level's largest half-extent covers — or, when those are more than the level's objects, the
// level's own list. A packed level (hs_hgrid_pack) keeps the cells it occupies in a dense window,
// read without hashing. Results come sorted by index: a query never changes what its caller computes,
// only how much it looks at. Everything is allocated once (hs_hgrid_alloc); nothing per query.
#ifndef HS_HGRID_H
#define HS_HGRID_H

#include <stdbool.h>

#include "hs_math.h"

#define HS_HGRID_LEVELS 48

typedef struct hs_hgrid {
	int capacity;     // objects
	int dims;         // 2: filed by x, y (the floor plane); 3: by x, y, z
	int buckets;      // a power of two, at least twice capacity
	int count;        // objects filed by the last build
	double cell0;     // m: level 0's cell edge
	int levels;       // levels in use (1 + the highest level of an object)
	double size[HS_HGRID_LEVELS];   // m: cell edge of each level, cell0 · 2^level
	double inv[HS_HGRID_LEVELS];    // 1/m: its inverse (cells only need a monotonic map, not exact)
	double reach[HS_HGRID_LEVELS];  // m: largest half-extent filed at each level
	int first[HS_HGRID_LEVELS + 1]; // level L's objects are by_level[first[L] .. first[L + 1])
	long occupied[HS_HGRID_LEVELS][2][3]; // cells filed at each level since the last reset: [lo, hi] per axis
	// Packed levels (hs_hgrid_pack): a window of cells laid out densely in `dense`, read without
	// hashing; win_n[L][0] == 0: level L is not packed. Objects filed outside a level's window
	// go to the hash (outside[L] of them).
	long win_lo[HS_HGRID_LEVELS][3]; // the window's first cell per axis
	long win_n[HS_HGRID_LEVELS][3];  // its cells per axis
	long win_base[HS_HGRID_LEVELS];  // its first cell in dense
	int outside[HS_HGRID_LEVELS];    // objects of each level filed in the hash
	long pool;        // cells of dense
	int *dense;       // pool: the packed windows' cells → first object (-1: none)
	int *by_level;    // objects by level, in index order within each
	int *head;        // bucket → first object (-1: none)
	int *next, *level;
	int *slot;        // per object: -1 not filed, ≥ 0 its hash bucket, ≤ -2 its cell -2 - slot in dense
	long *cell;       // dims per object
	double *half;     // m: half-extent per object, written by the caller before hs_hgrid_build
	double *scratch;  // capacity: the sizes, sorted for the median
	int *merge;       // capacity: a query's second buffer when it merges the levels' sorted runs
} hs_hgrid;

// Allocates for `capacity` objects; false when out of memory (hs_hgrid_free is then still safe).
bool hs_hgrid_alloc(hs_hgrid *g, int capacity, int dims);
void hs_hgrid_free(hs_hgrid *g);
// Assigns objects 0 .. n-1 their levels from their half-extents g->half[i] (m) and empties the
// grid; file each object next (hs_hgrid_file).
void hs_hgrid_build(hs_hgrid *g, int n);
// Files object i by its centre (again after it moved; a no-op when it stays in its cell).
void hs_hgrid_file(hs_hgrid *g, int i, hs_vec3 centre);
// Lays the levels' filed objects out densely over the cells they occupy (as far as the pool
// holds), so that queries there read cells without hashing; call it after filing every object.
// Objects filed later outside a window are hashed. Queries answer the same either way.
void hs_hgrid_pack(hs_hgrid *g);
// Forgets which cells were filed before; the caller then files every object again. Queries visit
// only the cells between the lowest and highest filed since (objects on a floor: one layer).
void hs_hgrid_reset_occupied(hs_hgrid *g);
// Objects whose bounds (centre ± half-extent) may meet the box [lo, hi], in index order.
// Returns how many were written to out (capacity long).
int hs_hgrid_query(const hs_hgrid *g, hs_vec3 lo, hs_vec3 hi, int *out);
// Sorts n object indices ascending (heapsort: no allocation; a sorted or reversed run is O(n)).
void hs_sort_indices(int *v, int n);

#endif
