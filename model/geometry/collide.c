// collide.c — interference of posed shapes: bounding spheres, then libccd on convex part pairs
// (two boxes are first put to the separating-axis test, which answers when the answer is clear).
//
// libccd compares against absolute epsilons (DBL_EPSILON on squared lengths), so each pair is
// handed to it in normalised coordinates, (x - origin) / (r_a + r_b): its tolerances become
// relative to the size of the pair, the same for a 5 cm block as for a 1 m box.
// Nothing here allocates: support points are posed on the fly from the body-frame vertices.
#include <ccd/ccd.h>
#include <float.h>
#if defined(HS_SELFCHECK)
#include <stdio.h>
#include <stdlib.h>
#endif

#include "collide.h"
#include "inline.h"
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

// m added around each shape, so that faces touching within 1e-12 m always count as
// interference instead of being left to rounding (handspring.h: hs_shapes_overlap).
#define HS_TOUCH_MARGIN 0.5e-12
#define HS_CCD_MAX_ITERATIONS 100UL
// in normalised coordinates, i.e. relative to r_a + r_b
#define HS_CCD_TOLERANCE 1e-10

// One convex part posed in the world, as libccd sees it.
typedef struct posed_part {
	const hs_vec3 *vertices; // body frame
	int vertex_count;
	hs_vec3 box_center, box_half; // body frame: the box of the vertices (hs_part)
	double sphere_radius; // > 0: an exact sphere about `center`
	hs_vec3 pos;          // body → world: x = pos + rot(v)
	hs_quat rot;
	hs_vec3 center; // world: centre of the part's bounding sphere (inside the part)
	double radius;  // m
	hs_vec3 origin; // world point that is 0 in libccd coordinates
	double inv_scale;
	double margin; // m added around the part (HS_TOUCH_MARGIN, plus half a gap: collide.h)
} posed_part;

static posed_part pose_part(const hs_shape *shape, int index, hs_vec3 pos, hs_quat rot) {
	const hs_part *part = &shape->parts[index];
	posed_part p;
	p.vertices = shape->vertices + part->first_vertex;
	p.vertex_count = part->vertex_count;
	p.box_center = part->box_center;
	p.box_half = part->box_half;
	p.sphere_radius = shape->kind == HS_SHAPE_SPHERE ? shape->sphere_radius : 0.0;
	p.pos = pos;
	p.rot = rot;
	p.center = hs_add(pos, hs_quat_rotate(rot, part->center));
	p.radius = part->radius;
	p.origin = hs_v3(0.0, 0.0, 0.0);
	p.inv_scale = 1.0;
	p.margin = HS_TOUCH_MARGIN;
	return p;
}

static hs_vec3 from_ccd(const ccd_vec3_t *v) { return hs_v3(v->v[0], v->v[1], v->v[2]); }

static void to_ccd(const posed_part *p, hs_vec3 x, ccd_vec3_t *out) {
	hs_vec3 n = hs_scale(hs_sub(x, p->origin), p->inv_scale);
	out->v[0] = n.x;
	out->v[1] = n.y;
	out->v[2] = n.z;
}

// Farthest point of the (margin-inflated) part along dir; ties go to the lowest vertex index.
static void support(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out) {
	const posed_part *p = obj;
	hs_vec3 d = from_ccd(dir);
	double len = hs_length(d);
	hs_vec3 x;
	if (p->sphere_radius > 0.0) {
		x = len > 0.0 ? hs_mul_add(p->center, p->sphere_radius / len, d)
		              : hs_add(p->center, hs_v3(p->sphere_radius, 0.0, 0.0));
	} else {
		hs_vec3 body_dir = hs_quat_inv_rotate(p->rot, d);
		int best = 0;
		double best_dot = hs_dot(body_dir, p->vertices[0]);
		for (int i = 1; i < p->vertex_count; i++) {
			double s = hs_dot(body_dir, p->vertices[i]);
			if (s > best_dot) {
				best_dot = s;
				best = i;
			}
		}
		x = hs_add(p->pos, hs_quat_rotate(p->rot, p->vertices[best]));
	}
	if (len > 0.0)
		x = hs_mul_add(x, p->margin / len, d);
	to_ccd(p, x, out);
}

static void center(const void *obj, ccd_vec3_t *out) {
	const posed_part *p = obj;
	to_ccd(p, p->center, out);
}

