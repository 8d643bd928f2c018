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

// The world's fields in four roles, each a sub-struct, plus the last step's output and the work
// counters. What each holds, and which header owns each type: docs/architecture.md, "The world's
// data".

// MODEL: what the scenario describes, built by hs_world_create and hs_world_add_* and read-only
// while stepping; enters the saved state only as a checksum (state.c).
typedef struct hs_world_model {
	hs_world_def def;
	uint16_t tag;         // this world's tag in its handles (never 0)
	bool skip_work;       // culls, the grid and sleeping on (hs_bench.h; true unless a benchmark or test says)
	int shape_count;
	hs_shape *shapes;     // deep copies, def.max_shapes of them
	hs_part_cache **part_cache; // each shape's parts' box faces and grow reach (part_cache.h), made with its copy
	double *shape_grow_reach;   // each shape's largest part grow_reach (part_reach.h)
	hs_face_edges *face_edges;  // each shape's edges by face (face_edges.h), made with its copy
	hs_face_tree *face_trees;   // each shape's many-faced parts as normal-cone trees (face_tree.h), made with its copy
	int object_count;
	int hand_count;
	double grasp_limit;   // hs_grasp_limit(def.grasp_threshold_deg)
	double oppose_cos;    // cos(90° − threshold / 2 + 10°), a grasp's opposition cone (grasp.c)
	int hold_frames;      // round(tracking_hold_s / dt), the frames a lost hand keeps its grasps (tracking.c)
} hs_world_model;

// STATE: saved, loaded and hashed by state.c's world walk (and spring_state.c's for the spring).
typedef struct hs_world_state {
	long frame;
	long first_fault_frame; // frame of the first numeric fault (-1: none)
	int first_fault_object; // its object index (-1: none or not an object's)
	hs_body *bodies;        // all but shape and mass (the model's), def.max_objects of them
	hs_hand *hands;         // all but def and the caches, def.max_hands of them
	struct hs_spring_system *spring; // made by hs_world_create for a spring world (def.kind), NULL otherwise
} hs_world_state;

// CACHE: derived from model and state; invalidated or rebuilt after a load.
typedef struct hs_world_cache {
	int *every; // 0 .. max_objects - 1, filled when the world is made: a full scan's answer
	// broad phase (broadphase.c): objects filed by the floor cell of their centre, each at the level
	// of its bounding radius (hgrid.c), and the resting objects near a few boxes (near_list.h)
	hs_hgrid grid;
	hs_near_lists near_lists;
	bool grid_built; // false until built at the first step
	bool grid_dirty; // objects were added (or a state loaded) since it was built
	// the awake objects in index order, the only ones the step visits when skip_work is on;
	// between steps exactly the objects with !asleep || held || carried (hs_awake_rebuild)
	int awake_count;
	int *awake;
	uint8_t *awake_flag;
	// the state hash's object digests (state.c), so that a hash costs in the objects that changed,
	// not in all of them: digest[i] is object i's walk hashed alone, digest_sum their sum. stale
	// lists the objects that may have changed since they were digested (each step's awake list, new
	// objects); all_stale says any of them may have (a load, the spring model's calls).
	uint64_t *digest;
	uint64_t digest_sum;
	int *stale;
	uint8_t *stale_flag;
	int stale_count;
	bool all_stale;
	hs_box_memo *box_memo; // single-part objects' world boxes at their last two poses (box_memo.h)
} hs_world_cache;

// SCRATCH: per call, never read before it is written in the same step. Every array is carved from
// one allocation (arena), made when the world is created and again when a shape larger than any
// before is added (world_core.c); a step never allocates.
typedef struct hs_world_scratch {
	void *arena;
	// the hand pass (manipulate.c), max_objects long each
	int *queue;          // objects to move along with a moved one (§4.3)
	hs_vec3 *moved_from; // support mode: where each object in queue began the frame
	int *candidates;     // objects a hand may touch this frame, in index order
	int candidate_count;
	int *found;          // a grid query's answer (hs_grid_near)
	const int *near;     // the last query's answer: cache.every or found
	// the floor and support tests, for the largest shape's vertices (and a closing hull point):
	// hs_motion_pose_vertices writes posed, hs_motion_floor_points / support.c write points,
	// hs_motion_settle builds hull; each is read only by the caller that just filled it
	int vertex_room;
	hs_vec3 *posed;
	hs_vec2 *points;
	hs_vec2 *hull;
	// a swept check line against a many-faced part (contact_swept.c): the faces its sweep reaches,
	// the edges of those faces (ascending) and a mark per edge (all 0 between uses), for the shape
	// with the most faces and edges
	int pick_faces, pick_edges;
	int *face_pick, *edge_pick;
	uint8_t *edge_mark;
	// the spring step, max_objects long each in a spring world (empty in a hand world): each
	// object's position and velocity when the frame began (the numeric guard, step_spring.c), where
	// its path through the frame starts and at which fraction of the frame (spring_collide.c), and
	// the floor layer's projection (spring_collide.c): its objects, their count and a mark per
	// object (count and marks 0 between uses)
	struct {
		hs_vec3 *saved_pos, *saved_vel;
		hs_vec3 *path_pos, *path_vel;
		double *path_t0;
		int *layer;
		int layer_count;
		uint8_t *in_layer;
	} spring;
} hs_world_scratch;

