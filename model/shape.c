// shape.c — rigid polyhedra made of convex parts: built-ins, validation, mass properties.
//
// Every shape goes through one builder: it validates each convex part, orients its faces
// outward, lists its edges, integrates volume and centre of gravity G (divergence theorem),
// then moves the body frame to G. Built-ins and user polyhedra share the same checks.
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "handspring.h"

// Planarity and convexity are judged relative to the part's size (its bounding-box diagonal).
#define HS_SHAPE_REL_TOL 1e-9
// A face whose area is below this fraction of size² has no usable normal.
#define HS_SHAPE_REL_AREA 1e-12

const char *hs_status_string(hs_status status) {
	switch (status) {
	case HS_OK:
		return "ok";
	case HS_ERR_INVALID_ARGUMENT:
		return "invalid argument";
	case HS_ERR_DEGENERATE:
		return "degenerate shape";
	case HS_ERR_CAPACITY:
		return "capacity exceeded";
	case HS_ERR_NO_MEMORY:
		return "out of memory";
	case HS_ERR_STATE_MISMATCH:
		return "saved state does not match this world";
	}
	return "unknown status";
}

// One convex part as given: vertices and faces (lists of indices into `vertices`, any winding).
typedef struct part_src {
	const hs_vec3 *vertices;
	int vertex_count;
	const int *face_vertices; // concatenated, face_sizes[f] entries per face
	const int *face_sizes;
	int face_count;
} part_src;

// One side of an edge seen from a face, for sorting edges into pairs.
typedef struct half_edge {
	int lo, hi; // local vertex indices, lo < hi
	int face;   // local face index
} half_edge;

static void set_status(hs_status *status, hs_status value) {
	if (status)
		*status = value;
}

static void set_why(char *why, size_t why_size, const char *format, ...) {
	if (!why || why_size == 0)
		return;
	va_list args;
	va_start(args, format);
	vsnprintf(why, why_size, format, args);
	va_end(args);
}

void hs_shape_destroy(hs_shape *shape) {
	if (!shape)
		return;
	free(shape->parts);
	free(shape->vertices);
	free(shape->faces);
	free(shape->face_vertices);
	free(shape->edges);
	free(shape);
}

static int compare_half_edges(const void *pa, const void *pb) {
	const half_edge *a = pa, *b = pb;
	if (a->lo != b->lo)
		return a->lo < b->lo ? -1 : 1;
	if (a->hi != b->hi)
		return a->hi < b->hi ? -1 : 1;
	if (a->face != b->face)
		return a->face < b->face ? -1 : 1;
	return 0;
}

// Topology of one part (counts and face sizes already checked): index range, repeats, unused
// vertices, every edge shared by exactly two faces, Euler characteristic 2. Fills `halves`
// (sorted in pairs); `used` is scratch.
static hs_status check_topology(const part_src *src, half_edge *halves, unsigned char *used, char *why,
                                size_t why_size) {
	int nv = src->vertex_count, nf = src->face_count;
	memset(used, 0, (size_t)nv);
	int first = 0, half_count = 0;
	for (int f = 0; f < nf; f++) {
		int k = src->face_sizes[f];
		const int *idx = src->face_vertices + first;
		for (int i = 0; i < k; i++) {
			if (idx[i] < 0 || idx[i] >= nv) {
				set_why(why, why_size, "vertex index %d out of range", idx[i]);
				return HS_ERR_DEGENERATE;
			}
		}
		for (int i = 0; i < k; i++) {
			for (int j = i + 1; j < k; j++) {
				if (idx[i] == idx[j]) {
					set_why(why, why_size, "face %d repeats vertex %d", f, idx[i]);
					return HS_ERR_DEGENERATE;
				}
			}
			used[idx[i]] = 1;
			int u = idx[i], w = idx[(i + 1) % k];
			halves[half_count].lo = u < w ? u : w;
			halves[half_count].hi = u < w ? w : u;
			halves[half_count].face = f;
			half_count++;
		}
		first += k;
	}
	for (int v = 0; v < nv; v++) {
		if (!used[v]) {
			set_why(why, why_size, "vertex %d is unused", v);
			return HS_ERR_DEGENERATE;
		}
	}
	// keys (lo, hi, face) are unique, so the sorted order does not depend on qsort's stability
	qsort(halves, (size_t)half_count, sizeof *halves, compare_half_edges);
	int edge_count = 0;
	for (int i = 0; i < half_count;) {
		int j = i + 1;
		while (j < half_count && halves[j].lo == halves[i].lo && halves[j].hi == halves[i].hi)
			j++;
		if (j - i != 2) {
			set_why(why, why_size, "edge %d-%d is not shared by exactly two faces", halves[i].lo, halves[i].hi);
			return HS_ERR_DEGENERATE;
		}
		edge_count++;
		i = j;
	}
	int euler = nv - edge_count + nf;
	if (euler != 2) {
		set_why(why, why_size, "v - e + f is %d, not 2", euler);
		return HS_ERR_DEGENERATE;
	}
	return HS_OK;
}

