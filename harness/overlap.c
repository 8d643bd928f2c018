// overlap.c — objects that overlap at load are refused (scenarios/README.md, Objects): a scene of
// thousands of objects at one point gave no answer in minutes, so the loader names two objects
// that overlap instead of running it. Touching is not overlap: a point of one object must lie
// deeper than HS_OVERLAP_TOLERANCE inside a convex part of the other (for a point inside a convex
// part, its depth is its least distance to the part's face planes, so the test is exact for the
// points tested: each object's centre of gravity and vertices). Objects stacked or side by side
// touch at depth 0 and load.
//
// Cost: the objects' boxes are sorted along x and swept, so only pairs whose boxes overlap by more
// than the tolerance on every axis are tested; a scene of objects at one point stops at its first
// pair.
#include <math.h>
#include <stdlib.h>

#include "overlap.h"

typedef struct box {
	hs_vec3 lo, hi;
	int object;
} box;

// The object's shape in the world frame: its pose applied to a body-frame point.
typedef struct placed {
	const hs_shape *shape;
	hs_vec3 position;
	hs_quat orientation;
} placed;

static placed place(const hs_world *w, hs_object_id id) {
	placed p = {hs_world_shape(w, hs_world_object_shape(w, id)), hs_v3(0, 0, 0), hs_quat_identity()};
	hs_object_state st;
	if (hs_world_object_state(w, id, &st) == HS_OK) {
		p.position = st.position;
		p.orientation = st.orientation;
	}
	return p;
}

static hs_vec3 world_point(const placed *p, hs_vec3 body) { return hs_add(p->position, hs_quat_rotate(p->orientation, body)); }

// How deep the world point x lies inside part k of p (negative or zero: outside or on it).
static double depth_in_part(const placed *p, int k, hs_vec3 x) {
	const hs_part *part = &p->shape->parts[k];
	hs_vec3 local = hs_quat_inv_rotate(p->orientation, hs_sub(x, p->position));
	double depth = INFINITY;
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f) {
		const hs_face *face = &p->shape->faces[f];
		double d = face->offset - hs_dot(face->normal, local);
		depth = d < depth ? d : depth;
	}
	return depth;
}

static double depth_in(const placed *p, hs_vec3 x) {
	double depth = -INFINITY;
	for (int k = 0; k < p->shape->part_count; ++k) {
		double d = depth_in_part(p, k, x);
		depth = d > depth ? d : depth;
	}
	return depth;
}

// The deepest of a's centre and vertices inside b.
static double points_in(const placed *a, const placed *b) {
	double depth = depth_in(b, a->position);
	for (int v = 0; v < a->shape->vertex_count; ++v) {
		double d = depth_in(b, world_point(a, a->shape->vertices[v]));
		depth = d > depth ? d : depth;
	}
	return depth;
}

static box box_of(const hs_world *w, int i) {
	placed p = place(w, hs_world_object_at(w, i));
	box b = {p.position, p.position, i};
	for (int v = 0; p.shape && v < p.shape->vertex_count; ++v) {
		hs_vec3 x = world_point(&p, p.shape->vertices[v]);
		b.lo = hs_v3(fmin(b.lo.x, x.x), fmin(b.lo.y, x.y), fmin(b.lo.z, x.z));
		b.hi = hs_v3(fmax(b.hi.x, x.x), fmax(b.hi.y, x.y), fmax(b.hi.z, x.z));
	}
	return b;
}

static int by_lo_x(const void *a, const void *b) {
	const box *p = a, *q = b;
	return p->lo.x < q->lo.x ? -1 : p->lo.x > q->lo.x ? 1 : p->object - q->object;
}

static bool boxes_overlap(const box *a, const box *b, double tol) {
	return a->lo.x + tol < b->hi.x && b->lo.x + tol < a->hi.x && a->lo.y + tol < b->hi.y && b->lo.y + tol < a->hi.y &&
	       a->lo.z + tol < b->hi.z && b->lo.z + tol < a->hi.z;
}

static bool pair_overlaps(const hs_world *w, int i, int j, double tolerance, double *depth) {
	placed a = place(w, hs_world_object_at(w, i)), b = place(w, hs_world_object_at(w, j));
	if (!a.shape || !b.shape)
		return false;
	double ab = points_in(&a, &b), ba = points_in(&b, &a);
	*depth = ab > ba ? ab : ba;
	return *depth > tolerance;
}

bool hs_find_overlap(const hs_world *w, int *first, int *second, double *depth) {
	return hs_find_overlap_beyond(w, HS_OVERLAP_TOLERANCE, first, second, depth);
}

bool hs_find_overlap_beyond(const hs_world *w, double tolerance, int *first, int *second, double *depth) {
	int n = hs_world_object_count(w);
	box *boxes = malloc((size_t)(n > 0 ? n : 1) * sizeof *boxes);
	if (!boxes)
		return false; // out of memory: the run goes on unchecked (the world was built)
	for (int i = 0; i < n; ++i)
		boxes[i] = box_of(w, i);
	qsort(boxes, (size_t)n, sizeof *boxes, by_lo_x);
	bool found = false;
	for (int i = 0; i < n && !found; ++i)
		for (int j = i + 1; j < n && boxes[j].lo.x + tolerance < boxes[i].hi.x && !found; ++j) {
			if (!boxes_overlap(&boxes[i], &boxes[j], tolerance))
				continue;
			int a = boxes[i].object < boxes[j].object ? boxes[i].object : boxes[j].object;
			int b = boxes[i].object ^ boxes[j].object ^ a;
			if ((found = pair_overlaps(w, a, b, tolerance, depth))) {
				*first = a;
				*second = b;
			}
		}
	free(boxes);
	return found;
}

double hs_object_overlap(const hs_world *w, int object, int *other) {
	int n = hs_world_object_count(w);
	box a = box_of(w, object);
	placed pa = place(w, hs_world_object_at(w, object));
	double deepest = 0.0;
	*other = -1;
	for (int j = 0; j < n && pa.shape; ++j) {
		box b = box_of(w, j);
		if (j == object || !boxes_overlap(&a, &b, 0.0))
			continue;
		placed pb = place(w, hs_world_object_at(w, j));
		double depth = 0.0;
		hs_vec3 dir;
		if (pb.shape && hs_shapes_penetration(pa.shape, pa.position, pa.orientation, pb.shape, pb.position, pb.orientation,
		                                      &depth, &dir) && depth > deepest) {
			deepest = depth;
			*other = j;
		}
	}
	return deepest;
}