// Start along the line between the centres (the Minkowski difference's centre).
static void first_dir(const void *obj1, const void *obj2, ccd_vec3_t *dir) {
	const posed_part *a = obj1, *b = obj2;
	hs_vec3 d = hs_sub(a->center, b->center);
	if (!(hs_length_sq(d) > 0.0))
		d = hs_v3(1.0, 0.0, 0.0);
	dir->v[0] = d.x;
	dir->v[1] = d.y;
	dir->v[2] = d.z;
}

static void setup_ccd(ccd_t *ccd) {
	CCD_INIT(ccd);
	ccd->first_dir = first_dir;
	ccd->support1 = support;
	ccd->support2 = support;
	ccd->center1 = center;
	ccd->center2 = center;
	ccd->max_iterations = HS_CCD_MAX_ITERATIONS;
	ccd->epa_tolerance = HS_CCD_TOLERANCE;
	ccd->mpr_tolerance = HS_CCD_TOLERANCE;
	ccd->dist_tolerance = HS_CCD_TOLERANCE;
}

// Bounding spheres touch (within the margins and a gap). Written so that NaN poses never pass.
static bool spheres_within(hs_vec3 ca, double ra, hs_vec3 cb, double rb, double gap) {
	double reach = ra + rb + 2.0 * HS_TOUCH_MARGIN + gap;
	return hs_length_sq(hs_sub(cb, ca)) <= reach * reach;
}
static bool spheres_meet(hs_vec3 ca, double ra, hs_vec3 cb, double rb) {
	double reach = ra + rb + 2.0 * HS_TOUCH_MARGIN;
	return hs_length_sq(hs_sub(cb, ca)) <= reach * reach;
}

// Both parts in the pair's normalised coordinates (origin at a's centre, unit r_a + r_b).
static void normalise_pair(posed_part *a, posed_part *b) {
	double inv = 1.0 / (a->radius + b->radius);
	a->origin = b->origin = a->center;
	a->inv_scale = b->inv_scale = inv;
}

// The body axes x, y, z turned by rot: hs_quat_rotate of each with its products by 0 and 1 left
// out, so only the signs of zeros can differ from it. Inlined, as it was in box_of before the box
// test shared it: called, it cost the world-box queries ~20 instructions each.
static HS_FORCE_INLINE void turned_axes(hs_quat rot, hs_vec3 u[3]) {
	double x = rot.x, y = rot.y, z = rot.z, w = rot.w, a = 2.0 * x, b = 2.0 * y, d = 2.0 * z;
	u[0] = hs_v3(1.0 + (y * -b - z * d), d * w - x * -b, -b * w + x * d);
	u[1] = hs_v3(-d * w + y * a, 1.0 + (z * -d - x * a), a * w - y * -d);
	u[2] = hs_v3(b * w - z * -a, -a * w + z * b, 1.0 + (x * -a - y * b));
}

// |R| times the half extents h of a body box turned into axes u: its world box's half extents.
static HS_FORCE_INLINE hs_vec3 turned_half(const hs_vec3 u[3], hs_vec3 h) {
	return hs_v3(fabs(u[0].x) * h.x + fabs(u[1].x) * h.y + fabs(u[2].x) * h.z,
	             fabs(u[0].y) * h.x + fabs(u[1].y) * h.y + fabs(u[2].y) * h.z,
	             fabs(u[0].z) * h.x + fabs(u[1].z) * h.y + fabs(u[2].z) * h.z);
}

// World-axis box around a part posed at (pos, rot): its body-frame box (c, h) turned (|R| times
// the half extents); an exact sphere (sphere_radius > 0) about `center` (world).
static void box_of(hs_vec3 pos, hs_quat rot, hs_vec3 c, hs_vec3 h, double sphere_radius, hs_vec3 center,
                   hs_vec3 *centre, hs_vec3 *half) {
	if (sphere_radius > 0.0) {
		*centre = center;
		*half = hs_v3(sphere_radius, sphere_radius, sphere_radius);
		return;
	}
	hs_vec3 u[3];
	turned_axes(rot, u);
	*centre = hs_add(pos, hs_quat_rotate(rot, c));
	*half = turned_half(u, h);
}

static void part_box(const posed_part *p, hs_vec3 *centre, hs_vec3 *half) {
	box_of(p->pos, p->rot, p->box_center, p->box_half, p->sphere_radius, p->center, centre, half);
}

