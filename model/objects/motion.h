// motion.h — free motion (1999 paper eq. 3) and the floor (§4.2): rectification, stability
// (eq. 4-5) and tipping (rules (1)-(3), eq. 6-7).
#ifndef HS_MOTION_H
#define HS_MOTION_H

#include <stdbool.h>

#include "world_internal.h"

// The parts of a world free motion reads and writes: the model (shapes, definition, object
// count, skip_work), the bodies (read: those a turn or a landing may meet; the moving body is
// passed on its own), the scratch (posed vertices, floor points, hull; a support's query answer)
// and the counters (object steps, floor checks).
typedef struct hs_motion_pass {
	const hs_world_model *model;
	const hs_body *bodies;
	hs_world_scratch *scratch;
	hs_world_counters *counters;
} hs_motion_pass;

// A world's free-motion parts.
static inline hs_motion_pass hs_motion_pass_of(hs_world *world) {
	return (hs_motion_pass){&world->model, world->state.bodies, &world->scratch, &world->counters};
}

// Advances one unheld object by one frame: free flight or, in floor contact, stability and tipping.
void hs_motion_step(const hs_motion_pass *m, hs_body *body);
// Poses the body's vertices into scratch->posed; returns the lowest z.
double hs_motion_pose_vertices(const hs_world_model *model, hs_world_scratch *scratch, const hs_body *body);
// Counts the posed vertices (scratch->posed) within the floor tolerance and stores their (x, y)
// in scratch->points.
int hs_motion_floor_points(const hs_world_model *model, hs_world_scratch *scratch, const hs_body *body);
// §4.2 rectification alone: lifts the body out of the floor and counts its floor contacts.
void hs_motion_keep_above_floor(const hs_world_model *model, hs_world_scratch *scratch, hs_body *body);
// The supports an object settles on (support mode): m->scratch->near[0 .. near_count) filtered as
// support.c does, and the plane normal . x = offset of the face it rests on; a tipping turn stops
// where a vertex reaches that face over one of them.
typedef struct hs_settle_supports {
	int object;
	int near_count;
	hs_vec3 normal;
	double offset;
	// p, on the plane, lies over one of the supports (not past its edge)
	bool (*over)(const hs_motion_pass *m, const struct hs_settle_supports *sup, hs_vec3 p);
} hs_settle_supports;

// Eq. 4-5 with the `count` contact points in m->scratch->points on the plane z = height:
// stable → the body stops (true); otherwise it tips by rules (1)-(3) when `may_tip`, its turn
// bounded by the floor (sup NULL) or by the supports' face.
bool hs_motion_settle(const hs_motion_pass *m, hs_body *body, int count, double height, hs_vec3 gm, bool may_tip,
                      const hs_settle_supports *sup);

#endif
