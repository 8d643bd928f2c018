// overlap.h — objects that overlap at load (overlap.c; scenarios/README.md, Objects).
#ifndef HS_HARNESS_OVERLAP_H
#define HS_HARNESS_OVERLAP_H

#include <stdbool.h>

#include "handspring.h"

// m: how deep a point of one object may lie inside another before they overlap (touching and
// stacked objects are at depth 0; rounding in their poses stays far below this).
#define HS_OVERLAP_TOLERANCE 1e-3

// True when two objects of the world overlap: *first < *second their indices (in the order
// added), *depth (m) how deep a point of one lies inside the other. The pair found first along x.
bool hs_find_overlap(const hs_world *w, int *first, int *second, double *depth);
// The same for points deeper than `tolerance` (m): a lesser overlap, warned of (scenario_warn.c).
bool hs_find_overlap_beyond(const hs_world *w, double tolerance, int *first, int *second, double *depth);

// m: the deepest penetration of `object` into another object as posed now (libccd's, over their
// convex parts: face-to-face overlaps too); 0 when it is inside none. *other: that object (-1:
// none). A pass over every other object's box: for an expectation at one frame.
double hs_object_overlap(const hs_world *w, int object, int *other);

#endif
