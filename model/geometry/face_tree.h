// face_tree.h — a hierarchy of normal cones over each many-faced convex part, so the hand check's
// per-point and per-line face loops (inside, nearest face, Cyrus-Beck clip, a sweep beyond a face)
// visit the faces near the point, not every face of the part (docs/model.md §3 "Many faces").
//
// A node holds faces whose outward normals lie within `spread` of its unit `axis`, and the least
// of their plane offsets; so for every face f of the node and any point p,
//     dot(n_f, p) - o_f <= dot(axis, p) + spread * |p| - offset_min        (the node's bound),
// and a node whose bound lies below what a query needs (with a slack far above rounding) cannot
// change that query's answer. Every query returns exactly what the scan of all faces in index
// order returns: ties go to the lower face index, as the scan's strict comparisons give them;
// a NaN skips nothing.
#ifndef HS_FACE_TREE_H
#define HS_FACE_TREE_H

#include <stdbool.h>

#include "clip.h"
#include "handspring.h"

// Parts with fewer faces than this are scanned: the scan is cheaper than the bounds.
#define HS_FACE_TREE_MIN_FACES 48
#define HS_FACE_TREE_LEAF 8

typedef struct hs_face_node {
	hs_vec3 axis;      // unit
	double spread;     // >= |n_f - axis| for every face below (rounded up)
	double offset_min; // least plane offset below
	int first, count;  // faces order[first .. first + count)
	int child;         // first of two children (child + 1 the second), -1 for a leaf
} hs_face_node;

typedef struct hs_face_tree {
	int *order;         // face indices, grouped by node
	hs_face_node *nodes;
	int *root;          // per part: its root node, -1 for a part that is scanned
	double *deviation;  // per part: how far a vertex of one of its faces lies off that face's plane, at most
	int part_count;
} hs_face_tree;

// Builds the tree of every part of `shape` with HS_FACE_TREE_MIN_FACES faces or more; false when
// out of memory (the tree is then empty and safe to free).
bool hs_face_tree_build(hs_face_tree *tree, const hs_shape *shape);
void hs_face_tree_free(hs_face_tree *tree);

// All four points lie beyond the face's plane by more than `margin` (the sweep test's per-face
// step, shared by contact_part.h's scan and the tree, and contact_cull.c's pass-overs with a margin).
static inline bool hs_face_beyond_by(const hs_face *face, const hs_vec3 q[4], double margin) {
	hs_vec3 n = face->normal;
	double o = face->offset + margin;
	return hs_dot(n, q[0]) > o && hs_dot(n, q[1]) > o && hs_dot(n, q[2]) > o && hs_dot(n, q[3]) > o;
}
static inline bool hs_face_beyond(const hs_face *face, const hs_vec3 q[4]) { return hs_face_beyond_by(face, q, 0.0); }

// The root of the part's tree, or -1 when the part is scanned (few faces, or no tree).
static inline int hs_face_tree_root(const hs_face_tree *tree, const hs_shape *shape, const hs_part *part) {
	if (!tree || !tree->root || !part)
		return -1;
	long p = part - shape->parts;
	return p >= 0 && p < tree->part_count ? tree->root[p] : -1;
}

// The queries from a part's root (hs_face_tree_root >= 0), each equal to the scan of the part's
// faces in index order that its comment names.
// Every face plane pushed out by `grow` has p strictly inside.
bool hs_face_tree_inside(const hs_face_tree *tree, int root, const hs_shape *shape, hs_vec3 p, double grow);
// The face whose plane p lies least deep below; `first` (the part's first face) when none compares
// (NaN), the first in index order on ties.
int hs_face_tree_nearest(const hs_face_tree *tree, int root, const hs_shape *shape, int first, hs_vec3 p);
// hs_clip_segment (clip.c): the same fields whenever it hits; a miss is a miss.
hs_clip hs_face_tree_clip(const hs_face_tree *tree, int root, const hs_shape *shape, hs_vec3 a, hs_vec3 b,
                          double grow);
// True when all four points lie strictly beyond one face plane of the part.
bool hs_face_tree_beyond(const hs_face_tree *tree, int root, const hs_shape *shape, const hs_vec3 q[4]);
// The faces of part `p` (its index) whose planes the convex hull of the four points may reach,
// into `out` (room for the part's faces), in no particular order; their count. A face left out
// has every point inside its plane by more than its vertices' deviation from it and the slack,
// so no edge of it meets the hull: an edge that does lies on two faces that are both listed.
int hs_face_tree_reached(const hs_face_tree *tree, int root, int p, const hs_shape *shape, const hs_vec3 q[4],
                         int *out);

#endif
