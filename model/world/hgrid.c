// hgrid.c — the hierarchical hashed grid of hgrid.h (docs/model.md §10: collisions that scale,
// with objects of very different sizes and many objects in one place).
//
// Why levels: one cell size for all (twice the largest radius, as before) files 4000 cubes of
// 5 cm in one cell when a 400 m box is among them, and every query returns all of them. Filing
// each object at the level its size fits keeps every cell's share of objects O(1) for any mix.
// Results are sorted by index, so callers iterate in the order a full scan would: no result
// depends on the grid (docs/model.md §10: iteration is in array order).
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "hgrid.h"

// in cells: beyond this a coordinate is clamped (never a conversion out of range, NaN included)
#define HS_HGRID_CLAMP 1e9

bool hs_hgrid_alloc(hs_hgrid *g, int capacity, int dims) {
	memset(g, 0, sizeof *g);
	size_t cap = capacity > 0 ? (size_t)capacity : 1;
	g->capacity = (int)cap;
	g->dims = dims;
	g->buckets = 16;
	while ((size_t)g->buckets < 2 * cap)
		g->buckets *= 2;
	g->pool = 4 * (long)g->buckets; // packed windows: at least 8 cells per object
	g->pool = g->pool < INT_MAX / 2 ? g->pool : INT_MAX / 2; // slots are ints
	g->head = malloc((size_t)g->buckets * sizeof *g->head);
	g->dense = malloc((size_t)g->pool * sizeof *g->dense);
	g->next = calloc(cap, sizeof *g->next);
	g->slot = calloc(cap, sizeof *g->slot);
	g->level = calloc(cap, sizeof *g->level);
	g->by_level = calloc(cap, sizeof *g->by_level);
	g->cell = calloc(cap * (size_t)dims, sizeof *g->cell);
	g->half = calloc(cap, sizeof *g->half);
	g->scratch = calloc(cap, sizeof *g->scratch);
	g->merge = calloc(cap, sizeof *g->merge);
	return g->head && g->dense && g->next && g->slot && g->level && g->by_level && g->cell && g->half && g->scratch && g->merge;
}

void hs_hgrid_free(hs_hgrid *g) {
	free(g->head);
	free(g->next);
	free(g->slot);
	free(g->dense);
	free(g->level);
	free(g->by_level);
	free(g->cell);
	free(g->half);
	free(g->scratch);
	free(g->merge);
	memset(g, 0, sizeof *g);
}

static void sift_double(double *v, int root, int n) {
	for (int child; (child = 2 * root + 1) < n; root = child) {
		if (child + 1 < n && v[child + 1] > v[child])
			++child;
		if (!(v[child] > v[root]))
			return;
		double t = v[root];
		v[root] = v[child];
		v[child] = t;
	}
}

