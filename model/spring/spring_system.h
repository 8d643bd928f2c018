// spring_system.h — the spring model's system: its definition and everything a step changes
// (stylus, spring, tracker, per-object flags), shared by the files of the spring model. Every
// field a later step reads is an entry of spring_state.c's field table (spring_fields), which
// save, load, check and hash all follow: a field added here is added there.
#ifndef HS_SPRING_SYSTEM_H
#define HS_SPRING_SYSTEM_H

#include "hgrid.h"
#include "spring_geom.h"
#include "spring_params.h"
#include "spring_technique_state.h"
#include "tracker.h"

typedef struct hs_spring_system hs_spring_system; // (as spring_world.h names it for the world)

// Touches the resting contacts hold per object (the world's max_objects of them): equal spheres
// packed closest have 6 per object (12 neighbours, each shared); beyond, a frame counts the
// touches it had no room for in counters.dropped_contacts and answers them as collisions.
#define HS_SPRING_TOUCHES_PER_OBJECT 8
#define HS_SPRING_NEAR_PER_OBJECT 32 // neighbour-list entries per object (beyond: the grid is asked)

// Two objects touching at the frame start (spring_rest.c): within floor_tolerance of each other;
// or apart by less than a slow meeting can close within the frame (`ahead`, spring_rest.c).
typedef struct hs_spring_touch {
	int a, b;        // body indices, a < b
	hs_vec3 n;       // unit normal from a to b
	hs_vec3 slide;   // unit direction of b's sliding on a at the frame start; zero: sticking
	double depth;    // m: overlap (negative: apart by less than the gap)
	double mass;     // kg: 1 / (1/m_a + 1/m_b)
	double e;        // restitution of the pair: the smaller of the two objects'
	double normal;   // N: normal force on b (on a: its opposite)
	hs_vec3 friction; // N: friction force on b, across n
	double bias;     // m/s²: the relative acceleration along n the pair takes before its force acts
	uint8_t open;    // moving apart at the frame start: no force (it would do work)
	uint8_t ahead;   // apart by more than the touch gap: its force only closes the gap by the frame's end
} hs_spring_touch;

// A touch's forces at the end of a frame: the next frame's solve starts from them where the
// touch goes on (spring_solve.c's warm start).
typedef struct hs_spring_warm {
	int a, b;         // body indices, a < b
	double normal;    // N
	hs_vec3 friction; // N
} hs_spring_warm;

// A meeting of objects i < j at the fraction tau of the frame (spring_collide.c).
typedef struct hs_spring_event {
	int i, j;
	double tau;
	uint32_t vi, vj; // the objects' versions when it was listed: stale once either is answered
} hs_spring_event;

// What the resting contacts know of one object in a frame (spring_rest.c).
typedef struct hs_spring_rest_body {
	hs_vec3 force;   // N: gravity and the spring with the object held where it is
	hs_vec3 acc;     // m/s²: its acceleration under the forces found so far
	hs_vec3 floor_friction; // N
	double floor_normal;    // N
	double wall[4];  // N: walls x_min, x_max, y_min, y_max
	uint8_t floor;   // on the floor at the frame start (as the floor's step sees it)
	uint8_t walls;   // bit k: touching wall k
	uint8_t sliding; // on the floor and moving: sliding friction
} hs_spring_rest_body;

// The neighbour lists' state (spring_near.c).
typedef enum hs_near_state {
	HS_NEAR_STALE = 0, // to be made at the next query
	HS_NEAR_LISTS = 1, // good: queries answered from them
	HS_NEAR_GRID = 2   // an object went beyond the skin in this phase: the grid answers until the next
} hs_near_state;

