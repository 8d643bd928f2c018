// world_internal.h — struct hs_world: what every stage of the step reads and writes (as MuJoCo's
// mjData is seen by every engine_*.c), the handles that name its objects, and fault recording.
#ifndef HS_WORLD_INTERNAL_H
#define HS_WORLD_INTERNAL_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "body.h"
#include "box_memo.h"
#include "hand_internal.h"
#include "face_edges.h"
#include "face_tree.h"
#include "handspring.h"
#include "hgrid.h"
#include "hull.h"
#include "near_list.h"
#include "part_cache.h"

// Fields are MODEL (built by hs_world_create / add_*, read-only while stepping), STATE (saved,
// loaded and hashed by state.c's world walk: frame, faults, bodies, hands, spring), CACHE (derived
// from model and state; invalidated or rebuilt after a load) or SCRATCH (per call, never read
// before it is written in the same step). Work counters other than numeric_faults are outside
// the state: they count what was done, not what will happen.
struct hs_world {
	hs_world_def def;   // MODEL
	uint16_t tag;       // MODEL: this world's tag in its handles (never 0)
	bool skip_work;     // MODEL: culls, the grid and sleeping on (hs_bench.h; true unless a benchmark or test says)
	int shape_count;    // MODEL
	hs_shape *shapes;   // MODEL: deep copies, def.max_shapes of them
	hs_face_edges *face_edges; // MODEL: each shape's edges by face (contact.c), built with its copy
	hs_part_cache **part_cache; // MODEL: each shape's parts' box faces and grow reach (part_cache.h), built with its copy
	double *shape_grow_reach; // MODEL: each shape's largest part grow_reach (part_reach.h)
	hs_face_tree *face_trees;  // MODEL: each shape's many-faced parts as normal-cone trees (face_tree.h), built with its copy
	int object_count;   // MODEL
	hs_body *bodies;    // STATE (but shape, mass), def.max_objects of them
	int hand_count;     // MODEL
	hs_hand *hands;     // STATE (but def and caches), def.max_hands of them
	double grasp_limit; // MODEL: hs_grasp_limit(def.grasp_threshold_deg)
	double oppose_cos;  // MODEL: cos(90° − threshold / 2 + 10°), a grasp's opposition cone (grasp.c)
	int hold_frames;    // MODEL: round(tracking_hold_s / dt), the frames a lost hand keeps its grasps (tracking.c)
	long frame;         // STATE
	hs_world_counters counters; // numeric_faults is STATE, the rest are work counters
	long first_fault_frame;     // STATE: frame of the first numeric fault (-1: none)
	int first_fault_object;     // STATE: its object index (-1: none or not an object's)
	struct hs_spring_system *spring; // STATE (its own walk); made by hs_world_create for a spring world (def.kind), NULL otherwise
	// SCRATCH for the floor and support tests, sized at hs_world_add_shape for the largest shape:
	// hs_motion_pose_vertices writes scratch_world, hs_motion_floor_points / support.c write
	// scratch_points, hs_motion_settle builds scratch_hull; each is read only by the caller that
	// just filled it.
	int scratch_capacity;
	hs_vec3 *scratch_world; // posed vertices
	hs_vec2 *scratch_points;
	hs_vec2 *scratch_hull;
	// SCRATCH of a swept check line against a many-faced part (contact.c, swept_line): the faces
	// its sweep reaches, the edges of those faces (ascending) and a mark per edge, sized at
	// hs_world_add_shape for the most faces and edges a shape has
	int pick_faces, pick_edges;
	int *face_pick, *edge_pick;
	uint8_t *edge_mark;
	// OUTPUT of the last step (hs_world_contacts), rebuilt from scratch by every step: not state
	int contact_count, contact_capacity;
	hs_contact *contacts; // this frame's hand contacts, grouped by object
	// SCRATCH of the hand pass (manipulate.c)
	int *queue;          // objects to move along with a moved one (§4.3), max_objects long
	hs_vec3 *moved_from; // support mode: where each object in queue began the frame, max_objects long
	int *candidates;     // objects a hand may touch this frame, in index order
	int candidate_count;
	const int *near;     // the last query's answer (hs_grid_near): `every` or `found`
	int *every;          // 0 .. max_objects - 1, filled when the world is made: a full scan's answer
	int *found;          // a grid query's answer, max_objects long
	// CACHE: broad phase (broadphase.c), objects filed by the floor cell of their centre, each at
	// the level of its bounding radius (hgrid.c)
	hs_hgrid grid;
	// CACHE: the resting objects near a few boxes, listed from the grid (near_list.h)
	hs_near_lists near_lists;
	bool grid_built;    // false until built at the first step
	bool grid_dirty;    // objects were added (or a state loaded) since it was built
	// CACHE: the awake objects in index order, the only ones the step visits when skip_work is on;
	// between steps exactly the objects with !asleep || held || carried (hs_awake_rebuild)
	int awake_count;
	int *awake;
	uint8_t *awake_flag;
	// CACHE: the state hash's object digests (state.c), so that a hash costs in the objects that
	// changed, not in all of them: digest[i] is object i's walk hashed alone, digest_sum their sum.
	// stale lists the objects that may have changed since they were digested (each step's awake
	// list, new objects); all_stale says any of them may have (a load, the spring model's calls).
	uint64_t *digest;
	uint64_t digest_sum;
	int *stale;
	uint8_t *stale_flag;
	int stale_count;
	bool all_stale;
	// CACHE: the world boxes of single-part objects at their last two poses tested for interference
	// (box_memo.h, interfere.h)
	hs_box_memo *box_memo;
	char state_error[160]; // why the last hs_world_load_state refused ("" when it did not)
};