// A part's body box posed in the world: box_of's centre and world box, and the turned axes, kept
// for the separating-axis test (zero for an exact sphere).
typedef struct posed_box {
	hs_vec3 centre, half, axis[3];
} posed_box;

static posed_box pose_box(const posed_part *p) {
	hs_vec3 zero = hs_v3(0.0, 0.0, 0.0);
	posed_box b = {p->center, hs_v3(p->sphere_radius, p->sphere_radius, p->sphere_radius), {zero, zero, zero}};
	if (p->sphere_radius > 0.0)
		return b;
	turned_axes(p->rot, b.axis);
	b.centre = hs_add(p->pos, hs_quat_rotate(p->rot, p->box_center));
	b.half = turned_half(b.axis, p->box_half);
	return b;
}

// Cheap rejection before libccd: the parts' world boxes are apart by more than 1e-8 of the pair's
// size (beyond libccd's 1e-10 and the touch margins, though not GJK's touching band of ~1.5e-8
// that the box test below steps over: a pair within it is found apart here, as it always was). A
// small part beside a huge one (a 5 cm cube within the bounding sphere of a 400 m box) no longer
// costs a GJK run. `margin`: each part's (posed_part).
static double pair_slack(double ra, double rb, double margin) {
	return 1e-8 * (ra + rb) + 4.0 * HS_TOUCH_MARGIN + (margin - HS_TOUCH_MARGIN) * 2.0;
}

static bool boxes_apart_by(hs_vec3 ca, hs_vec3 ha, double ra, hs_vec3 cb, hs_vec3 hb, double rb, double margin) {
	double m = pair_slack(ra, rb, margin);
	return fabs(cb.x - ca.x) > ha.x + hb.x + m || fabs(cb.y - ca.y) > ha.y + hb.y + m ||
	       fabs(cb.z - ca.z) > ha.z + hb.z + m;
}

static bool boxes_apart(const posed_part *a, const posed_part *b) {
	hs_vec3 ca, ha, cb, hb;
	part_box(a, &ca, &ha);
	part_box(b, &cb, &hb);
	return boxes_apart_by(ca, ha, a->radius, cb, hb, b->radius, a->margin);
}

// ---------------------------------------------------------------------------------------------
// Two boxes by the separating-axis test (15 axes: 3 + 3 face normals, 9 edge cross products),
// before libccd: a few hundred instructions instead of GJK's ~3,400. It answers only when the
// answer is clear of touching by a slack, and leaves every other pair to libccd, so the result is
// libccd's (hs_shapes_overlap_gjk, the rule this stands for). The slack is boxes_apart_by's m plus
// 1e-6 of the pair's radii sum: GJK counts as touching whatever its simplex brings within
// sqrt(DBL_EPSILON) ≈ 1.5e-8 of the origin in the pair's normalised coordinates (its zero tests
// are on squared lengths), and finds boxes apart by up to ~3e-8 of the size overlapping
// (tests/test_collide.c shows that band); 1e-6 is far beyond it, and no slower in practice.

// of the pair's radii sum, beyond libccd's touching band (above)
#define HS_SAT_SLACK 1e-6
// |1 - |q|^2| up to which a quaternion's turned axes count as a frame (beyond: libccd decides)
#define HS_SAT_UNIT 1e-9
// cross axes shorter than this (edges parallel within 1e-12 rad) are skipped when proving an
// overlap: their sliver of the boxes' Minkowski sum is that thin, and the face axes cover the rest
#define HS_SAT_PARALLEL 1e-12

