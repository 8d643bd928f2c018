// handspring.h — the public API of handspring.
//
// Two classic models of hands-on manipulation in virtual reality:
//  - the virtual hand of "A Model for Manipulation of Objects with Virtual Hand in 3D
//    Virtual Space" (Syst. Comp. Jpn 30(11), 1999): free motion by Verlet (eq. 3),
//    floor rectification, stability and tipping (§4.2);
//  - the spring model of "Dynamics in Interaction on the Responsive Workbench".
//
// Conventions: SI units (m, s, kg), z up, floor at z = 0, orientation as unit quaternion,
// one fixed time step per world. Worlds are deterministic: the same calls give bit-identical
// states on every run and across compilers (see hs_world_hash).
//
// Ownership: the caller owns what it creates (hs_shape_*, hs_world_create; hs_scenario_load of
// hs_harness.h) and destroys it with the matching *_destroy. A world copies the shapes added to
// it, so the caller's shape may be destroyed right after hs_world_add_shape. Objects are named
// by handles (hs_object_id, hs_shape_id, hs_hand_id) that stay valid for the life of the world
// and name nothing in any other world.
//
// Use: #include <handspring/handspring.h>, link with `pkg-config --cflags --libs handspring`
// (libm; libccd is compiled into the library; add --static for libhandspring.a). Valid C99/C11
// and C++11.
// The models in detail: docs/model.md in the repository (index docs/README.md) — the 18-sensor
// glove layout, check points and lines, contact states, stacking modes `paper` and `support`,
// and every choice made where the papers are silent.
#ifndef HANDSPRING_H
#define HANDSPRING_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "hs_math.h"