// What the world derived from `part`, a part of `shape`, the world's copy of one of its shapes.
static inline const hs_part_cache *hs_part_cache_of(const hs_world *world, const hs_shape *shape, const hs_part *part) {
	return &world->part_cache[shape - world->shapes][part - shape->parts];
}

// Every live handle has this generation: objects, shapes and hands are never removed, so no slot
// is reused yet. A handle whose generation differs is refused, so a removal can bump it later.
#define HS_GENERATION 1

// Object i may have changed: its digest is computed again at the next hash (state.c).
static inline void hs_digest_stale(hs_world *world, int i) {
	if (!world->stale_flag[i]) {
		world->stale_flag[i] = 1;
		world->stale[world->stale_count++] = i;
	}
}

// Any object may have changed (a load, a spring step, a test writing fields): all are digested again.
static inline void hs_digest_all_stale(hs_world *world) { world->all_stale = true; }

static inline hs_object_id hs_object_handle(const hs_world *world, int i) {
	hs_object_id id = {0, 0, 0};
	if (i >= 0 && i < world->object_count)
		id = (hs_object_id){(uint32_t)i + 1, world->tag, HS_GENERATION};
	return id;
}

static inline hs_hand_id hs_hand_handle(const hs_world *world, int h) {
	hs_hand_id id = {0, 0, 0};
	if (h >= 0 && h < world->hand_count)
		id = (hs_hand_id){(uint32_t)h + 1, world->tag, HS_GENERATION};
	return id;
}

// The object index a handle names in this world; -1 for the null handle, a handle of another
// world, a stale generation or an index out of range.
static inline int hs_object_index(const hs_world *world, hs_object_id id) {
	if (!world || id.world != world->tag || id.generation != HS_GENERATION || id.index1 < 1 ||
	    id.index1 > (uint32_t)world->object_count)
		return -1;
	return (int)id.index1 - 1;
}

static inline int hs_hand_index(const hs_world *world, hs_hand_id id) {
	if (!world || id.world != world->tag || id.generation != HS_GENERATION || id.index1 < 1 ||
	    id.index1 > (uint32_t)world->hand_count)
		return -1;
	return (int)id.index1 - 1;
}

static inline int hs_shape_index(const hs_world *world, hs_shape_id id) {
	if (!world || id.world != world->tag || id.generation != HS_GENERATION || id.index1 < 1 ||
	    id.index1 > (uint32_t)world->shape_count)
		return -1;
	return (int)id.index1 - 1;
}

// *status = value, when the caller asked for it.
static inline void hs_set_status(hs_status *status, hs_status value) {
	if (status)
		*status = value;
}

// Every component finite and within ±limit (the API's checks of coordinates and speeds).
static inline bool hs_within(hs_vec3 v, double limit) {
	return fabs(v.x) <= limit && fabs(v.y) <= limit && fabs(v.z) <= limit;
}

// Numeric trouble (a non-finite value caught and frozen): counts it and remembers the first
// (frame, object); `object` -1 when the fault belongs to no single object.
// Defined in world_base.c, below every stage.
void hs_world_note_fault(hs_world *world, int object);

#endif
