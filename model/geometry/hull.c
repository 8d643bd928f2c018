// hull.c — 2D convex hull of the floor contact vertices V_i and the G' tests (1999 paper §4.2, Fig. 5).
#include "hull.h"

static double cross2(hs_vec2 o, hs_vec2 a, hs_vec2 b) {
	return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

static bool less2(hs_vec2 a, hs_vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// Insertion sort: contact sets are small and qsort may allocate, which the step must not.
static void sort2(hs_vec2 *p, int n) {
	for (int i = 1; i < n; ++i) {
		hs_vec2 v = p[i];
		int j = i - 1;
		while (j >= 0 && less2(v, p[j])) {
			p[j + 1] = p[j];
			--j;
		}
		p[j + 1] = v;
	}
}

// Andrew's monotone chain; `hull` needs room for count + 1 points.
int hs_hull_build(hs_vec2 *points, int count, hs_vec2 *hull) {
	if (count <= 0)
		return 0;
	sort2(points, count);
	int k = 0;
	for (int i = 0; i < count; ++i) { // lower chain
		while (k >= 2 && cross2(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
			--k;
		hull[k++] = points[i];
	}
	for (int i = count - 2, lower = k + 1; i >= 0; --i) { // upper chain
		while (k >= lower && cross2(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
			--k;
		hull[k++] = points[i];
	}
	// the last point repeats the first; a single distinct point collapses to one
	int n = k > 1 ? k - 1 : k;
	if (n == 2 && hull[0].x == hull[1].x && hull[0].y == hull[1].y)
		n = 1;
	return n;
}

bool hs_hull_contains(const hs_vec2 *hull, int count, hs_vec2 p, double eps) {
	if (count < 3)
		return false; // a point or a segment supports nothing (§4.2 rules (1), (2))
	for (int i = 0; i < count; ++i) {
		hs_vec2 a = hull[i], b = hull[(i + 1) % count];
		double len = sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
		// signed distance of p to the left of edge a→b
		if (cross2(a, b, p) < -eps * len)
			return false;
	}
	return true;
}

// In the plane z = 0 the 3D projection gives the same bits as a 2D one: every added z term is +0.
static double segment_distance_sq(hs_vec2 a, hs_vec2 b, hs_vec2 p) {
	hs_vec3 p3 = hs_v3(p.x, p.y, 0.0);
	return hs_length_sq(hs_sub(hs_segment_closest(hs_v3(a.x, a.y, 0.0), hs_v3(b.x, b.y, 0.0), p3), p3));
}

int hs_hull_nearest_edge(const hs_vec2 *hull, int count, hs_vec2 p) {
	int best = 0;
	double best_d = INFINITY;
	for (int i = 0; i < count; ++i) {
		double d = segment_distance_sq(hull[i], hull[(i + 1) % count], p);
		if (d < best_d) { // strict: the first of equals wins, so the choice is deterministic
			best_d = d;
			best = i;
		}
	}
	return best;
}
