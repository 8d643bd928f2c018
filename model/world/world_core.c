// world_core.c — a world with a fixed dt that owns its shapes and objects: made (with the model of
// its kind: a spring world's spring system), freed, its shapes and objects added and read back.
// Everything is allocated when the world is built; hs_world_step (world_step.c) never allocates.
// It calls no stage of a step: the step pipelines (step_hand.c, step_spring.c) sit above it.
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "broadphase.h"
#include "contact.h"
#include "grasp.h"
#include "motion.h"
#include "part_box.h"
#include "part_reach.h"
#include "spring_params.h"
#include "spring_technique.h"
#include "spring_system.h"
#include "world_scratch.h"
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
	def.glove_deadband = 3;
	def.release_window_s = 0.05;
	def.release_fit = HS_RELEASE_FIT_MEAN;
	def.grasp_opposed = true;
	def.grasp_close_mm = 10.0;
	def.tracking_hold_s = 0.2;
	def.kind = HS_WORLD_HAND;
	def.spring = hs_default_spring_def();
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

static bool valid_def(const hs_world_def *def) {
	return def && def->dt >= HS_MIN_DT && def->dt <= HS_MAX_DT && hs_within(def->gravity, HS_MAX_GRAVITY) &&
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
	       (def->release_fit == HS_RELEASE_FIT_MEAN || def->release_fit == HS_RELEASE_FIT_QUADRATIC ||
	        def->release_fit == HS_RELEASE_FIT_OBJECT) &&
	       isfinite(def->grasp_close_mm) && def->grasp_close_mm >= 0.0 && def->grasp_close_mm <= 1000.0 &&
	       isfinite(def->tracking_hold_s) && def->tracking_hold_s >= 0.0 && def->tracking_hold_s <= HS_MAX_TRACKING_HOLD &&
	       (def->kind == HS_WORLD_HAND || (def->kind == HS_WORLD_SPRING && hs_spring_def_valid(&def->spring)));
}

