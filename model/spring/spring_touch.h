// spring_touch.h — where two objects of the spring model meet: the narrow phase and the touch list.
#ifndef HS_SPRING_TOUCH_H
#define HS_SPRING_TOUCH_H

#include "spring_system.h"
#include "world_internal.h"

// Contact of object a (geometry ga, G at pa) with object b: the unit normal from a to b and the
// depth (m) of the true shapes' overlap; false when they do not meet.
bool hs_spring_contact(const hs_world *world, const hs_spring_geom *ga, hs_vec3 pa, const hs_spring_geom *gb,
                       hs_vec3 pb, hs_vec3 *n, double *depth);
// As hs_spring_contact, for shapes within `gap` (m) of each other: *depth is their overlap,
// negative for shapes apart (by less than the gap), for every kind of pair.
bool hs_spring_contact_within(const hs_world *world, const hs_spring_geom *ga, hs_vec3 pa, const hs_spring_geom *gb,
                     hs_vec3 pb, double gap, hs_vec3 *n, double *depth);
// Every pair of objects within `reach` (≥ gap) of each other where they are now, into sys->touch in
// ascending (a, b) (normal and depth set, `ahead` for a pair apart by more than `gap`, the rest
// zero), through the broad phase.
void hs_spring_find_touches(hs_world *world, hs_spring_system *sys, double gap, double reach);
// True when (a, b), a < b, is among sys->touch and touches, or is ahead and its force acts (the
// rest solve closes it by the frame's end): a resting pair.
bool hs_spring_touching(const hs_spring_system *sys, int a, int b);

// The bounding boxes of a at pa and b at pb, each grown by m, overlap.
static inline bool hs_spring_boxes_meet(const hs_spring_geom *ga, hs_vec3 pa, const hs_spring_geom *gb, hs_vec3 pb, double m) {
	return pa.x + ga->lo.x - m <= pb.x + gb->hi.x && pb.x + gb->lo.x <= pa.x + ga->hi.x + m &&
	       pa.y + ga->lo.y - m <= pb.y + gb->hi.y && pb.y + gb->lo.y <= pa.y + ga->hi.y + m &&
	       pa.z + ga->lo.z - m <= pb.z + gb->hi.z && pb.z + gb->lo.z <= pa.z + ga->hi.z + m;
}

#endif
