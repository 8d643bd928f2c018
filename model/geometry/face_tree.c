// face_tree.c — normal-cone hierarchies over many-faced convex parts (face_tree.h): built once
// when a shape is added to a world, queried by the hand check (contact_part.h, contact_swept.c).
#include <math.h>
#include <stdlib.h>

#include "face_tree.h"

#define HS_FACE_TREE_DEPTH 64 // a median split halves the faces: far more than 2^31 faces fit

// ---------------------------------------------------------------------------------------------
// Building

typedef struct builder {
	const hs_shape *shape;
	hs_face_tree *tree;
	int node_count;
	double *key; // scratch: the sort key of each face of the node being split
	int *buffer; // scratch: merge sort
} builder;

// Sorts order[0 .. n) by (key of the face, face index), bottom-up merge sort (stable, no recursion).
static void sort_by_key(int *order, int n, const double *key, int *buffer) {
	for (int width = 1; width < n; width *= 2) {
		for (int lo = 0; lo < n; lo += 2 * width) {
			int mid = lo + width < n ? lo + width : n, hi = lo + 2 * width < n ? lo + 2 * width : n;
			int i = lo, j = mid, o = lo;
			while (i < mid && j < hi) {
				int a = order[i], b = order[j];
				bool first = key[a] < key[b] || (key[a] == key[b] && a < b);
				buffer[o++] = first ? order[i++] : order[j++];
			}
			while (i < mid)
				buffer[o++] = order[i++];
			while (j < hi)
				buffer[o++] = order[j++];
		}
		for (int k = 0; k < n; ++k)
			order[k] = buffer[k];
	}
}

static double component(hs_vec3 v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }

// The cone of faces order[first .. first + count): its axis, spread and least offset.
static void fit_cone(const builder *b, hs_face_node *node) {
	const hs_face *faces = b->shape->faces;
	const int *order = b->tree->order + node->first;
	hs_vec3 sum = hs_v3(0.0, 0.0, 0.0);
	node->offset_min = INFINITY;
	for (int k = 0; k < node->count; ++k) {
		sum = hs_add(sum, faces[order[k]].normal);
		node->offset_min = fmin(node->offset_min, faces[order[k]].offset);
	}
	double len = hs_length(sum);
	// opposite normals may cancel: any unit axis bounds (only more loosely)
	node->axis = len > 1e-6 ? hs_scale(sum, 1.0 / len) : faces[order[0]].normal;
	double spread = 0.0;
	for (int k = 0; k < node->count; ++k)
		spread = fmax(spread, hs_length(hs_sub(faces[order[k]].normal, node->axis)));
	node->spread = spread * (1.0 + 1e-9) + 1e-12; // rounded up, so the bound stays a bound
}

// The normal component along which the node's faces spread most: the split's key.
static int widest_axis(const builder *b, const hs_face_node *node) {
	const hs_face *faces = b->shape->faces;
	const int *order = b->tree->order + node->first;
	double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
	for (int k = 0; k < node->count; ++k)
		for (int d = 0; d < 3; ++d) {
			double v = component(faces[order[k]].normal, d);
			lo[d] = fmin(lo[d], v);
			hi[d] = fmax(hi[d], v);
		}
	int best = 0;
	for (int d = 1; d < 3; ++d)
		if (hi[d] - lo[d] > hi[best] - lo[best])
			best = d;
	return best;
}

static void build_node(builder *b, int index) {
	hs_face_node *node = &b->tree->nodes[index];
	fit_cone(b, node);
	node->child = -1;
	if (node->count <= HS_FACE_TREE_LEAF)
		return;
	int axis = widest_axis(b, node);
	int *order = b->tree->order + node->first;
	for (int k = 0; k < node->count; ++k)
		b->key[order[k]] = component(b->shape->faces[order[k]].normal, axis);
	sort_by_key(order, node->count, b->key, b->buffer);
	int child = b->node_count;
	b->node_count += 2;
	int half = node->count / 2;
	b->tree->nodes[child] = (hs_face_node){.first = node->first, .count = half};
	b->tree->nodes[child + 1] = (hs_face_node){.first = node->first + half, .count = node->count - half};
	node->child = child; // (node may move no more: the node array is allocated once)
	build_node(b, child);
	build_node(b, child + 1);
}

