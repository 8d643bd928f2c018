// spring_near.c — which objects may meet one object in the spring model (docs/model.md §8).
//
// The grid (hgrid.c) answers a query in O(1) per object, but a frame asks it about every object
// three or four times (the touches at the frame start, the meetings, the end passes). Neighbour
// lists with a skin (Verlet lists) answer most of those instead: object q's list holds every
// object whose bounding box came within its query box grown by 2 skins + the largest margin when
// the lists were made. While no object moved more than a skin since, and a query's box lies within
// a skin of the box its list was made for, every object whose box meets the query's box is on the
// list — the callers test each candidate exactly, so a longer list changes nothing they compute
// (the lists are in index order, as the grid's answers). A list that would not fit, an object gone
// too far, or a query box beyond its skin falls back to the grid.
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "hgrid.h"
#include "spring_near.h"
#include "spring_technique.h"

#define HS_NEAR_SKIN 0.5 // of a typical object's width (the grid's cell)

static hs_vec3 box_centre(const hs_spring_geom *g, hs_vec3 p) {
	return hs_add(p, hs_scale(hs_add(g->lo, g->hi), 0.5));
}

static bool within(hs_vec3 a, hs_vec3 b, double d) {
	return fabs(a.x - b.x) <= d && fabs(a.y - b.y) <= d && fabs(a.z - b.z) <= d;
}

// Files object i where it is now (grid and bounding box); false when the lists are good but it
// moved beyond their skin.
static bool file_one(const hs_world *world, hs_spring_system *sys, int i) {
	hs_vec3 p = world->state.bodies[i].pos;
	hs_hgrid_file(&sys->grid, i, box_centre(&sys->geom[i], p));
	sys->box_lo[i] = hs_add(p, sys->geom[i].lo);
	sys->box_hi[i] = hs_add(p, sys->geom[i].hi);
	return sys->nb_state != HS_NEAR_LISTS || within(p, sys->nb_pos[i], sys->nb_skin);
}

void hs_spring_file_all(hs_world *world, hs_spring_system *sys) {
	int n = world->model.object_count;
	if (sys->grid_count != n) {
		for (int i = 0; i < n; ++i) {
			hs_vec3 w = hs_sub(sys->geom[i].hi, sys->geom[i].lo);
			sys->grid.half[i] = 0.5 * fmax(w.x, fmax(w.y, w.z));
		}
		hs_hgrid_build(&sys->grid, n);
		sys->grid_count = n;
		sys->nb_state = HS_NEAR_STALE;
		sys->nb_skin = HS_NEAR_SKIN * sys->grid.cell0;
	}
	if (sys->nb_state == HS_NEAR_GRID) // a new phase: the lists may be made again
		sys->nb_state = HS_NEAR_STALE;
	hs_hgrid_reset_occupied(&sys->grid);
	for (int i = 0; i < n; ++i)
		if (!file_one(world, sys, i))
			sys->nb_state = HS_NEAR_STALE;
	hs_hgrid_pack(&sys->grid); // the cells the boxes occupy, read without hashing
}

void hs_spring_refile(hs_world *world, hs_spring_system *sys, int i) {
	if (!file_one(world, sys, i))
		sys->nb_state = HS_NEAR_GRID; // the grid until the next phase: no rebuild per answered pair
}

// Object i's query box at its position (and path, grown by reach when reach > 0).
static void query_box(const hs_world *world, const hs_spring_system *sys, int i, double reach, hs_vec3 *lo,
                      hs_vec3 *hi) {
	const hs_spring_geom *g = &sys->geom[i];
	hs_vec3 p = world->state.bodies[i].pos, s = world->scratch.spring.path_pos[i];
	double m = hs_spring_margin(g, p);
	*lo = hs_add(p, hs_sub(g->lo, hs_v3(m, m, m)));
	*hi = hs_add(p, hs_add(g->hi, hs_v3(m, m, m)));
	if (reach > 0.0) {
		*lo = hs_v3(fmin(lo->x, s.x + g->lo.x) - reach, fmin(lo->y, s.y + g->lo.y) - reach,
		            fmin(lo->z, s.z + g->lo.z) - reach);
		*hi = hs_v3(fmax(hi->x, s.x + g->hi.x) + reach, fmax(hi->y, s.y + g->hi.y) + reach,
		            fmax(hi->z, s.z + g->hi.z) + reach);
	}
}

// Every object's list from where the objects are now; false (no lists) when they do not fit.
static bool build_lists(const hs_world *world, hs_spring_system *sys) {
	int n = world->model.object_count, used = 0;
	double margin = 0.0;
	for (int i = 0; i < n; ++i) // the largest margin any object may have within a skin of here
		margin = fmax(margin, hs_spring_margin(&sys->geom[i], world->state.bodies[i].pos));
	sys->nb_margin = margin;
	double pad = 2.0 * sys->nb_skin + 2.0 * margin + 1e-6;
	for (int q = 0; q < n; ++q) {
		hs_vec3 lo, hi;
		query_box(world, sys, q, 0.0, &lo, &hi);
		sys->nb_start[q] = used;
		sys->nb_lo[q] = lo;
		sys->nb_hi[q] = hi;
		sys->nb_pos[q] = world->state.bodies[q].pos;
		int count = hs_hgrid_query(&sys->grid, hs_sub(lo, hs_v3(pad, pad, pad)), hs_add(hi, hs_v3(pad, pad, pad)),
		                           sys->near);
		if (count > sys->nb_capacity - used)
			return false;
		memcpy(sys->nb + used, sys->near, (size_t)count * sizeof *sys->nb);
		used += count;
	}
	sys->nb_start[n] = used;
	return true;
}