// Vertex i is corner i of [lo, hi] (x from bit 0 of i, y bit 1, z bit 2), the order hs_shape_box
// makes: twelve comparisons of two coordinates each with SSE2 (cmpeq is ==).
static bool corners_in_order(const hs_vec3 *v, hs_vec3 lo, hs_vec3 hi) {
#if defined(__SSE2__)
	__m128d xy0 = _mm_set_pd(lo.y, lo.x), xy1 = _mm_set_pd(lo.y, hi.x), xy2 = _mm_set_pd(hi.y, lo.x),
	        xy3 = _mm_set_pd(hi.y, hi.x), lz = _mm_set1_pd(lo.z), hz = _mm_set1_pd(hi.z);
	// written out: the loop over an array of the four x-y corners was not unrolled
	__m128d z = _mm_and_pd(_mm_and_pd(_mm_cmpeq_pd(_mm_set_pd(v[1].z, v[0].z), lz), _mm_cmpeq_pd(_mm_set_pd(v[3].z, v[2].z), lz)),
	                       _mm_and_pd(_mm_cmpeq_pd(_mm_set_pd(v[5].z, v[4].z), hz), _mm_cmpeq_pd(_mm_set_pd(v[7].z, v[6].z), hz)));
	__m128d low = _mm_and_pd(_mm_and_pd(_mm_cmpeq_pd(_mm_loadu_pd(&v[0].x), xy0), _mm_cmpeq_pd(_mm_loadu_pd(&v[1].x), xy1)),
	                         _mm_and_pd(_mm_cmpeq_pd(_mm_loadu_pd(&v[2].x), xy2), _mm_cmpeq_pd(_mm_loadu_pd(&v[3].x), xy3)));
	__m128d high = _mm_and_pd(_mm_and_pd(_mm_cmpeq_pd(_mm_loadu_pd(&v[4].x), xy0), _mm_cmpeq_pd(_mm_loadu_pd(&v[5].x), xy1)),
	                          _mm_and_pd(_mm_cmpeq_pd(_mm_loadu_pd(&v[6].x), xy2), _mm_cmpeq_pd(_mm_loadu_pd(&v[7].x), xy3)));
	return _mm_movemask_pd(_mm_and_pd(z, _mm_and_pd(low, high))) == 3;
#else
	for (int i = 0; i < 8; i++)
		if (!(v[i].x == (i & 1 ? hi.x : lo.x) && v[i].y == (i & 2 ? hi.y : lo.y) && v[i].z == (i & 4 ? hi.z : lo.z)))
			return false;
	return true;
#endif
}

// Exactly a box: 8 vertices, each a corner box_center ± box_half, all 8 corners present. The hull
// libccd sees (support() reads only the vertices) is then that box. An exact sphere never is.
static bool part_is_box(const posed_part *p) {
	if (p->vertex_count != 8 || p->sphere_radius > 0.0)
		return false;
	hs_vec3 lo = hs_sub(p->box_center, p->box_half), hi = hs_add(p->box_center, p->box_half);
	const hs_vec3 *v = p->vertices;
	if (corners_in_order(v, lo, hi))
		return true;
	unsigned corners = 0; // any other order: the corner each vertex is, all 8 once
	for (int i = 0; i < 8; i++) {
		bool x = v[i].x == hi.x, y = v[i].y == hi.y, z = v[i].z == hi.z;
		if (!(x || v[i].x == lo.x) || !(y || v[i].y == lo.y) || !(z || v[i].z == lo.z))
			return false;
		corners |= 1u << ((unsigned)x | (unsigned)y << 1 | (unsigned)z << 2);
	}
	return corners == 0xffu;
}

// Box b seen from box a: b's axes (r[i][j] = a_i . b_j) and centre (t) in a's frame.
typedef struct box_pair {
	double r[3][3], ar[3][3]; // and |r|
	double t[3], ha[3], hb[3];
	hs_vec3 d;    // m, world: centre of b less centre of a
	double slack; // m per unit of axis length: a projection's distance to touching must pass it
	double rate;  // relative rounding of the turned frames (a few 1e-16, plus ~|1 - |q|^2|)
	double err;   // m, absolute: what that rounding may move a projection on any axis
} box_pair;

// The pair's centres, half extents and slack (the axes and centres box_of and support() pose);
// false when a quaternion is too far from unit (or NaN) for its turned axes to be a frame.
static bool box_pair_of(const posed_part *a, const posed_box *ba, const posed_part *b, const posed_box *bb,
                        box_pair *p) {
	double eta_a = fabs(hs_quat_dot(a->rot, a->rot) - 1.0), eta_b = fabs(hs_quat_dot(b->rot, b->rot) - 1.0);
	if (!(eta_a <= HS_SAT_UNIT && eta_b <= HS_SAT_UNIT))
		return false;
	hs_vec3 ca = ba->centre, cb = bb->centre;
	p->d = hs_sub(cb, ca);
	p->ha[0] = a->box_half.x, p->ha[1] = a->box_half.y, p->ha[2] = a->box_half.z;
	p->hb[0] = b->box_half.x, p->hb[1] = b->box_half.y, p->hb[2] = b->box_half.z;
	p->rate = 2.0 * (4e-15 + 4.0 * (eta_a + eta_b));
	// posed corners and centres round by ~1e-16 of their coordinates (far from the origin that
	// passes the slack: then nothing is clear and libccd decides)
	double far = fabs(ca.x) + fabs(ca.y) + fabs(ca.z) + fabs(cb.x) + fabs(cb.y) + fabs(cb.z);
	p->slack = pair_slack(a->radius, b->radius, a->margin) + HS_SAT_SLACK * (a->radius + b->radius) +
	           8.0 * DBL_EPSILON * far;
	return true;
}

