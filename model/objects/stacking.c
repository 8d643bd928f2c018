// stacking.c — objects against objects, both stacking modes (1999 paper §4.3, Fig. 11: the
// penetration of the L-block into the cube "is handled by the rectification process for the
// penetration of the cube into a floor"). An object that sinks into objects under it is lifted
// along +z, as §4.2 lifts it out of the floor, until its lowest point rests on their surface.
//
// A fall is tested along its path: at 12 frames/s a cube falling 2 m moves 0.5 m in its last
// frame, more than the object it lands on is tall. The frame's motion is cut into sub-poses no
// longer than an eighth of the smaller bounding radius (conservative for the compact shapes of
// the catalog), and the first sub-pose that penetrates an object under it is where it landed.
#include "broadphase.h"
#include "stacking.h"

// Penetration shallower than this (m) is touching, not interference (libccd's own accuracy).
#define HS_STACK_SLOP 1e-9
// At most this many sub-poses per frame (a fall of 1000 bounding radii in one frame).
#define HS_STACK_MAX_SUBSTEPS 8192

static hs_vec3 to_local(const hs_body *b, hs_vec3 p) { return hs_quat_inv_rotate(b->rot, hs_sub(p, b->pos)); }

// Distance along `dir` (unit, local) from q, inside the part, to the part's boundary; -1 if q is outside.
static double exit_distance(const hs_shape *shape, const hs_part *part, hs_vec3 q, hs_vec3 dir, double slop) {
	double best = INFINITY;
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f) {
		const hs_face *face = &shape->faces[f];
		double gap = face->offset - hs_dot(face->normal, q);
		if (gap <= slop)
			return -1.0; // outside or on this face's plane
		double along = hs_dot(face->normal, dir);
		if (along > 0.0 && gap / along < best)
			best = gap / along;
	}
	return best;
}

double hs_stack_lift_out(const hs_shape *sa, const hs_body *a, const hs_shape *sb, const hs_body *b) {
	double lift = 0.0, slop = 1e-12;
	hs_vec3 up_in_b = hs_quat_inv_rotate(b->rot, hs_v3(0, 0, 1));
	hs_vec3 down_in_a = hs_quat_inv_rotate(a->rot, hs_v3(0, 0, -1));
	for (int p = 0; p < sb->part_count; ++p)
		for (int i = 0; i < sa->vertex_count; ++i) {
			hs_vec3 q = to_local(b, hs_add(a->pos, hs_quat_rotate(a->rot, sa->vertices[i])));
			double t = exit_distance(sb, &sb->parts[p], q, up_in_b, slop);
			lift = t > lift && isfinite(t) ? t : lift;
		}
	for (int p = 0; p < sa->part_count; ++p)
		for (int i = 0; i < sb->vertex_count; ++i) {
			hs_vec3 q = to_local(a, hs_add(b->pos, hs_quat_rotate(b->rot, sb->vertices[i])));
			double t = exit_distance(sa, &sa->parts[p], q, down_in_a, slop);
			lift = t > lift && isfinite(t) ? t : lift;
		}
	return lift;
}

// a, posed at `pos`, sinks into b deeper than touching.
static bool penetrates(const hs_world_model *model, const hs_body *a, hs_vec3 pos, const hs_body *b) {
	const hs_shape *sa = &model->shapes[a->shape], *sb = &model->shapes[b->shape];
	double r = sa->radius + sb->radius;
	if (hs_length_sq(hs_sub(pos, b->pos)) > r * r)
		return false;
	double depth = 0.0;
	hs_vec3 dir;
	return hs_shapes_penetration(sb, b->pos, b->rot, sa, pos, a->rot, &depth, &dir) && depth > HS_STACK_SLOP;
}

// Vertex-face interpenetration is lifted exactly; what is left (faces flush with each other, edges
// crossing: no vertex strictly inside) is found by bisection on the lift, ending within 0.1 um
// clear of touching (libccd GJK counts touching within ~1e-12 m as interference, and its builds
// differ by a few ulps between architectures: a bisection to 1e-13 m decided its last probes by them).
static double lift_from(const hs_world_model *model, const hs_body *a, const hs_body *b) {
	hs_body lifted = *a;
	double lo = hs_stack_lift_out(&model->shapes[a->shape], a, &model->shapes[b->shape], b);
	lifted.pos.z = a->pos.z + lo;
	if (!penetrates(model, &lifted, lifted.pos, b))
		return lo;
	const hs_shape *sa = &model->shapes[a->shape], *sb = &model->shapes[b->shape];
	double hi = lo + 2.0 * (sa->radius + sb->radius); // clear of b for certain
	for (int k = 0; k < 64 && hi - lo > 1e-7; ++k) {
		double mid = 0.5 * (lo + hi);
		lifted.pos.z = a->pos.z + mid;
		if (hs_shapes_overlap(sa, lifted.pos, lifted.rot, sb, b->pos, b->rot))
			lo = mid;
		else
			hi = mid;
	}
	return hi;
}

