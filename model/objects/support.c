// support.c — the 'support' stacking mode (docs/model.md §6, an alternative to the 1999 paper's §4.3):
// an object that sinks into objects under it is rectified upward exactly as on the floor (§4.2),
// and its stability is judged with the hull of its contacts on their faces and G' (eq. 4-5).
//
// The lift is vertical (stacking.c: exact for vertex-face interpenetration of convex parts; the
// world step has already swept the fall and rectified faces flush with each other).
#include "broadphase.h"
#include "clip.h"
#include "interfere.h"
#include "motion.h"
#include "stacking.h"
#include "support.h"

static hs_vec3 to_local(const hs_body *b, hs_vec3 p) { return hs_quat_inv_rotate(b->rot, hs_sub(p, b->pos)); }

static bool near_spheres(const hs_world_model *model, const hs_body *bodies, int i, int j, double margin) {
	const hs_body *a = &bodies[i], *b = &bodies[j];
	double r = model->shapes[a->shape].radius + model->shapes[b->shape].radius + margin;
	return hs_length_sq(hs_sub(a->pos, b->pos)) <= r * r;
}

static int add_point(hs_world_scratch *scratch, int n, hs_vec3 p, double *height_sum) {
	if (n >= scratch->vertex_room)
		return n; // more contacts than vertices: the hull is already well defined
	scratch->points[n] = (hs_vec2){p.x, p.y};
	*height_sum += p.z;
	return n + 1;
}

// Contact points of a resting on b: every edge of each clipped to the other. The clipped ends are
// the corners of the region where their faces meet: vertices inside and edge-edge crossings.
static int clip_edges(const hs_world_model *model, hs_world_scratch *scratch, const hs_body *a, const hs_body *b, int n,
                      double *height_sum) {
	const hs_shape *sa = &model->shapes[a->shape], *sb = &model->shapes[b->shape];
	double tol = model->def.floor_tolerance;
	for (int e = 0; e < sa->edge_count; ++e) {
		hs_vec3 p0 = hs_add(a->pos, hs_quat_rotate(a->rot, sa->vertices[sa->edges[e].a]));
		hs_vec3 p1 = hs_add(a->pos, hs_quat_rotate(a->rot, sa->vertices[sa->edges[e].b]));
		hs_vec3 q0 = to_local(b, p0), q1 = to_local(b, p1);
		for (int k = 0; k < sb->part_count; ++k) {
			hs_clip c = hs_clip_segment(sb, &sb->parts[k], q0, q1, tol);
			if (!c.hit)
				continue;
			n = add_point(scratch, n, hs_lerp(p0, p1, c.t_in), height_sum);
			n = add_point(scratch, n, hs_lerp(p0, p1, c.t_out), height_sum);
		}
	}
	return n;
}

static int support_points(const hs_world_model *model, hs_world_scratch *scratch, const hs_body *a, const hs_body *b, int n,
                          double *height_sum) {
	n = clip_edges(model, scratch, a, b, n, height_sum);
	return clip_edges(model, scratch, b, a, n, height_sum);
}

// j can hold `object` up: near it, not itself, its G not above the object's.
static bool is_support(const hs_world_model *model, const hs_body *bodies, int object, int j, double tol) {
	return j != object && near_spheres(model, bodies, object, j, tol) && bodies[j].pos.z <= bodies[object].pos.z;
}

// Contact points (scratch.points) of `object` on the supports among bp->scratch->near[0 .. near_count).
static int contacts(const hs_broadphase *bp, int object, int near_count, double *height_sum) {
	double tol = bp->model->def.floor_tolerance;
	int n = 0;
	for (int k = 0; k < near_count; ++k)
		if (is_support(bp->model, bp->bodies, object, bp->scratch->near[k], tol))
			n = support_points(bp->model, bp->scratch, &bp->bodies[object], &bp->bodies[bp->scratch->near[k]], n, height_sum);
	return n;
}

// Depth under a support's face at which a point counts as over it: a tilted support's face lies
// off the contact plane by its tilt times the object's size (a noisy hand's 0.15 deg: 0.1 mm).
#define HS_SUPPORT_PROBE 1e-3

static bool inside_part(const hs_shape *shape, const hs_part *part, hs_vec3 q) {
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f)
		if (hs_dot(shape->faces[f].normal, q) >= shape->faces[f].offset)
			return false;
	return true;
}