hs_world *hs_world_create(const hs_world_def *def, hs_status *status) {
	if (!valid_def(def)) {
		hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	hs_world *world = calloc(1, sizeof *world);
	if (!world) {
		hs_set_status(status, HS_ERR_NO_MEMORY);
		return NULL;
	}
	world->model.def = *def;
	world->model.tag = next_world_tag();
	world->model.skip_work = true;
	world->state.first_fault_frame = -1;
	world->state.first_fault_object = -1;
	world->model.grasp_limit = hs_grasp_limit(def->grasp_threshold_deg);
	world->model.oppose_cos = hs_cos((100.0 - 0.5 * def->grasp_threshold_deg) * (HS_PI / 180.0));
	world->model.hold_frames = (int)floor(def->tracking_hold_s / def->dt + 0.5);
	world->model.shapes = calloc((size_t)def->max_shapes, sizeof *world->model.shapes);
	world->model.face_edges = calloc((size_t)def->max_shapes, sizeof *world->model.face_edges);
	world->model.face_trees = calloc((size_t)def->max_shapes, sizeof *world->model.face_trees);
	world->model.shape_grow_reach = calloc((size_t)def->max_shapes, sizeof *world->model.shape_grow_reach);
	world->model.part_cache = calloc((size_t)def->max_shapes, sizeof *world->model.part_cache);
	size_t objects = def->max_objects > 0 ? (size_t)def->max_objects : 1;
	world->state.bodies = calloc(objects, sizeof *world->state.bodies);
	world->state.hands = calloc(def->max_hands > 0 ? (size_t)def->max_hands : 1, sizeof *world->state.hands);
	// every check point and line of every hand in up to 4 objects' parts at once
	world->out.contact_capacity = (def->max_hands > 0 ? def->max_hands : 1) * (HS_HAND_POINTS + HS_HAND_LINES) * 4;
	world->out.contacts = calloc((size_t)world->out.contact_capacity, sizeof *world->out.contacts);
	bool grid = hs_hgrid_alloc(&world->cache.grid, (int)objects, 2);
	world->cache.every = malloc(objects * sizeof *world->cache.every);
	if (world->cache.every)
		for (size_t i = 0; i < objects; ++i)
			world->cache.every[i] = (int)i;
	bool scratch = hs_world_scratch_reserve(world, 0, 0, 0); // the shapes' part grows with them
	world->cache.near_lists.epoch = 1; // a neighbour list never made (epoch 0) never answers
	world->cache.awake = calloc(objects, sizeof *world->cache.awake);
	world->cache.awake_flag = calloc(objects, sizeof *world->cache.awake_flag);
	world->cache.digest = calloc(objects, sizeof *world->cache.digest);
	world->cache.stale = calloc(objects, sizeof *world->cache.stale);
	world->cache.stale_flag = calloc(objects, sizeof *world->cache.stale_flag);
	world->cache.box_memo = calloc(objects, sizeof *world->cache.box_memo);
	world->cache.all_stale = true;
	if (def->kind == HS_WORLD_SPRING) // its tracker starts at the world's time, 0
		world->state.spring = hs_spring_system_create(&def->spring, def->max_objects, 0.0);
	if ((def->kind == HS_WORLD_SPRING && !world->state.spring) || !world->model.shapes || !world->model.face_edges || !world->model.face_trees || !world->model.shape_grow_reach || !world->model.part_cache || !world->state.bodies || !world->state.hands || !world->out.contacts || !grid ||
	    !scratch || !world->cache.every || !world->cache.awake || !world->cache.awake_flag || !world->cache.digest || !world->cache.stale ||
	    !world->cache.stale_flag || !world->cache.box_memo) {
		hs_world_destroy(world);
		hs_set_status(status, HS_ERR_NO_MEMORY);
		return NULL;
	}
	hs_set_status(status, HS_OK);
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
	hs_spring_system_destroy(world->state.spring);
	for (int i = 0; i < world->model.shape_count; ++i) {
		free_shape_arrays(&world->model.shapes[i]);
		hs_face_edges_free(&world->model.face_edges[i]);
		free(world->model.part_cache[i]);
		hs_face_tree_free(&world->model.face_trees[i]);
	}
	free(world->model.shapes);
	free(world->model.face_edges);
	free(world->model.face_trees);
	free(world->model.shape_grow_reach);
	free(world->model.part_cache);
	free(world->state.bodies);
	free(world->state.hands);
	free(world->out.contacts);
	hs_hgrid_free(&world->cache.grid);
	free(world->cache.every);
	free(world->cache.awake);
	free(world->cache.awake_flag);
	free(world->cache.digest);
	free(world->cache.box_memo);
	free(world->cache.stale);
	free(world->cache.stale_flag);
	hs_world_scratch_free(world);
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

hs_shape_id hs_world_add_shape(hs_world *world, const hs_shape *shape, hs_status *status) {
	hs_shape_id none = {0};
	if (!world || !shape || shape->vertex_count <= 0 || !shape->vertices || !(shape->volume > 0.0)) {
		hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
		return none;
	}
	if (world->model.shape_count >= world->model.def.max_shapes) {
		hs_set_status(status, HS_ERR_CAPACITY);
		return none;
	}
	hs_shape *copy = &world->model.shapes[world->model.shape_count];
	if (!hs_world_scratch_reserve(world, shape->vertex_count, shape->face_count, shape->edge_count) ||
	    !copy_shape(copy, shape)) {
		hs_set_status(status, HS_ERR_NO_MEMORY);
		return none;
	}
	hs_part_cache *pc = calloc(copy->part_count > 0 ? (size_t)copy->part_count : 1, sizeof *pc);
	world->model.part_cache[world->model.shape_count] = pc;
	world->model.shape_grow_reach[world->model.shape_count] = 1.0;
	for (int p = 0; p < copy->part_count && pc; ++p) {
		hs_part_box_find(copy, &copy->parts[p], &pc[p]);
		pc[p].grow_reach = hs_part_grow_reach(copy, &copy->parts[p]);
		world->model.shape_grow_reach[world->model.shape_count] = fmax(world->model.shape_grow_reach[world->model.shape_count], pc[p].grow_reach);
	}
	if (!pc || !hs_face_edges_build(&world->model.face_edges[world->model.shape_count], copy) ||
	    !hs_face_tree_build(&world->model.face_trees[world->model.shape_count], copy)) {
		hs_face_edges_free(&world->model.face_edges[world->model.shape_count]);
		free(pc);
		world->model.part_cache[world->model.shape_count] = NULL;
		free_shape_arrays(copy);
		hs_set_status(status, HS_ERR_NO_MEMORY);
		return none;
	}
	hs_set_status(status, HS_OK);
	hs_shape_id id = {(uint32_t)++world->model.shape_count, world->model.tag, HS_GENERATION};
	return id;
}

const hs_shape *hs_world_shape(const hs_world *world, hs_shape_id id) {
	int i = hs_shape_index(world, id);
	return i >= 0 ? &world->model.shapes[i] : NULL;
}

hs_shape_id hs_world_shape_at(const hs_world *world, int i) {
	hs_shape_id id = {0, 0, 0};
	if (world && i >= 0 && i < world->model.shape_count)
		id = (hs_shape_id){(uint32_t)i + 1, world->model.tag, HS_GENERATION};
	return id;
}

hs_object_id hs_world_add_object(hs_world *world, const hs_object_def *def, hs_status *status) {
	hs_object_id none = {0};
	if (!world || !def || hs_shape_index(world, def->shape) < 0 || !hs_within(def->position, HS_MAX_COORDINATE) ||
	    !hs_within(def->velocity, HS_MAX_SPEED) || !hs_within(def->angular_velocity, HS_MAX_SPEED) ||
	    !hs_quat_is_unit(def->orientation) || !isfinite(def->density) ||
	    !(def->density > 0.0 || (def->density == 0.0 && hs_spring_massless_allowed(world))) ||
	    !(def->restitution <= 1.0)) {
		hs_set_status(status, HS_ERR_INVALID_ARGUMENT);
		return none;
	}
	if (world->model.object_count >= world->model.def.max_objects) {
		hs_set_status(status, HS_ERR_CAPACITY);
		return none;
	}
	double dt = world->model.def.dt;
	hs_body *body = &world->state.bodies[world->model.object_count];
	memset(body, 0, sizeof *body);
	body->shape = hs_shape_index(world, def->shape);
	body->pos = def->position;
	body->rot = hs_quat_normalize(def->orientation);
	body->rot_prev = body->rot;
	// P(-dt) on the exact parabola, so eq. 3 reproduces P0 + v t + g t²/2 at every frame
	body->prev = hs_add(hs_sub(def->position, hs_scale(def->velocity, dt)),
	                    hs_scale(world->model.def.gravity, 0.5 * dt * dt));
	double w = hs_length(def->angular_velocity);
	body->spin = w > 0.0 ? hs_quat_from_axis_angle(hs_scale(def->angular_velocity, 1.0 / w), w * dt)
	                     : hs_quat_identity();
	body->mass = def->density * world->model.shapes[body->shape].volume;
	body->restitution = def->restitution < 0.0 ? -1.0 : def->restitution;
	body->vel = def->velocity;
	if (hs_motion_pose_vertices(&world->model, &world->scratch, body) <= world->model.def.floor_tolerance) {
		body->grounded = 1;
		body->floor_contacts = hs_motion_floor_points(&world->model, &world->scratch, body);
	}
	hs_set_status(status, HS_OK);
	int index = world->model.object_count++;
	hs_wake(world->state.bodies, &world->cache, index); // new objects look at the world once
	hs_digest_stale(&world->cache, index);
	world->cache.grid_dirty = true;
	return hs_object_handle(&world->model, index);
}

static const hs_body *body_of(const hs_world *world, hs_object_id id) {
	int i = hs_object_index(world, id);
	return i >= 0 ? &world->state.bodies[i] : NULL;
}

hs_status hs_world_object_state(const hs_world *world, hs_object_id id, hs_object_state *out) {
	const hs_body *body = body_of(world, id);
	if (!body || !out)
		return HS_ERR_INVALID_ARGUMENT;
	out->position = body->pos;
	out->orientation = body->rot;
	out->velocity = hs_scale(hs_sub(body->pos, body->prev), 1.0 / world->model.def.dt);
	out->contact = (hs_contact_state)body->contact;
	out->floor_contacts = body->floor_contacts;
	out->resting = body->asleep != 0;
	return HS_OK;
}

int hs_world_object_count(const hs_world *world) { return world ? world->model.object_count : 0; }

hs_object_id hs_world_object_at(const hs_world *world, int i) {
	hs_object_id none = {0, 0, 0};
	return world ? hs_object_handle(&world->model, i) : none;
}

hs_shape_id hs_world_object_shape(const hs_world *world, hs_object_id id) {
	int i = world ? hs_object_index(world, id) : -1;
	return i < 0 ? (hs_shape_id){0, 0, 0} : hs_world_shape_at(world, world->state.bodies[i].shape);
}