// Each box holds the ball of its least half extent about its centre; two such balls overlapping
// by more than the slack show the boxes overlapping by as much along every axis (the Minkowski
// difference holds the difference of the balls), with no axis to test.
static bool balls_overlap(const box_pair *p) {
	double ra = fmin(fmin(p->ha[0], p->ha[1]), p->ha[2]), rb = fmin(fmin(p->hb[0], p->hb[1]), p->hb[2]);
	hs_vec3 d = p->d;
	double size = fabs(d.x) + fabs(d.y) + fabs(d.z) + ra + rb;
	double reach = ra + rb - p->slack - p->rate * size;
	return reach > 0.0 && hs_length_sq(d) < reach * reach;
}

// b's axes and centre in a's frame, and the rounding they carry.
static void box_pair_turn(box_pair *p, const posed_box *ba, const posed_box *bb) {
	double size = 0.0;
	for (int i = 0; i < 3; i++) {
		p->t[i] = hs_dot(p->d, ba->axis[i]);
		size += fabs(p->t[i]) + p->ha[i] + p->hb[i];
		for (int j = 0; j < 3; j++) {
			p->r[i][j] = hs_dot(ba->axis[i], bb->axis[j]);
			p->ar[i][j] = fabs(p->r[i][j]);
		}
	}
	p->err = p->rate * size;
}

enum { SAT_OVERLAP = HS_BOXES_OVERLAP, SAT_APART = HS_BOXES_APART, SAT_CLOSE = HS_BOXES_CLOSE, SAT_SKIP };

// One axis of length len: the boxes' projections lie `dist` apart at the centres and reach `reach`.
static HS_FORCE_INLINE int axis_verdict(const box_pair *p, double dist, double reach, double len) {
	double gap = dist - reach, clear = p->slack * len + p->err;
	if (gap > clear)
		return SAT_APART;
	return -gap > clear ? SAT_OVERLAP : SAT_CLOSE; // NaN: close, left to libccd
}

// The cross axis a_i x b_j, in a's frame (0, -r[2][j], r[1][j]) for i = 0 (inlined with constant
// i and j). Parallel edges' axis is skipped (HS_SAT_PARALLEL) unless it shows a gap.
static HS_FORCE_INLINE int cross_verdict(const box_pair *p, int i, int j) {
	const double(*r)[3] = p->r, (*ar)[3] = p->ar;
	int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
	double len = sqrt(r[i1][j] * r[i1][j] + r[i2][j] * r[i2][j]);
	double reach = p->ha[i1] * ar[i2][j] + p->ha[i2] * ar[i1][j] + p->hb[j1] * ar[i][j2] + p->hb[j2] * ar[i][j1];
	int v = axis_verdict(p, fabs(p->t[i2] * r[i1][j] - p->t[i1] * r[i2][j]), reach, len);
	return v == SAT_CLOSE && len < HS_SAT_PARALLEL ? SAT_SKIP : v;
}