// Newell's normal of a polygon (length = twice its area), counter-clockwise order.
static hs_vec3 newell_normal(const hs_vec3 *p, const int *idx, int k) {
	hs_vec3 n = hs_v3(0.0, 0.0, 0.0);
	for (int i = 0; i < k; i++) {
		hs_vec3 a = p[idx[i]];
		hs_vec3 b = p[idx[(i + 1) % k]];
		n.x += (a.y - b.y) * (a.z + b.z);
		n.y += (a.z - b.z) * (a.x + b.x);
		n.z += (a.x - b.x) * (a.y + b.y);
	}
	return n;
}

static hs_vec3 face_mean(const hs_vec3 *p, const int *idx, int k) {
	hs_vec3 m = hs_v3(0.0, 0.0, 0.0);
	for (int i = 0; i < k; i++)
		m = hs_add(m, p[idx[i]]);
	return hs_scale(m, 1.0 / (double)k);
}

// Where the shape being built stands: next free slot in each array.
typedef struct cursor {
	int vertex, face, face_vertex, edge;
} cursor;

// Geometry of one part, after check_topology: planar faces, a solid, convex faces and solid;
// then writes the part into `shape` (faces oriented outward, coordinates still as given) and
// adds its volume and first moment. `local` (vertex_count) and `flip` (face_count) are scratch.
static hs_status build_part(hs_shape *shape, int part_index, const part_src *src, const half_edge *halves,
                            hs_vec3 *local, unsigned char *flip, cursor *at, double *volume, hs_vec3 *moment,
                            char *why, size_t why_size) {
	int nv = src->vertex_count, nf = src->face_count;
	// work relative to the vertex mean: it keeps rounding small and is inside a convex solid
	hs_vec3 c = hs_v3(0.0, 0.0, 0.0);
	for (int v = 0; v < nv; v++)
		c = hs_add(c, src->vertices[v]);
	c = hs_scale(c, 1.0 / (double)nv);
	hs_vec3 lo = hs_v3(INFINITY, INFINITY, INFINITY), hi = hs_neg(lo);
	for (int v = 0; v < nv; v++) {
		local[v] = hs_sub(src->vertices[v], c);
		lo = hs_v3(fmin(lo.x, local[v].x), fmin(lo.y, local[v].y), fmin(lo.z, local[v].z));
		hi = hs_v3(fmax(hi.x, local[v].x), fmax(hi.y, local[v].y), fmax(hi.z, local[v].z));
	}
	double size = hs_distance(lo, hi);
	double tol = HS_SHAPE_REL_TOL * size;
	if (!(size > 0.0) || !isfinite(size)) {
		set_why(why, why_size, "shape has no volume");
		return HS_ERR_DEGENERATE;
	}

	// planes: Newell normal, offset through the face's vertex mean
	hs_face *faces = shape->faces + at->face;
	int first = 0;
	for (int f = 0; f < nf; f++) {
		int k = src->face_sizes[f];
		const int *idx = src->face_vertices + first;
		hs_vec3 n = newell_normal(local, idx, k);
		double len = hs_length(n);
		if (!(0.5 * len > HS_SHAPE_REL_AREA * size * size)) {
			set_why(why, why_size, "face %d has no area", f);
			return HS_ERR_DEGENERATE;
		}
		n = hs_scale(n, 1.0 / len);
		double offset = hs_dot(n, face_mean(local, idx, k));
		for (int i = 0; i < k; i++) {
			if (fabs(hs_dot(n, local[idx[i]]) - offset) > tol) {
				set_why(why, why_size, "face %d is not planar", f);
				return HS_ERR_DEGENERATE;
			}
		}
		faces[f].normal = n;
		faces[f].offset = offset;
		first += k;
	}

	// all vertices on one plane: a flat shape
	bool flat = true;
	for (int v = 0; v < nv && flat; v++)
		flat = fabs(hs_dot(faces[0].normal, local[v]) - faces[0].offset) <= tol;
	if (flat) {
		set_why(why, why_size, "shape has no volume");
		return HS_ERR_DEGENERATE;
	}

	// orient outward: the vertex mean (local origin) must lie behind every face plane;
	// a face plane through it cannot belong to a convex solid
	for (int f = 0; f < nf; f++) {
		double d = -faces[f].offset; // dot(n, 0) - offset
		if (fabs(d) <= tol) {
			set_why(why, why_size, "shape is not convex");
			return HS_ERR_DEGENERATE;
		}
		flip[f] = d > 0.0;
		if (flip[f]) {
			faces[f].normal = hs_neg(faces[f].normal);
			faces[f].offset = -faces[f].offset;
		}
	}

	// each face a convex polygon: every turn is to the left about the outward normal
	first = 0;
	for (int f = 0; f < nf; f++) {
		int k = src->face_sizes[f];
		const int *idx = src->face_vertices + first;
		for (int i = 0; i < k; i++) {
			int i0 = flip[f] ? k - 1 - i : i;
			int i1 = flip[f] ? (2 * k - 2 - i) % k : (i + 1) % k;
			int i2 = flip[f] ? (3 * k - 3 - i) % k : (i + 2) % k;
			hs_vec3 e0 = hs_sub(local[idx[i1]], local[idx[i0]]);
			hs_vec3 e1 = hs_sub(local[idx[i2]], local[idx[i1]]);
			if (hs_dot(hs_cross(e0, e1), faces[f].normal) < -tol * size) {
				set_why(why, why_size, "face %d is not convex", f);
				return HS_ERR_DEGENERATE;
			}
		}
		first += k;
	}

	// convex solid: every vertex behind every face plane
	for (int f = 0; f < nf; f++) {
		for (int v = 0; v < nv; v++) {
			if (hs_dot(faces[f].normal, local[v]) - faces[f].offset > tol) {
				set_why(why, why_size, "shape is not convex");
				return HS_ERR_DEGENERATE;
			}
		}
	}

	// volume and first moment: signed tetrahedra (0, v0, vi, vi+1) fanned over each face,
	// in face order, so the sums are the same on every run
	double vol6 = 0.0;
	hs_vec3 mom24 = hs_v3(0.0, 0.0, 0.0);
	first = 0;
	for (int f = 0; f < nf; f++) {
		int k = src->face_sizes[f];
		const int *idx = src->face_vertices + first;
		hs_vec3 a = local[idx[flip[f] ? k - 1 : 0]];
		for (int i = 1; i + 1 < k; i++) {
			hs_vec3 b = local[idx[flip[f] ? k - 1 - i : i]];
			hs_vec3 d = local[idx[flip[f] ? k - 2 - i : i + 1]];
			double t6 = hs_dot(a, hs_cross(b, d));
			vol6 += t6;
			mom24 = hs_mul_add(mom24, t6, hs_add(hs_add(a, b), d)); // centroid (0 + a + b + d) / 4
		}
		first += k;
	}
	double part_volume = vol6 / 6.0;
	if (!(part_volume > tol * tol * tol) || !isfinite(part_volume)) {
		set_why(why, why_size, "shape has no volume");
		return HS_ERR_DEGENERATE;
	}
	// the part's centroid, back in the coordinates it was given in
	hs_vec3 centroid = hs_add(c, hs_scale(mom24, 1.0 / (4.0 * vol6)));
	*volume += part_volume;
	*moment = hs_mul_add(*moment, part_volume, centroid);

	// write vertices, faces (outward winding), edges
	hs_part *part = &shape->parts[part_index];
	part->first_vertex = at->vertex;
	part->vertex_count = nv;
	part->first_face = at->face;
	part->face_count = nf;
	part->first_edge = at->edge;
	for (int v = 0; v < nv; v++)
		shape->vertices[at->vertex + v] = src->vertices[v];
	first = 0;
	for (int f = 0; f < nf; f++) {
		int k = src->face_sizes[f];
		const int *idx = src->face_vertices + first;
		faces[f].first_index = at->face_vertex;
		faces[f].index_count = k;
		faces[f].part = part_index;
		for (int i = 0; i < k; i++)
			shape->face_vertices[at->face_vertex + i] = at->vertex + idx[flip[f] ? k - 1 - i : i];
		at->face_vertex += k;
		first += k;
	}
	// halves come in pairs; a -> b runs counter-clockwise in faces[0]
	int half_count = first;
	for (int i = 0; i < half_count; i += 2) {
		const half_edge *h = &halves[i];
		int f0 = h->face, f1 = halves[i + 1].face;
		// does face f0, as now oriented, run lo -> hi?
		const hs_face *face = &shape->faces[at->face + f0];
		const int *fv = shape->face_vertices + face->first_index;
		bool forward = false;
		for (int j = 0; j < face->index_count; j++) {
			if (fv[j] == at->vertex + h->lo) {
				forward = fv[(j + 1) % face->index_count] == at->vertex + h->hi;
				break;
			}
		}
		hs_edge *e = &shape->edges[at->edge++];
		e->a = at->vertex + h->lo;
		e->b = at->vertex + h->hi;
		e->faces[0] = at->face + (forward ? f0 : f1);
		e->faces[1] = at->face + (forward ? f1 : f0);
	}
	part->edge_count = at->edge - part->first_edge;
	at->vertex += nv;
	at->face += nf;
	return HS_OK;
}