// p lies on the top of one of the supports (a point just under it is inside one).
static bool over_support(const hs_motion_pass *m, const hs_settle_supports *sup, hs_vec3 p) {
	hs_vec3 below = hs_v3(p.x, p.y, p.z - HS_SUPPORT_PROBE);
	for (int k = 0; k < sup->near_count; ++k) {
		int j = m->scratch->near[k];
		if (!is_support(m->model, m->bodies, sup->object, j, m->model->def.floor_tolerance))
			continue;
		const hs_body *b = &m->bodies[j];
		const hs_shape *sb = &m->model->shapes[b->shape];
		for (int part = 0; part < sb->part_count; ++part)
			if (inside_part(sb, &sb->parts[part], to_local(b, below)))
				return true;
	}
	return false;
}

static hs_vec3 centre(const hs_vec2 *points, int n, double z) {
	double x = 0.0, y = 0.0;
	for (int i = 0; i < n; ++i) {
		x += points[i].x;
		y += points[i].y;
	}
	return hs_v3(x / n, y / n, z);
}

// The upward face (within 60 deg of +z, as stacking.c's vertical lift) of a support nearest the
// contacts' centre `p`: the plane a tipping turn lands on. Horizontal through p when none is.
static void support_plane(const hs_broadphase *bp, hs_settle_supports *sup, hs_vec3 p) {
	double best = INFINITY;
	sup->normal = hs_v3(0, 0, 1);
	sup->offset = p.z;
	for (int k = 0; k < sup->near_count; ++k) {
		int j = bp->scratch->near[k];
		if (!is_support(bp->model, bp->bodies, sup->object, j, bp->model->def.floor_tolerance))
			continue;
		const hs_body *b = &bp->bodies[j];
		const hs_shape *sb = &bp->model->shapes[b->shape];
		for (int f = 0; f < sb->face_count; ++f) {
			hs_vec3 n = hs_quat_rotate(b->rot, sb->faces[f].normal);
			double off = sb->faces[f].offset + hs_dot(n, b->pos);
			double d = fabs(hs_dot(n, p) - off);
			if (n.z > 0.5 && d < best) {
				best = d;
				sup->normal = n;
				sup->offset = off;
			}
		}
	}
}

// Vertices of the body on the floor, added to the support contacts (resting on both at once).
static int floor_points(const hs_world_model *model, hs_world_scratch *scratch, const hs_body *body, int n,
                        double *height_sum) {
	const hs_shape *shape = &model->shapes[body->shape];
	double tol = model->def.floor_tolerance;
	int floor_n = 0;
	if (body->pos.z - shape->radius > tol)
		return 0;
	for (int i = 0; i < shape->vertex_count; ++i)
		if (scratch->posed[i].z <= tol)
			floor_n = add_point(scratch, n + floor_n, scratch->posed[i], height_sum) - n;
	return floor_n;
}

void hs_support_step(const hs_broadphase *bp, hs_world_counters *counters, int object) {
	hs_body *body = &bp->bodies[object];
	double tol = bp->model->def.floor_tolerance;
	double lift = 0.0;
	bool touching = false;
	int near_count = hs_grid_near(bp, body->pos, bp->model->shapes[body->shape].radius + tol);
	for (int k = 0; k < near_count; ++k) {
		int j = bp->scratch->near[k];
		if (!is_support(bp->model, bp->bodies, object, j, tol))
			continue; // a support is under the body's G
		double t = hs_stack_lift_out(&bp->model->shapes[body->shape], body, &bp->model->shapes[bp->bodies[j].shape],
		                             &bp->bodies[j]);
		lift = t > lift ? t : lift;
		touching = true;
	}
	if (!touching)
		return;
	hs_vec3 gm = hs_sub(body->pos, body->prev);
	body->pos.z += lift; // §4.2 rectification, against a support instead of the floor
	double height_sum = 0.0;
	int n = contacts(bp, object, near_count, &height_sum);
	if (n == 0)
		return; // near a neighbour but not resting on it
	body->spin = hs_quat_identity(); // §4.1: no inertia kept after interfering
	hs_motion_pose_vertices(bp->model, bp->scratch, body);
	int floor_n = floor_points(bp->model, bp->scratch, body, n, &height_sum);
	// stability on the support faces, tipping about their hull's edge when unstable; a turn stops
	// where a vertex reaches a support's face (eq. 7), or the floor when it touches the floor too
	hs_settle_supports sup = {object, near_count, hs_v3(0, 0, 1), 0.0, over_support};
	if (!floor_n)
		support_plane(bp, &sup, centre(bp->scratch->points, n, height_sum / n));
	hs_motion_pass m = {bp->model, bp->bodies, bp->scratch, counters};
	hs_motion_settle(&m, body, n + floor_n, height_sum / (n + floor_n), gm, true, floor_n ? NULL : &sup);
	body->grounded = 0; // the floor rules do not apply on a support; the next frame looks again
}

