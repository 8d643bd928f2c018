// world.c — a world with a fixed dt that owns its shapes and objects and steps them.
// Everything is allocated when the world is built; hs_world_step never allocates.
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "broadphase.h"
#include "contact.h"
#include "fall_group.h"
#include "grasp.h"
#include "interfere.h"
#include "manipulate.h"
#include "motion.h"
#include "part_box.h"
#include "part_reach.h"
#include "stacking.h"
#include "support.h"
#include "tracking.h"
#include "world_internal.h"

// Tags of the worlds of this process, 1 to 65535 and round again (0 is the null handle's): a
// handle of one world is refused by another for the first 65535 worlds created after it.
static atomic_uint world_tags;

static uint16_t next_world_tag(void) {
	return (uint16_t)(atomic_fetch_add(&world_tags, 1u) % 65535u + 1u);
}

hs_world_def hs_default_world_def(void) {
	hs_world_def def;
	memset(&def, 0, sizeof def);
	def.dt = 1.0 / 60.0;
	def.gravity = hs_v3(0.0, 0.0, -9.81);
	def.floor_tolerance = 1e-6;
	def.max_objects = 64;
	def.max_shapes = 16;
	def.max_hands = 2;
	def.stacking = HS_STACKING_PAPER;
	def.grasp_threshold_deg = 90.0;
	def.grasp_release_mm = 5.0;
	def.grasp_open_mm = 8.0;
	def.skip_work = true;
	def.glove_deadband = 3;
	def.release_window_s = 0.05;
	def.release_fit = HS_RELEASE_FIT_MEAN;
	def.grasp_opposed = true;
	def.grasp_close_mm = 10.0;
	def.tracking_hold_s = 0.2;
	return def;
}

hs_object_def hs_default_object_def(void) {
	hs_object_def def;
	memset(&def, 0, sizeof def);
	def.orientation = hs_quat_identity();
	def.density = 500.0;
	def.restitution = -1.0;
	return def;
}

static void set_status(hs_status *status, hs_status value) {
	if (status)
		*status = value;
}

// every component finite and within ±limit
static bool within(hs_vec3 v, double limit) {
	return fabs(v.x) <= limit && fabs(v.y) <= limit && fabs(v.z) <= limit;
}

static bool valid_def(const hs_world_def *def) {
	return def && def->dt >= HS_MIN_DT && def->dt <= HS_MAX_DT && within(def->gravity, HS_MAX_GRAVITY) &&
	       isfinite(def->floor_tolerance) && def->floor_tolerance > 0.0 && def->max_objects >= 0 &&
	       def->max_objects <= 10000000 && def->max_shapes >= 1 && def->max_shapes <= 100000 &&
	       def->max_hands >= 0 && def->max_hands <= 64 &&
	       isfinite(def->grasp_threshold_deg) && def->grasp_threshold_deg > 0.0 &&
	       def->grasp_threshold_deg <= 180.0 && isfinite(def->grasp_release_mm) && def->grasp_release_mm >= 0.0 &&
	       def->grasp_release_mm <= 1000.0 && isfinite(def->grasp_open_mm) && def->grasp_open_mm >= 0.0 &&
	       def->grasp_open_mm <= 1000.0 && def->glove_deadband >= 0 && def->glove_deadband <= HS_MAX_GLOVE_DEADBAND &&
	       (def->stacking == HS_STACKING_PAPER || def->stacking == HS_STACKING_SUPPORT) &&
	       isfinite(def->release_window_s) && def->release_window_s >= 0.0 &&
	       def->release_window_s <= HS_MAX_RELEASE_WINDOW &&
	       (def->release_fit == HS_RELEASE_FIT_MEAN || def->release_fit == HS_RELEASE_FIT_QUADRATIC) &&
	       isfinite(def->grasp_close_mm) && def->grasp_close_mm >= 0.0 && def->grasp_close_mm <= 1000.0 &&
	       isfinite(def->tracking_hold_s) && def->tracking_hold_s >= 0.0 && def->tracking_hold_s <= HS_MAX_TRACKING_HOLD;
}