// Validates and assembles a shape from convex parts, then moves the body frame to G.
// `exact_sphere` > 0 makes an HS_SHAPE_SPHERE: G stays at the given origin and the volume is exact.
static hs_shape *build_shape(hs_shape_kind kind, const part_src *parts, int part_count, double exact_sphere,
                             char *why, size_t why_size, hs_status *status) {
	long long total_v = 0, total_f = 0, total_fv = 0;
	int max_v = 0, max_f = 0, max_fv = 0;
	// counts first: they bound every array below
	for (int p = 0; p < part_count; p++) {
		const char *bad = NULL;
		if (parts[p].vertex_count < 4)
			bad = "fewer than 4 vertices";
		else if (parts[p].face_count < 4)
			bad = "fewer than 4 faces";
		if (bad) {
			set_why(why, why_size, "%s", bad);
			set_status(status, HS_ERR_DEGENERATE);
			return NULL;
		}
		int fv = 0;
		for (int f = 0; f < parts[p].face_count; f++) {
			int k = parts[p].face_sizes[f];
			if (k < 3 || k > parts[p].vertex_count) {
				set_why(why, why_size, k < 3 ? "face %d has fewer than 3 vertices" : "face %d has more vertices than the shape", f);
				set_status(status, HS_ERR_DEGENERATE);
				return NULL;
			}
			fv += k; // k <= vertex_count, checked against the limit each step: no overflow
			if (fv > INT_MAX / 4) {
				set_why(why, why_size, "shape too large");
				set_status(status, HS_ERR_INVALID_ARGUMENT);
				return NULL;
			}
		}
		total_v += parts[p].vertex_count;
		total_f += parts[p].face_count;
		total_fv += fv;
		max_v = parts[p].vertex_count > max_v ? parts[p].vertex_count : max_v;
		max_f = parts[p].face_count > max_f ? parts[p].face_count : max_f;
		max_fv = fv > max_fv ? fv : max_fv;
	}
	if (total_v > INT_MAX / 4 || total_f > INT_MAX / 4 || total_fv > INT_MAX / 4) {
		set_why(why, why_size, "shape too large");
		set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}

	hs_shape *shape = calloc(1, sizeof *shape);
	half_edge *halves = malloc((size_t)(max_fv > 0 ? max_fv : 1) * sizeof *halves);
	unsigned char *used = malloc((size_t)(max_v > 0 ? max_v : 1));
	unsigned char *flip = malloc((size_t)(max_f > 0 ? max_f : 1));
	hs_vec3 *local = malloc((size_t)(max_v > 0 ? max_v : 1) * sizeof *local);
	if (shape) {
		shape->parts = calloc((size_t)part_count, sizeof *shape->parts);
		shape->vertices = calloc((size_t)(total_v > 0 ? total_v : 1), sizeof *shape->vertices);
		shape->faces = calloc((size_t)(total_f > 0 ? total_f : 1), sizeof *shape->faces);
		shape->face_vertices = calloc((size_t)(total_fv > 0 ? total_fv : 1), sizeof *shape->face_vertices);
		shape->edges = calloc((size_t)(total_fv / 2 > 0 ? total_fv / 2 : 1), sizeof *shape->edges);
	}
	hs_status result = HS_OK;
	if (!shape || !halves || !used || !flip || !local || !shape->parts || !shape->vertices || !shape->faces ||
	    !shape->face_vertices || !shape->edges) {
		set_why(why, why_size, "out of memory");
		result = HS_ERR_NO_MEMORY;
	}

	cursor at = {0, 0, 0, 0};
	double volume = 0.0;
	hs_vec3 moment = hs_v3(0.0, 0.0, 0.0);
	for (int p = 0; p < part_count && result == HS_OK; p++) {
		result = check_topology(&parts[p], halves, used, why, why_size);
		if (result == HS_OK)
			result = build_part(shape, p, &parts[p], halves, local, flip, &at, &volume, &moment, why, why_size);
	}
	free(halves);
	free(used);
	free(flip);
	free(local);
	if (result != HS_OK) {
		hs_shape_destroy(shape);
		set_status(status, result);
		return NULL;
	}

	shape->kind = kind;
	shape->part_count = part_count;
	shape->vertex_count = at.vertex;
	shape->face_count = at.face;
	shape->face_vertex_count = at.face_vertex;
	shape->edge_count = at.edge;
	// G of the uniform solid: volume-weighted part centroids
	hs_vec3 g = hs_scale(moment, 1.0 / volume);
	if (exact_sphere > 0.0) {
		g = hs_v3(0.0, 0.0, 0.0);
		volume = 4.0 / 3.0 * HS_PI * exact_sphere * exact_sphere * exact_sphere;
	}
	shape->volume = volume;
	shape->centroid_shift = g;
	shape->sphere_radius = exact_sphere;
	for (int v = 0; v < shape->vertex_count; v++)
		shape->vertices[v] = hs_sub(shape->vertices[v], g);
	for (int f = 0; f < shape->face_count; f++) {
		hs_face *face = &shape->faces[f];
		hs_vec3 m = face_mean(shape->vertices, shape->face_vertices + face->first_index, face->index_count);
		face->offset = hs_dot(face->normal, m);
	}
	// bounding spheres: about the vertex mean for a part (inside it, as MPR needs), about G for the shape
	double radius = 0.0;
	for (int p = 0; p < part_count; p++) {
		hs_part *part = &shape->parts[p];
		hs_vec3 c = hs_v3(0.0, 0.0, 0.0);
		for (int v = 0; v < part->vertex_count; v++)
			c = hs_add(c, shape->vertices[part->first_vertex + v]);
		c = hs_scale(c, 1.0 / (double)part->vertex_count);
		double r = 0.0;
		for (int v = 0; v < part->vertex_count; v++) {
			hs_vec3 x = shape->vertices[part->first_vertex + v];
			r = fmax(r, hs_distance(x, c));
			radius = fmax(radius, hs_length(x));
		}
		part->center = c;
		part->radius = r;
	}
	shape->radius = radius;
	if (exact_sphere > 0.0) {
		shape->radius = exact_sphere;
		shape->parts[0].center = hs_v3(0.0, 0.0, 0.0);
		shape->parts[0].radius = exact_sphere;
	}
	if (!isfinite(shape->volume) || !hs_vec3_is_finite(g) || !isfinite(shape->radius)) {
		set_why(why, why_size, "shape has no volume");
		hs_shape_destroy(shape);
		set_status(status, HS_ERR_DEGENERATE);
		return NULL;
	}
	if (why && why_size > 0)
		why[0] = '\0';
	set_status(status, HS_OK);
	return shape;
}