// j rests on `support` posed as `old`: they touch, the contact is above the support's G and is
// j's lowest point (on top of it, not beside it).
static bool rests_on(const hs_world_model *model, const hs_body *bodies, hs_world_scratch *scratch, int j,
                     const hs_body *old) {
	const hs_body *b = &bodies[j];
	if (b->held || b->pos.z <= old->pos.z)
		return false;
	double height_sum = 0.0;
	int n = support_points(model, scratch, b, old, 0, &height_sum);
	if (n == 0)
		return false;
	double mean = height_sum / n, zmin = hs_motion_pose_vertices(model, scratch, b);
	return mean > old->pos.z && zmin >= mean - HS_SUPPORT_PROBE;
}

// A hand moved the support (held, from prev / rot_prev to pos / rot): what rests on top of it is
// carried by the same rigid motion, its contact kept (not rectified out of it a frame later).
static void carry(const hs_broadphase *bp, int j, const hs_body *support) {
	hs_body *b = &bp->bodies[j];
	hs_quat q = hs_quat_normalize(hs_quat_mul(support->rot, hs_quat_conj(support->rot_prev)));
	hs_vec3 v = hs_sub(b->pos, b->prev);
	b->pos = hs_add(support->pos, hs_quat_rotate(q, hs_sub(b->pos, support->prev)));
	b->rot = hs_quat_normalize(hs_quat_mul(q, b->rot));
	b->prev = hs_sub(b->pos, v); // carried, not thrown: no inertia gained
	hs_grid_update(bp->model, bp->bodies, bp->cache, j);
}

// A push does not sink the object into a support (§4.2 rectification, as on the floor); the lift
// is not motion: a push that ends does not launch it by it (its release keeps the frame's motion).
static void rectify_pushed(const hs_broadphase *bp, int object) {
	hs_body *body = &bp->bodies[object];
	hs_vec3 before = body->pos;
	if (!hs_stack_rectify(bp, object))
		return;
	body->prev = hs_add(body->prev, hs_sub(body->pos, before));
	hs_grid_update(bp->model, bp->bodies, bp->cache, object);
}

// Where the held body's rigid motion this frame took carried object j from: its pose at the frame's
// start (the held body's own: prev and rot_prev).
static hs_body pose_before(const hs_body *bodies, int j, const hs_body *held) {
	hs_body old = bodies[j];
	if (&bodies[j] == held) {
		old.pos = held->prev;
		old.rot = held->rot_prev;
		return old;
	}
	hs_quat q = hs_quat_normalize(hs_quat_mul(held->rot, hs_quat_conj(held->rot_prev)));
	old.pos = hs_add(held->prev, hs_quat_inv_rotate(q, hs_sub(old.pos, held->pos)));
	old.rot = hs_quat_normalize(hs_quat_mul(hs_quat_conj(q), old.rot));
	return old;
}

static bool queued(const int *queue, int tail, int j) {
	for (int k = 0; k < tail; ++k)
		if (queue[k] == j)
			return true;
	return false;
}

