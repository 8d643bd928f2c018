// motion.h — free motion (1999 paper eq. 3) and the floor (§4.2): rectification, stability
// (eq. 4-5) and tipping (rules (1)-(3), eq. 6-7).
#ifndef HS_MOTION_H
#define HS_MOTION_H

#include <stdbool.h>

#include "world_internal.h"

// Advances one unheld object by one frame: free flight or, in floor contact, stability and tipping.
void hs_motion_step(hs_world *world, hs_body *body);
// Poses the body's vertices into world->scratch.posed; returns the lowest z.
double hs_motion_pose_vertices(hs_world *world, const hs_body *body);
// Counts the posed vertices (scratch.posed) within the floor tolerance and stores their (x, y)
// in world->scratch.points.
int hs_motion_floor_points(hs_world *world, const hs_body *body);
// §4.2 rectification alone: lifts the body out of the floor and counts its floor contacts.
void hs_motion_keep_above_floor(hs_world *world, hs_body *body);
// The supports an object settles on (support mode): world->scratch.near[0 .. near_count) filtered as
// support.c does, and the plane normal . x = offset of the face it rests on; a tipping turn stops
// where a vertex reaches that face over one of them.
typedef struct hs_settle_supports {
	int object;
	int near_count;
	hs_vec3 normal;
	double offset;
	// p, on the plane, lies over one of the supports (not past its edge)
	bool (*over)(const hs_world *world, const struct hs_settle_supports *sup, hs_vec3 p);
} hs_settle_supports;

// Eq. 4-5 with the `count` contact points in world->scratch.points on the plane z = height:
// stable → the body stops (true); otherwise it tips by rules (1)-(3) when `may_tip`, its turn
// bounded by the floor (sup NULL) or by the supports' face.
bool hs_motion_settle(hs_world *world, hs_body *body, int count, double height, hs_vec3 gm, bool may_tip,
                      const hs_settle_supports *sup);

#endif