// How far a vertex of one of the part's faces lies off that face's plane, at most (the shape
// builder accepts faces planar to 1e-9 of the part's size).
static double plane_deviation(const hs_shape *shape, const hs_part *part) {
	double worst = 0.0;
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f) {
		const hs_face *face = &shape->faces[f];
		for (int k = 0; k < face->index_count; ++k) {
			hs_vec3 v = shape->vertices[shape->face_vertices[face->first_index + k]];
			worst = fmax(worst, fabs(hs_dot(face->normal, v) - face->offset));
		}
	}
	return worst * 2.0;
}

bool hs_face_tree_build(hs_face_tree *tree, const hs_shape *shape) {
	*tree = (hs_face_tree){0};
	int faces = shape->face_count > 0 ? shape->face_count : 1;
	tree->order = malloc((size_t)faces * sizeof *tree->order);
	tree->nodes = malloc((size_t)(2 * faces) * sizeof *tree->nodes); // a binary tree on F leaves: < 2F nodes
	tree->root = malloc((size_t)(shape->part_count > 0 ? shape->part_count : 1) * sizeof *tree->root);
	tree->deviation = calloc((size_t)(shape->part_count > 0 ? shape->part_count : 1), sizeof *tree->deviation);
	builder b = {shape, tree, 0, malloc((size_t)faces * sizeof(double)), malloc((size_t)faces * sizeof(int))};
	bool ok = tree->order && tree->nodes && tree->root && tree->deviation && b.key && b.buffer;
	if (ok) {
		tree->part_count = shape->part_count;
		for (int f = 0; f < shape->face_count; ++f)
			tree->order[f] = f;
		for (int p = 0; p < shape->part_count; ++p) {
			const hs_part *part = &shape->parts[p];
			tree->root[p] = -1;
			if (part->face_count < HS_FACE_TREE_MIN_FACES)
				continue;
			tree->deviation[p] = plane_deviation(shape, part);
			tree->root[p] = b.node_count++;
			tree->nodes[tree->root[p]] = (hs_face_node){.first = part->first_face, .count = part->face_count};
			build_node(&b, tree->root[p]);
		}
	}
	free(b.key);
	free(b.buffer);
	if (!ok)
		hs_face_tree_free(tree);
	return ok;
}

void hs_face_tree_free(hs_face_tree *tree) {
	free(tree->order);
	free(tree->nodes);
	free(tree->root);
	free(tree->deviation);
	*tree = (hs_face_tree){0};
}

// ---------------------------------------------------------------------------------------------
// Queries

static double node_bound(const hs_face_node *n, hs_vec3 p, double length) {
	return hs_dot(n->axis, p) + n->spread * length - n->offset_min;
}

// True when every face below the node has dot(n_f, p) - o_f < limit, whatever the rounding of
// the scan's own sums: the slack (1 nm, and 1e-12 of the magnitudes) is some 10^4 times the
// largest rounding error of either side. False for NaN.
static double slack(double length, double offset, double limit) {
	return 1e-9 + 1e-12 * (length + fabs(offset) + fabs(limit));
}

static bool node_below(const hs_face_node *n, hs_vec3 p, double length, double limit) {
	return node_bound(n, p, length) < limit - slack(length, n->offset_min, limit);
}

// Whether the four points lie below the node by node_below: any of them (`all` false) or all.
static bool quad_below(const hs_face_node *n, const hs_vec3 q[4], const double length[4], double limit, bool all) {
	for (int k = 0; k < 4; ++k)
		if (node_below(n, q[k], length[k], limit) != all)
			return !all;
	return all;
}

bool hs_face_tree_inside(const hs_face_tree *tree, int root, const hs_shape *shape, hs_vec3 p, double grow) {
	double length = hs_length(p);
	int stack[HS_FACE_TREE_DEPTH], top = 0;
	stack[top++] = root;
	while (top > 0) {
		const hs_face_node *n = &tree->nodes[stack[--top]];
		if (node_below(n, p, length, grow))
			continue; // p is inside every plane below
		if (n->child >= 0) {
			stack[top++] = n->child;
			stack[top++] = n->child + 1;
			continue;
		}
		for (int k = n->first; k < n->first + n->count; ++k) {
			int f = tree->order[k];
			if (hs_dot(shape->faces[f].normal, p) >= shape->faces[f].offset + grow)
				return false;
		}
	}
	return true;
}