// What rests on the held object where it was at the frame's start, what rests on that, and so on:
// all carried by its rigid motion (a stack of three lifted by its bottom cube keeps its top).
// Only for a held object, moved in the hand pass: the world step's own use of scratch->queue (the
// objects free motion moved) never reaches here.
static void carry_stack(const hs_broadphase *bp, int object) {
	const hs_body *held = &bp->bodies[object];
	double tol = bp->model->def.floor_tolerance + hs_length(hs_sub(held->pos, held->prev));
	int head = 0, tail = 0;
	bp->scratch->queue[tail++] = object;
	while (head < tail) {
		int s = bp->scratch->queue[head++];
		hs_body old = pose_before(bp->bodies, s, held);
		int n = hs_grid_near(bp, bp->bodies[s].pos, bp->model->shapes[old.shape].radius + tol);
		for (int k = 0; k < n; ++k) {
			int j = bp->scratch->near[k];
			if (j == s || queued(bp->scratch->queue, tail, j) || !near_spheres(bp->model, bp->bodies, s, j, tol))
				continue;
			if (rests_on(bp->model, bp->bodies, bp->scratch, j, &old)) {
				carry(bp, j, held);
				bp->scratch->queue[tail++] = j;
			}
			if (bp->bodies[j].asleep)
				hs_wake(bp->bodies, bp->cache, j);
		}
	}
}

// The lowest and highest z of a body's vertices as posed now.
static void z_range(const hs_world_model *model, hs_world_scratch *scratch, const hs_body *b, double *lo, double *hi) {
	*lo = hs_motion_pose_vertices(model, scratch, b);
	*hi = -INFINITY;
	for (int i = 0; i < model->shapes[b->shape].vertex_count; ++i)
		*hi = scratch->posed[i].z > *hi ? scratch->posed[i].z : *hi;
}

// Objects beside what a hand pushes (docs/model.md §6): an object the pushed one moved into, not
// resting on it nor under it (one's G within the other's heights), is pushed
// along by the push's horizontal motion d, and what that one moves into in turn: a box pushed into
// a cube on the floor moves the cube, instead of stopping while the fingers sink into it.
static void push_aside(const hs_broadphase *bp, int object, hs_vec3 d) {
	if (!(d.x * d.x + d.y * d.y > 0.0))
		return;
	int head = 0, tail = 0;
	bp->scratch->queue[tail++] = object;
	while (head < tail) {
		int s = bp->scratch->queue[head++];
		double slo, shi;
		z_range(bp->model, bp->scratch, &bp->bodies[s], &slo, &shi);
		int n = hs_grid_near(bp, bp->bodies[s].pos, bp->model->shapes[bp->bodies[s].shape].radius);
		for (int k = 0; k < n; ++k) {
			int j = bp->scratch->near[k];
			hs_body *b = &bp->bodies[j];
			if (b->held || queued(bp->scratch->queue, tail, j) ||
			    !hs_objects_interfere(bp->model, bp->bodies, bp->cache->box_memo, s, j))
				continue;
			double jlo, jhi, sz = bp->bodies[s].pos.z;
			z_range(bp->model, bp->scratch, b, &jlo, &jhi);
			bool beside = (b->pos.z > slo && b->pos.z < shi) || (sz > jlo && sz < jhi); // not on it nor under it
			if (!beside || d.x * (b->pos.x - bp->bodies[s].pos.x) + d.y * (b->pos.y - bp->bodies[s].pos.y) <= 0.0)
				continue; // on it, under it, or behind the push
			b->pos = hs_add(b->pos, d);
			b->prev = hs_add(b->prev, d); // pushed, not thrown: no inertia gained
			hs_grid_update(bp->model, bp->bodies, bp->cache, j);
			hs_wake(bp->bodies, bp->cache, j);
			bp->scratch->queue[tail++] = j;
		}
	}
}

void hs_support_wake_neighbours(const hs_broadphase *bp, int object, hs_vec3 from) {
	const hs_body *body = &bp->bodies[object];
	if (body->held && body->contact != HS_CONTACT_GRASP) {
		push_aside(bp, object, hs_v3(body->pos.x - body->prev.x, body->pos.y - body->prev.y, 0.0));
		rectify_pushed(bp, object);
	}
	if (body->held) {
		carry_stack(bp, object);
		return;
	}
	// what rested on it where it was at the frame's start: its motion this frame is the margin (from
	// the frame's start: a landing sets prev to where it landed)
	double tol = bp->model->def.floor_tolerance + hs_length(hs_sub(body->pos, from));
	int n = hs_grid_near(bp, body->pos, bp->model->shapes[body->shape].radius + tol);
	for (int k = 0; k < n; ++k) {
		int j = bp->scratch->near[k];
		if (j != object && near_spheres(bp->model, bp->bodies, object, j, tol) && bp->bodies[j].asleep)
			hs_wake(bp->bodies, bp->cache, j);
	}
}