// The median of v[0 .. n-1] (n ≥ 1), sorting v in place (heapsort: no allocation).
static double median_of(double *v, int n) {
	for (int k = n / 2 - 1; k >= 0; --k)
		sift_double(v, k, n);
	for (int end = n - 1; end > 0; --end) {
		double t = v[0];
		v[0] = v[end];
		v[end] = t;
		sift_double(v, 0, end);
	}
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static double cell_of_level(const hs_hgrid *g, int level) { return g->size[level]; }

void hs_hgrid_build(hs_hgrid *g, int n) {
	g->count = n;
	for (int i = 0; i < n; ++i)
		g->scratch[i] = g->half[i];
	double median = n > 0 ? median_of(g->scratch, n) : 0.0;
	g->cell0 = median > 0.0 && isfinite(median) ? 2.0 * median : 1.0;
	g->size[0] = g->cell0;
	for (int l = 1; l < HS_HGRID_LEVELS; ++l) // doubling is exact
		g->size[l] = 2.0 * g->size[l - 1];
	for (int l = 0; l < HS_HGRID_LEVELS; ++l)
		g->inv[l] = 1.0 / g->size[l];
	int per_level[HS_HGRID_LEVELS] = {0};
	g->levels = 1;
	memset(g->reach, 0, sizeof g->reach);
	for (int i = 0; i < n; ++i) { // the lowest level whose cell holds the object's whole width
		int level = 0;
		while (level < HS_HGRID_LEVELS - 1 && !(2.0 * g->half[i] <= cell_of_level(g, level)))
			++level;
		g->level[i] = level;
		g->reach[level] = g->half[i] > g->reach[level] ? g->half[i] : g->reach[level];
		per_level[level]++;
		g->levels = level + 1 > g->levels ? level + 1 : g->levels;
		g->slot[i] = -1;
	}
	g->first[0] = 0;
	for (int l = 0; l < HS_HGRID_LEVELS; ++l)
		g->first[l + 1] = g->first[l] + per_level[l];
	int fill[HS_HGRID_LEVELS];
	memcpy(fill, g->first, sizeof fill);
	for (int i = 0; i < n; ++i) // index order within each level
		g->by_level[fill[g->level[i]]++] = i;
	for (int b = 0; b < g->buckets; ++b)
		g->head[b] = -1;
	memset(g->win_n, 0, sizeof g->win_n); // no level packed, none hashed
	memset(g->outside, 0, sizeof g->outside);
	hs_hgrid_reset_occupied(g);
}

void hs_hgrid_reset_occupied(hs_hgrid *g) {
	for (int l = 0; l < HS_HGRID_LEVELS; ++l)
		for (int d = 0; d < 3; ++d) {
			g->occupied[l][0][d] = LONG_MAX;
			g->occupied[l][1][d] = LONG_MIN;
		}
}

// The cell of coordinate v at a level of inverse cell size inv: x ↦ floor(x · inv) is monotonic,
// all filing and queries need (a centre within a query's range lies in one of its cells).
static long cell_coord(double v, double inv) {
	double x = v * inv;
	if (!(x > -HS_HGRID_CLAMP))
		x = -HS_HGRID_CLAMP;
	if (x > HS_HGRID_CLAMP)
		x = HS_HGRID_CLAMP;
	long q = (long)x; // floor without a library call: truncation, one less below zero
	return q - (x < (double)q ? 1 : 0);
}

static int bucket_of(const hs_hgrid *g, int level, const long *c) {
	// a multiplicative mix of the level and the cell; any fixed mix is deterministic
	unsigned long h = (unsigned long)level * 2654435761ul ^ (unsigned long)c[0] * 73856093ul ^
	                  (unsigned long)c[1] * 19349663ul;
	if (g->dims == 3)
		h ^= (unsigned long)c[2] * 83492791ul;
	return (int)(h & (unsigned long)(g->buckets - 1));
}

// The first object of slot s (s ≠ -1): a hash bucket, or a packed window's cell.
static int *slot_head(hs_hgrid *g, int s) { return s >= 0 ? &g->head[s] : &g->dense[-2 - s]; }

static void unlink_object(hs_hgrid *g, int i) {
	int s = g->slot[i];
	if (s == -1)
		return;
	int *link = slot_head(g, s);
	while (*link != i)
		link = &g->next[*link];
	*link = g->next[i];
	g->outside[g->level[i]] -= s >= 0;
	g->slot[i] = -1;
}

// Files object i in cell c: its level's window when the cell is inside, else the hash.
static void link_object(hs_hgrid *g, int i, const long *c) {
	int level = g->level[i];
	const long *lo = g->win_lo[level], *n = g->win_n[level];
	long k = 0;
	bool inside = n[0] > 0;
	for (int d = g->dims - 1; d >= 0 && inside; --d) {
		inside = c[d] >= lo[d] && c[d] - lo[d] < n[d];
		k = k * n[d] + (c[d] - lo[d]);
	}
	int s = inside ? (int)(-2 - (g->win_base[level] + k)) : bucket_of(g, level, c);
	g->outside[level] += !inside;
	int *head = slot_head(g, s);
	g->next[i] = *head;
	*head = i;
	g->slot[i] = s;
}

void hs_hgrid_file(hs_hgrid *g, int i, hs_vec3 centre) {
	double inv = g->inv[g->level[i]], x[3] = {centre.x, centre.y, centre.z};
	long c[3];
	bool same = g->slot[i] != -1;
	long(*occ)[3] = g->occupied[g->level[i]];
	for (int d = 0; d < g->dims; ++d) {
		c[d] = cell_coord(x[d], inv);
		same = same && g->cell[(size_t)i * (size_t)g->dims + (size_t)d] == c[d];
		occ[0][d] = c[d] < occ[0][d] ? c[d] : occ[0][d];
		occ[1][d] = c[d] > occ[1][d] ? c[d] : occ[1][d];
	}
	if (same)
		return;
	unlink_object(g, i);
	link_object(g, i, c);
	for (int d = 0; d < g->dims; ++d)
		g->cell[(size_t)i * (size_t)g->dims + (size_t)d] = c[d];
}

// Level L's window: the cells it occupies, widened on each side by a cell and an eighth of their
// extent when `margin` (objects that move a little stay inside). Returns its cells, 0 when none
// of the level is filed.
static double window_of(const hs_hgrid *g, int level, bool margin, long *lo, long *n) {
	double cells = 1.0;
	for (int d = 0; d < 3; ++d) {
		lo[d] = 0;
		n[d] = 1;
		if (d >= g->dims)
			continue;
		long a = g->occupied[level][0][d], b = g->occupied[level][1][d];
		if (a > b)
			return 0.0;
		double extent = (double)b - (double)a + 1.0, m = margin ? floor(extent / 8.0) + 1.0 : 0.0;
		cells *= extent + 2.0 * m;
		if (cells > (double)g->pool)
			return cells; // too large: the fields are not used
		lo[d] = a - (long)m;
		n[d] = (long)(extent + 2.0 * m);
	}
	return cells;
}

void hs_hgrid_pack(hs_hgrid *g) {
	bool hashed = false;
	for (int level = 0; level < g->levels; ++level)
		hashed = hashed || g->outside[level] > 0;
	if (!hashed)
		return; // every filed object is in its level's window already
	long used = 0;
	for (int level = 0; level < g->levels; ++level) {
		long lo[3], n[3];
		double room = (double)(g->pool - used), cells = window_of(g, level, true, lo, n);
		if (cells > room)
			cells = window_of(g, level, false, lo, n);
		g->win_n[level][0] = 0;
		if (!(cells > 0.0 && cells <= room))
			continue; // nothing filed, or no room: the level stays hashed
		memcpy(g->win_lo[level], lo, sizeof lo);
		memcpy(g->win_n[level], n, sizeof n);
		g->win_base[level] = used;
		for (long end = used + (long)cells; used < end; ++used)
			g->dense[used] = -1;
	}
	for (int b = 0; b < g->buckets; ++b)
		g->head[b] = -1;
	memset(g->outside, 0, sizeof g->outside);
	for (int i = 0; i < g->count; ++i)
		if (g->slot[i] != -1)
			link_object(g, i, &g->cell[(size_t)i * (size_t)g->dims]);
}

// Objects of one level hashed in the cells x0 .. x1 of row (y, z).
static int visit_hashed(const hs_hgrid *g, int level, long x0, long x1, long y, long z, int *out, int n) {
	int dims = g->dims;
	// bucket_of's mix (xor: the same value in any order)
	unsigned long mask = (unsigned long)(g->buckets - 1), h = (unsigned long)level * 2654435761ul;
	h ^= (unsigned long)y * 19349663ul;
	if (dims == 3)
		h ^= (unsigned long)z * 83492791ul;
	for (long x = x0; x <= x1; ++x)
		for (int i = g->head[(h ^ (unsigned long)x * 73856093ul) & mask]; i >= 0; i = g->next[i]) {
			const long *ci = &g->cell[(size_t)i * (size_t)dims];
			if (ci[0] == x && ci[1] == y && (dims == 2 || ci[2] == z) && g->level[i] == level)
				out[n++] = i; // not a hash neighbour
		}
	return n;
}

// The objects filed in cells x0 .. x1 of one row of a packed window (its cell 0 at row).
static inline int window_row(const hs_hgrid *g, const int *row, long x0, long x1, int *out, int n) {
	for (long x = x0; x <= x1; ++x)
		for (int i = row[x]; i >= 0; i = g->next[i])
			out[n++] = i;
	return n;
}

// Objects of one level in the cells lo[] .. hi[] when all of it is in its packed window: the
// range's cells inside the window (each cell's list is exact), row by row.
static int visit_window(const hs_hgrid *g, int level, const long *lo, const long *hi, int *out, int n) {
	const long *wl = g->win_lo[level], *wn = g->win_n[level];
	bool z = g->dims == 3; // the range in window cells, clipped to the window
	long x0 = lo[0] - wl[0], x1 = hi[0] - wl[0], y0 = lo[1] - wl[1], y1 = hi[1] - wl[1];
	long z0 = z ? lo[2] - wl[2] : 0, z1 = z ? hi[2] - wl[2] : 0;
	x0 = x0 > 0 ? x0 : 0;
	y0 = y0 > 0 ? y0 : 0;
	z0 = z0 > 0 ? z0 : 0;
	x1 = x1 < wn[0] - 1 ? x1 : wn[0] - 1;
	y1 = y1 < wn[1] - 1 ? y1 : wn[1] - 1;
	z1 = z1 < wn[2] - 1 ? z1 : wn[2] - 1;
	const int *cells = g->dense + g->win_base[level];
	for (long k = z0; k <= z1; ++k)
		for (long y = y0; y <= y1; ++y)
			n = window_row(g, cells + (k * wn[1] + y) * wn[0], x0, x1, out, n);
	return n;
}

// Objects of one level filed in the cells lo[] .. hi[] (dims of them, inclusive): from its packed
// window's cells where the range meets it (each cell's list is exact), from the hash elsewhere
// (only when some object of the level is hashed: none is in the window's cells).
static int visit_cells(const hs_hgrid *g, int level, const long *lo, const long *hi, int *out, int n) {
	const long *wl = g->win_lo[level], *wn = g->win_n[level];
	bool hashed = g->outside[level] > 0;
	long z0 = g->dims == 3 ? lo[2] : 0, z1 = g->dims == 3 ? hi[2] : 0;
	long x0 = lo[0] > wl[0] ? lo[0] : wl[0], x1 = hi[0] < wl[0] + wn[0] - 1 ? hi[0] : wl[0] + wn[0] - 1;
	for (long z = z0; z <= z1; ++z)
		for (long y = lo[1]; y <= hi[1]; ++y) {
			bool row = wn[0] > 0 && y >= wl[1] && y - wl[1] < wn[1] && z >= wl[2] && z - wl[2] < wn[2];
			if (!row || x0 > x1) { // the window has no cell in this row of the range
				n = hashed ? visit_hashed(g, level, lo[0], hi[0], y, z, out, n) : n;
				continue;
			}
			if (hashed) { // the row's cells left and right of the window
				n = visit_hashed(g, level, lo[0], x0 - 1, y, z, out, n);
				n = visit_hashed(g, level, x1 + 1, hi[0], y, z, out, n);
			}
			const int *cells = g->dense + g->win_base[level] + ((z - wl[2]) * wn[1] + (y - wl[1])) * wn[0];
			n = window_row(g, cells, x0 - wl[0], x1 - wl[0], out, n);
		}
	return n;
}

// Merges the sorted runs v[run[k] .. run[k + 1]) (runs of them) into one, through buf.
static void merge_runs(int *v, int *buf, int *run, int runs) {
	while (runs > 1) {
		int kept = 0;
		for (int k = 0; k < runs; k += 2) {
			if (k + 1 == runs) {
				run[kept++] = run[k];
				continue;
			}
			int a = run[k], mid = run[k + 1], b = run[k + 2], i = a, j = mid, o = a;
			while (i < mid && j < b)
				buf[o++] = v[i] <= v[j] ? v[i++] : v[j++];
			while (i < mid)
				buf[o++] = v[i++];
			while (j < b)
				buf[o++] = v[j++];
			memcpy(v + a, buf + a, (size_t)(b - a) * sizeof *v);
			run[kept++] = a;
		}
		run[kept] = run[runs];
		runs = kept;
	}
}

int hs_hgrid_query(const hs_hgrid *g, hs_vec3 lo, hs_vec3 hi, int *out) {
	int n = 0, runs = 0, run[HS_HGRID_LEVELS + 1];
	double a[3] = {lo.x, lo.y, lo.z}, b[3] = {hi.x, hi.y, hi.z};
	for (int level = 0; level < g->levels; ++level) {
		int count = g->first[level + 1] - g->first[level];
		if (count == 0)
			continue;
		double inv = g->inv[level], r = g->reach[level], cells = 1.0;
		long c0[3] = {0, 0, 0}, c1[3] = {0, 0, 0};
		for (int d = 0; d < g->dims; ++d) {
			c0[d] = cell_coord(a[d] - r, inv);
			c1[d] = cell_coord(b[d] + r, inv);
			cells *= (double)(c1[d] - c0[d] + 1);
		}
		int start = n;
		if (cells > (double)count) { // more cells than objects: the level's list (sorted) is cheaper
			memcpy(out + n, g->by_level + g->first[level], (size_t)count * sizeof *out);
			n += count;
		} else if (g->win_n[level][0] > 0 && g->outside[level] == 0) { // all of the level packed
			n = visit_window(g, level, c0, c1, out, n);
			hs_sort_indices(out + start, n - start);
		} else { // (the choice above is made on the unclipped range: the same result as before)
			for (int d = 0; d < g->dims; ++d) { // no object filed outside the occupied cells
				c0[d] = c0[d] > g->occupied[level][0][d] ? c0[d] : g->occupied[level][0][d];
				c1[d] = c1[d] < g->occupied[level][1][d] ? c1[d] : g->occupied[level][1][d];
			}
			n = visit_cells(g, level, c0, c1, out, n);
			hs_sort_indices(out + start, n - start);
		}
		if (n > start)
			run[runs++] = start;
	}
	run[runs] = n;
	merge_runs(out, g->merge, run, runs);
	return n;
}

static void sift_int(int *v, int root, int n) {
	for (int child; (child = 2 * root + 1) < n; root = child) {
		if (child + 1 < n && v[child + 1] > v[child])
			++child;
		if (v[child] <= v[root])
			return;
		int t = v[root];
		v[root] = v[child];
		v[child] = t;
	}
}

void hs_sort_indices(int *v, int n) {
	if (n <= 16) { // insertion sort: fastest for the few a query usually finds
		for (int k = 1; k < n; ++k) {
			int x = v[k], j = k;
			for (; j > 0 && v[j - 1] > x; --j)
				v[j] = v[j - 1];
			v[j] = x;
		}
		return;
	}
	bool up = true, down = true;
	for (int k = 1; k < n && (up || down); ++k) {
		up = up && v[k - 1] <= v[k];
		down = down && v[k - 1] >= v[k];
	}
	if (up)
		return;
	if (down) { // one cell's chain comes newest first
		for (int k = 0; k < n / 2; ++k) {
			int t = v[k];
			v[k] = v[n - 1 - k];
			v[n - 1 - k] = t;
		}
		return;
	}
	for (int k = n / 2 - 1; k >= 0; --k)
		sift_int(v, k, n);
	for (int end = n - 1; end > 0; --end) {
		int t = v[0];
		v[0] = v[end];
		v[end] = t;
		sift_int(v, 0, end);
	}
}