int hs_face_tree_nearest(const hs_face_tree *tree, int root, const hs_shape *shape, int first, hs_vec3 p) {
	int best = first;
	double best_depth = INFINITY;
	double length = hs_length(p);
	int stack[HS_FACE_TREE_DEPTH], top = 0;
	stack[top++] = root;
	while (top > 0) {
		const hs_face_node *n = &tree->nodes[stack[--top]];
		if (node_below(n, p, length, -best_depth))
			continue; // every face below lies deeper than the best: none replaces it, even on a tie
		if (n->child >= 0) { // the child whose faces may lie least deep first: the best comes early
			const hs_face_node *c0 = &tree->nodes[n->child], *c1 = c0 + 1;
			bool c0_first = node_bound(c0, p, length) >= node_bound(c1, p, length);
			stack[top++] = c0_first ? n->child + 1 : n->child;
			stack[top++] = c0_first ? n->child : n->child + 1;
			continue;
		}
		for (int k = n->first; k < n->first + n->count; ++k) {
			int f = tree->order[k];
			double depth = shape->faces[f].offset - hs_dot(shape->faces[f].normal, p);
			if (depth < best_depth || (depth == best_depth && f < best)) { // the scan's first on a tie
				best_depth = depth;
				best = f;
			}
		}
	}
	return best;
}

hs_clip hs_face_tree_clip(const hs_face_tree *tree, int root, const hs_shape *shape, hs_vec3 a, hs_vec3 b,
                          double grow) {
	hs_clip c = {0.0, 1.0, -1, -1, false};
	hs_vec3 d = hs_sub(b, a);
	double la = hs_length(a), lb = hs_length(b);
	int stack[HS_FACE_TREE_DEPTH], top = 0;
	stack[top++] = root;
	while (top > 0) {
		const hs_face_node *n = &tree->nodes[stack[--top]];
		// both ends inside every plane below: t < 0 entering, t > 1 leaving, never parallel outside
		if (node_below(n, a, la, grow) && node_below(n, b, lb, grow))
			continue;
		if (n->child >= 0) {
			stack[top++] = n->child;
			stack[top++] = n->child + 1;
			continue;
		}
		for (int k = n->first; k < n->first + n->count; ++k) {
			int f = tree->order[k];
			if (!hs_clip_face(&c, &shape->faces[f], f, a, d, grow) || c.t_in > c.t_out)
				return c; // parallel outside a face, or misses
		}
	}
	c.hit = c.t_in <= c.t_out;
	return c;
}

bool hs_face_tree_beyond(const hs_face_tree *tree, int root, const hs_shape *shape, const hs_vec3 q[4]) {
	double length[4];
	for (int k = 0; k < 4; ++k)
		length[k] = hs_length(q[k]);
	int stack[HS_FACE_TREE_DEPTH], top = 0;
	stack[top++] = root;
	while (top > 0) {
		const hs_face_node *n = &tree->nodes[stack[--top]];
		if (quad_below(n, q, length, 0.0, false))
			continue; // a point inside every plane below: no face below has all four beyond
		if (n->child >= 0) {
			stack[top++] = n->child;
			stack[top++] = n->child + 1;
			continue;
		}
		for (int k = n->first; k < n->first + n->count; ++k)
			if (hs_face_beyond(&shape->faces[tree->order[k]], q))
				return true;
	}
	return false;
}

int hs_face_tree_reached(const hs_face_tree *tree, int root, int p, const hs_shape *shape, const hs_vec3 q[4],
                         int *out) {
	double length[4], off = -tree->deviation[p]; // a face's vertices may lie this far inside its plane
	for (int k = 0; k < 4; ++k)
		length[k] = hs_length(q[k]);
	int count = 0, stack[HS_FACE_TREE_DEPTH], top = 0;
	stack[top++] = root;
	while (top > 0) {
		const hs_face_node *n = &tree->nodes[stack[--top]];
		if (quad_below(n, q, length, off, true))
			continue; // every point inside every plane below, by the margin
		if (n->child >= 0) {
			stack[top++] = n->child;
			stack[top++] = n->child + 1;
			continue;
		}
		for (int k = n->first; k < n->first + n->count; ++k) {
			int f = tree->order[k];
			const hs_face *face = &shape->faces[f];
			bool inside = true;
			for (int j = 0; j < 4 && inside; ++j) {
				inside = hs_dot(face->normal, q[j]) - face->offset < off - slack(length[j], face->offset, off);
			}
			if (!inside)
				out[count++] = f;
		}
	}
	return count;
}