struct hs_spring_system {
	hs_spring_def def;
	hs_tracker tracker;
	int capacity;   // objects the per-object arrays hold (the world's max_objects, at least 1)
	int geom_count; // bodies whose geometry is cached (a cache: 0 makes the next step rebuild it)
	hs_spring_geom *geom;
	uint8_t *on_floor;
	uint8_t *sliding;
	uint8_t *separated; // pushed apart from a neighbour this frame: moved without a velocity
	// (the frame-start state, the swept paths and the floor layer: the world's scratch, spring)
	// CACHE: each object's spring parameters (hs_spring_params_of: a power per call), for the mass
	// params_mass holds (NaN: none); all forgotten when what else they depend on changes
	hs_spring_params *params;
	double *params_mass;
	double params_key[8]; // rest_length_ref, rest_mass_ref, rest_exponent, min, max, gravity
	hs_spring_event *events; // the meetings still to answer this frame (a heap by tau, i, j)
	uint32_t *version;       // per object: bumped when it is answered, so its listed meetings go stale
	uint8_t *moved;          // moved by a separation pass (bit 0: the last, bit 1: this one)
	bool shock;              // an end pass is separating bottom up (spring_collide.c)
	int event_count, event_capacity;
	// CACHE: the collisions' broad phase (spring_collide.c), 3D, built for grid_count objects
	// (-1: to build), refiled every frame; near holds a query's result
	hs_hgrid grid;
	int grid_count;
	int *near;
	// CACHE: neighbour lists (spring_near.c): object q's candidates nb[nb_start[q] .. nb_start[q + 1]),
	// found for its box nb_lo .. nb_hi with the objects at nb_pos; good while no object moved more
	// than nb_skin from there and a query's box stays within nb_skin of q's
	int *nb_start, *nb;
	hs_vec3 *box_lo, *box_hi; // each object's bounding box where it was last filed
	int nb_capacity;
	hs_vec3 *nb_pos, *nb_lo, *nb_hi;
	double nb_skin, nb_margin; // m: the skin; the largest margin when the lists were made
	uint8_t nb_state; // hs_near_state
	// SCRATCH of the resting contacts (spring_rest.c), found again every frame from the state:
	// touches in ascending (a, b), the objects in any (active, ascending), their forces
	hs_spring_touch *touch;
	int touch_count, touch_capacity;
	// the touches' forces at the end of the last frame, ascending (a, b), touch_capacity slots,
	// those beyond warm_count zero (the state visits every slot)
	hs_spring_warm *warm;
	int warm_count;
	int *active;
	int active_count;
	int *rest_index;          // object → its place in `active`, -1 when in no touch
	hs_spring_rest_body *rest; // per active object
	hs_vec3 *load;            // N: force of the touching objects on each object this frame
	uint8_t *held;            // held still by its contacts this frame: not stepped
	bool all_pairs; // tests only: every object is near every other (the double loop the grid replaces)
	// the stylus: pose at the end of the coming frame and at its start
	bool has_stylus;
	hs_vec3 stylus, stylus_prev;
	hs_quat rot, rot_prev;
	bool button, button_prev;
	hs_vec3 stylus_velocity; // m/s during the last frame
	// the spring
	int attached; // body index, -1 when none
	hs_attach_kind attach_kind;
	hs_vec3 axis;  // unit direction A → G used when they coincide
	hs_vec3 anchor_offset; // A − S: the spring's anchor A beside the stylus S, fixed at the press
	                       // so that the spring has its rest length there (spring_grab.c); in the
	                       // stylus's frame for the fishing rod (HS_ATTACH_ROD)
	int candidate; // body index, -1 when none
	hs_release release;
	hs_spring_technique tech; // the techniques beyond the spring (spring_technique.c)
};

// The spring's anchor at the end of the coming frame and at its start: the stylus plus the offset
// fixed at the press (spring_grab.c), in the world frame, or for the fishing rod in the stylus's
// frame (the rod turns with the pen).
static inline hs_vec3 hs_spring_anchor_at(const hs_spring_system *sys, hs_vec3 stylus, hs_quat rot) {
	return hs_add(stylus, sys->attach_kind == HS_ATTACH_ROD ? hs_quat_rotate(rot, sys->anchor_offset) : sys->anchor_offset);
}
static inline hs_vec3 hs_spring_anchor(const hs_spring_system *sys) { return hs_spring_anchor_at(sys, sys->stylus, sys->rot); }
static inline hs_vec3 hs_spring_anchor_prev(const hs_spring_system *sys) {
	return hs_spring_anchor_at(sys, sys->stylus_prev, sys->rot_prev);
}

// The anchor's velocity over the frame: the stylus's, or for the fishing rod, whose tip swings as
// the pen turns, its tip's chord over the frame.
static inline hs_vec3 hs_spring_anchor_velocity(const hs_spring_system *sys, double dt) {
	if (sys->attach_kind != HS_ATTACH_ROD)
		return sys->stylus_velocity;
	return hs_scale(hs_sub(hs_spring_anchor(sys), hs_spring_anchor_prev(sys)), 1.0 / dt);
}

// The system for a world of up to max_objects objects whose tracker starts at `time` (s); NULL
// when out of memory. `def` is valid (hs_spring_def_valid).
hs_spring_system *hs_spring_system_create(const hs_spring_def *def, int max_objects, double time);
void hs_spring_system_destroy(hs_spring_system *system);

// The stylus points along its own +x axis: the pointing ray (ray casting, §3) and the fishing rod.
#define HS_STYLUS_AXIS hs_v3(1.0, 0.0, 0.0)

#endif