// The 15 axes: SAT_APART as soon as one is clear of touching, SAT_OVERLAP when all are (skipping
// parallel edges' cross axes), otherwise SAT_CLOSE.
static int boxes_sat(const box_pair *p) {
	const double(*r)[3] = p->r, (*ar)[3] = p->ar;
	const double *t = p->t, *ha = p->ha, *hb = p->hb;
	unsigned seen = 0; // 1 << verdict
	for (int i = 0; i < 3; i++) { // a's face normals
		seen |= 1u << axis_verdict(p, fabs(t[i]), ha[i] + hb[0] * ar[i][0] + hb[1] * ar[i][1] + hb[2] * ar[i][2], 1.0);
		seen |= 1u << axis_verdict(p, fabs(t[0] * r[0][i] + t[1] * r[1][i] + t[2] * r[2][i]),
		                           ha[0] * ar[0][i] + ha[1] * ar[1][i] + ha[2] * ar[2][i] + hb[i], 1.0); // b's
	}
	if (seen & 1u << SAT_APART)
		return SAT_APART;
	seen |= 1u << cross_verdict(p, 0, 0) | 1u << cross_verdict(p, 0, 1) | 1u << cross_verdict(p, 0, 2);
	seen |= 1u << cross_verdict(p, 1, 0) | 1u << cross_verdict(p, 1, 1) | 1u << cross_verdict(p, 1, 2);
	seen |= 1u << cross_verdict(p, 2, 0) | 1u << cross_verdict(p, 2, 1) | 1u << cross_verdict(p, 2, 2);
	return seen & 1u << SAT_APART ? SAT_APART : seen & 1u << SAT_CLOSE ? SAT_CLOSE : SAT_OVERLAP;
}

// SAT_OVERLAP or SAT_APART when two box parts' answer is clear, SAT_CLOSE for libccd to decide.
static int parts_sat(const posed_part *a, const posed_box *ba, const posed_part *b, const posed_box *bb) {
	box_pair p;
	if (!part_is_box(a) || !part_is_box(b) || !box_pair_of(a, ba, b, bb, &p))
		return SAT_CLOSE;
	if (balls_overlap(&p)) // most overlapping pairs: no frame needed
		return SAT_OVERLAP;
	box_pair_turn(&p, ba, bb);
	return boxes_sat(&p);
}

static bool parts_gjk(posed_part *a, posed_part *b, const ccd_t *ccd) {
	normalise_pair(a, b);
	return ccdGJKIntersect(a, b, ccd);
}

// One pair of parts: bounding spheres, world boxes (boxes_apart's), then the box test or libccd.
static bool parts_overlap(posed_part *a, posed_part *b, const ccd_t *ccd, bool sat) {
	if (!spheres_meet(a->center, a->radius, b->center, b->radius))
		return false;
	posed_box ba = pose_box(a), bb = pose_box(b);
	if (boxes_apart_by(ba.centre, ba.half, a->radius, bb.centre, bb.half, b->radius, a->margin))
		return false;
	int verdict = sat ? parts_sat(a, &ba, b, &bb) : SAT_CLOSE;
	if (verdict == SAT_CLOSE)
		return parts_gjk(a, b, ccd);
#if defined(HS_SELFCHECK)
	// self-check builds: the box test's answer is libccd's
	posed_part ga = *a, gb = *b;
	if (parts_gjk(&ga, &gb, ccd) != (verdict == SAT_OVERLAP)) {
		fprintf(stderr, "selfcheck: the box test says %s where libccd says otherwise\n",
		        verdict == SAT_OVERLAP ? "overlap" : "apart");
		abort();
	}
#endif
	return verdict == SAT_OVERLAP;
}

hs_box_verdict hs_box_parts_verdict(const hs_shape *a, int part_a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b,
                                    int part_b, hs_vec3 pos_b, hs_quat rot_b) {
	posed_part pa = pose_part(a, part_a, pos_a, rot_a), pb = pose_part(b, part_b, pos_b, rot_b);
	posed_box ba = pose_box(&pa), bb = pose_box(&pb);
	return (hs_box_verdict)parts_sat(&pa, &ba, &pb, &bb);
}

void hs_part_world_box(const hs_shape *shape, int part, hs_vec3 pos, hs_quat rot, hs_vec3 *centre, hs_vec3 *half) {
	const hs_part *p = &shape->parts[part];
	if (shape->kind == HS_SHAPE_SPHERE) // as pose_part
		box_of(pos, rot, p->box_center, p->box_half, shape->sphere_radius, hs_add(pos, hs_quat_rotate(rot, p->center)),
		       centre, half);
	else
		box_of(pos, rot, p->box_center, p->box_half, 0.0, pos, centre, half);
}

bool hs_part_world_boxes_apart(const hs_shape *a, int part_a, hs_vec3 centre_a, hs_vec3 half_a, const hs_shape *b,
                               int part_b, hs_vec3 centre_b, hs_vec3 half_b) {
	return boxes_apart_by(centre_a, half_a, a->parts[part_a].radius, centre_b, half_b, b->parts[part_b].radius,
	                      HS_TOUCH_MARGIN); // hs_shapes_overlap's margin
}

