// hull.h — 2D convex hull of floor (or support) contact points and the G' tests
// (1999 paper §4.2, Fig. 5). Pure geometry: depends on nothing but hs_math.h.
#ifndef HS_HULL_H
#define HS_HULL_H

#include <stdbool.h>

#include "hs_math.h"

// A point of the floor plane (m).
typedef struct hs_vec2 {
	double x, y;
} hs_vec2;

// Convex hull of `points` (sorted in place) into `hull`, counter-clockwise, without collinear
// points. Returns the hull's vertex count (1 or 2 for degenerate input). `hull` needs room for
// count + 1 points. Never allocates.
int hs_hull_build(hs_vec2 *points, int count, hs_vec2 *hull);
// True when p lies inside the counter-clockwise hull or within `eps` (m) of its boundary.
bool hs_hull_contains(const hs_vec2 *hull, int count, hs_vec2 p, double eps);
// Index i of the hull edge hull[i] → hull[i + 1] nearest to p.
int hs_hull_nearest_edge(const hs_vec2 *hull, int count, hs_vec2 p);

#endif
