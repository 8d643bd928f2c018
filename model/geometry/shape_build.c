// shape_build.c — the one builder of rigid polyhedra made of convex parts: it validates each
// convex part (topology, planar and convex faces, a convex solid), orients its faces outward,
// lists its edges, integrates volume and centre of gravity G (divergence theorem), then moves
// the body frame to G. Built-ins (shape.c) and user polyhedra share the same checks. What it
// allocates, hs_shape_destroy frees.
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shape_build.h"

// Planarity and convexity are judged relative to the part's size (its bounding-box diagonal).
#define HS_SHAPE_REL_TOL 1e-9
// A face whose area is below this fraction of size² has no usable normal.
#define HS_SHAPE_REL_AREA 1e-12

// One side of an edge seen from a face, for sorting edges into pairs.
typedef struct half_edge {
	int lo, hi; // local vertex indices, lo < hi
	int face;   // local face index
} half_edge;

void hs_shape_why(char *why, size_t why_size, const char *format, ...) {
	if (!why || why_size == 0)
		return;
	va_list args;
	va_start(args, format);
	vsnprintf(why, why_size, format, args);
	va_end(args);
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
				hs_shape_why(why, why_size, "vertex index %d out of range", idx[i]);
				return HS_ERR_DEGENERATE;
			}
		}
		for (int i = 0; i < k; i++) {
			for (int j = i + 1; j < k; j++) {
				if (idx[i] == idx[j]) {
					hs_shape_why(why, why_size, "face %d repeats vertex %d", f, idx[i]);
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
			hs_shape_why(why, why_size, "vertex %d is unused", v);
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
			hs_shape_why(why, why_size, "edge %d-%d is not shared by exactly two faces", halves[i].lo, halves[i].hi);
			return HS_ERR_DEGENERATE;
		}
		edge_count++;
		i = j;
	}
	int euler = nv - edge_count + nf;
	if (euler != 2) {
		hs_shape_why(why, why_size, "v - e + f is %d, not 2", euler);
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

// One part's working frame: its vertices relative to their mean `c` (which keeps rounding small
// and lies inside a convex solid) and its size, the bounding-box diagonal.
typedef struct part_frame {
	hs_vec3 c;
	double size, tol;
} part_frame;

static part_frame frame_of_part(const part_src *src, hs_vec3 *local) {
	int nv = src->vertex_count;
	part_frame fr;
	fr.c = hs_v3(0.0, 0.0, 0.0);
	for (int v = 0; v < nv; v++)
		fr.c = hs_add(fr.c, src->vertices[v]);
	fr.c = hs_scale(fr.c, 1.0 / (double)nv);
	hs_vec3 lo = hs_v3(INFINITY, INFINITY, INFINITY), hi = hs_neg(lo);
	for (int v = 0; v < nv; v++) {
		local[v] = hs_sub(src->vertices[v], fr.c);
		lo = hs_v3(fmin(lo.x, local[v].x), fmin(lo.y, local[v].y), fmin(lo.z, local[v].z));
		hi = hs_v3(fmax(hi.x, local[v].x), fmax(hi.y, local[v].y), fmax(hi.z, local[v].z));
	}
	fr.size = hs_distance(lo, hi);
	fr.tol = HS_SHAPE_REL_TOL * fr.size;
	return fr;
}

// Face planes: Newell normal, offset through the face's vertex mean; every face planar.
static hs_status part_planes(const part_src *src, const hs_vec3 *local, part_frame fr, hs_face *faces, char *why,
                             size_t why_size) {
	int first = 0;
	for (int f = 0; f < src->face_count; f++) {
		int k = src->face_sizes[f];
		const int *idx = src->face_vertices + first;
		hs_vec3 n = newell_normal(local, idx, k);
		double len = hs_length(n);
		if (!(0.5 * len > HS_SHAPE_REL_AREA * fr.size * fr.size)) {
			hs_shape_why(why, why_size, "face %d has no area", f);
			return HS_ERR_DEGENERATE;
		}
		n = hs_scale(n, 1.0 / len);
		double offset = hs_dot(n, face_mean(local, idx, k));
		for (int i = 0; i < k; i++) {
			if (fabs(hs_dot(n, local[idx[i]]) - offset) > fr.tol) {
				hs_shape_why(why, why_size, "face %d is not planar", f);
				return HS_ERR_DEGENERATE;
			}
		}
		faces[f].normal = n;
		faces[f].offset = offset;
		first += k;
	}
	return HS_OK;
}

// Not flat, and every face oriented outward: the vertex mean (local origin) must lie behind every
// face plane; a face plane through it cannot belong to a convex solid. Sets flip[f] for faces
// given clockwise.
static hs_status part_orient(const part_src *src, const hs_vec3 *local, part_frame fr, hs_face *faces,
                             unsigned char *flip, char *why, size_t why_size) {
	bool flat = true;
	for (int v = 0; v < src->vertex_count && flat; v++)
		flat = fabs(hs_dot(faces[0].normal, local[v]) - faces[0].offset) <= fr.tol;
	if (flat) {
		hs_shape_why(why, why_size, "shape has no volume");
		return HS_ERR_DEGENERATE;
	}
	for (int f = 0; f < src->face_count; f++) {
		double d = -faces[f].offset; // dot(n, 0) - offset
		if (fabs(d) <= fr.tol) {
			hs_shape_why(why, why_size, "shape is not convex");
			return HS_ERR_DEGENERATE;
		}
		flip[f] = d > 0.0;
		if (flip[f]) {
			faces[f].normal = hs_neg(faces[f].normal);
			faces[f].offset = -faces[f].offset;
		}
	}
	return HS_OK;
}

// Each face a convex polygon (every turn to the left about the outward normal) and the part a
// convex solid (every vertex behind every face plane).
static hs_status part_convex(const part_src *src, const hs_vec3 *local, part_frame fr, const hs_face *faces,
                             const unsigned char *flip, char *why, size_t why_size) {
	int first = 0;
	for (int f = 0; f < src->face_count; f++) {
		int k = src->face_sizes[f];
		const int *idx = src->face_vertices + first;
		for (int i = 0; i < k; i++) {
			int i0 = flip[f] ? k - 1 - i : i;
			int i1 = flip[f] ? (2 * k - 2 - i) % k : (i + 1) % k;
			int i2 = flip[f] ? (3 * k - 3 - i) % k : (i + 2) % k;
			hs_vec3 e0 = hs_sub(local[idx[i1]], local[idx[i0]]);
			hs_vec3 e1 = hs_sub(local[idx[i2]], local[idx[i1]]);
			if (hs_dot(hs_cross(e0, e1), faces[f].normal) < -fr.tol * fr.size) {
				hs_shape_why(why, why_size, "face %d is not convex", f);
				return HS_ERR_DEGENERATE;
			}
		}
		first += k;
	}
	for (int f = 0; f < src->face_count; f++) {
		for (int v = 0; v < src->vertex_count; v++) {
			if (hs_dot(faces[f].normal, local[v]) - faces[f].offset > fr.tol) {
				hs_shape_why(why, why_size, "shape is not convex");
				return HS_ERR_DEGENERATE;
			}
		}
	}
	return HS_OK;
}

// Volume and first moment: signed tetrahedra (0, v0, vi, vi+1) fanned over each face, in face
// order, so the sums are the same on every run. Adds the part's volume and moment (the centroid
// back in the coordinates the part was given in) to the shape's.
static hs_status part_mass(const part_src *src, const hs_vec3 *local, part_frame fr, const unsigned char *flip,
                           double *volume, hs_vec3 *moment, char *why, size_t why_size) {
	double vol6 = 0.0;
	hs_vec3 mom24 = hs_v3(0.0, 0.0, 0.0);
	int first = 0;
	for (int f = 0; f < src->face_count; f++) {
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
	if (!(part_volume > fr.tol * fr.tol * fr.tol) || !isfinite(part_volume)) {
		hs_shape_why(why, why_size, "shape has no volume");
		return HS_ERR_DEGENERATE;
	}
	hs_vec3 centroid = hs_add(fr.c, hs_scale(mom24, 1.0 / (4.0 * vol6)));
	*volume += part_volume;
	*moment = hs_mul_add(*moment, part_volume, centroid);
	return HS_OK;
}

// Edges from the sorted half-edge pairs; faces[0] of an edge is the face in which a -> b runs
// counter-clockwise (as now oriented).
static void part_edges(hs_shape *shape, const half_edge *halves, int half_count, cursor *at) {
	for (int i = 0; i < half_count; i += 2) {
		const half_edge *h = &halves[i];
		int f0 = h->face, f1 = halves[i + 1].face;
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
}

// Writes the part's vertices (as given), faces (outward winding) and edges into `shape`.
static void part_write(hs_shape *shape, int part_index, const part_src *src, const half_edge *halves,
                       const unsigned char *flip, cursor *at) {
	hs_part *part = &shape->parts[part_index];
	hs_face *faces = shape->faces + at->face;
	part->first_vertex = at->vertex;
	part->vertex_count = src->vertex_count;
	part->first_face = at->face;
	part->face_count = src->face_count;
	part->first_edge = at->edge;
	for (int v = 0; v < src->vertex_count; v++)
		shape->vertices[at->vertex + v] = src->vertices[v];
	int first = 0;
	for (int f = 0; f < src->face_count; f++) {
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
	part_edges(shape, halves, first, at);
	part->edge_count = at->edge - part->first_edge;
	at->vertex += src->vertex_count;
	at->face += src->face_count;
}

// Scratch of the builder, sized for the largest part.
typedef struct scratch {
	half_edge *halves;
	unsigned char *used, *flip;
	hs_vec3 *local;
} scratch;

// Geometry of one part, after check_topology, then the part written into `shape` (coordinates
// still as given) with its volume and first moment added.
static hs_status build_part(hs_shape *shape, int part_index, const part_src *src, scratch *sc, cursor *at,
                            double *volume, hs_vec3 *moment, char *why, size_t why_size) {
	part_frame fr = frame_of_part(src, sc->local);
	if (!(fr.size > 0.0) || !isfinite(fr.size)) {
		hs_shape_why(why, why_size, "shape has no volume");
		return HS_ERR_DEGENERATE;
	}
	hs_face *faces = shape->faces + at->face;
	hs_status r = part_planes(src, sc->local, fr, faces, why, why_size);
	if (r == HS_OK)
		r = part_orient(src, sc->local, fr, faces, sc->flip, why, why_size);
	if (r == HS_OK)
		r = part_convex(src, sc->local, fr, faces, sc->flip, why, why_size);
	if (r == HS_OK)
		r = part_mass(src, sc->local, fr, sc->flip, volume, moment, why, why_size);
	if (r == HS_OK)
		part_write(shape, part_index, src, sc->halves, sc->flip, at);
	return r;
}

// Totals and largest part, from the counts alone: they bound every array of the builder.
typedef struct totals {
	long long v, f, fv;
	int max_v, max_f, max_fv;
} totals;

static hs_status count_parts(const part_src *parts, int part_count, totals *t, char *why, size_t why_size) {
	memset(t, 0, sizeof *t);
	for (int p = 0; p < part_count; p++) {
		if (parts[p].vertex_count < 4 || parts[p].face_count < 4) {
			hs_shape_why(why, why_size, "%s", parts[p].vertex_count < 4 ? "fewer than 4 vertices" : "fewer than 4 faces");
			return HS_ERR_DEGENERATE;
		}
		int fv = 0;
		for (int f = 0; f < parts[p].face_count; f++) {
			int k = parts[p].face_sizes[f];
			if (k < 3 || k > parts[p].vertex_count) {
				hs_shape_why(why, why_size,
				             k < 3 ? "face %d has fewer than 3 vertices" : "face %d has more vertices than the shape", f);
				return HS_ERR_DEGENERATE;
			}
			fv += k; // k <= vertex_count, checked against the limit each step: no overflow
			if (fv > INT_MAX / 4) {
				hs_shape_why(why, why_size, "shape too large");
				return HS_ERR_INVALID_ARGUMENT;
			}
		}
		t->v += parts[p].vertex_count;
		t->f += parts[p].face_count;
		t->fv += fv;
		t->max_v = parts[p].vertex_count > t->max_v ? parts[p].vertex_count : t->max_v;
		t->max_f = parts[p].face_count > t->max_f ? parts[p].face_count : t->max_f;
		t->max_fv = fv > t->max_fv ? fv : t->max_fv;
	}
	if (t->v > INT_MAX / 4 || t->f > INT_MAX / 4 || t->fv > INT_MAX / 4) {
		hs_shape_why(why, why_size, "shape too large");
		return HS_ERR_INVALID_ARGUMENT;
	}
	return HS_OK;
}

static size_t at_least_one(long long n) { return (size_t)(n > 0 ? n : 1); }

// The shape's arrays and the builder's scratch; false when any allocation failed.
static bool allocate(hs_shape **out, scratch *sc, int part_count, const totals *t) {
	hs_shape *shape = calloc(1, sizeof *shape);
	sc->halves = malloc(at_least_one(t->max_fv) * sizeof *sc->halves);
	sc->used = malloc(at_least_one(t->max_v));
	sc->flip = malloc(at_least_one(t->max_f));
	sc->local = malloc(at_least_one(t->max_v) * sizeof *sc->local);
	if (shape) {
		shape->parts = calloc((size_t)part_count, sizeof *shape->parts);
		shape->vertices = calloc(at_least_one(t->v), sizeof *shape->vertices);
		shape->faces = calloc(at_least_one(t->f), sizeof *shape->faces);
		shape->face_vertices = calloc(at_least_one(t->fv), sizeof *shape->face_vertices);
		shape->edges = calloc(at_least_one(t->fv / 2), sizeof *shape->edges);
	}
	*out = shape;
	return shape && sc->halves && sc->used && sc->flip && sc->local && shape->parts && shape->vertices &&
	       shape->faces && shape->face_vertices && shape->edges;
}

// Bounding spheres: about the vertex mean for a part (inside it, as MPR needs), about G for the shape.
static void bound_parts(hs_shape *shape, double exact_sphere) {
	double radius = 0.0;
	for (int p = 0; p < shape->part_count; p++) {
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
		hs_vec3 lo = shape->vertices[part->first_vertex], hi = lo;
		for (int v = 1; v < part->vertex_count; v++) {
			hs_vec3 x = shape->vertices[part->first_vertex + v]; // (comparisons: collide.c's part_box read them so)
			lo = hs_v3(x.x < lo.x ? x.x : lo.x, x.y < lo.y ? x.y : lo.y, x.z < lo.z ? x.z : lo.z);
			hi = hs_v3(x.x > hi.x ? x.x : hi.x, x.y > hi.y ? x.y : hi.y, x.z > hi.z ? x.z : hi.z);
		}
		part->box_center = hs_scale(hs_add(lo, hi), 0.5);
		part->box_half = hs_scale(hs_sub(hi, lo), 0.5);
	}
	shape->radius = radius;
	if (exact_sphere > 0.0) {
		shape->radius = exact_sphere;
		shape->parts[0].center = hs_v3(0.0, 0.0, 0.0);
		shape->parts[0].radius = exact_sphere;
	}
}

// Moves the body frame to G (volume-weighted part centroids; the given origin for an exact sphere,
// whose volume is then exact) and bounds the parts. False when the result is not finite.
static bool move_to_g(hs_shape *shape, double volume, hs_vec3 moment, double exact_sphere) {
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
	bound_parts(shape, exact_sphere);
	return isfinite(shape->volume) && hs_vec3_is_finite(g) && isfinite(shape->radius);
}

hs_shape *hs_shape_build(hs_shape_kind kind, const part_src *parts, int part_count, double exact_sphere,
                         char *why, size_t why_size, hs_status *status) {
	totals t;
	hs_status result = count_parts(parts, part_count, &t, why, why_size);
	if (result != HS_OK) {
		hs_set_status(status, result);
		return NULL;
	}
	hs_shape *shape = NULL;
	scratch sc;
	if (!allocate(&shape, &sc, part_count, &t)) {
		hs_shape_why(why, why_size, "out of memory");
		result = HS_ERR_NO_MEMORY;
	}
	cursor at = {0, 0, 0, 0};
	double volume = 0.0;
	hs_vec3 moment = hs_v3(0.0, 0.0, 0.0);
	for (int p = 0; p < part_count && result == HS_OK; p++) {
		result = check_topology(&parts[p], sc.halves, sc.used, why, why_size);
		if (result == HS_OK)
			result = build_part(shape, p, &parts[p], &sc, &at, &volume, &moment, why, why_size);
	}
	free(sc.halves);
	free(sc.used);
	free(sc.flip);
	free(sc.local);
	if (result == HS_OK) {
		shape->kind = kind;
		shape->part_count = part_count;
		shape->vertex_count = at.vertex;
		shape->face_count = at.face;
		shape->face_vertex_count = at.face_vertex;
		shape->edge_count = at.edge;
		if (!move_to_g(shape, volume, moment, exact_sphere)) {
			hs_shape_why(why, why_size, "shape has no volume");
			result = HS_ERR_DEGENERATE;
		}
	}
	if (result != HS_OK) {
		hs_shape_destroy(shape);
		hs_set_status(status, result);
		return NULL;
	}
	if (why && why_size > 0)
		why[0] = '\0';
	hs_set_status(status, HS_OK);
	return shape;
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