static bool valid_size(double x) { return isfinite(x) && x > 0.0; }
static bool valid_size3(hs_vec3 s) { return valid_size(s.x) && valid_size(s.y) && valid_size(s.z); }

// Box part over [lo, hi]: vertex i = (x bit 0, y bit 1, z bit 2) of i, faces wound outward.
static const int box_face_vertices[24] = {
    0, 2, 3, 1, // z = lo
    4, 5, 7, 6, // z = hi
    0, 1, 5, 4, // y = lo
    2, 6, 7, 3, // y = hi
    0, 4, 6, 2, // x = lo
    1, 3, 7, 5, // x = hi
};
static const int box_face_sizes[6] = {4, 4, 4, 4, 4, 4};

static void box_vertices(hs_vec3 lo, hs_vec3 hi, hs_vec3 out[8]) {
	for (int i = 0; i < 8; i++)
		out[i] = hs_v3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
}

static part_src box_src(const hs_vec3 vertices[8]) {
	part_src src = {vertices, 8, box_face_vertices, box_face_sizes, 6};
	return src;
}

hs_shape *hs_shape_box(hs_vec3 size, hs_status *status) {
	if (!valid_size3(size)) {
		set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	hs_vec3 v[8];
	hs_vec3 half = hs_scale(size, 0.5);
	box_vertices(hs_neg(half), half, v);
	part_src src = box_src(v);
	return build_shape(HS_SHAPE_BOX, &src, 1, 0.0, NULL, 0, status);
}

hs_shape *hs_shape_pyramid(double base, double height, hs_status *status) {
	if (!valid_size(base) || !valid_size(height)) {
		set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	double h = 0.5 * base;
	// base on z = 0, apex above its centre; the builder moves the origin to G (h/4 up)
	hs_vec3 v[5] = {hs_v3(-h, -h, 0.0), hs_v3(h, -h, 0.0), hs_v3(h, h, 0.0), hs_v3(-h, h, 0.0),
	                hs_v3(0.0, 0.0, height)};
	static const int fv[16] = {0, 3, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
	static const int fs[5] = {4, 3, 3, 3, 3};
	part_src src = {v, 5, fv, fs, 5};
	return build_shape(HS_SHAPE_PYRAMID, &src, 1, 0.0, NULL, 0, status);
}

hs_shape *hs_shape_l_block(hs_vec3 size, double thickness, hs_status *status) {
	if (!valid_size3(size) || !valid_size(thickness) || !(thickness < size.x) || !(thickness < size.z)) {
		set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	// two convex boxes in the x–z plane (the L-block is not convex): foot, then upright
	hs_vec3 foot[8], upright[8];
	box_vertices(hs_v3(0.0, 0.0, 0.0), hs_v3(size.x, size.y, thickness), foot);
	box_vertices(hs_v3(0.0, 0.0, thickness), hs_v3(thickness, size.y, size.z), upright);
	part_src src[2] = {box_src(foot), box_src(upright)};
	return build_shape(HS_SHAPE_L_BLOCK, src, 2, 0.0, NULL, 0, status);
}

// cos(k · 22.5°) from square roots only, so that no libm trigonometry (which the compiler may
// fold at compile time with another rounding) can make two builds differ.
static double cos16(int k) {
	double q[5] = {1.0, 0.5 * sqrt(2.0 + sqrt(2.0)), sqrt(0.5), 0.5 * sqrt(2.0 - sqrt(2.0)), 0.0};
	k = ((k % 16) + 16) % 16;
	if (k <= 4)
		return q[k];
	if (k <= 8)
		return -q[8 - k];
	if (k <= 12)
		return -q[k - 8];
	return q[16 - k];
}
static double sin16(int k) { return cos16(k - 4); }

// Largest UV polyhedron built here (the sphere's 16 slices × 8 stacks).
#define UV_MAX_VERTICES (2 + 16 * 7)
#define UV_MAX_FACES (16 * 8)
#define UV_MAX_FACE_VERTICES (16 * 3 * 2 + 16 * 6 * 4)

// UV polyhedron with semi-axes `axes`: `slices` around z, `stacks` from pole to pole (both divide
// 16 and 8 steps of 22.5°). Vertex 0 is the north pole, then rings top to bottom, then the south pole.
static hs_shape *uv_shape(hs_shape_kind kind, hs_vec3 axes, int slices, int stacks, double exact_sphere,
                          hs_status *status) {
	hs_vec3 v[UV_MAX_VERTICES];
	int fv[UV_MAX_FACE_VERTICES], fs[UV_MAX_FACES];
	int ds = 16 / slices, dt = 8 / stacks, nv = 0, nfv = 0, nf = 0;
	v[nv++] = hs_v3(0.0, 0.0, axes.z);
	for (int j = 1; j < stacks; j++) {
		double st = sin16(j * dt), ct = cos16(j * dt);
		for (int i = 0; i < slices; i++)
			v[nv++] = hs_v3(axes.x * st * cos16(i * ds), axes.y * st * sin16(i * ds), axes.z * ct);
	}
	v[nv++] = hs_v3(0.0, 0.0, -axes.z);
	int south = nv - 1;
	// ring j (1-based) slice i is vertex 1 + (j - 1) * slices + i
	for (int i = 0; i < slices; i++) { // north cap
		int i1 = (i + 1) % slices;
		fv[nfv++] = 0;
		fv[nfv++] = 1 + i;
		fv[nfv++] = 1 + i1;
		fs[nf++] = 3;
	}
	for (int j = 1; j + 1 < stacks; j++) { // planar trapezoids between rings j and j + 1
		for (int i = 0; i < slices; i++) {
			int i1 = (i + 1) % slices, top = 1 + (j - 1) * slices, low = top + slices;
			fv[nfv++] = top + i;
			fv[nfv++] = low + i;
			fv[nfv++] = low + i1;
			fv[nfv++] = top + i1;
			fs[nf++] = 4;
		}
	}
	int last = 1 + (stacks - 2) * slices;
	for (int i = 0; i < slices; i++) { // south cap
		int i1 = (i + 1) % slices;
		fv[nfv++] = south;
		fv[nfv++] = last + i1;
		fv[nfv++] = last + i;
		fs[nf++] = 3;
	}
	part_src src = {v, nv, fv, fs, nf};
	return build_shape(kind, &src, 1, exact_sphere, NULL, 0, status);
}

hs_shape *hs_shape_ellipsoid(hs_vec3 semi_axes, hs_status *status) {
	if (!valid_size3(semi_axes)) {
		set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	// 1999 paper, Exp. 3: "an ellipsoid of 32 faces and 56 edges" = 8 slices × 4 stacks
	return uv_shape(HS_SHAPE_ELLIPSOID, semi_axes, 8, 4, 0.0, status);
}

hs_shape *hs_shape_sphere(double radius, hs_status *status) {
	if (!valid_size(radius)) {
		set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	// exact sphere for the spring model's masses and collisions; the inscribed 16 × 8
	// polyhedron (poles on the sphere) serves display and floor contact
	return uv_shape(HS_SHAPE_SPHERE, hs_v3(radius, radius, radius), 16, 8, radius, status);
}

hs_shape *hs_shape_polyhedron(const hs_vec3 *vertices, int vertex_count, const int *face_vertices,
                              const int *face_sizes, int face_count, char *why, size_t why_size,
                              hs_status *status) {
	if (vertex_count < 0 || face_count < 0) {
		set_why(why, why_size, "negative count");
		set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	if ((vertex_count > 0 && !vertices) || (face_count > 0 && (!face_sizes || !face_vertices))) {
		set_why(why, why_size, "null pointer");
		set_status(status, HS_ERR_INVALID_ARGUMENT);
		return NULL;
	}
	for (int v = 0; v < vertex_count; v++) {
		if (!hs_vec3_is_finite(vertices[v])) {
			set_why(why, why_size, "vertex %d is not finite", v);
			set_status(status, HS_ERR_INVALID_ARGUMENT);
			return NULL;
		}
	}
	part_src src = {vertices, vertex_count, face_vertices, face_sizes, face_count};
	return build_shape(HS_SHAPE_POLYHEDRON, &src, 1, 0.0, why, why_size, status);
}
