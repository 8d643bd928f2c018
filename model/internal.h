// internal.h — private structures shared by the model's .c files (not installed).
#ifndef HS_INTERNAL_H
#define HS_INTERNAL_H

#include "handspring.h"

#if defined(__GNUC__)
#define HS_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define HS_PRINTF(f, a)
#endif

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
	hs_quat rot_prev; // orientation at t - dt: a released object keeps rot * rot_prev⁻¹ (§4.1)
	int grasped_by;   // hand index + 1 holding it (0: none)
	hs_vec3 grip_pos; // pose in the grasping wrist frame, fixed when the grasp began (§3.2 (2))
	hs_quat grip_rot;
	uint8_t carried;  // moved along with a hand-moved object this frame (§4.3)
} hs_body;

// hand.c — the hand's shape in its wrist frame (depends on the sensors only) and its placement
void hs_hand_local_shape(const hs_hand_def *def, const uint8_t sensors[HS_GLOVE_SENSORS],
                         hs_vec3 points[HS_HAND_POINTS], hs_vec3 lines[HS_HAND_LINES][2]);
void hs_hand_place(const hs_vec3 local_points[HS_HAND_POINTS], const hs_vec3 local_lines[HS_HAND_LINES][2],
                   hs_vec3 wrist_position, hs_quat wrist_orientation, hs_vec3 points[HS_HAND_POINTS],
                   hs_vec3 lines[HS_HAND_LINES][2]);

// A hand: wrist pose, glove sensors and its check points now and one frame ago.
typedef struct hs_hand {
	hs_hand_def def;
	hs_vec3 wrist_pos;
	hs_quat wrist_rot;
	uint8_t sensors[HS_GLOVE_SENSORS];
	hs_vec3 points[HS_HAND_POINTS], prev_points[HS_HAND_POINTS];
	hs_vec3 lines[HS_HAND_LINES][2], prev_lines[HS_HAND_LINES][2];
	hs_vec3 center; // bounding sphere of the check points and lines
	double radius;
	bool placed; // set at least once: before that its previous points are its current ones
	// the shape in the wrist frame for `sensors`: recomputed only when the glove reading changes
	hs_vec3 local_points[HS_HAND_POINTS], local_lines[HS_HAND_LINES][2];
	hs_vec3 local_center; // its bounding sphere in the wrist frame
	double local_radius;
} hs_hand;

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
	int hand_count;
	hs_hand *hands; // def.max_hands of them
	int contact_count, contact_capacity;
	hs_contact *contacts; // this frame's hand contacts, grouped by object
	int *queue;           // objects to move along with a moved one (§4.3), max_objects long
	double grasp_limit;   // hs_grasp_limit(def.grasp_threshold_deg)
	// broad phase (broadphase.c): objects filed by the floor cell of their centre
	double grid_cell;   // m; 0 until built at the first step
	double grid_radius; // m: the largest object's bounding radius
	bool grid_dirty;    // objects were added since it was built
	int grid_buckets;   // a power of two, at least twice max_objects
	int *grid_head;     // bucket → first object (-1: none)
	int *grid_next, *grid_bucket;
	long *grid_ix, *grid_iy;
	int *candidates, *near; // query results, max_objects long each
	int candidate_count;    // this frame's hand pass
	// the awake objects in index order: the only ones the step visits when skip_work is on
	int awake_count;
	int *awake;
	uint8_t *awake_flag;
};

// broadphase.c
void hs_grid_build(hs_world *world);
// Files object i again after it moved.
void hs_grid_update(hs_world *world, int i);
// Objects whose centre may lie within radius + the largest object radius of center, in index
// order (every object when skip_work is off). Returns how many were written to out.
int hs_grid_query(const hs_world *world, hs_vec3 center, double radius, int *out);
// Marks object i awake and puts it on the awake list.
void hs_wake(hs_world *world, int i);
// Drops objects that fell asleep from the awake list.
void hs_awake_compact(hs_world *world);

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
// §4.2 rectification alone: lifts the body out of the floor and counts its floor contacts.
void hs_motion_keep_above_floor(hs_world *world, hs_body *body);
// Eq. 4-5 with the `count` contact points in world->scratch_points on the plane z = height:
// stable → the body stops (true); otherwise it tips by rules (1)-(3) when `may_tip`.
bool hs_motion_settle(hs_world *world, hs_body *body, int count, double height, hs_vec3 gm, bool may_tip);

// support.c — the 'support' stacking mode: objects rest on the faces of objects under them

// After its free step: lifts a body out of the objects it sank into and settles it on them.
void hs_support_step(hs_world *world, int object);
// A hand moved `object`: objects resting on or against it wake up and look again.
void hs_support_wake_neighbours(hs_world *world, int object);

// Cyrus-Beck clip of the segment a → b (in the shape's body frame) against a convex part whose
// faces are pushed out by `grow` (m): where it enters and leaves, and through which faces
// (-1 where that end is already inside).
typedef struct hs_clip {
	double t_in, t_out;
	int face_in, face_out;
	bool hit;
} hs_clip;
hs_clip hs_clip_segment(const hs_shape *shape, const hs_part *part, hs_vec3 a, hs_vec3 b, double grow);

// contact.c — hand-object contacts (1999 paper §3.2: (A) points in faces, (B) lines across edges)

// Appends the contacts of every hand with the object to world->contacts; returns how many.
// `before` is the object's pose one frame ago when it has moved since (NULL: it has not).
int hs_contact_detect(hs_world *world, int object, const hs_body *before);
// The largest n_i · n_j of a grasp: cos(threshold) plus a tolerance (DESIGN.md), once per world.
double hs_grasp_limit(double grasp_threshold_deg);
// Fig. 2: the contact state of a set of contacts (grasp when two normals are >= threshold apart).
hs_contact_state hs_contact_classify(const hs_contact *contacts, int count, double grasp_limit);
// True when two of the contacts (only those of hand index + 1 `hand1`, or all when 0) grasp.
bool hs_contact_grasps(const hs_contact *contacts, int count, uint32_t hand1, double grasp_limit);

// manipulate.c — object motion by the hand (eq. 1-2, grasp, push) and interference among objects (§4.3)

// Eq. 1-2: moves the surface point c of the body toward b (translation T ∥ CG, rotation about G).
void hs_push_at_one_point(hs_body *body, hs_vec3 c, hs_vec3 b);
// One frame of the hands: detect, classify, move touched objects, release the untouched.
void hs_manipulate(hs_world *world);
// §4.3: true when an untouched free object interferes with another and so ignores gravity.
bool hs_object_interferes(hs_world *world, int object);
// True when the object's bounding sphere overlaps the hand's.
bool hs_hand_near(const hs_world *world, const hs_hand *hand, int object);

#endif