// OUTPUT of the last call, rebuilt by every step (or load): not state.
typedef struct hs_world_output {
	int contact_count, contact_capacity;
	hs_contact *contacts;  // this frame's hand contacts, grouped by object (hs_world_contacts)
	char state_error[160]; // why the last hs_world_load_state refused ("" when it did not)
} hs_world_output;

struct hs_world {
	hs_world_model model;
	hs_world_state state;
	hs_world_cache cache;
	hs_world_scratch scratch;
	hs_world_output out;
	// work counters, outside the state (they count what was done, not what will happen), but for
	// numeric_faults, which is STATE
	hs_world_counters counters;
};

// What the world derived from `part`, a part of `shape`, the world's copy of one of its shapes.
static inline const hs_part_cache *hs_part_cache_of(const hs_world_model *model, const hs_shape *shape, const hs_part *part) {
	return &model->part_cache[shape - model->shapes][part - shape->parts];
}

// Every live handle has this generation: objects, shapes and hands are never removed, so no slot
// is reused yet. A handle whose generation differs is refused, so a removal can bump it later.
#define HS_GENERATION 1

// Object i may have changed: its digest is computed again at the next hash (state.c).
static inline void hs_digest_stale(hs_world_cache *cache, int i) {
	if (!cache->stale_flag[i]) {
		cache->stale_flag[i] = 1;
		cache->stale[cache->stale_count++] = i;
	}
}

// Any object may have changed (a load, a spring step, a test writing fields): all are digested again.
static inline void hs_digest_all_stale(hs_world_cache *cache) { cache->all_stale = true; }

// The handles of object i and hand h (null out of range): the model's tag and the generation.
static inline hs_object_id hs_object_handle(const hs_world_model *model, int i) {
	hs_object_id id = {0, 0, 0};
	if (i >= 0 && i < model->object_count)
		id = (hs_object_id){(uint32_t)i + 1, model->tag, HS_GENERATION};
	return id;
}

static inline hs_hand_id hs_hand_handle(const hs_world_model *model, int h) {
	hs_hand_id id = {0, 0, 0};
	if (h >= 0 && h < model->hand_count)
		id = (hs_hand_id){(uint32_t)h + 1, model->tag, HS_GENERATION};
	return id;
}

// The object index a handle names in this world; -1 for the null handle, a handle of another
// world, a stale generation or an index out of range.
static inline int hs_object_index(const hs_world *world, hs_object_id id) {
	if (!world || id.world != world->model.tag || id.generation != HS_GENERATION || id.index1 < 1 ||
	    id.index1 > (uint32_t)world->model.object_count)
		return -1;
	return (int)id.index1 - 1;
}

static inline int hs_hand_index(const hs_world *world, hs_hand_id id) {
	if (!world || id.world != world->model.tag || id.generation != HS_GENERATION || id.index1 < 1 ||
	    id.index1 > (uint32_t)world->model.hand_count)
		return -1;
	return (int)id.index1 - 1;
}

static inline int hs_shape_index(const hs_world *world, hs_shape_id id) {
	if (!world || id.world != world->model.tag || id.generation != HS_GENERATION || id.index1 < 1 ||
	    id.index1 > (uint32_t)world->model.shape_count)
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
// (frame, object) in the state's fault words; `object` -1 when the fault belongs to no single
// object. Reads the state's frame and writes nothing else of it. Defined in world_base.c, below
// every stage.
void hs_world_note_fault(hs_world_counters *counters, hs_world_state *state, int object);

#endif