#ifdef __cplusplus
extern "C" {
#endif

#define HS_VERSION "0.1.0"

/// Result of a call that can fail.
typedef enum hs_status {
	HS_OK = 0,
	HS_ERR_INVALID_ARGUMENT, ///< a null pointer, an invalid handle, a non-finite or out-of-range number
	HS_ERR_DEGENERATE,       ///< a shape with no volume, a non-planar or non-convex face, an open surface
	HS_ERR_CAPACITY,         ///< more objects or shapes than the world was created for
	HS_ERR_NO_MEMORY,
	HS_ERR_STATE_MISMATCH,   ///< a saved state from another kind of world, layout or version
} hs_status;

/// Human-readable name of a status code.
const char *hs_status_string(hs_status status);

// ---------------------------------------------------------------------------------------------
// Shapes: rigid polyhedra made of one or more convex parts.

/// One convex part of a shape: ranges into the shape's arrays.
typedef struct hs_part {
	int first_vertex, vertex_count;
	int first_face, face_count;
	int first_edge, edge_count;
	hs_vec3 center; ///< m, body frame: centre of the part's bounding sphere
	double radius;  ///< m: bounding-sphere radius
	hs_vec3 box_center, box_half; ///< m, body frame: the box of its vertices (centre, half extents)
} hs_part;

/// A planar convex face: vertex indices (counter-clockwise seen from outside) and its plane.
typedef struct hs_face {
	int first_index, index_count; ///< range into hs_shape.face_vertices
	hs_vec3 normal;               ///< outward unit normal, body frame
	double offset;                ///< plane: dot(normal, x) = offset for points x of the face
	int part;
} hs_face;

/// An edge between two vertices, with the two faces that meet there.
typedef struct hs_edge {
	int a, b;       ///< vertex indices
	int faces[2];   ///< the two adjacent faces
} hs_edge;

typedef enum hs_shape_kind {
	HS_SHAPE_BOX,
	HS_SHAPE_PYRAMID,
	HS_SHAPE_L_BLOCK,
	HS_SHAPE_ELLIPSOID,
	HS_SHAPE_SPHERE, ///< spring model only: an exact sphere (vertices are a fine polyhedron for display)
	HS_SHAPE_POLYHEDRON,
} hs_shape_kind;

/// A rigid shape. Read-only after creation; every coordinate is in the body frame, whose
/// origin is the centre of gravity (uniform density), so an object's position is its G.
typedef struct hs_shape {
	hs_shape_kind kind;
	int part_count;
	hs_part *parts;
	int vertex_count;
	hs_vec3 *vertices; ///< m
	int face_count;
	hs_face *faces;
	int face_vertex_count;
	int *face_vertices;
	int edge_count;
	hs_edge *edges;
	double volume;          ///< m³
	hs_vec3 centroid_shift; ///< m: where G was in the coordinates the shape was given in
	double radius;          ///< m: bounding-sphere radius about G
	double sphere_radius;   ///< m: exact radius for HS_SHAPE_SPHERE, else 0
} hs_shape;

/// Box with full side lengths (m). A cube is a box with equal sides.
hs_shape *hs_shape_box(hs_vec3 size, hs_status *status);
/// Square pyramid: base side (m) and height (m), base on its local z = -h/4 plane (G at origin).
hs_shape *hs_shape_pyramid(double base, double height, hs_status *status);
/// L-block: two boxes. `size` is the bounding box (m); `thickness` the arm thickness (m),
/// in the x–z plane: a foot along x of height thickness and an upright along z of width thickness.
hs_shape *hs_shape_l_block(hs_vec3 size, double thickness, hs_status *status);
/// UV ellipsoid with semi-axes (m): 8 slices, 4 stacks → V = 26, E = 56, F = 32 (1999 paper, Exp. 3).
hs_shape *hs_shape_ellipsoid(hs_vec3 semi_axes, hs_status *status);
/// Sphere of radius r (m) for the spring model's elastic collisions.
hs_shape *hs_shape_sphere(double radius, hs_status *status);
/// A convex polyhedron from vertices (m) and faces (lists of vertex indices, any winding).
/// Rejects empty, open, non-planar, non-convex or zero-volume input with HS_ERR_DEGENERATE and
/// writes the reason into `why` (may be NULL).
hs_shape *hs_shape_polyhedron(const hs_vec3 *vertices, int vertex_count, const int *face_vertices,
                              const int *face_sizes, int face_count, char *why, size_t why_size,
                              hs_status *status);
void hs_shape_destroy(hs_shape *shape);

/// True when the two posed shapes interfere (libccd GJK on every pair of convex parts,
/// after a bounding-sphere rejection). Touching within ~1e-12 m counts as interference.
bool hs_shapes_overlap(const hs_shape *a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b, hs_vec3 pos_b,
                       hs_quat rot_b);
/// Deepest penetration over part pairs (libccd MPR): *depth (m) and *direction, the unit vector
/// along which to move b out of a. False (outputs untouched) when no part pair penetrates.
bool hs_shapes_penetration(const hs_shape *a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b, hs_vec3 pos_b,
                           hs_quat rot_b, double *depth, hs_vec3 *direction);

// ---------------------------------------------------------------------------------------------
// World: fixed dt, owns its shapes and objects, steps them.

typedef struct hs_world hs_world;

/// Handle of an object in a world, as Box2D's b2BodyId: `{0}` is the null handle. A handle of
/// another world (world tag), a stale one (generation) or one out of range is refused by every
/// call: HS_ERR_INVALID_ARGUMENT or a null result. Compare handles by all three fields.
typedef struct hs_object_id {
	uint32_t index1;     ///< index + 1 in creation order (0: null)
	uint16_t world;      ///< tag of the world that made it (1..65535, assigned at hs_world_create)
	uint16_t generation; ///< bumped when a slot is reused (objects are never removed yet: always 1)
} hs_object_id;

/// Handle of a shape registered in a world; the same rules as hs_object_id.
typedef struct hs_shape_id {
	uint32_t index1;
	uint16_t world;
	uint16_t generation;
} hs_shape_id;

/// How objects touching objects behave (1999 paper §4.3; docs/model.md §6).
typedef enum hs_stacking {
	HS_STACKING_PAPER,   ///< objects interfering with a moved object move with it; untouched interfering objects ignore gravity
	HS_STACKING_SUPPORT, ///< a resting object is supported by the faces under it (rectify and stability as on the floor)
} hs_stacking;

/// Limits checked at the API boundary, so nothing inside a step can overflow.
#define HS_MIN_DT 1e-6        ///< s
#define HS_MAX_DT 1.0         ///< s
#define HS_MAX_GRAVITY 1e4    ///< m/s², per component
#define HS_MAX_COORDINATE 1e6 ///< m, per component of positions and wrist poses
#define HS_MAX_SPEED 1e6      ///< m/s and rad/s, per component of initial velocities
#define HS_MAX_GLOVE_DEADBAND 32 ///< sensor units (16 deg)
#define HS_MAX_RELEASE_WINDOW 0.5 ///< s, hs_world_def.release_window_s
#define HS_MAX_RELEASE_FRAMES 64  ///< frames a release's velocity is taken over at most: a longer window (0.5 s above 128 frames/s) is clamped to this many frames
#define HS_MAX_TRACKING_HOLD 10.0 ///< s, hs_world_def.tracking_hold_s

/// How a grasp's release velocity is estimated from the wrist's last frames (docs/model.md §4
/// "Release"; the 1999 paper's eq. 3 continues from the object's last two positions instead).
typedef enum hs_release_fit {
	HS_RELEASE_FIT_MEAN,      ///< the mean motion over the window: where the wrist carries the object at the release less where it carried it a window before, over that time
	HS_RELEASE_FIT_QUADRATIC, ///< the slope at the release of the least-squares quadratic through where the wrist carried the object at each frame of the window; the mean for a window of one frame (two points)
	HS_RELEASE_FIT_OBJECT,    ///< the 1999 paper's letter: eq. 3 goes on from the object's last two held positions and its last turn (the window is not used; at 12 frames/s a throw lands about a frame's swing short)
} hs_release_fit;

// The spring model's definition, part of a spring world's (its section below says what it runs).
/// How the per-frame spring-damper equation is integrated.
typedef enum hs_integrator {
	HS_INTEGRATOR_EXACT = 0,             ///< closed-form critically damped solution: exact for any dt (default)
	HS_INTEGRATOR_IMPLICIT_EULER,        ///< backward Euler: unconditionally stable, first order
	HS_INTEGRATOR_SEMI_IMPLICIT_EULER,   ///< symplectic Euler: benchmark only, unstable for large ω dt
	HS_INTEGRATOR_RK4,                   ///< classic Runge–Kutta: benchmark only, unstable for ω dt ≳ 2.8
} hs_integrator;

/// Optional walls: vertical planes bounding the table top to [x_min, x_max] × [y_min, y_max] (m).
typedef struct hs_spring_walls {
	bool enabled; ///< default false
	double x_min, x_max, y_min, y_max;
} hs_spring_walls;

typedef struct hs_spring_def {
	hs_integrator integrator;  ///< default HS_INTEGRATOR_EXACT
	double friction_static;    ///< μ: no sliding while the horizontal force ≤ μ N (default 0.5)
	double friction_sliding;   ///< μ while sliding, ≤ friction_static (default 0.5: the paper's constant μ)
	double restitution;        ///< e in [0, 1] for object–object collisions (default 1: elastic)
	hs_spring_walls walls;     ///< default disabled
	/// Rest length x0(m) = rest_length_ref · (m / rest_mass_ref)^rest_exponent, clamped to
	/// [rest_length_min, rest_length_max] (m). Defaults 0.10 m at 1 kg, exponent 1/3, [0.01, 1.0] m:
	/// x0 grows like the size of an object of fixed density (1 g → 1 cm, 1000 kg → 1 m).
	double rest_length_ref;
	double rest_mass_ref;      ///< kg (default 1)
	double rest_exponent;      ///< default 1/3
	double rest_length_min, rest_length_max;
	double tracker_rate;       ///< Hz: tracker samples per second (default 50, §5.1)
	int tracker_window;        ///< samples in the velocity fit, 3..HS_TRACKER_CAPACITY (default 9)
	double rest_speed;         ///< m/s: a moving hand comes to rest below this speed (default 0.10)
	double motion_speed;       ///< m/s: a resting hand starts moving above this speed (default 0.20)
	double catch_radius;       ///< m: a press this close to a flying object's surface catches it, and so does a button held down with nothing attached when one arrives this close (default 0.05)
	double grab_range;         ///< m: a press attaches the candidate only this close to its surface (default 0.5)
	double select_range;       ///< m: length of the selection rays ('I want this one' and the stylus's pointing ray), and how far the fishing rod reaches (default 2.0)
	double select_speed;       ///< m/s: the hand's path over the tracker's fit window selects along its heading from this speed (default 0.05)
	// The Responsive Workbench paper's letter, one rule at a time (docs/model.md §11); false by default.
	bool pen_tip_spring;       ///< true: a press hangs the spring from the pen tip itself, at its length then (§4.4 as written; the default's anchor puts the spring at rest, so nothing jerks at the press)
	bool paper_collisions;     ///< true: objects touching objects are only impacts ([W] §4.5: "equivalent with geometric intersection"): no resting-contact forces, every impact bounces with the pair's restitution (no 5 cm/s threshold)
	/// The manipulation techniques beyond the spring (hs_world_spring_set_technique: slave, stick,
	/// cross-plane, cross-surface, the magnet gesture, the release back home) and massless objects
	/// (density 0); docs/techniques.md. Their settings and each hold's grab then belong to the
	/// world's state (saved, loaded, hashed); off (default false), a world saves and hashes as without them.
	bool techniques;
} hs_spring_def;

/// Which model a world runs, fixed when it is created: the 1999 paper's hands (hs_world_add_hand,
/// hs_world_set_hand, ...) or the Responsive Workbench's spring and stylus (hs_world_set_stylus,
/// ...; the spring model's section below).
typedef enum hs_world_kind {
	HS_WORLD_HAND = 0,   ///< the hand model (default)
	HS_WORLD_SPRING = 1, ///< the spring model, as hs_world_def.spring defines it
} hs_world_kind;

typedef struct hs_world_def {
	double dt;                  ///< s, fixed frame time (default 1/60)
	hs_vec3 gravity;            ///< m/s² (default (0, 0, -9.81))
	double floor_tolerance;     ///< m: vertices this close to z = 0 are floor contacts (default 1e-6)
	int max_objects;            ///< capacity, allocated at creation (default 64)
	int max_shapes;             ///< capacity, allocated at creation (default 16)
	int max_hands;              ///< capacity, allocated at creation (default 2)
	hs_stacking stacking;       ///< default HS_STACKING_PAPER
	double grasp_threshold_deg; ///< deg: two contact normals this far apart make a grasp (default 90)
	bool grasp_any_contacts;    ///< false (default): a grasp's two contacts lie on different fingers or hands; true: any two (the 1999 paper's rule)
	bool paper_contacts;        ///< false (default): swept detection, rectification and contact hysteresis (docs/model.md §3); true: the 1999 paper's letter (parts tested where they end the frame; a part inside drives C to where it is)
	double grasp_release_mm;    ///< mm: a held object stays grasped while its holder's fingers grasp it grown by this much (default 5; docs/model.md §3)
	double grasp_open_mm;       ///< mm: the grasp ends when the holding fingertips spread or reach out this much more than when it began (default 8)
	int glove_deadband;         ///< sensor units, 0..HS_MAX_GLOVE_DEADBAND: a glove sensor moves the hand only once its reading leaves ±this around the value last used, which then follows it at this distance (default 3; 0: every raw reading, the 1999 paper's letter; docs/model.md §1)
	double release_window_s;    ///< s, 0..HS_MAX_RELEASE_WINDOW: a released grasp flies with the hand's velocity over its last round(this / dt) frames, at least 1, at most HS_MAX_RELEASE_FRAMES (default 0.05: 1 frame at 12 frames/s, 3 at 60, 6 at 120; docs/model.md §4 "Release")
	hs_release_fit release_fit; ///< how that velocity is taken from those frames (default HS_RELEASE_FIT_MEAN); the spin is the wrist's mean turn over them either way
	bool grasp_opposed;         ///< true (default): a new grasp's two contacts must press toward each other across the object, each within 90° − threshold / 2 + 10° of the line between them (a flat hand on a top and a side face is no grasp); false: the normals' angle alone (the 1999 paper's letter; docs/model.md §3 "Grasp start")
	double grasp_close_mm;      ///< mm, 0..1000: a new grasp's two fingers (of one hand) must have closed by this much: their tips this much nearer than when the hand was first placed, came back from a tracking loss or last let go; 0: no closing needed (the 1999 paper's letter). Default 10
	bool paper_landing;         ///< false (default): a flying object that reaches the floor lands where its path through the frame met it, then is lifted out; true: lifted straight up from where the frame left it (the 1999 paper's §4.2 letter: up to the horizontal speed × dt further on; docs/model.md §5)
	double tracking_hold_s;     ///< s, 0..HS_MAX_TRACKING_HOLD: a hand whose tracking is lost (hs_world_set_hand_tracked) keeps its grasps this long, then lets them go in place and touches nothing until tracked again (default 0.2)
	// The 1999 paper's letter, one rule at a time (docs/model.md §11 "The papers' letter"); each false by default.
	bool paper_grasp_end;       ///< true: a grasp goes on while this frame's contacts make a grasp ([H] §3.2: "successive instances in which grasping is recognized"): no opening or margin rule, no release set-aside
	bool paper_floor_push;      ///< true: a push on an object on the floor moves it by eq. 1-2 and the floor lifts it out (§4.2), with no sliding, yaw or tipping about a floor edge
	bool paper_push_end;        ///< true: a push that ends goes on by eq. 3 from the object's last two positions: no stop on the floor, no speed over the time after the touch, a finger that drives nothing stops it, no object outrunning a finger
	bool paper_tipping;         ///< true: a turn about one floor vertex that lands a second loses its motion there (§4.2 rule (1)) instead of turning on about the new edge
	bool paper_carry;           ///< true: in paper stacking what interferes with a moved object is translated with it (§4.3), not turned with it
	hs_world_kind kind;         ///< the model the world runs, for its whole life (default HS_WORLD_HAND)
	hs_spring_def spring;       ///< the spring model's definition, read when kind is HS_WORLD_SPRING (default hs_default_spring_def())
} hs_world_def;

hs_world_def hs_default_world_def(void);

/// The papers' letter as a whole (docs/model.md §11 "The papers' letter").
typedef enum hs_letter {
	HS_LETTER_NONE = 0,      ///< the defaults: every realistic rule on
	HS_LETTER_HAND1999 = 1,  ///< the 1999 virtual-hand paper as written: every departure of the hand model off
	HS_LETTER_WORKBENCH = 2, ///< the Responsive Workbench paper as written: every departure of the spring model off
} hs_letter;

/// Sets in *def every option the letter names to that paper's letter (HS_LETTER_NONE: to the
/// defaults), leaving every other field as it is. HS_ERR_INVALID_ARGUMENT for an unknown letter.
hs_status hs_world_def_letter(hs_world_def *def, hs_letter letter);

/// Creates a world; NULL with *status set on an invalid definition (dt outside [HS_MIN_DT, HS_MAX_DT],
/// gravity beyond HS_MAX_GRAVITY, non-finite numbers, capacities out of range, release_window_s
/// outside [0, HS_MAX_RELEASE_WINDOW], an unknown release_fit, an unknown kind, or for a spring
/// world an invalid hs_world_def.spring) or out of memory.
hs_world *hs_world_create(const hs_world_def *def, hs_status *status);
void hs_world_destroy(hs_world *world);

/// Copies `shape` into the world. Returns the null handle on error.
hs_shape_id hs_world_add_shape(hs_world *world, const hs_shape *shape, hs_status *status);
/// The world's copy of a registered shape (NULL for an invalid handle).
const hs_shape *hs_world_shape(const hs_world *world, hs_shape_id id);
/// The handle of the i-th shape (0 ≤ i < shapes added), in the order added; null otherwise.
hs_shape_id hs_world_shape_at(const hs_world *world, int i);

typedef struct hs_object_def {
	hs_shape_id shape;
	hs_vec3 position;         ///< m: centre of gravity G
	hs_quat orientation;      ///< unit quaternion, body → world
	hs_vec3 velocity;         ///< m/s at t = 0
	hs_vec3 angular_velocity; ///< rad/s at t = 0, world frame
	double density;           ///< kg/m³ (spring model: mass = density × volume; default 500); 0 (massless, kinematic: docs/techniques.md) only in a spring world with hs_spring_def.techniques
	/// Spring model: e in [0, 1] of this object's collisions with objects; a pair takes the smaller
	/// of its two objects' e (the less elastic decides). Negative (default −1): the model's
	/// hs_spring_def.restitution.
	double restitution;
} hs_object_def;

hs_object_def hs_default_object_def(void);

/// Adds an object. Returns the null handle and sets *status on error (invalid shape handle,
/// non-finite numbers or beyond HS_MAX_COORDINATE / HS_MAX_SPEED, a non-unit orientation, capacity).
hs_object_id hs_world_add_object(hs_world *world, const hs_object_def *def, hs_status *status);

/// Hand contact state of an object (1999 paper, Fig. 12).
typedef enum hs_contact_state {
	HS_CONTACT_NONE = 0,     ///< no contact
	HS_CONTACT_PUSH_ONE = 1, ///< push at one point
	HS_CONTACT_GRASP = 2,    ///< grasp
	HS_CONTACT_PUSH_MANY = 3 ///< push at several points
} hs_contact_state;

/// The state of one object after the last step.
typedef struct hs_object_state {
	hs_vec3 position;    ///< m: centre of gravity
	hs_quat orientation;
	hs_vec3 velocity;    ///< m/s: (P(t) - P(t - dt)) / dt
	hs_contact_state contact;
	int floor_contacts;  ///< vertices on the floor (within floor_tolerance)
	bool resting;        ///< stable on the floor or a support and asleep
} hs_object_state;

/// State of an object; HS_ERR_INVALID_ARGUMENT for an invalid handle.
hs_status hs_world_object_state(const hs_world *world, hs_object_id id, hs_object_state *out);
int hs_world_object_count(const hs_world *world);
/// The handle of the i-th object (0 ≤ i < count), in creation order.
hs_object_id hs_world_object_at(const hs_world *world, int i);
/// The shape an object was made of (its faces and vertices: hs_world_shape); the null handle for
/// an invalid object handle.
hs_shape_id hs_world_object_shape(const hs_world *world, hs_object_id id);

/// Advances the world by one frame of dt. Never allocates.
hs_status hs_world_step(hs_world *world);
/// Frames stepped so far; time is frame × dt.
long hs_world_frame(const hs_world *world);
double hs_world_time(const hs_world *world);
double hs_world_dt(const hs_world *world);

/// 64-bit hash of the whole state: the same words hs_world_save_state writes after its header
/// (every pose, previous pose, velocity, contact and grasp field of every object, every hand's
/// wrist and sensors now and at the last step's end, the frame counter, the numeric faults, the
/// spring and tracker), each mixed in as one 64-bit word (multiply-xorshift in four lanes), so it
/// is the same on every machine. Each object's words are hashed apart, with its index, and the
/// objects enter as the sum of those digests; the world keeps them and hashes again only the
/// objects changed since the last hash (awake, touched by a hand, added, loaded), so in the hand
/// model a hash every frame costs in what moves, not in the objects at rest (the spring model
/// hashes every object again after each step). Keeping them is why this call writes inside the
/// world: like every call on a world, do not make it concurrently with another on the same world.
/// Two worlds built from the same definitions with equal hashes continue identically (up to
/// 64-bit collisions); a change of any single state field changes it.
/// Not hashed: the definitions (they do not change while stepping), the work counters, caches.
uint64_t hs_world_hash(const hs_world *world);

// ---------------------------------------------------------------------------------------------
// State: everything a step changes, as one block (MuJoCo's mjData, Box2D's snapshots). What the
// world was built from (definitions, shapes, masses, hand and spring definitions) is not in it:
// a state loads only into a world built from the same definitions (same calls, same order).
//
// Layout: a sequence of 64-bit little-endian words (doubles by their IEEE bits, integers
// sign-extended), so the bytes are the same on every machine whatever its struct padding.
// A 9-word header: magic "HSSTATE1", format version, library version (a hash of HS_VERSION),
// kind (0 hand world, 1 spring world), object count, hand count, shape count, contact capacity,
// and a checksum of the definitions (dt, gravity, floor tolerance, stacking, grasp threshold and rule,
// every shape's counts, vertices and volume, every object's shape and mass, every hand
// definition; not max_objects, max_shapes or the skipping of work (hs_bench.h), which change no result). Then the
// world: frame, numeric faults, first fault frame and object; per object 39 words (pose, previous
// pose, rot_prev, spin, velocity, contact state, floor contacts, grounded / asleep / held /
// carried, grasped_by, grip pose, grip spread and reach, grip fingers, released_by); per hand 67 words and 7 a kept older wrist pose (wrist pose and 18 sensors as last set and as
// at the end of the last step, placed, tracked and frames lost, the ten fingertip pairs' closing references: the check points and lines now and a frame ago are their
// kinematics, rebuilt bit for bit after a load; which check points and lines touch, which started inside); then the spring system and its tracker when on.
// The seed scene (10 cubes, no hand) saves 403 words, 3224 bytes.
// Not in it: caches rebuilt after a load (check points and lines, the hand's shape in its wrist
// frame, bounding spheres, the broad-phase grid, the awake list), the last step's contact list
// (hs_world_contacts is empty after a load until the next step) and the work counters.

/// Bytes hs_world_save_state writes for this world (fixed once its objects and hands are added,
/// and springs enabled); 0 for a NULL world.
size_t hs_world_state_size(const hs_world *world);
/// Writes the state into buffer (size >= hs_world_state_size). Portable: the same bytes on every
/// machine for the same state. HS_ERR_INVALID_ARGUMENT for a NULL world or buffer, a short size.
hs_status hs_world_save_state(const hs_world *world, void *buffer, size_t size);
/// Loads a state saved from a world built from the same definitions; the world then continues
/// bit-identically. The whole buffer is checked before anything is written: a buffer from another
/// kind of world, another layout or another version, of the wrong size, or holding a non-finite
/// number or an out-of-range value is refused with HS_ERR_STATE_MISMATCH, the world untouched;
/// hs_world_state_error says why. HS_ERR_INVALID_ARGUMENT for a NULL world or buffer. Never
/// allocates.
hs_status hs_world_load_state(hs_world *world, const void *buffer, size_t size);
/// Why the last hs_world_load_state on this world was refused ("" when it was not).
const char *hs_world_state_error(const hs_world *world);

/// Counters of work done, for benchmarks and tests of what skipping saves.
typedef struct hs_world_counters {
	long object_steps;    ///< objects moved by free motion or tipping
	long sleeping_skips;  ///< object-frames skipped because the object was asleep
	long floor_checks;    ///< object-frames whose vertices were tested against the floor
	long numeric_faults;  ///< non-finite values caught (the object is frozen, never propagated)
	long hand_tests;      ///< object-frames tested against a hand after the bounding-volume check
	long dropped_contacts;///< contacts beyond the world's capacity (never expected; counted, not lost silently)
} hs_world_counters;
hs_world_counters hs_world_get_counters(const hs_world *world);
/// The first numeric fault of the world (counters.numeric_faults): its frame (-1 when none) and
/// the object frozen there (the null handle when none or when the fault was not one object's),
/// so a runner can name it in one line. Part of the saved state. HS_ERR_INVALID_ARGUMENT for a
/// NULL world; frame and object may be NULL.
hs_status hs_world_first_fault(const hs_world *world, long *frame, hs_object_id *object);

// ---------------------------------------------------------------------------------------------
// Hands (1999 paper §3, §5.1): wrist pose from the tracker plus 18 glove sensors.

#define HS_GLOVE_SENSORS 18 ///< 8 bit each, 0.5 deg per unit
#define HS_HAND_POINTS 20   ///< check points: 4 per finger
#define HS_HAND_LINES 60    ///< check lines: 4 long edges of each of the 15 finger segments

/// Glove sensor layout (docs/model.md §1). Flexion, abduction, roll and arch: angle = v × 0.5 deg.
/// Wrist pitch and yaw are signed: angle = (v − 128) × 0.5 deg.
enum hs_glove_sensor {
	HS_SENSOR_THUMB_ROLL = 0,
	HS_SENSOR_THUMB_MCP,
	HS_SENSOR_THUMB_IP,
	HS_SENSOR_THUMB_ABDUCTION,
	HS_SENSOR_INDEX_MCP,
	HS_SENSOR_INDEX_PIP,
	HS_SENSOR_MIDDLE_MCP,
	HS_SENSOR_MIDDLE_PIP,
	HS_SENSOR_RING_MCP,
	HS_SENSOR_RING_PIP,
	HS_SENSOR_LITTLE_MCP,
	HS_SENSOR_LITTLE_PIP,
	HS_SENSOR_INDEX_MIDDLE_ABDUCTION,
	HS_SENSOR_MIDDLE_RING_ABDUCTION,
	HS_SENSOR_RING_LITTLE_ABDUCTION,
	HS_SENSOR_PALM_ARCH,
	HS_SENSOR_WRIST_PITCH,
	HS_SENSOR_WRIST_YAW,
};

/// Fingers 0 thumb, 1 index, 2 middle, 3 ring, 4 little. Check point i = finger × 4 + joint with
/// joint 0 MCP (thumb: CMC), 1 PIP (thumb: MCP), 2 DIP (thumb: IP), 3 tip. Check line
/// j = (finger × 3 + segment) × 4 + edge, segment s joining check points s and s + 1.
typedef struct hs_hand_def {
	bool left;                   ///< mirror image of the right hand (thumb on −y of the wrist frame)
	double finger_radius;        ///< m: check lines lie this far from the finger axis
	double segment_length[5][3]; ///< m: per finger, its three segments from the base outward
	hs_vec3 base[5];             ///< m: MCP (thumb: CMC) in the wrist frame of a right hand
	double dip_per_pip;          ///< DIP = dip_per_pip × PIP (not sensed; default 2/3)
	/// The hand is driven by tracked joint positions (hs_world_set_hand_joints), not by a glove:
	/// its check points are the joints it is given (docs/model.md §1 "Joint-driven hands").
	/// Default false. Fixed when the hand is added.
	bool joint_driven;
} hs_hand_def;

/// Adult defaults. Wrist frame: x toward the fingertips, y toward the thumb (right hand),
/// z out of the back of the hand (the palm faces −z).
hs_hand_def hs_default_hand_def(void);

/// Joint angles in radians.
typedef struct hs_hand_joints {
	double thumb_roll, thumb_mcp, thumb_ip, thumb_abduction;
	double mcp[4], pip[4], dip[4]; ///< index, middle, ring, little
	double abduction[3];           ///< index–middle, middle–ring, ring–little
	double palm_arch, wrist_pitch, wrist_yaw;
} hs_hand_joints;

/// Zero angles when def or sensors is NULL.
hs_hand_joints hs_hand_joints_from_sensors(const hs_hand_def *def, const uint8_t sensors[HS_GLOVE_SENSORS]);
/// Angles (rad) → sensor values, rounded to the nearest unit and clamped to 0..255.
void hs_hand_sensors_from_angles(const hs_hand_joints *joints, uint8_t sensors[HS_GLOVE_SENSORS]);

/// Forward kinematics: the 20 check points and the 60 check lines (two endpoints each), world frame.
/// Writes nothing when def or sensors is NULL; points or lines may be NULL.
void hs_hand_kinematics(const hs_hand_def *def, hs_vec3 wrist_position, hs_quat wrist_orientation,
                        const uint8_t sensors[HS_GLOVE_SENSORS], hs_vec3 points[HS_HAND_POINTS],
                        hs_vec3 lines[HS_HAND_LINES][2]);

typedef enum hs_posture {
	HS_POSTURE_OPEN,  ///< flat hand
	HS_POSTURE_FIST,  ///< amount 0..1 from open to a full fist
	HS_POSTURE_PINCH, ///< amount 0..1: thumb tip toward index tip
	HS_POSTURE_POINT, ///< amount 0..1: all but the index finger curled
	HS_POSTURE_GRASP, ///< amount = width (m) of the object held between thumb and fingertips
} hs_posture;

/// Sensor values of a named posture. HS_ERR_INVALID_ARGUMENT for an amount out of range.
hs_status hs_hand_posture(const hs_hand_def *def, hs_posture posture, double amount,
                          uint8_t sensors[HS_GLOVE_SENSORS]);

/// The grip of a posture in the wrist frame: the midpoint between the thumb tip and the mean of
/// the index and middle fingertips, and the unit axis from the thumb tip toward them.
void hs_hand_grip(const hs_hand_def *def, const uint8_t sensors[HS_GLOVE_SENSORS], hs_vec3 *center,
                  hs_vec3 *axis);

/// Handle of a hand in a world; the same rules as hs_object_id.
typedef struct hs_hand_id {
	uint32_t index1; ///< index + 1; 0 is the null handle
	uint16_t world;
	uint16_t generation;
} hs_hand_id;

/// Adds a hand to the world (open, at the origin, touching nothing until it is set).
hs_hand_id hs_world_add_hand(hs_world *world, const hs_hand_def *def, hs_status *status);
/// The handle of the i-th hand (0 ≤ i < hands added), in the order added; null otherwise.
hs_hand_id hs_world_hand_at(const hs_world *world, int i);
/// Sets a hand's wrist pose and glove reading (its 18 sensors) for the next step (HS_ERR_INVALID_ARGUMENT for an
/// invalid handle, a joint-driven hand, a NULL reading, a non-unit orientation or a position beyond HS_MAX_COORDINATE).
/// After the first call each sensor passes the world's glove_deadband: the hand keeps the value it
/// used until the reading leaves ±glove_deadband around it, then follows the reading at that distance.
hs_status hs_world_set_hand(hs_world *world, hs_hand_id hand, hs_vec3 wrist_position,
                            hs_quat wrist_orientation, const uint8_t reading[HS_GLOVE_SENSORS]);
/// Sets a joint-driven hand's (hs_hand_def.joint_driven) wrist pose and its 20 check points, in
/// the wrist frame, for the next step: the hand's shape is the points as given (a left hand's as
/// they are, not mirrored), no glove, no deadband; each finger segment's four check lines lie
/// finger_radius around the line between its two check points (docs/model.md §1 "Joint-driven
/// hands"). HS_ERR_INVALID_ARGUMENT for an invalid handle, a hand that is not joint-driven (and
/// hs_world_set_hand for one that is), NULL points, a non-unit orientation, or a position or a
/// point beyond HS_MAX_COORDINATE (or not finite).
hs_status hs_world_set_hand_joints(hs_world *world, hs_hand_id hand, hs_vec3 wrist_position,
                                   hs_quat wrist_orientation, const hs_vec3 points[HS_HAND_POINTS]);
/// Says whether the hand's tracker sees the hand for the next step (hands start tracked). An
/// untracked hand should be set (hs_world_set_hand) to the last pose it was seen in: it keeps its
/// grasps for tracking_hold_s, then lets them go where they are (no velocity) and touches nothing
/// until it is tracked again. The first tracked step after a loss moves nothing by the jump (the
/// hand is placed anew, as at its first pose), and a grasp the hand still kept is let go in place
/// when the hand came back further than 5 cm plus 0.5 m/s times the time since it was last seen
/// (docs/model.md §3 "Tracking loss").
hs_status hs_world_set_hand_tracked(hs_world *world, hs_hand_id hand, bool tracked);
/// The hand's check points after the last step.
hs_status hs_world_hand_points(const hs_world *world, hs_hand_id hand, hs_vec3 points[HS_HAND_POINTS]);
/// The hand's check points after the last step, rectified (1999 paper §3.2: "the joint angles of
/// the finger are rectified so that the contacting point is moved to the object surface"): a check
/// point that touched an object in the last step and lies inside it is moved to the nearest face
/// of the convex part it is in (the object's pose after the step); every other point is as
/// hs_world_hand_points gives it. `touching` (may be NULL) gets bit i set for check point i in
/// contact in the last step. The glove reading itself is never changed: the model keeps only
/// which parts touch, and judges a touching part by its motion since the last frame.
hs_status hs_world_hand_rectified_points(const hs_world *world, hs_hand_id hand, hs_vec3 points[HS_HAND_POINTS],
                                         uint32_t *touching);

/// One contact between a finger part and an object, found in the last step.
typedef struct hs_contact {
	hs_object_id object;
	hs_hand_id hand;
	int part;       ///< check point index (face contact) or check line index (edge contact)
	bool edge;      ///< true: check line against an edge (B); false: check point in a face (A)
	int feature;    ///< the face or edge index of the object's shape
	hs_vec3 point;  ///< m: the contact point C on the object's surface
	hs_vec3 normal; ///< face normal, or the edge's pseudo-normal (from G to the edge), world frame
	/// m: where the finger part drives C this frame (B of eq. 1-2), world frame: the part itself
	/// when it reached the surface this frame (or passed through it: swept detection); for a part
	/// already in contact last frame that has sunk in, C plus the part's motion relative to the
	/// object since then (§3.2 rectification: the finger is drawn back to the surface, so how deep
	/// it sank never moves the object). docs/model.md §3.
	hs_vec3 finger;
	/// When in the frame the part reached the surface (0..1 along its path through the frame, swept
	/// detection; 0 for a part that touched already and for a check line found across the object).
	double t;
} hs_contact;

/// Copies up to `max` contacts of the last step into `out`; returns how many there were.
int hs_world_contacts(const hs_world *world, hs_contact *out, int max);

// ---------------------------------------------------------------------------------------------
// Spring model (Responsive Workbench): a tracked stylus moves objects through a critically damped
// spring (Koutek & Post, §4). A world runs it when made with hs_world_def.kind HS_WORLD_SPRING
// (hs_world_create allocates it for up to max_objects, from hs_world_def.spring); its
// hs_world_step advances every object by this model instead of the 1999 free motion.
//
// Per frame: hs_world_set_stylus gives the stylus pose and button at the END of the coming frame
// (the stylus moves linearly from its previous pose during the frame), then hs_world_step. Button
// edges take effect at the end of the frame: a press attaches the spring (direct pick, catch, the
// selection candidate — 'I want this one' along the hand's path, or, the hand still, the first
// object beyond grab_range on the stylus's pointing ray, its +x axis — and beyond grab_range by
// the fishing rod, its anchor fixed in the stylus's frame) at its rest length — its anchor is the stylus plus an offset
// fixed at the press (hs_spring_state.anchor), so nothing moves until the pen does — and a release
// drops (hand at rest) or throws (hand moving; a velocity estimate against the hand's recent path,
// the fit's overshoot at a stop, counts as none).
// Objects keep their orientation (no torque, §4.2); spheres collide as exact spheres, boxes as
// oriented boxes, every other shape through libccd; touching objects rest on each other (contact
// forces with static and sliding friction, docs/model.md §8), and collide in the order of time
// with the smaller of the two objects' restitutions. In spring worlds hs_object_state.contact is
// HS_CONTACT_GRASP for the object on the spring, HS_CONTACT_NONE otherwise, and `resting` means
// lying still on the floor or held still by its contacts.
//
// Noise is input, not physics: the model holds no random generator. The tracker records exactly
// the stylus poses it is given, so a caller that simulates a real tracker (the Fastrak's 0.03 inch
// and 0.15° static accuracy, §5.1) adds that noise to the poses it passes to hs_world_set_stylus;
// the spring's anchor then sees it too, as the paper computes the spring from the tracker data.

hs_spring_def hs_default_spring_def(void);

/// True when the world runs the spring model.
bool hs_world_springs_enabled(const hs_world *world);
/// The spring model's definition (walls, friction, ...) the world was made with; HS_ERR_INVALID_ARGUMENT when
/// the world does not run it or out is NULL.
hs_status hs_world_spring_def(const hs_world *world, hs_spring_def *out);

/// The stylus pose (m, unit quaternion) and button at the end of the next frame.
hs_status hs_world_set_stylus(hs_world *world, hs_vec3 position, hs_quat orientation, bool button);

/// Attaches the spring to an object now, whatever the button (scripts and tests); a later button
/// release detaches it as usual. Unlike a button press it anchors the spring at the stylus itself
/// (the literal spring: a stylus away from x0 pulls or pushes at once). A press is neutral: the
/// spring's anchor is the stylus plus an offset fixed at the press so that |G - anchor| = x0 (x0
/// straight above G when the stylus is inside the object, else on the line from G toward the
/// stylus); nothing moves at the press and the force grows only as the pen moves.
hs_status hs_world_spring_attach(hs_world *world, hs_object_id id);
/// Detaches the spring now as a drop: the object keeps its own velocity.
hs_status hs_world_spring_detach(hs_world *world);

/// How the spring got its object.
typedef enum hs_attach_kind {
	HS_ATTACH_NONE = 0,
	HS_ATTACH_PICK,   ///< the stylus was inside the object (direct picking)
	HS_ATTACH_CATCH,  ///< the object was flying, within catch_radius of the stylus or around it
	HS_ATTACH_SELECT, ///< the 'I want this one' candidate, within grab_range
	HS_ATTACH_API,    ///< hs_world_spring_attach
	HS_ATTACH_ROD,    ///< the candidate beyond grab_range, within select_range: the 'fishing rod' (§4.4), the anchor fixed in the stylus's frame
	HS_ATTACH_MAGNET, ///< the magnet gesture (§3; hs_technique_def.magnet): brought to the stylus from afar
} hs_attach_kind;

/// How a held object follows the stylus (§2.2, §3; docs/techniques.md). Set with
/// hs_world_spring_set_technique; a hold keeps the technique it began with.
typedef enum hs_technique {
	HS_TECHNIQUE_SPRING = 0,    ///< the spring of §4 (default)
	HS_TECHNIQUE_SLAVE,         ///< no spring: the pen's translation and rotation since the grab applied to the object (it turns about its own G)
	HS_TECHNIQUE_STICK,         ///< no spring: the object rides rigidly on the pen's ray (it turns about the pen)
	HS_TECHNIQUE_CROSS_PLANE,   ///< no spring: G follows where the pointing ray meets the plane z = G's z at the grab
	HS_TECHNIQUE_CROSS_SURFACE, ///< no spring: the object sits where the pointing ray first meets another object or the floor
} hs_technique;

/// What a button release does besides ending the hold.
typedef enum hs_release_mode {
	HS_RELEASE_MODE_HAND = 0, ///< a drop or a throw, by the hand's motion (§4.4; default)
	HS_RELEASE_MODE_RETURN,   ///< the object is sent back to where it was at the grab, at rest (§3)
} hs_release_mode;

/// The techniques in force (state of the world, not definition).
typedef struct hs_technique_def {
	hs_technique technique;   ///< for the next grab (default HS_TECHNIQUE_SPRING)
	hs_release_mode release;  ///< for button releases (default HS_RELEASE_MODE_HAND)
	bool magnet;              ///< the magnet gesture grabs (default false)
	hs_vec3 body;             ///< m: the user's shoulder, centre of the working sphere (default (0, 0, 0))
	double magnet_far;        ///< m: the arm counts as extended with the stylus this far from `body` (default 0.6)
	double magnet_near;       ///< m: the working sphere's radius, < magnet_far (default 0.35)
	double magnet_within;     ///< s: from extended to inside the working sphere at most this long (default 0.6)
} hs_technique_def;
hs_technique_def hs_default_technique_def(void);
/// Sets the techniques; HS_ERR_INVALID_ARGUMENT unless the world was made with
/// hs_spring_def.techniques, or for values out of range (non-finite, 0 < magnet_near < magnet_far,
/// magnet_within > 0, body within HS_MAX_COORDINATE).
hs_status hs_world_spring_set_technique(hs_world *world, const hs_technique_def *def);
hs_status hs_world_spring_technique(const hs_world *world, hs_technique_def *out);

/// The stylus and the spring after the last step.
typedef struct hs_spring_state {
	hs_object_id attached;      ///< the object on the spring (null handle when none)
	hs_attach_kind attach_kind;
	hs_technique technique;     ///< how the attached object follows (HS_TECHNIQUE_SPRING when none); without the spring anchor is the stylus and length, extension and force are 0
	hs_object_id candidate;     ///< the selection candidate ('I want this one', §3), null when none
	hs_vec3 stylus;             ///< m
	hs_quat stylus_orientation;
	bool button;
	hs_vec3 stylus_velocity;    ///< m/s over the last frame
	hs_vec3 anchor;             ///< m: the spring's anchor, stylus + the offset fixed at the press (0 when nothing is attached)
	double length;              ///< m: |G − anchor| (0 when nothing is attached)
	double extension;           ///< m: length − x0, negative when compressed (0 when nothing is attached)
	hs_vec3 force;              ///< N: spring + damper force on the attached object
} hs_spring_state;
hs_status hs_world_spring_state(const hs_world *world, hs_spring_state *out);

/// Spring-model quantities of one object.
typedef struct hs_spring_object {
	double mass;        ///< kg: density × volume
	double rest_length; ///< m: x0 of the object's spring
	double stiffness;   ///< N/m: k = m g / (0.2 x0), so hanging stretches it by 0.2 x0 (§4.2)
	double damping;     ///< N s/m: c = 2 √(k m), critical (§4.3)
	double omega;       ///< rad/s: √(k / m)
	hs_vec3 velocity;   ///< m/s: the integrated velocity at the end of the last frame
	bool on_floor;      ///< supported by the floor
	bool sliding;       ///< on the floor and moving against sliding friction
	bool attached;      ///< on the spring
} hs_spring_object;
hs_status hs_world_spring_object(const hs_world *world, hs_object_id id, hs_spring_object *out);

#define HS_TRACKER_CAPACITY 64 ///< samples kept in the tracker's ring buffer

typedef enum hs_tracker_event {
	HS_TRACKER_EVENT_NONE = 0,
	HS_TRACKER_EVENT_MOTION_START, ///< the hand was at rest and its speed rose above motion_speed
	HS_TRACKER_EVENT_MOTION_END,   ///< the hand was moving and its speed fell below rest_speed
} hs_tracker_event;

typedef struct hs_tracker_sample {
	double time;      ///< s
	hs_vec3 position; ///< m: the stylus as given to hs_world_set_stylus, interpolated to the sample time
	hs_quat orientation;
	bool button;
} hs_tracker_sample;

/// What the tracker daemon knows after the last step (§3, §5.1).
typedef struct hs_tracker_state {
	long sample_count;          ///< samples taken since the model was enabled
	hs_tracker_sample newest;   ///< the last sample (zero when none)
	hs_vec3 velocity;           ///< m/s at the newest sample: quadratic least-squares fit
	hs_vec3 acceleration;       ///< m/s²
	double speed;               ///< m/s: |velocity|
	hs_vec3 heading;            ///< unit direction of the hand's path over the fit window (zero until known)
	bool at_rest;
	hs_tracker_event last_event;
	double last_event_time;     ///< s
	long motion_starts, motion_ends;
} hs_tracker_state;
hs_status hs_world_tracker_state(const hs_world *world, hs_tracker_state *out);
/// A stored sample: age 0 is the newest, up to min(sample_count, HS_TRACKER_CAPACITY) − 1.
hs_status hs_world_tracker_sample(const hs_world *world, int age, hs_tracker_sample *out);

typedef enum hs_release_kind {
	HS_RELEASE_NONE = 0,
	HS_RELEASE_DROP,  ///< released with the hand at rest: the object keeps its own velocity and falls
	HS_RELEASE_THROW, ///< released with the hand moving: the object takes the hand's velocity
	HS_RELEASE_RETURN, ///< HS_RELEASE_MODE_RETURN: sent back to where it was at the grab, at rest
} hs_release_kind;

typedef struct hs_release {
	hs_release_kind kind;
	hs_object_id object;
	double time;        ///< s
	hs_vec3 velocity;   ///< m/s the object left the spring with
	double hand_speed;  ///< m/s: the tracker's speed estimate at release
} hs_release;
/// The last release (kind HS_RELEASE_NONE before the first one).
hs_status hs_world_spring_last_release(const hs_world *world, hs_release *out);

#ifdef __cplusplus
}
#endif

#endif