hs_world *hs_world_create(const hs_world_def *def, hs_status *status) {
	if (!valid_def(def)) {
		set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	hs_world *world = calloc(1, sizeof *world);
	if (!world) {
		set_status(status, HS_ERR_NO_MEMORY);
		return NULL;
	}
	world->def = *def;
	world->tag = next_world_tag();
	world->first_fault_frame = -1;
	world->first_fault_object = -1;
	world->grasp_limit = hs_grasp_limit(def->grasp_threshold_deg);
	world->oppose_cos = hs_cos((100.0 - 0.5 * def->grasp_threshold_deg) * (HS_PI / 180.0));
	world->hold_frames = (int)floor(def->tracking_hold_s / def->dt + 0.5);
	world->shapes = calloc((size_t)def->max_shapes, sizeof *world->shapes);
	world->face_edges = calloc((size_t)def->max_shapes, sizeof *world->face_edges);
	world->face_trees = calloc((size_t)def->max_shapes, sizeof *world->face_trees);
	world->shape_grow_reach = calloc((size_t)def->max_shapes, sizeof *world->shape_grow_reach);
	size_t objects = def->max_objects > 0 ? (size_t)def->max_objects : 1;
	world->bodies = calloc(objects, sizeof *world->bodies);
	world->queue = calloc(objects, sizeof *world->queue);
	world->moved_from = calloc(objects, sizeof *world->moved_from);
	world->hands = calloc(def->max_hands > 0 ? (size_t)def->max_hands : 1, sizeof *world->hands);
	// every check point and line of every hand in up to 4 objects' parts at once
	world->contact_capacity = (def->max_hands > 0 ? def->max_hands : 1) * (HS_HAND_POINTS + HS_HAND_LINES) * 4;
	world->contacts = calloc((size_t)world->contact_capacity, sizeof *world->contacts);
	bool grid = hs_hgrid_alloc(&world->grid, (int)objects, 2);
	world->candidates = calloc(objects, sizeof *world->candidates);
	world->every = malloc(objects * sizeof *world->every);
	world->found = calloc(objects, sizeof *world->found);
	if (world->every)
		for (size_t i = 0; i < objects; ++i)
			world->every[i] = (int)i;
	world->near = world->every;
	world->near_epoch = 1; // a neighbour list never made (epoch 0) never answers
	world->awake = calloc(objects, sizeof *world->awake);
	world->awake_flag = calloc(objects, sizeof *world->awake_flag);
	world->digest = calloc(objects, sizeof *world->digest);
	world->stale = calloc(objects, sizeof *world->stale);
	world->stale_flag = calloc(objects, sizeof *world->stale_flag);
	world->box_memo = calloc(objects, sizeof *world->box_memo);
	world->all_stale = true;
	if (!world->shapes || !world->face_edges || !world->face_trees || !world->shape_grow_reach || !world->bodies || !world->queue || !world->moved_from || !world->hands || !world->contacts || !grid ||
	    !world->candidates || !world->every || !world->found || !world->awake || !world->awake_flag || !world->digest || !world->stale ||
	    !world->stale_flag || !world->box_memo) {
		hs_world_destroy(world);
		set_status(status, HS_ERR_NO_MEMORY);
		return NULL;
	}
	set_status(status, HS_OK);
	return world;
}

static void free_shape_arrays(hs_shape *shape) {
	free(shape->parts);
	free(shape->vertices);
	free(shape->faces);
	free(shape->face_vertices);
	free(shape->edges);
}

void hs_world_destroy(hs_world *world) {
	if (!world)
		return;
	hs_spring_system_destroy(world->spring);
	for (int i = 0; i < world->shape_count; ++i) {
		free_shape_arrays(&world->shapes[i]);
		free(world->face_edges[i].first);
		free(world->face_edges[i].edges);
		hs_face_tree_free(&world->face_trees[i]);
	}
	free(world->shapes);
	free(world->face_edges);
	free(world->face_trees);
	free(world->shape_grow_reach);
	free(world->bodies);
	free(world->queue);
	free(world->moved_from);
	free(world->hands);
	free(world->contacts);
	hs_hgrid_free(&world->grid);
	free(world->candidates);
	free(world->every);
	free(world->found);
	free(world->awake);
	free(world->awake_flag);
	free(world->digest);
	free(world->box_memo);
	free(world->stale);
	free(world->stale_flag);
	free(world->scratch_world);
	free(world->scratch_points);
	free(world->scratch_hull);
	free(world->face_pick);
	free(world->edge_pick);
	free(world->edge_mark);
	free(world);
}

static void *copy_array(const void *src, int count, size_t size) {
	if (count <= 0)
		return NULL;
	void *dst = malloc((size_t)count * size);
	if (dst)
		memcpy(dst, src, (size_t)count * size);
	return dst;
}

static bool copy_shape(hs_shape *dst, const hs_shape *src) {
	*dst = *src;
	dst->parts = copy_array(src->parts, src->part_count, sizeof *src->parts);
	dst->vertices = copy_array(src->vertices, src->vertex_count, sizeof *src->vertices);
	dst->faces = copy_array(src->faces, src->face_count, sizeof *src->faces);
	dst->face_vertices = copy_array(src->face_vertices, src->face_vertex_count, sizeof *src->face_vertices);
	dst->edges = copy_array(src->edges, src->edge_count, sizeof *src->edges);
	if ((src->part_count > 0 && !dst->parts) || (src->vertex_count > 0 && !dst->vertices) ||
	    (src->face_count > 0 && !dst->faces) || (src->face_vertex_count > 0 && !dst->face_vertices) ||
	    (src->edge_count > 0 && !dst->edges)) {
		free_shape_arrays(dst);
		return false;
	}
	return true;
}

static bool face_in_range(const hs_shape *shape, int f) { return f >= 0 && f < shape->face_count; }

// The shape's edges listed by face (hs_face_edges): counted, then filled in edge order.
static bool index_face_edges(const hs_shape *shape, hs_face_edges *out) {
	out->first = calloc((size_t)shape->face_count + 1, sizeof *out->first);
	out->edges = malloc((size_t)(2 * shape->edge_count > 0 ? 2 * shape->edge_count : 1) * sizeof *out->edges);
	if (!out->first || !out->edges) {
		free(out->first);
		free(out->edges);
		out->first = out->edges = NULL;
		return false;
	}
	for (int e = 0; e < shape->edge_count; ++e)
		for (int k = 0; k < 2; ++k)
			if (face_in_range(shape, shape->edges[e].faces[k]))
				out->first[shape->edges[e].faces[k] + 1]++;
	for (int f = 0; f < shape->face_count; ++f)
		out->first[f + 1] += out->first[f];
	int *fill = out->first; // advanced per face while filling, then moved back
	for (int e = 0; e < shape->edge_count; ++e)
		for (int k = 0; k < 2; ++k)
			if (face_in_range(shape, shape->edges[e].faces[k]))
				out->edges[fill[shape->edges[e].faces[k]]++] = e;
	for (int f = shape->face_count; f > 0; --f)
		fill[f] = fill[f - 1];
	fill[0] = 0;
	return true;
}

// Scratch for the floor test sized for the largest shape (room for a closing hull point).
static bool reserve_scratch(hs_world *world, int vertex_count) {
	if (vertex_count <= world->scratch_capacity)
		return true;
	size_t n = (size_t)vertex_count + 1;
	hs_vec3 *posed = realloc(world->scratch_world, n * sizeof *posed);
	if (posed)
		world->scratch_world = posed;
	hs_vec2 *points = realloc(world->scratch_points, n * sizeof *points);
	if (points)
		world->scratch_points = points;
	hs_vec2 *hull = realloc(world->scratch_hull, n * sizeof *hull);
	if (hull)
		world->scratch_hull = hull;
	if (!posed || !points || !hull)
		return false;
	world->scratch_capacity = vertex_count;
	return true;
}

// Scratch for a swept line's faces and edges (contact.c), sized for the shape with most of them.
static bool reserve_picks(hs_world *world, const hs_shape *shape) {
	if (shape->face_count > world->pick_faces) {
		int *faces = realloc(world->face_pick, (size_t)shape->face_count * sizeof *faces);
		if (!faces)
			return false;
		world->face_pick = faces;
		world->pick_faces = shape->face_count;
	}
	if (shape->edge_count > world->pick_edges) {
		int *edges = realloc(world->edge_pick, (size_t)shape->edge_count * sizeof *edges);
		if (edges)
			world->edge_pick = edges;
		uint8_t *mark = realloc(world->edge_mark, (size_t)shape->edge_count * sizeof *mark);
		if (mark)
			world->edge_mark = mark;
		if (!edges || !mark)
			return false;
		memset(world->edge_mark, 0, (size_t)shape->edge_count);
		world->pick_edges = shape->edge_count;
	}
	return true;
}

hs_shape_id hs_world_add_shape(hs_world *world, const hs_shape *shape, hs_status *status) {
	hs_shape_id none = {0};
	if (!world || !shape || shape->vertex_count <= 0 || !shape->vertices || !(shape->volume > 0.0)) {
		set_status(status, HS_ERR_INVALID_ARGUMENT);
		return none;
	}
	if (world->shape_count >= world->def.max_shapes) {
		set_status(status, HS_ERR_CAPACITY);
		return none;
	}
	hs_shape *copy = &world->shapes[world->shape_count];
	if (!reserve_scratch(world, shape->vertex_count) || !reserve_picks(world, shape) || !copy_shape(copy, shape)) {
		set_status(status, HS_ERR_NO_MEMORY);
		return none;
	}
	world->shape_grow_reach[world->shape_count] = 1.0;
	for (int p = 0; p < copy->part_count; ++p) {
		hs_part_box_find(copy, &copy->parts[p]);
		copy->parts[p].grow_reach = hs_part_grow_reach(copy, &copy->parts[p]);
		world->shape_grow_reach[world->shape_count] =
		    fmax(world->shape_grow_reach[world->shape_count], copy->parts[p].grow_reach);
	}
	if (!index_face_edges(copy, &world->face_edges[world->shape_count]) ||
	    !hs_face_tree_build(&world->face_trees[world->shape_count], copy)) {
		free(world->face_edges[world->shape_count].first);
		free(world->face_edges[world->shape_count].edges);
		world->face_edges[world->shape_count] = (hs_face_edges){0};
		free_shape_arrays(copy);
		set_status(status, HS_ERR_NO_MEMORY);
		return none;
	}
	set_status(status, HS_OK);
	hs_shape_id id = {(uint32_t)++world->shape_count, world->tag, HS_GENERATION};
	return id;
}

const hs_shape *hs_world_shape(const hs_world *world, hs_shape_id id) {
	int i = hs_shape_index(world, id);
	return i >= 0 ? &world->shapes[i] : NULL;
}

hs_shape_id hs_world_shape_at(const hs_world *world, int i) {
	hs_shape_id id = {0, 0, 0};
	if (world && i >= 0 && i < world->shape_count)
		id = (hs_shape_id){(uint32_t)i + 1, world->tag, HS_GENERATION};
	return id;
}

hs_object_id hs_world_add_object(hs_world *world, const hs_object_def *def, hs_status *status) {
	hs_object_id none = {0};
	if (!world || !def || hs_shape_index(world, def->shape) < 0 || !within(def->position, HS_MAX_COORDINATE) ||
	    !within(def->velocity, HS_MAX_SPEED) || !within(def->angular_velocity, HS_MAX_SPEED) ||
	    !hs_quat_is_unit(def->orientation) || !isfinite(def->density) || !(def->density > 0.0) ||
	    !(def->restitution <= 1.0)) {
		set_status(status, HS_ERR_INVALID_ARGUMENT);
		return none;
	}
	if (world->object_count >= world->def.max_objects) {
		set_status(status, HS_ERR_CAPACITY);
		return none;
	}
	double dt = world->def.dt;
	hs_body *body = &world->bodies[world->object_count];
	memset(body, 0, sizeof *body);
	body->shape = hs_shape_index(world, def->shape);
	body->pos = def->position;
	body->rot = hs_quat_normalize(def->orientation);
	body->rot_prev = body->rot;
	// P(-dt) on the exact parabola, so eq. 3 reproduces P0 + v t + g t²/2 at every frame
	body->prev = hs_add(hs_sub(def->position, hs_scale(def->velocity, dt)),
	                    hs_scale(world->def.gravity, 0.5 * dt * dt));
	double w = hs_length(def->angular_velocity);
	body->spin = w > 0.0 ? hs_quat_from_axis_angle(hs_scale(def->angular_velocity, 1.0 / w), w * dt)
	                     : hs_quat_identity();
	body->mass = def->density * world->shapes[body->shape].volume;
	body->restitution = def->restitution < 0.0 ? -1.0 : def->restitution;
	body->vel = def->velocity;
	if (hs_motion_pose_vertices(world, body) <= world->def.floor_tolerance) {
		body->grounded = 1;
		body->floor_contacts = hs_motion_floor_points(world, body);
	}
	set_status(status, HS_OK);
	int index = world->object_count++;
	hs_wake(world, index); // new objects look at the world once
	hs_digest_stale(world, index);
	world->grid_dirty = true;
	return hs_object_handle(world, index);
}

static const hs_body *body_of(const hs_world *world, hs_object_id id) {
	int i = hs_object_index(world, id);
	return i >= 0 ? &world->bodies[i] : NULL;
}

hs_status hs_world_object_state(const hs_world *world, hs_object_id id, hs_object_state *out) {
	const hs_body *body = body_of(world, id);
	if (!body || !out)
		return HS_ERR_INVALID_ARGUMENT;
	out->position = body->pos;
	out->orientation = body->rot;
	out->velocity = hs_scale(hs_sub(body->pos, body->prev), 1.0 / world->def.dt);
	out->contact = (hs_contact_state)body->contact;
	out->floor_contacts = body->floor_contacts;
	out->resting = body->asleep != 0;
	return HS_OK;
}

int hs_world_object_count(const hs_world *world) { return world ? world->object_count : 0; }

hs_object_id hs_world_object_at(const hs_world *world, int i) {
	hs_object_id none = {0, 0, 0};
	return world ? hs_object_handle(world, i) : none;
}

hs_shape_id hs_world_object_shape(const hs_world *world, hs_object_id id) {
	int i = world ? hs_object_index(world, id) : -1;
	return i < 0 ? (hs_shape_id){0, 0, 0} : hs_world_shape_at(world, world->bodies[i].shape);
}

static bool body_is_finite(const hs_body *body) {
	return hs_vec3_is_finite(body->pos) && hs_vec3_is_finite(body->prev) && hs_quat_is_finite(body->rot) &&
	       hs_quat_is_finite(body->spin);
}

static bool in_list(const int *list, int n, int i) {
	for (int k = 0; k < n; ++k)
		if (list[k] == i)
			return true;
	return false;
}

// Paper mode, an awake object that interferes with others: if nothing holds it up, it falls with
// what rests on it (fall_group.c), whose indices go to world->queue from *fallen (support mode's
// list there is never used in paper mode).
static bool paper_group_falls(hs_world *world, int i, int *fallen) {
	int n = hs_fall_group(world, i, world->queue + *fallen, world->object_count - *fallen);
	*fallen += n;
	return n > 0;
}

// One unheld object's frame: §4.3 in paper mode (interfering and untouched: no gravity, no
// inertia, but rectified out of the objects under it as out of the floor, Fig. 11), else eq. 3 and
// the floor (§4.2), the fall swept over the objects under it, and in support mode its supports.
static void step_object(hs_world *world, int i, bool interferes) {
	hs_body *body = &world->bodies[i];
	hs_vec3 from = body->pos;
	if (interferes) {
		hs_stack_rectify(world, i);
		hs_motion_keep_above_floor(world, body);
		body->grounded = body->floor_contacts > 0; // it may rest above the floor (carried up)
		body->prev = body->pos;
		body->spin = hs_quat_identity();
		body->asleep = 1;
		return;
	}
	body->rot_prev = body->rot;
	hs_motion_step(world, body);
	if (hs_stack_sweep(world, i, from)) {
		hs_motion_keep_above_floor(world, body); // its floor contacts where it landed
		// Gm of eq. 4-5 as on the floor (motion.c): the rectified motion and this frame's gravity
		double dt = world->def.dt;
		body->prev = hs_mul_add(from, -dt * dt, world->def.gravity);
		if (world->def.stacking == HS_STACKING_PAPER) { // §4.1: stops at the interference, no rebound
			body->prev = body->pos;
			body->asleep = 1;
		}
	}
	if (world->def.stacking == HS_STACKING_SUPPORT && !body->asleep) {
		hs_support_step(world, i);
		hs_stack_rectify(world, i); // a turn about a support's edge stops at the floor only (eq. 7)
	}
}

hs_status hs_world_step(hs_world *world) {
	if (!world)
		return HS_ERR_INVALID_ARGUMENT;
	if (world->spring) { // the workbench model replaces the 1999 motion in its worlds
		long faults = world->counters.numeric_faults;
		hs_spring_step(world);
		hs_digest_all_stale(world); // the spring model keeps no awake list: every object is hashed again
		if (world->counters.numeric_faults > faults && world->first_fault_frame < 0)
			world->first_fault_frame = world->frame; // counted without an object: still the first
		world->frame++;
		return HS_OK;
	}
	if (world->grid_dirty || !world->grid_built) { // objects were added: file them again
		hs_grid_build(world);
		world->grid_dirty = false;
	}
	if (world->hand_count > 0) { // a scene without hands never runs the hand subsystem
		hs_tracking_update(world);
		hs_manipulate(world);
	}
	bool skip = world->def.skip_work;
	int visits = skip ? world->awake_count : world->object_count;
	if (skip) // the sleeping objects cost nothing (the awake list holds the others, in index order)
		world->counters.sleeping_skips += world->object_count - world->awake_count;
	int moved = 0; // support mode: objects that moved, to wake what rested on them (after the loop)
	int fallen = 0; // paper mode: objects moved with a falling group (to wake after the loop)
	for (int k = 0; k < visits; ++k) {
		int i = skip ? world->awake[k] : k;
		hs_body *body = &world->bodies[i];
		if (body->held || body->carried || in_list(world->queue, fallen, i))
			continue;
		// asleep: stays as it is until woken — on the floor, on a support (support mode), where it
		// stopped at an interference (paper mode, §4.3) — with skip_work off too (the same bits:
		// its pose and its last turn, rot_prev, kept); one that fell asleep this frame leaves the
		// awake list below
		if (body->asleep)
			continue;
		bool interferes = world->def.stacking == HS_STACKING_PAPER && hs_object_interferes(world, i);
		if (interferes && paper_group_falls(world, i, &fallen))
			continue;
		hs_body saved = *body;
		step_object(world, i, interferes);
		if (!body_is_finite(body)) { // never let a NaN spread: freeze the object and count it
			*body = saved;
			hs_world_note_fault(world, i);
		}
		// support mode: what moved by more than the floor's tolerance wakes what rests on it (a
		// settling stack's rounding-size moves woke each other for good)
		if (world->def.stacking == HS_STACKING_SUPPORT && hs_length(hs_sub(body->pos, saved.pos)) > world->def.floor_tolerance) {
			world->moved_from[moved] = saved.pos;
			world->queue[moved++] = i;
		}
		hs_grid_update(world, i);
	}
	for (int k = 0; k < moved; ++k) // the awake list may grow only once the loop is over
		hs_support_wake_neighbours(world, world->queue[k], world->moved_from[k]);
	for (int k = 0; k < fallen; ++k)
		hs_wake(world, world->queue[k]);
	hs_awake_compact(world);
	if (!skip) // every object was looked at (the awake list does not bound what may have changed)
		hs_digest_all_stale(world);
	for (int h = 0; h < world->hand_count; ++h) { // a hand not set again stays where it is
		hs_hand_age_wrist(&world->hands[h]);
		hs_hand_keep_previous(&world->hands[h]);
	}
	world->frame++;
	return HS_OK;
}

long hs_world_frame(const hs_world *world) { return world ? world->frame : 0; }
double hs_world_time(const hs_world *world) { return world ? (double)world->frame * world->def.dt : 0.0; }
double hs_world_dt(const hs_world *world) { return world ? world->def.dt : 0.0; }

void hs_world_note_fault(hs_world *world, int object) {
	world->counters.numeric_faults++;
	if (world->first_fault_frame < 0) {
		world->first_fault_frame = world->frame;
		world->first_fault_object = object;
	}
}

hs_status hs_world_first_fault(const hs_world *world, long *frame, hs_object_id *object) {
	if (!world)
		return HS_ERR_INVALID_ARGUMENT;
	if (frame)
		*frame = world->first_fault_frame;
	if (object)
		*object = hs_object_handle(world, world->first_fault_object);
	return HS_OK;
}

hs_world_counters hs_world_get_counters(const hs_world *world) {
	hs_world_counters none;
	memset(&none, 0, sizeof none);
	return world ? world->counters : none;
}

hs_hand_id hs_world_add_hand(hs_world *world, const hs_hand_def *def, hs_status *status) {
	hs_hand_id none = {0};
	if (!world || !def || !(def->finger_radius > 0.0) || !isfinite(def->finger_radius) ||
	    !(def->dip_per_pip >= 0.0) || !isfinite(def->dip_per_pip)) {
		set_status(status, HS_ERR_INVALID_ARGUMENT);
		return none;
	}
	for (int f = 0; f < 5; ++f) {
		if (!hs_vec3_is_finite(def->base[f])) {
			set_status(status, HS_ERR_INVALID_ARGUMENT);
			return none;
		}
		for (int s = 0; s < 3; ++s)
			if (!(def->segment_length[f][s] > 0.0) || !isfinite(def->segment_length[f][s])) {
				set_status(status, HS_ERR_INVALID_ARGUMENT);
				return none;
			}
	}
	if (world->hand_count >= world->def.max_hands) {
		set_status(status, HS_ERR_CAPACITY);
		return none;
	}
	hs_hand *hand = &world->hands[world->hand_count];
	memset(hand, 0, sizeof *hand);
	hand->def = *def;
	hs_glove_table_build(&hand->def, &hand->glove);
	hand->wrist_rot = hand->prev_wrist_rot = hs_quat_identity();
	hand->older_capacity = hs_hand_older_capacity(world->def.release_window_s, world->def.dt);
	for (int k = 0; k < HS_HAND_OLDER_MAX; ++k) // not yet reached: a unit rotation, as a state file must hold
		hand->older_rot[k] = hs_quat_identity();
	hand->lines_ready = hand->prev_lines_ready = hand->local_ready = HS_HAND_ALL_SEGMENTS; // all zero until set
	hs_hand_update_bounds(hand); // touches nothing until it is set
	set_status(status, HS_OK);
	int index = world->hand_count++;
	return hs_hand_handle(world, index);
}

hs_hand_id hs_world_hand_at(const hs_world *world, int i) {
	hs_hand_id none = {0, 0, 0};
	return world ? hs_hand_handle(world, i) : none;
}

static hs_hand *hand_of(const hs_world *world, hs_hand_id id) {
	int h = hs_hand_index(world, id);
	return h >= 0 ? &world->hands[h] : NULL;
}

// The hand placed from its new reading (its shape made): the first placement moves nothing.
static hs_status place_hand(hs_hand *hand) {
	hs_hand_place_points(hand);
	bool first = !hand->placed;
	hand->placed = true;
	hs_hand_update_bounds(hand);
	if (first) { // no motion before the first pose, no closing either
		hs_hand_keep_previous(hand);
		hs_grasp_reset_pairs(hand);
	}
	return HS_OK;
}

hs_status hs_world_set_hand(hs_world *world, hs_hand_id id, hs_vec3 wrist_position, hs_quat wrist_orientation,
                            const uint8_t reading[HS_GLOVE_SENSORS]) {
	hs_hand *hand = hand_of(world, id);
	if (!hand || hand->def.joint_driven || !reading || !within(wrist_position, HS_MAX_COORDINATE) ||
	    !hs_quat_is_unit(wrist_orientation))
		return HS_ERR_INVALID_ARGUMENT;
	hand->wrist_pos = wrist_position;
	hand->wrist_rot = hs_quat_normalize(wrist_orientation);
	// The glove's deadband (docs/model.md §1). Without it a glove's per-frame noise (±4 units, ±2°,
	// is ±6 mm at a fingertip from the wrist sensors alone) moves a still hand every frame:
	// fingertips on a face drag and turn what they touch, and the drags add up frame after frame (a
	// two-fingertip push drifted 2 cm sideways). A still reading keeps the hand's bits; a moving one
	// lags by the band. The first reading is used as it is.
	uint8_t sensors[HS_GLOVE_SENSORS];
	hs_glove_deadband(hand->placed ? hand->sensors : reading, world->def.glove_deadband, reading, sensors);
	if (!hand->placed || memcmp(hand->sensors, sensors, sizeof hand->sensors) != 0) {
		memcpy(hand->sensors, sensors, sizeof hand->sensors); // the glove moved: a new hand shape
		hs_hand_update_shape(hand);
	}
	return place_hand(hand);
}

hs_status hs_world_set_hand_joints(hs_world *world, hs_hand_id id, hs_vec3 wrist_position, hs_quat wrist_orientation,
                                   const hs_vec3 points[HS_HAND_POINTS]) {
	hs_hand *hand = hand_of(world, id);
	if (!hand || !hand->def.joint_driven || !points || !within(wrist_position, HS_MAX_COORDINATE) ||
	    !hs_quat_is_unit(wrist_orientation))
		return HS_ERR_INVALID_ARGUMENT;
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		if (!within(points[i], HS_MAX_COORDINATE))
			return HS_ERR_INVALID_ARGUMENT;
	hand->wrist_pos = wrist_position;
	hand->wrist_rot = hs_quat_normalize(wrist_orientation);
	if (!hand->placed || memcmp(hand->joints, points, sizeof hand->joints) != 0) {
		memcpy(hand->joints, points, sizeof hand->joints); // a new hand shape
		hs_hand_update_shape(hand);
	}
	return place_hand(hand);
}

hs_status hs_world_set_hand_tracked(hs_world *world, hs_hand_id id, bool tracked) {
	hs_hand *hand = hand_of(world, id);
	if (!hand)
		return HS_ERR_INVALID_ARGUMENT;
	hand->untracked = !tracked;
	return HS_OK;
}

hs_status hs_world_hand_points(const hs_world *world, hs_hand_id id, hs_vec3 points[HS_HAND_POINTS]) {
	const hs_hand *hand = hand_of(world, id);
	if (!hand || !points)
		return HS_ERR_INVALID_ARGUMENT;
	memcpy(points, hand->points, sizeof hand->points);
	return HS_OK;
}

hs_status hs_world_hand_rectified_points(const hs_world *world, hs_hand_id id, hs_vec3 points[HS_HAND_POINTS],
                                         uint32_t *touching) {
	const hs_hand *hand = hand_of(world, id);
	if (!hand || !points)
		return HS_ERR_INVALID_ARGUMENT;
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		points[i] = hand->touch_points >> i & 1u ? hs_contact_rectify(world, hand->points[i]) : hand->points[i];
	if (touching)
		*touching = hand->touch_points;
	return HS_OK;
}

int hs_world_contacts(const hs_world *world, hs_contact *out, int max) {
	if (!world)
		return 0;
	int n = world->contact_count;
	for (int i = 0; i < n && i < max && out; ++i)
		out[i] = world->contacts[i];
	return n;
}