bool hs_stack_pile_onto(const hs_world_model *model, hs_body *bodies, int object, int mover) {
	hs_body *b = &bodies[object];
	const hs_shape *shape = &model->shapes[b->shape];
	double low = INFINITY;
	for (int i = 0; i < shape->vertex_count; ++i) {
		double z = b->pos.z + hs_quat_rotate(b->rot, shape->vertices[i]).z;
		low = z < low ? z : low;
	}
	double lift = lift_from(model, b, &bodies[mover]);
	if (!(lift <= b->pos.z - low))
		return false;
	// it stays sunk in by half the slop: interfering, so the next frames carry it along (§4.3),
	// yet not deep enough to be lifted again (rectify_against)
	lift -= 0.5 * HS_STACK_SLOP;
	b->pos.z += lift;
	b->prev.z += lift; // lifted, not thrown: no inertia gained
	return true;
}

static bool is_under(const hs_body *bodies, int object, int j, double z) {
	return j != object && bodies[j].pos.z <= z;
}

// Out of one object under it: vertically (§4.2) when that lift is at most twice the least
// penetration depth (the contact faces up, within 60 deg); against a steeper face (a wall, where a
// vertical lift grows as 1 / cos of the slope, up to the object's height) along libccd's
// direction of least penetration.
static bool rectify_against(const hs_world_model *model, hs_body *body, const hs_body *under) {
	const hs_shape *sa = &model->shapes[body->shape], *sb = &model->shapes[under->shape];
	double r = sa->radius + sb->radius, depth = 0.0;
	hs_vec3 dir;
	if (hs_length_sq(hs_sub(body->pos, under->pos)) > r * r ||
	    !hs_shapes_penetration(sb, under->pos, under->rot, sa, body->pos, body->rot, &depth, &dir) ||
	    !(depth > HS_STACK_SLOP))
		return false;
	double lift = lift_from(model, body, under);
	if (lift <= 2.0 * depth)
		body->pos.z += lift; // §4.2 rectification, against an object
	else
		body->pos = hs_mul_add(body->pos, depth, dir);
	return true;
}

bool hs_stack_rectify(const hs_broadphase *bp, int object) {
	hs_body *body = &bp->bodies[object];
	bool inside = false;
	for (int pass = 0; pass < 4; ++pass) { // leaving one may not leave another: look again
		bool moved = false;
		int n = hs_grid_near(bp, body->pos, bp->model->shapes[body->shape].radius);
		for (int k = 0; k < n; ++k)
			if (is_under(bp->bodies, object, bp->scratch->near[k], body->pos.z))
				moved = rectify_against(bp->model, body, &bp->bodies[bp->scratch->near[k]]) || moved;
		if (!moved)
			break;
		inside = true;
	}
	return inside;
}

// The first sub-pose (fraction of the frame's motion) at which the body sinks into an object
// under it; -1 when none does.
static double first_contact(const hs_broadphase *bp, int object, hs_vec3 from, hs_vec3 d) {
	const hs_body *body = &bp->bodies[object];
	double r = bp->model->shapes[body->shape].radius, len = hs_length(d);
	hs_vec3 mid = hs_mul_add(from, 0.5, d);
	int n = hs_grid_near(bp, mid, r + 0.5 * len);
	const int *near = bp->scratch->near;
	double step = INFINITY;
	for (int k = 0; k < n; ++k) {
		int j = near[k];
		double rj = bp->model->shapes[bp->bodies[j].shape].radius;
		if (is_under(bp->bodies, object, j, from.z))
			step = 0.125 * (r < rj ? r : rj) < step ? 0.125 * (r < rj ? r : rj) : step;
	}
	if (!isfinite(step))
		return -1.0;
	double cuts = len / step;
	int count = cuts < HS_STACK_MAX_SUBSTEPS ? (int)cuts + 1 : HS_STACK_MAX_SUBSTEPS;
	for (int s = 0; s <= count; ++s) {
		double t = (double)s / count;
		hs_vec3 p = hs_mul_add(from, t, d);
		for (int k = 0; k < n; ++k)
			if (is_under(bp->bodies, object, near[k], from.z) && penetrates(bp->model, body, p, &bp->bodies[near[k]]))
				return t;
	}
	return -1.0;
}

bool hs_stack_sweep(const hs_broadphase *bp, int object, hs_vec3 from) {
	hs_body *body = &bp->bodies[object];
	hs_vec3 d = hs_sub(body->pos, from);
	double t = first_contact(bp, object, from, d);
	if (t < 0.0)
		return false;
	body->pos = hs_mul_add(from, t, d);
	hs_stack_rectify(bp, object);
	body->spin = hs_quat_identity(); // §4.1: no inertia kept after interfering
	body->grounded = 0;               // on an object, not on the floor
	body->asleep = 0; // a frame's fall that ended below the floor settled it there: it lies here now
	return true;
}
