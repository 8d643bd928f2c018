// internal.h — private structures shared by the model's .c files (not installed).
#ifndef HS_INTERNAL_H
#define HS_INTERNAL_H

#include "handspring.h"

typedef struct hs_vec2 {
	double x, y;
} hs_vec2;

// The state of one object that changes per frame (1999 paper §4.1: Verlet needs P(t - dt)).
typedef struct hs_body {
	hs_vec3 pos;  // P(t): centre of gravity, m
	hs_vec3 prev; // P(t - dt), m
	hs_quat rot;  // orientation, body → world
	hs_quat spin; // relative rotation per frame, carried over after release (§4.1)
	int shape;    // index into hs_world.shapes
	int floor_contacts;
	uint8_t contact;  // hs_contact_state
	uint8_t grounded; // touched the floor at the end of the last frame: §4.2 tipping, not free flight
	uint8_t asleep;   // stable and at rest: skipped until something touches it
	uint8_t held;     // moved by a hand this frame: free motion does not run
	double mass;      // kg: density × volume (spring model)
	hs_vec3 vel;      // m/s: the spring model integrates velocity explicitly
} hs_body;

// The Responsive Workbench spring model (spring.c, tracker.c): present only in worlds that use it.
typedef struct hs_spring_system hs_spring_system;
// One frame of the spring model for every object of the world (replaces the 1999 motion).
void hs_spring_step(hs_world *world);
void hs_spring_system_destroy(hs_spring_system *system);

struct hs_world {
	hs_world_def def;
	int shape_count;
	hs_shape *shapes; // deep copies, def.max_shapes of them
	int object_count;
	hs_body *bodies; // def.max_objects of them
	// scratch for the floor test, sized at hs_world_add_shape for the largest shape
	int scratch_capacity;
	hs_vec3 *scratch_world; // posed vertices
	hs_vec2 *scratch_points;
	hs_vec2 *scratch_hull;
	long frame;
	hs_world_counters counters;
	hs_spring_system *spring; // NULL unless the world runs the spring model
};

// hull.c — 2D convex hull of floor contact points (§4.2, Fig. 5)

// Convex hull of `points` (sorted in place) into `hull`, counter-clockwise, without collinear
// points. Returns the hull's vertex count (1 or 2 for degenerate input). Never allocates.
int hs_hull_build(hs_vec2 *points, int count, hs_vec2 *hull);
// True when p lies inside the counter-clockwise hull or within `eps` (m) of its boundary.
bool hs_hull_contains(const hs_vec2 *hull, int count, hs_vec2 p, double eps);
// Index i of the hull edge hull[i] → hull[i + 1] nearest to p.
int hs_hull_nearest_edge(const hs_vec2 *hull, int count, hs_vec2 p);

// motion.c — free motion (eq. 3) and the floor (§4.2)

// Advances one unheld object by one frame: free flight or, in floor contact, stability and tipping.
void hs_motion_step(hs_world *world, hs_body *body);
// Poses the body's vertices into world->scratch_world; returns the lowest z.
double hs_motion_pose_vertices(hs_world *world, const hs_body *body);
// Counts vertices within the floor tolerance and stores their (x, y) in world->scratch_points.
int hs_motion_floor_points(hs_world *world, const hs_body *body);

#endif