static bool valid_shape(const hs_shape *s) { return s && s->part_count > 0 && s->parts && s->vertices; }

static bool shapes_overlap(const hs_shape *a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b, hs_vec3 pos_b,
                           hs_quat rot_b, bool sat) {
	if (!valid_shape(a) || !valid_shape(b) || !spheres_meet(pos_a, a->radius, pos_b, b->radius))
		return false;
	// two exact spheres: the bounding test is the answer
	if (a->kind == HS_SHAPE_SPHERE && b->kind == HS_SHAPE_SPHERE)
		return true;
	ccd_t ccd;
	setup_ccd(&ccd);
	for (int i = 0; i < a->part_count; i++) {
		posed_part pa = pose_part(a, i, pos_a, rot_a);
		for (int j = 0; j < b->part_count; j++) {
			posed_part pb = pose_part(b, j, pos_b, rot_b);
			if (parts_overlap(&pa, &pb, &ccd, sat))
				return true;
		}
	}
	return false;
}

bool hs_shapes_overlap(const hs_shape *a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b, hs_vec3 pos_b,
                       hs_quat rot_b) {
	return shapes_overlap(a, pos_a, rot_a, b, pos_b, rot_b, true);
}

bool hs_shapes_overlap_gjk(const hs_shape *a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b, hs_vec3 pos_b,
                           hs_quat rot_b) {
	return shapes_overlap(a, pos_a, rot_a, b, pos_b, rot_b, false);
}

bool hs_shapes_penetration(const hs_shape *a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b, hs_vec3 pos_b,
                           hs_quat rot_b, double *depth, hs_vec3 *direction) {
	return hs_shapes_within(a, pos_a, rot_a, b, pos_b, rot_b, 0.0, depth, direction);
}

bool hs_shapes_within(const hs_shape *a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b, hs_vec3 pos_b,
                      hs_quat rot_b, double gap, double *depth, hs_vec3 *direction) {
	if (!valid_shape(a) || !valid_shape(b) || !depth || !direction || !(gap >= 0.0) ||
	    !spheres_within(pos_a, a->radius, pos_b, b->radius, gap))
		return false;
	double best = -gap - 1.0;
	hs_vec3 best_dir = hs_v3(0.0, 0.0, 1.0);
	if (a->kind == HS_SHAPE_SPHERE && b->kind == HS_SHAPE_SPHERE) {
		// exact: along the line of centres (up when they coincide)
		hs_vec3 d = hs_sub(pos_b, pos_a);
		double dist = hs_length(d);
		best = fmax(-gap, a->sphere_radius + b->sphere_radius - dist);
		if (dist > 0.0)
			best_dir = hs_scale(d, 1.0 / dist);
	} else {
		ccd_t ccd;
		setup_ccd(&ccd);
		for (int i = 0; i < a->part_count; i++) {
			posed_part pa = pose_part(a, i, pos_a, rot_a);
			pa.margin += 0.5 * gap;
			for (int j = 0; j < b->part_count; j++) {
				posed_part pb = pose_part(b, j, pos_b, rot_b);
				pb.margin += 0.5 * gap;
				if (!spheres_within(pa.center, pa.radius, pb.center, pb.radius, gap) || boxes_apart(&pa, &pb))
					continue;
				normalise_pair(&pa, &pb);
				ccd_real_t d = 0.0;
				ccd_vec3_t dir = {{0.0, 0.0, 0.0}}, pos;
				if (ccdMPRPenetration(&pa, &pb, &ccd, &d, &dir, &pos) != 0)
					continue;
				// back to metres, without the touch margins
				double pair_depth = fmax(-gap, d / pa.inv_scale - 2.0 * HS_TOUCH_MARGIN - gap);
				if (!(pair_depth > best))
					continue;
				best = pair_depth;
				hs_vec3 u = from_ccd(&dir);
				if (!(hs_length_sq(u) > 0.0)) // touching: libccd gives no direction
					u = hs_sub(pb.center, pa.center);
				if (hs_length_sq(u) > 0.0)
					best_dir = hs_normalize(u);
				else
					best_dir = hs_v3(0.0, 0.0, 1.0);
			}
		}
	}
	if (!(best >= -gap))
		return false;
	*depth = best;
	*direction = best_dir;
	return true;
}