// The objects of list[0 .. n) whose bounding boxes meet [lo, hi], in list order, into sys->near.
static int filter_list(hs_spring_system *sys, const int *list, int n, hs_vec3 lo, hs_vec3 hi) {
	int count = 0;
	const hs_vec3 *blo = sys->box_lo, *bhi = sys->box_hi;
#if defined(__SSE2__)
	// Without branches, two axes a compare (the same <= as below, false for NaN alike): in a pile
	// whether a neighbour's box meets is a coin toss, and the short-circuit test mispredicted about
	// 36 times an object a frame at 1000 objects.
	const __m128d hxy = _mm_loadu_pd(&hi.x), lxy = _mm_loadu_pd(&lo.x);
	const __m128d lz = _mm_set1_pd(lo.z), hz = _mm_set1_pd(hi.z);
	for (int k = 0; k < n; ++k) {
		int r = list[k];
		__m128d below = _mm_cmple_pd(_mm_loadu_pd(&blo[r].x), hxy); // blo.x <= hi.x, blo.y <= hi.y
		__m128d above = _mm_cmple_pd(lxy, _mm_loadu_pd(&bhi[r].x)); // lo.x <= bhi.x, lo.y <= bhi.y
		// (blo.z, lo.z) <= (hi.z, bhi.z)
		__m128d z = _mm_cmple_pd(_mm_loadl_pd(lz, &blo[r].z), _mm_loadh_pd(hz, &bhi[r].z));
		sys->near[count] = r;
		count += _mm_movemask_pd(_mm_and_pd(_mm_and_pd(below, above), z)) == 3;
	}
#else
	for (int k = 0; k < n; ++k) {
		int r = list[k];
		if (blo[r].x <= hi.x && lo.x <= bhi[r].x && blo[r].y <= hi.y && lo.y <= bhi[r].y && blo[r].z <= hi.z &&
		    lo.z <= bhi[r].z)
			sys->near[count++] = r;
	}
#endif
	return count;
}

// The objects whose boxes may meet lo..hi (a query about object i), from i's neighbour list while
// the query lies within its skin, else from the grid.
static int near_box_all(const hs_world *world, hs_spring_system *sys, int i, hs_vec3 lo, hs_vec3 hi, const int **out) {
	*out = sys->near;
	if (sys->all_pairs) {
		for (int j = 0; j < world->model.object_count; ++j)
			sys->near[j] = j;
		return world->model.object_count;
	}
	if (sys->nb_state == HS_NEAR_STALE)
		sys->nb_state = sys->nb_skin > 0.0 && build_lists(world, sys) ? HS_NEAR_LISTS : HS_NEAR_GRID;
	double s = sys->nb_skin;
	if (sys->nb_state == HS_NEAR_LISTS && lo.x >= sys->nb_lo[i].x - s && lo.y >= sys->nb_lo[i].y - s &&
	    lo.z >= sys->nb_lo[i].z - s && hi.x <= sys->nb_hi[i].x + s && hi.y <= sys->nb_hi[i].y + s &&
	    hi.z <= sys->nb_hi[i].z + s) {
		// the list's objects whose boxes (their margins and 1 µm more: rounding) meet the query's now
		double e = sys->nb_margin + 1e-6;
		lo = hs_sub(lo, hs_v3(e, e, e));
		hi = hs_add(hi, hs_v3(e, e, e));
		return filter_list(sys, sys->nb + sys->nb_start[i], sys->nb_start[i + 1] - sys->nb_start[i], lo, hi);
	}
	return hs_hgrid_query(&sys->grid, lo, hi, sys->near);
}

// As near_box_all, without the objects the techniques leave out of contacts (spring_technique.c).
static int near_box(const hs_world *world, hs_spring_system *sys, int i, hs_vec3 lo, hs_vec3 hi, const int **out) {
	int count = near_box_all(world, sys, i, lo, hi, out);
	return hs_spring_technique_filter(world, sys, i, sys->near, count);
}

int hs_spring_near(const hs_world *world, hs_spring_system *sys, int i, double reach, const int **out) {
	hs_vec3 lo, hi;
	query_box(world, sys, i, reach, &lo, &hi);
	return near_box(world, sys, i, lo, hi, out);
}

int hs_spring_near_grown(const hs_world *world, hs_spring_system *sys, int i, double grow, const int **out) {
	hs_vec3 lo, hi;
	query_box(world, sys, i, 0.0, &lo, &hi);
	lo = hs_sub(lo, hs_v3(grow, grow, grow));
	hi = hs_add(hi, hs_v3(grow, grow, grow));
	return near_box(world, sys, i, lo, hi, out);
}
