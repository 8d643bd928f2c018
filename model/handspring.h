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
// Ownership: the caller owns what it creates (hs_shape_*, hs_world_create, hs_scenario_load)
// and destroys it with the matching *_destroy. A world copies the shapes added to it, so the
// caller's shape may be destroyed right after hs_world_add_shape. Objects are named by
// handles (hs_object_id) that stay valid for the life of the world.
#ifndef HANDSPRING_H
#define HANDSPRING_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "hs_math.h"

#define HS_VERSION "0.1.0"

/// Result of a call that can fail.
typedef enum hs_status {
	HS_OK = 0,
	HS_ERR_INVALID_ARGUMENT, ///< a null pointer, an invalid handle, a non-finite or out-of-range number
	HS_ERR_DEGENERATE,       ///< a shape with no volume, a non-planar or non-convex face, an open surface
	HS_ERR_CAPACITY,         ///< more objects or shapes than the world was created for
	HS_ERR_NO_MEMORY,
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

/// Handle of an object in a world: index + 1 (0 is the null handle).
typedef struct hs_object_id {
	uint32_t index1;
} hs_object_id;

/// Handle of a shape registered in a world: index + 1 (0 is the null handle).
typedef struct hs_shape_id {
	uint32_t index1;
} hs_shape_id;

/// How objects touching objects behave (1999 paper §4.3; DESIGN.md).
typedef enum hs_stacking {
	HS_STACKING_PAPER,   ///< objects interfering with a moved object move with it; untouched interfering objects ignore gravity
	HS_STACKING_SUPPORT, ///< a resting object is supported by the faces under it (rectify and stability as on the floor)
} hs_stacking;

typedef struct hs_world_def {
	double dt;                  ///< s, fixed frame time (default 1/60)
	hs_vec3 gravity;            ///< m/s² (default (0, 0, -9.81))
	double floor_tolerance;     ///< m: vertices this close to z = 0 are floor contacts (default 1e-6)
	int max_objects;            ///< capacity, allocated at creation (default 64)
	int max_shapes;             ///< capacity, allocated at creation (default 16)
	hs_stacking stacking;       ///< default HS_STACKING_PAPER
	double grasp_threshold_deg; ///< deg: two contact normals this far apart make a grasp (default 90)
	bool skip_work;             ///< bounding-volume rejection and sleeping on (default true); off only to measure what they save
} hs_world_def;

hs_world_def hs_default_world_def(void);

/// Creates a world; NULL with *status set on invalid definition or out of memory.
hs_world *hs_world_create(const hs_world_def *def, hs_status *status);
void hs_world_destroy(hs_world *world);

/// Copies `shape` into the world. Returns the null handle on error.
hs_shape_id hs_world_add_shape(hs_world *world, const hs_shape *shape, hs_status *status);
/// The world's copy of a registered shape (NULL for an invalid handle).
const hs_shape *hs_world_shape(const hs_world *world, hs_shape_id id);

typedef struct hs_object_def {
	hs_shape_id shape;
	hs_vec3 position;         ///< m: centre of gravity G
	hs_quat orientation;      ///< unit quaternion, body → world
	hs_vec3 velocity;         ///< m/s at t = 0
	hs_vec3 angular_velocity; ///< rad/s at t = 0, world frame
	double density;           ///< kg/m³ (spring model: mass = density × volume; default 500)
} hs_object_def;

hs_object_def hs_default_object_def(void);

/// Adds an object. Returns the null handle and sets *status on error (invalid shape handle,
/// non-finite numbers, a non-unit orientation, capacity).
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

/// Advances the world by one frame of dt. Never allocates.
hs_status hs_world_step(hs_world *world);
/// Frames stepped so far; time is frame × dt.
long hs_world_frame(const hs_world *world);
double hs_world_time(const hs_world *world);
double hs_world_dt(const hs_world *world);

/// 64-bit FNV-1a hash of the exact bits of every object's pose and contact state.
uint64_t hs_world_hash(const hs_world *world);

/// Counters of work done, for benchmarks and tests of what skipping saves.
typedef struct hs_world_counters {
	long object_steps;    ///< objects moved by free motion or tipping
	long sleeping_skips;  ///< object-frames skipped because the object was asleep
	long floor_checks;    ///< object-frames whose vertices were tested against the floor
	long numeric_faults;  ///< non-finite values caught (the object is frozen, never propagated)
} hs_world_counters;
hs_world_counters hs_world_get_counters(const hs_world *world);

// ---------------------------------------------------------------------------------------------
// Scenarios: a YAML file that builds a world, drives it and states what must happen.

typedef struct hs_scenario hs_scenario;

/// An error message `file:line: what is wrong` (no trailing newline).
typedef struct hs_error {
	char message[512];
} hs_error;

/// Loads and validates a scenario file. NULL and `err` filled on any problem.
hs_scenario *hs_scenario_load(const char *path, hs_error *err);
void hs_scenario_destroy(hs_scenario *scenario);

const char *hs_scenario_name(const hs_scenario *scenario);
const char *hs_scenario_description(const hs_scenario *scenario);
/// The world the scenario built (owned by the scenario).
hs_world *hs_scenario_world(hs_scenario *scenario);
/// Name of the i-th object, in the order of the file.
const char *hs_scenario_object_name(const hs_scenario *scenario, int i);
/// Frames the scenario runs: round(duration / dt).
long hs_scenario_frame_count(const hs_scenario *scenario);

/// Steps one frame (inputs, then the world) and records what expectations need.
/// Returns false once every frame has run.
bool hs_scenario_step(hs_scenario *scenario);

/// Evaluates every `expect` clause; writes one line per clause (PASS/FAIL and the measured
/// value) to `report` when not NULL. Returns the number of failed clauses.
int hs_scenario_check(const hs_scenario *scenario, FILE *report);
/// Lines hs_scenario_check writes: one per clause and object it names ("*" names every object),
/// plus one when the world failed to step.
int hs_scenario_expectation_count(const hs_scenario *scenario);
/// s: the scenario's frame time.
double hs_scenario_dt(const hs_scenario *scenario);
int hs_scenario_object_count(const hs_scenario *scenario);

/// The scenario files below a folder: every *.yaml, recursively (hidden entries skipped), sorted
/// by name (strcmp). A name is the path relative to the folder without ".yaml", e.g. "hand/flick";
/// a path is the folder joined with that relative path.
typedef struct hs_catalog {
	int count;
	char **names;
	char **paths;
} hs_catalog;

/// Fills `out` (free it with hs_catalog_free). False and `err` = "DIR: what is wrong" when the
/// folder cannot be read; an empty folder is a valid, empty catalog.
bool hs_catalog_load(const char *dir, hs_catalog *out, hs_error *err);
void hs_catalog_free(hs_catalog *catalog);

// ---------------------------------------------------------------------------------------------
// Trajectories: CSV, one row per object per frame.

/// Writes the header line `frame,t,object,x,y,z,qw,qx,qy,qz,contact,floor,resting,hash`.
void hs_trajectory_write_header(FILE *out);
/// Writes the rows of the current frame of a scenario's world (numbers with 17 significant digits).
void hs_trajectory_write_frame(FILE *out, hs_scenario *scenario);

/// Compares a trajectory with its golden (both as written above; lines starting with '#' are
/// comments). Numbers must agree within `tolerance` (absolute), contact states and row keys exactly.
/// Returns true when they match; otherwise writes the first mismatch into `why`, as
/// "LABEL: frame F, object O, field X: golden G, now N (difference D)".
bool hs_trajectory_compare(FILE *golden, FILE *actual, double tolerance, const char *label, char *why,
                           size_t why_size);

#endif
