// test_collide.c — interference and penetration of posed shapes against hand-placed cases
// and against an exact separating-axis test for boxes; hs_shapes_overlap's own box test against
// libccd's answer (hs_shapes_overlap_gjk).
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <setjmp.h>
#include <cmocka.h>

#include "collide.h"
#include "test_util.h"

#define SQRT2 1.41421356237309504880

static const hs_quat ID = {1, 0, 0, 0};

static bool overlap(const hs_shape *a, hs_vec3 pa, const hs_shape *b, hs_vec3 pb) {
	bool ab = hs_shapes_overlap(a, pa, ID, b, pb, ID);
	// symmetric: swapping the two shapes gives the same answer
	assert_int_equal(ab, hs_shapes_overlap(b, pb, ID, a, pa, ID));
	return ab;
}

static void test_cubes(void **state) {
	(void)state;
	hs_shape *c = hs_shape_box(hs_v3(1, 1, 1), NULL);
	assert_non_null(c);
	hs_vec3 o = hs_v3(0, 0, 0);
	assert_false(overlap(c, o, c, hs_v3(3, 0, 0)));   // apart, bounding spheres too
	assert_false(overlap(c, o, c, hs_v3(1.5, 0, 0))); // apart, bounding spheres overlap
	assert_true(overlap(c, o, c, hs_v3(0.5, 0.2, -0.3)));
	assert_true(overlap(c, o, c, o)); // coincident
	// face to face: touching, touching within 1e-12, overlapping by 1e-13, separated by 1e-6
	const hs_vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
	for (int i = 0; i < 3; i++) {
		for (int sign = -1; sign <= 1; sign += 2) {
			hs_vec3 u = hs_scale(axes[i], sign);
			assert_true(overlap(c, o, c, u));
			assert_true(overlap(c, o, c, hs_scale(u, 1.0 + 5e-13)));
			assert_true(overlap(c, o, c, hs_scale(u, 1.0 - 1e-13)));
			assert_false(overlap(c, o, c, hs_scale(u, 1.0 + 1e-6)));
			// sliding along the face by 0.3 changes nothing
			hs_vec3 side = axes[(i + 1) % 3];
			assert_true(overlap(c, o, c, hs_mul_add(u, 0.3, side)));
			assert_false(overlap(c, o, c, hs_mul_add(hs_scale(u, 1.0 + 1e-6), 0.3, side)));
		}
	}
	// edge to edge and corner to corner, touching and 1e-6 apart
	assert_true(overlap(c, o, c, hs_v3(1, 1, 0)));
	assert_false(overlap(c, o, c, hs_v3(1 + 1e-6, 1 + 1e-6, 0)));
	assert_true(overlap(c, o, c, hs_v3(1, 1, 1)));
	assert_false(overlap(c, o, c, hs_v3(1 + 1e-6, 1 + 1e-6, 1 + 1e-6)));
	// far from the origin: only the relative pose matters
	hs_vec3 far = hs_v3(100, -200, 50);
	assert_true(overlap(c, far, c, hs_add(far, hs_v3(1, 0, 0))));
	assert_false(overlap(c, far, c, hs_add(far, hs_v3(1 + 1e-6, 0, 0))));
	hs_shape_destroy(c);
}

static void test_small_cubes(void **state) {
	(void)state;
	// the paper's 5 cm blocks: same answers at the scale of a hand
	hs_shape *c = hs_shape_box(hs_v3(0.05, 0.05, 0.05), NULL);
	hs_vec3 o = hs_v3(0.3, 0.1, 0.025);
	assert_true(overlap(c, o, c, hs_add(o, hs_v3(0.05, 0, 0))));
	assert_true(overlap(c, o, c, hs_add(o, hs_v3(0.049, 0.01, 0))));
	assert_false(overlap(c, o, c, hs_add(o, hs_v3(0.05 + 1e-6, 0.01, 0))));
	assert_false(overlap(c, o, c, hs_add(o, hs_v3(0, 0, 0.05 + 1e-6))));
	assert_true(overlap(c, o, c, hs_add(o, hs_v3(0, 0, 0.05))));
	hs_shape_destroy(c);
}

static void test_rotated_cube(void **state) {
	(void)state;
	hs_shape *c = hs_shape_box(hs_v3(1, 1, 1), NULL);
	hs_quat r45 = hs_quat_from_axis_angle(hs_v3(0, 0, 1), HS_PI / 4);
	hs_vec3 o = hs_v3(0, 0, 0);
	// turned 45° about z, its side corner reaches √2/2 along x: an edge meets a face
	double reach = 0.5 + SQRT2 / 2;
	assert_false(hs_shapes_overlap(c, o, ID, c, hs_v3(reach + 1e-6, 0.1, 0), r45));
	assert_true(hs_shapes_overlap(c, o, ID, c, hs_v3(reach - 1e-6, 0.1, 0), r45));
	assert_false(hs_shapes_overlap(c, hs_v3(reach + 1e-6, 0.1, 0), r45, c, o, ID));
	assert_true(hs_shapes_overlap(c, hs_v3(reach - 1e-6, 0.1, 0), r45, c, o, ID));
	// along the diagonal, the fixed cube's corner (√2/2 from its centre) meets the turned cube's
	// face (1/2 from its centre): apart while the centres are more than √2/2 + 1/2 apart
	double d = (SQRT2 / 2 + 0.5) / SQRT2; // per axis
	assert_false(hs_shapes_overlap(c, o, ID, c, hs_v3(d + 1e-6, d + 1e-6, 0.2), r45));
	assert_true(hs_shapes_overlap(c, o, ID, c, hs_v3(d - 1e-6, d - 1e-6, 0.2), r45));
	// the bounding spheres (√3/2 each) overlap there: spheres alone would have said yes
	assert_true(hs_length(hs_v3(d + 1e-6, d + 1e-6, 0.2)) < sqrt(3.0));
	hs_shape_destroy(c);
}

static void test_l_block_notch(void **state) {
	(void)state;
	// L-block of bounding box 3 × 1 × 2, arms 1 thick, G = (1.25, 0.5, 0.75) in its own corner frame
	hs_shape *l = hs_shape_l_block(hs_v3(3, 1, 2), 1, NULL);
	hs_shape *c = hs_shape_box(hs_v3(0.5, 0.5, 0.5), NULL);
	assert_non_null(l);
	assert_non_null(c);
	hs_vec3 g = hs_v3(1.25, 0.5, 0.75);
	hs_vec3 o = hs_v3(0, 0, 0);
	// in the notch (x in [1, 3], z in [1, 2]): centre (2, 0.5, 1.5), 0.25 above the foot, 0.75 off the upright
	hs_vec3 notch = hs_sub(hs_v3(2, 0.5, 1.5), g);
	assert_true(hs_length(notch) < l->radius + c->radius); // bounding spheres overlap ...
	assert_true(hs_distance(notch, l->parts[0].center) < l->parts[0].radius + c->radius); // ... the foot's too
	assert_false(overlap(l, o, c, notch));                                                 // ... but no overlap
	// in the foot
	assert_true(overlap(l, o, c, hs_sub(hs_v3(2, 0.5, 0.5), g)));
	// in the upright only
	assert_true(overlap(l, o, c, hs_sub(hs_v3(0.5, 0.5, 1.8), g)));
	// resting on the foot (touching) and just above it
	assert_true(overlap(l, o, c, hs_sub(hs_v3(2, 0.5, 1.25), g)));
	assert_false(overlap(l, o, c, hs_sub(hs_v3(2, 0.5, 1.25 + 1e-6), g)));
	// leaning on the upright's inner face
	assert_true(overlap(l, o, c, hs_sub(hs_v3(1.25, 0.5, 1.5), g)));
	assert_false(overlap(l, o, c, hs_sub(hs_v3(1.25 + 1e-6, 0.5, 1.5), g)));
	// the same, with both posed elsewhere and turned 90° about z: x becomes y
	hs_quat q = hs_quat_from_axis_angle(hs_v3(0, 0, 1), HS_PI / 2);
	hs_vec3 p = hs_v3(10, 5, 1);
	assert_false(hs_shapes_overlap(l, p, q, c, hs_add(p, hs_quat_rotate(q, notch)), q));
	assert_true(hs_shapes_overlap(l, p, q, c, hs_add(p, hs_quat_rotate(q, hs_sub(hs_v3(2, 0.5, 0.9), g))), q));
	hs_shape_destroy(l);
	hs_shape_destroy(c);
}

static void test_sphere_box(void **state) {
	(void)state;
	hs_shape *s = hs_shape_sphere(0.5, NULL);
	hs_shape *b = hs_shape_box(hs_v3(1, 1, 1), NULL);
	hs_vec3 o = hs_v3(0, 0, 0);
	assert_true(overlap(b, o, s, hs_v3(0.99, 0, 0)));
	assert_true(overlap(b, o, s, hs_v3(1.0, 0.2, 0.3))); // touching a face
	assert_false(overlap(b, o, s, hs_v3(1.0 + 1e-6, 0.2, 0.3)));
	// off a corner: the sphere's box would overlap (0.3 < 0.5 per axis), the sphere does not
	// (corner distance √3 · 0.3 ≈ 0.52 > 0.5)
	assert_false(overlap(b, o, s, hs_v3(0.8, 0.8, 0.8)));
	double t = 0.5 + 0.5 / sqrt(3.0); // corner exactly on the sphere
	assert_true(overlap(b, o, s, hs_v3(t - 1e-6, t - 1e-6, t - 1e-6)));
	assert_false(overlap(b, o, s, hs_v3(t + 1e-6, t + 1e-6, t + 1e-6)));
	// exact sphere, not its display polyhedron: turned by half a slice (11.25°) about z, the
	// polyhedron reaches only 0.5 cos 11.25° ≈ 0.4904 along -x; the sphere still overlaps by 0.005
	hs_quat half_slice = hs_quat_from_axis_angle(hs_v3(0, 0, 1), HS_PI / 16);
	assert_true(hs_shapes_overlap(b, o, ID, s, hs_v3(0.995, 0, 0), half_slice));
	assert_true(hs_shapes_overlap(s, hs_v3(0.995, 0, 0), half_slice, b, o, ID));
	// two spheres: exact, touching counts
	assert_true(overlap(s, o, s, hs_v3(0.6, 0.8, 0)));
	assert_false(overlap(s, o, s, hs_v3(0.6, 0.8 + 1e-9, 0)));
	hs_shape_destroy(s);
	hs_shape_destroy(b);
}

static void test_ellipsoid_box(void **state) {
	(void)state;
	hs_shape *e = hs_shape_ellipsoid(hs_v3(1, 0.5, 0.25), NULL);
	hs_shape *b = hs_shape_box(hs_v3(1, 1, 1), NULL);
	hs_vec3 o = hs_v3(0, 0, 0);
	// the tips of the axes are vertices: (±1, 0, 0), (0, ±0.5, 0), (0, 0, ±0.25)
	assert_true(overlap(e, o, b, hs_v3(1.49, 0, 0)));
	assert_false(overlap(e, o, b, hs_v3(1.51, 0, 0)));
	assert_true(overlap(e, o, b, hs_v3(0, 0.99, 0.1)));
	assert_false(overlap(e, o, b, hs_v3(0, 1.01, 0.1)));
	assert_true(overlap(e, o, b, hs_v3(0.2, 0, 0.74)));
	assert_false(overlap(e, o, b, hs_v3(0.2, 0, 0.76)));
	// between the axes the 32-face polyhedron is inside the true ellipsoid: at 45° in x–y the
	// equator vertex is (√2/2, √2/4, 0); a box turned 45° with its face through
	// that vertex's support distance (√2/2 · √2/2 + √2/4 · √2/2 = 0.75) just misses or hits
	hs_quat r45 = hs_quat_from_axis_angle(hs_v3(0, 0, 1), HS_PI / 4);
	hs_vec3 u = hs_v3(SQRT2 / 2, SQRT2 / 2, 0);
	assert_false(hs_shapes_overlap(e, o, ID, b, hs_scale(u, 0.75 + 0.5 + 1e-6), r45));
	assert_true(hs_shapes_overlap(e, o, ID, b, hs_scale(u, 0.75 + 0.5 - 1e-6), r45));
	hs_shape_destroy(e);
	hs_shape_destroy(b);
}

static void test_penetration(void **state) {
	(void)state;
	hs_shape *c = hs_shape_box(hs_v3(1, 1, 1), NULL);
	hs_vec3 o = hs_v3(0, 0, 0);
	double depth = -1;
	hs_vec3 dir = hs_v3(0, 0, 0);
	// overlapping by 0.1 along x: move b by 0.1 along +x to separate
	assert_true(hs_shapes_penetration(c, o, ID, c, hs_v3(0.9, 0, 0), ID, &depth, &dir));
	assert_near(depth, 0.1, 1e-6);
	assert_vec3_near(dir, hs_v3(1, 0, 0), 1e-6);
	assert_true(hs_shapes_penetration(c, o, ID, c, hs_v3(0, 0, -0.9), ID, &depth, &dir));
	assert_near(depth, 0.1, 1e-6);
	assert_vec3_near(dir, hs_v3(0, 0, -1), 1e-6);
	// apart: false, outputs untouched
	depth = 42;
	assert_false(hs_shapes_penetration(c, o, ID, c, hs_v3(1.01, 0, 0), ID, &depth, &dir));
	assert_near(depth, 42, 0);
	// a 5 cm sphere sunk 1 cm into the top of the box
	hs_shape *s = hs_shape_sphere(0.05, NULL);
	assert_true(hs_shapes_penetration(c, o, ID, s, hs_v3(0.1, 0.2, 0.54), ID, &depth, &dir));
	assert_near(depth, 0.01, 1e-6);
	assert_vec3_near(dir, hs_v3(0, 0, 1), 1e-6);
	// two spheres: exact, along the line of centres
	assert_true(hs_shapes_penetration(s, o, ID, s, hs_v3(0.06, 0.08, 0), ID, &depth, &dir));
	assert_near(depth, 0.0, 1e-15);
	assert_true(hs_shapes_penetration(s, o, ID, s, hs_v3(0.03, 0.04, 0), ID, &depth, &dir));
	assert_near(depth, 0.05, 1e-15);
	assert_vec3_near(dir, hs_v3(0.6, 0.8, 0), 1e-15);
	// L-block: the deeper of the two parts counts; a cube sunk 0.2 into the foot's top
	hs_shape *l = hs_shape_l_block(hs_v3(3, 1, 2), 1, NULL);
	hs_shape *small = hs_shape_box(hs_v3(0.5, 0.5, 0.5), NULL);
	hs_vec3 g = hs_v3(1.25, 0.5, 0.75);
	assert_true(hs_shapes_penetration(l, o, ID, small, hs_sub(hs_v3(1.5, 0.5, 1.05), g), ID, &depth, &dir));
	assert_near(depth, 0.2, 1e-6);
	assert_vec3_near(dir, hs_v3(0, 0, 1), 1e-6);
	// in the notch: nothing
	assert_false(hs_shapes_penetration(l, o, ID, small, hs_sub(hs_v3(2, 0.5, 1.5), g), ID, &depth, &dir));
	hs_shape_destroy(c);
	hs_shape_destroy(s);
	hs_shape_destroy(l);
	hs_shape_destroy(small);
}

static void test_bad_input(void **state) {
	(void)state;
	hs_shape *c = hs_shape_box(hs_v3(1, 1, 1), NULL);
	hs_vec3 o = hs_v3(0, 0, 0);
	assert_false(hs_shapes_overlap(NULL, o, ID, c, o, ID));
	assert_false(hs_shapes_overlap(c, o, ID, NULL, o, ID));
	// a NaN pose never interferes (and never hangs)
	assert_false(hs_shapes_overlap(c, hs_v3(NAN, 0, 0), ID, c, o, ID));
	assert_false(hs_shapes_overlap(c, o, hs_q(NAN, 0, 0, 0), c, hs_v3(0.5, 0, 0), ID));
	double depth;
	hs_vec3 dir;
	assert_false(hs_shapes_penetration(c, o, ID, c, o, ID, NULL, &dir));
	assert_false(hs_shapes_penetration(c, o, ID, c, o, ID, &depth, NULL));
	assert_false(hs_shapes_penetration(c, hs_v3(0, INFINITY, 0), ID, c, o, ID, &depth, &dir));
	hs_shape_destroy(c);
}

// ---------------------------------------------------------------------------------------------
// GJK against the exact separating-axis test for two boxes (15 axes), over random poses.

static uint64_t lcg_next(uint64_t *s) {
	*s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
	return *s >> 11;
}
static double uniform(uint64_t *s, double lo, double hi) {
	return lo + (hi - lo) * ((double)lcg_next(s) / 9007199254740992.0);
}

// Largest separation over the 15 candidate axes (> 0: apart, < 0: overlapping).
static double sat_separation(hs_vec3 ha, hs_vec3 pa, hs_quat qa, hs_vec3 hb, hs_vec3 pb, hs_quat qb) {
	hs_vec3 ea[3] = {hs_quat_rotate(qa, hs_v3(1, 0, 0)), hs_quat_rotate(qa, hs_v3(0, 1, 0)),
	                 hs_quat_rotate(qa, hs_v3(0, 0, 1))};
	hs_vec3 eb[3] = {hs_quat_rotate(qb, hs_v3(1, 0, 0)), hs_quat_rotate(qb, hs_v3(0, 1, 0)),
	                 hs_quat_rotate(qb, hs_v3(0, 0, 1))};
	double ra[3] = {ha.x, ha.y, ha.z}, rb[3] = {hb.x, hb.y, hb.z};
	hs_vec3 axes[15];
	int n = 0;
	for (int i = 0; i < 3; i++) {
		axes[n++] = ea[i];
		axes[n++] = eb[i];
		for (int j = 0; j < 3; j++)
			axes[n++] = hs_cross(ea[i], eb[j]);
	}
	double best = -INFINITY;
	hs_vec3 d = hs_sub(pb, pa);
	for (int k = 0; k < n; k++) {
		double len = hs_length(axes[k]);
		if (len < 1e-6)
			continue; // parallel edges: covered by the face axes
		hs_vec3 u = hs_scale(axes[k], 1.0 / len);
		double pr = 0;
		for (int i = 0; i < 3; i++)
			pr += ra[i] * fabs(hs_dot(u, ea[i])) + rb[i] * fabs(hs_dot(u, eb[i]));
		best = fmax(best, fabs(hs_dot(u, d)) - pr);
	}
	return best;
}

static hs_quat random_quat(uint64_t *s) {
	hs_quat q;
	do
		q = hs_q(uniform(s, -1, 1), uniform(s, -1, 1), uniform(s, -1, 1), uniform(s, -1, 1));
	while (hs_quat_dot(q, q) < 0.01 || hs_quat_dot(q, q) > 1);
	return hs_quat_normalize(q);
}

// hs_part_world_box holds the box's corners (posed as the vertices are, to its rounding); a pair
// whose boxes hs_part_world_boxes_apart finds apart is one hs_shapes_overlap finds apart too.
static bool check_world_boxes(const hs_shape *a, hs_vec3 sa, hs_vec3 pa, hs_quat qa, const hs_shape *b, hs_vec3 pb,
                              hs_quat qb, bool overlap) {
	hs_vec3 ca, ha, cb, hb;
	hs_part_world_box(a, 0, pa, qa, &ca, &ha);
	hs_part_world_box(b, 0, pb, qb, &cb, &hb);
	for (int k = 0; k < 8; ++k) {
		hs_vec3 v = hs_add(pa, hs_quat_rotate(qa, hs_v3((k & 1 ? 0.5 : -0.5) * sa.x, (k & 2 ? 0.5 : -0.5) * sa.y,
		                                                (k & 4 ? 0.5 : -0.5) * sa.z)));
		hs_vec3 d = hs_sub(v, ca);
		double slack = 1e-12 * (1.0 + hs_length(pa));
		assert_true(fabs(d.x) <= ha.x + slack && fabs(d.y) <= ha.y + slack && fabs(d.z) <= ha.z + slack);
	}
	bool apart = hs_part_world_boxes_apart(a, 0, ca, ha, b, 0, cb, hb);
	assert_false(apart && overlap);
	return apart;
}

// `trials` random pairs of boxes with sides in [0.01, 0.5] × scale, centres within 0.6 × scale.
static void random_boxes_against_sat(uint64_t seed, double scale, int trials) {
	int hits = 0, misses = 0, boxes_apart = 0;
	for (int trial = 0; trial < trials; trial++) {
		hs_vec3 sa = hs_scale(hs_v3(uniform(&seed, 0.01, 0.5), uniform(&seed, 0.01, 0.5), uniform(&seed, 0.01, 0.5)), scale);
		hs_vec3 sb = hs_scale(hs_v3(uniform(&seed, 0.01, 0.5), uniform(&seed, 0.01, 0.5), uniform(&seed, 0.01, 0.5)), scale);
		hs_vec3 pa = hs_v3(uniform(&seed, -1, 1), uniform(&seed, -1, 1), uniform(&seed, 0, 1));
		hs_vec3 pb = hs_add(pa, hs_scale(hs_v3(uniform(&seed, -0.6, 0.6), uniform(&seed, -0.6, 0.6),
		                                       uniform(&seed, -0.6, 0.6)), scale));
		hs_quat qa = random_quat(&seed), qb = random_quat(&seed);
		double sep = sat_separation(hs_scale(sa, 0.5), pa, qa, hs_scale(sb, 0.5), pb, qb);
		if (fabs(sep) < 1e-9 * scale)
			continue; // too close to call for either test
		hs_shape *a = hs_shape_box(sa, NULL), *b = hs_shape_box(sb, NULL);
		bool got = hs_shapes_overlap(a, pa, qa, b, pb, qb);
		if (got != (sep < 0))
			print_error("scale %g, trial %d: separation %.3g, overlap %d\n", scale, trial, sep, (int)got);
		assert_int_equal(got, sep < 0);
		boxes_apart += check_world_boxes(a, sa, pa, qa, b, pb, qb, got);
		hits += got;
		misses += !got;
		hs_shape_destroy(a);
		hs_shape_destroy(b);
	}
	// both outcomes well represented, and boxes apart among the misses
	assert_true(hits > trials / 10);
	assert_true(misses > trials / 10);
	assert_true(boxes_apart > trials / 20 && boxes_apart < misses);
}

static void test_random_boxes_against_sat(void **state) {
	(void)state;
	random_boxes_against_sat(12345, 1.0, 20000);
	// centimetre boxes: libccd's absolute epsilons would miss overlaps of a tenth of a
	// millimetre here without the per-pair normalisation
	random_boxes_against_sat(2, 0.02, 20000);
}

// ---------------------------------------------------------------------------------------------
// hs_shapes_overlap's separating-axis test for two boxes, whose answers must be libccd's
// (hs_shapes_overlap_gjk): closed-form cases, then random poses near contact.

static hs_box_verdict verdict(const hs_shape *a, hs_vec3 pa, hs_quat qa, const hs_shape *b, hs_vec3 pb, hs_quat qb) {
	return hs_box_parts_verdict(a, 0, pa, qa, b, 0, pb, qb);
}

// hs_shapes_overlap, which equals libccd's answer, both ways round (the cases are clear of touching)
static bool overlap_as_gjk(const hs_shape *a, hs_vec3 pa, hs_quat qa, const hs_shape *b, hs_vec3 pb, hs_quat qb) {
	bool got = hs_shapes_overlap(a, pa, qa, b, pb, qb);
	assert_int_equal(got, hs_shapes_overlap_gjk(a, pa, qa, b, pb, qb));
	assert_int_equal(got, hs_shapes_overlap(b, pb, qb, a, pa, qa));
	assert_int_equal(got, hs_shapes_overlap_gjk(b, pb, qb, a, pa, qa));
	return got;
}

static void test_sat_faces(void **state) {
	(void)state;
	hs_shape *c = hs_shape_box(hs_v3(1, 1, 1), NULL);
	hs_vec3 o = hs_v3(0, 0, 0);
	// apart by 1 mm along x: apart; overlapping by 1 mm: overlap, whether the centres lie within
	// the inscribed balls (1 m apart at most) or not (then by the 15 axes)
	assert_int_equal(verdict(c, o, ID, c, hs_v3(1.001, 0, 0), ID), HS_BOXES_APART);
	assert_false(overlap_as_gjk(c, o, ID, c, hs_v3(1.001, 0, 0), ID));
	assert_int_equal(verdict(c, o, ID, c, hs_v3(0.999, 0, 0), ID), HS_BOXES_OVERLAP);
	assert_true(overlap_as_gjk(c, o, ID, c, hs_v3(0.999, 0, 0), ID));
	assert_int_equal(verdict(c, o, ID, c, hs_v3(0.999, 0.6, -0.4), ID), HS_BOXES_OVERLAP);
	assert_true(overlap_as_gjk(c, o, ID, c, hs_v3(0.999, 0.6, -0.4), ID));
	assert_int_equal(verdict(c, o, ID, c, hs_v3(0.999, 1.001, 0), ID), HS_BOXES_APART);
	// touching, or within the slack (1e-6 of the radii sum): libccd decides
	assert_int_equal(verdict(c, o, ID, c, hs_v3(1, 0.3, 0), ID), HS_BOXES_CLOSE);
	assert_int_equal(verdict(c, o, ID, c, hs_v3(1 + 1e-7, 0.3, 0), ID), HS_BOXES_CLOSE);
	assert_int_equal(verdict(c, o, ID, c, hs_v3(1 - 1e-7, 0.3, 0), ID), HS_BOXES_CLOSE);
	assert_true(overlap_as_gjk(c, o, ID, c, hs_v3(1, 0.3, 0), ID));
	// a quaternion far from unit turns no frame: libccd decides
	assert_int_equal(verdict(c, o, hs_q(1.1, 0, 0, 0), c, hs_v3(0.5, 0, 0), ID), HS_BOXES_CLOSE);
	hs_shape_destroy(c);
}

static void test_sat_which_parts(void **state) {
	(void)state;
	hs_shape *c = hs_shape_box(hs_v3(1, 1, 1), NULL);
	hs_vec3 o = hs_v3(0, 0, 0), near = hs_v3(0.9, 0.2, 0), far = hs_v3(1.2, 0.2, 0);
	// a box whose vertices come in another order is still a box
	const hs_vec3 v[8] = {{0.5, 0.5, 0.5},   {-0.5, -0.5, -0.5}, {0.5, -0.5, 0.5},  {-0.5, 0.5, -0.5},
	                      {-0.5, -0.5, 0.5}, {0.5, 0.5, -0.5},   {-0.5, 0.5, 0.5},  {0.5, -0.5, -0.5}};
	const int cube_faces[24] = {1, 3, 5, 7, 4, 2, 0, 6, 1, 7, 2, 4, 3, 6, 0, 5, 1, 4, 6, 3, 7, 5, 0, 2};
	const int sizes[6] = {4, 4, 4, 4, 4, 4};
	char why[128];
	hs_shape *shuffled = hs_shape_polyhedron(v, 8, cube_faces, sizes, 6, why, sizeof why, NULL);
	assert_non_null(shuffled);
	assert_int_equal(verdict(shuffled, o, ID, c, near, ID), HS_BOXES_OVERLAP);
	assert_int_equal(verdict(shuffled, o, ID, c, far, ID), HS_BOXES_APART);
	// eight vertices but not a box (a frustum: the top face smaller): libccd decides
	hs_vec3 f[8];
	memcpy(f, v, sizeof f);
	for (int i = 0; i < 8; i++)
		if (f[i].z > 0) {
			f[i].x *= 0.5;
			f[i].y *= 0.5;
		}
	hs_shape *frustum = hs_shape_polyhedron(f, 8, cube_faces, sizes, 6, why, sizeof why, NULL);
	assert_non_null(frustum);
	assert_int_equal(frustum->parts[0].vertex_count, 8);
	assert_int_equal(verdict(frustum, o, ID, c, near, ID), HS_BOXES_CLOSE);
	assert_int_equal(verdict(c, far, ID, frustum, o, ID), HS_BOXES_CLOSE);
	assert_true(overlap_as_gjk(frustum, o, ID, c, near, ID));
	// an exact sphere, an ellipsoid: libccd decides
	hs_shape *s = hs_shape_sphere(0.5, NULL), *e = hs_shape_ellipsoid(hs_v3(1, 0.5, 0.25), NULL);
	assert_int_equal(verdict(s, o, ID, c, near, ID), HS_BOXES_CLOSE);
	assert_int_equal(verdict(c, o, ID, e, near, ID), HS_BOXES_CLOSE);
	// the L-block's two parts are boxes: each decided (the foot overlaps the cube, the upright not)
	hs_shape *l = hs_shape_l_block(hs_v3(3, 1, 2), 1, NULL);
	hs_vec3 foot = hs_sub(hs_v3(2, 0.5, 0.5), hs_v3(1.25, 0.5, 0.75)); // the cube sunk in the foot
	hs_shape *small = hs_shape_box(hs_v3(0.5, 0.5, 0.5), NULL);
	int overlaps = 0, aparts = 0;
	for (int k = 0; k < l->part_count; k++) {
		hs_box_verdict got = hs_box_parts_verdict(l, k, o, ID, small, 0, foot, ID);
		overlaps += got == HS_BOXES_OVERLAP;
		aparts += got == HS_BOXES_APART;
	}
	assert_int_equal(l->part_count, 2);
	assert_int_equal(overlaps, 1);
	assert_int_equal(aparts, 1);
	assert_true(overlap_as_gjk(l, o, ID, small, foot, ID));
	hs_shape_destroy(c);
	hs_shape_destroy(shuffled);
	hs_shape_destroy(frustum);
	hs_shape_destroy(s);
	hs_shape_destroy(e);
	hs_shape_destroy(l);
	hs_shape_destroy(small);
}

static void test_sat_edge_face(void **state) {
	(void)state;
	// turned 45° about z, the cube's vertical edge reaches √2/2 along x: it meets the fixed cube's
	// face at x = 1/2 when the centres are 1/2 + √2/2 apart
	hs_shape *c = hs_shape_box(hs_v3(1, 1, 1), NULL);
	hs_quat r45 = hs_quat_from_axis_angle(hs_v3(0, 0, 1), HS_PI / 4);
	hs_vec3 o = hs_v3(0, 0, 0);
	double reach = 0.5 + SQRT2 / 2;
	for (int k = 0; k < 2; k++) {
		double y = k ? -0.2 : 0.1;
		assert_int_equal(verdict(c, o, ID, c, hs_v3(reach + 1e-3, y, 0), r45), HS_BOXES_APART);
		assert_false(overlap_as_gjk(c, o, ID, c, hs_v3(reach + 1e-3, y, 0), r45));
		assert_int_equal(verdict(c, o, ID, c, hs_v3(reach - 1e-3, y, 0), r45), HS_BOXES_OVERLAP);
		assert_true(overlap_as_gjk(c, o, ID, c, hs_v3(reach - 1e-3, y, 0), r45));
		assert_int_equal(verdict(c, hs_v3(reach - 1e-3, y, 0), r45, c, o, ID), HS_BOXES_OVERLAP);
	}
	hs_shape_destroy(c);
}

// Largest separation of two unit cubes over their six face normals alone.
static double face_separation(hs_vec3 pa, hs_quat qa, hs_vec3 pb, hs_quat qb) {
	const hs_vec3 e[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
	double best = -INFINITY;
	for (int k = 0; k < 6; k++) {
		hs_vec3 u = hs_quat_rotate(k < 3 ? qa : qb, e[k % 3]);
		double reach = 0;
		for (int i = 0; i < 3; i++)
			reach += 0.5 * fabs(hs_dot(u, hs_quat_rotate(qa, e[i]))) + 0.5 * fabs(hs_dot(u, hs_quat_rotate(qb, e[i])));
		best = fmax(best, fabs(hs_dot(u, hs_sub(pb, pa))) - reach);
	}
	return best;
}

static void test_sat_edge_edge(void **state) {
	(void)state;
	// a turned 45° about x has an edge along x at y = √2/2; b turned 45° about z has one along z at
	// y = y_b - √2/2: the edges cross, √2 - y_b apart along y = x × z, which no face normal is.
	// The whole scene turned by q, so that y is no world axis either and the world boxes overlap.
	hs_shape *c = hs_shape_box(hs_v3(1, 1, 1), NULL);
	hs_quat q = hs_quat_from_axis_angle(hs_normalize(hs_v3(1, 2, 3)), 0.7);
	hs_quat qa = hs_quat_mul(q, hs_quat_from_axis_angle(hs_v3(1, 0, 0), HS_PI / 4));
	hs_quat qb = hs_quat_mul(q, hs_quat_from_axis_angle(hs_v3(0, 0, 1), HS_PI / 4));
	hs_vec3 o = hs_v3(0.3, -0.2, 0.5);
	for (int sign = -1; sign <= 1; sign += 2) {
		hs_vec3 pb = hs_add(o, hs_quat_rotate(q, hs_v3(0.1, SQRT2 + sign * 1e-3, -0.05)));
		hs_vec3 ca, ha, cb, hb;
		hs_part_world_box(c, 0, o, qa, &ca, &ha);
		hs_part_world_box(c, 0, pb, qb, &cb, &hb);
		assert_false(hs_part_world_boxes_apart(c, 0, ca, ha, c, 0, cb, hb));
		// the six face normals see an overlap of more than 0.1 m; all 15 axes a gap or an overlap of 1 mm
		assert_true(face_separation(o, qa, pb, qb) < -0.1);
		assert_near(sat_separation(hs_v3(0.5, 0.5, 0.5), o, qa, hs_v3(0.5, 0.5, 0.5), pb, qb), sign * 1e-3, 1e-12);
		assert_int_equal(verdict(c, o, qa, c, pb, qb), sign > 0 ? HS_BOXES_APART : HS_BOXES_OVERLAP);
		assert_int_equal(overlap_as_gjk(c, o, qa, c, pb, qb), sign < 0);
	}
	hs_shape_destroy(c);
}

static void test_sat_parallel_edges(void **state) {
	(void)state;
	// both cubes turned 45° about z, b's vertical edge facing a's a gap g apart along x, then b
	// tilted by `tilt` about the line joining the edges: the two edges are then nearly parallel, and
	// their cross axis (x, of length sin(tilt)) is the only one that separates the cubes, by g,
	// while a's face normals see an overlap of ~tilt / 3. The scene turned by q: no world axis.
	hs_shape *c = hs_shape_box(hs_v3(1, 1, 1), NULL);
	hs_quat q = hs_quat_from_axis_angle(hs_normalize(hs_v3(-2, 1, 3)), 0.5);
	hs_quat r45 = hs_quat_from_axis_angle(hs_v3(0, 0, 1), HS_PI / 4);
	const struct {
		double tilt, gap;
		hs_box_verdict want;
		bool overlap;
	} cases[] = {
	    {0, 1e-3, HS_BOXES_APART, false},      // parallel: the face normals separate (by g / √2)
	    {1e-4, 1e-5, HS_BOXES_APART, false},   // the short cross axis shows the gap
	    {1e-4, 1e-6, HS_BOXES_CLOSE, false},   // within the slack along it: libccd decides
	    {1e-4, -1e-5, HS_BOXES_OVERLAP, true}, // overlapping along every axis
	    {1e-13, -1e-3, HS_BOXES_OVERLAP, true} // parallel within 1e-12: its cross axis skipped
	};
	for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
		hs_quat qa = hs_quat_mul(q, r45);
		hs_quat qb = hs_quat_mul(q, hs_quat_mul(hs_quat_from_axis_angle(hs_v3(1, 0, 0), cases[k].tilt), r45));
		hs_vec3 pa = hs_v3(0.2, 0.1, -0.3), pb = hs_add(pa, hs_quat_rotate(q, hs_v3(SQRT2 + cases[k].gap, 0, 0)));
		if (cases[k].tilt > 0 && cases[k].gap > 0)
			assert_true(face_separation(pa, qa, pb, qb) < -1e-5);
		assert_int_equal(verdict(c, pa, qa, c, pb, qb), cases[k].want);
		assert_int_equal(overlap_as_gjk(c, pa, qa, c, pb, qb), cases[k].overlap);
	}
	hs_shape_destroy(c);
}

// A uniformly random rotation: a normalised 4-d Gaussian.
static hs_quat gauss_quat(gsl_rng *rng) {
	return hs_quat_normalize(hs_q(gsl_ran_gaussian(rng, 1), gsl_ran_gaussian(rng, 1), gsl_ran_gaussian(rng, 1),
	                              gsl_ran_gaussian(rng, 1)));
}

static hs_vec3 gauss_dir(gsl_rng *rng) {
	return hs_normalize(hs_v3(gsl_ran_gaussian(rng, 1), gsl_ran_gaussian(rng, 1), gsl_ran_gaussian(rng, 1)));
}

// The distance along dir from a's centre at which b's centre puts the boxes' exact separation
// (sat_separation) at target: bisection between the centres together (overlapping) and `far`
// (apart); along a line the separation is convex, so it crosses target once on the way out.
static double place_at(hs_vec3 ha, hs_vec3 pa, hs_quat qa, hs_vec3 hb, hs_quat qb, hs_vec3 dir, double target, double far) {
	double lo = 0, hi = far;
	for (int k = 0; k < 100; k++) {
		double mid = 0.5 * (lo + hi);
		if (sat_separation(ha, pa, qa, hb, hs_add(pa, hs_scale(dir, mid)), qb) > target)
			hi = mid;
		else
			lo = mid;
	}
	return 0.5 * (lo + hi);
}

static hs_vec3 random_size(gsl_rng *rng, double scale) {
	return hs_scale(hs_v3(gsl_ran_flat(rng, 0.2, 1), gsl_ran_flat(rng, 0.2, 1), gsl_ran_flat(rng, 0.2, 1)), scale);
}

typedef struct near_pair {
	hs_shape *a, *b;
	hs_vec3 pa, pb;
	hs_quat qa, qb;
	double sep; // exact separation (m, sat_separation)
} near_pair;

// Two boxes (sides in [0.2, 1] × scale, or two equal cubes) whose exact separation is rel times
// the sum of their bounding radii; b turned from a by `turn` rad when turn > 0 (nearly parallel
// edges), at random otherwise.
static near_pair random_near_pair(gsl_rng *rng, double scale, double rel, double turn) {
	near_pair p;
	hs_vec3 sa = random_size(rng, scale), sb = random_size(rng, scale);
	if (gsl_rng_uniform(rng) < 0.3)
		sa = sb = hs_v3(sa.x, sa.x, sa.x); // two equal cubes, as the paper's blocks
	p.a = hs_shape_box(sa, NULL);
	p.b = hs_shape_box(sb, NULL);
	p.qa = gauss_quat(rng);
	p.qb = turn > 0 ? hs_quat_normalize(hs_quat_mul(p.qa, hs_quat_from_axis_angle(gauss_dir(rng), turn))) : gauss_quat(rng);
	p.pa = hs_v3(gsl_ran_flat(rng, -1, 1), gsl_ran_flat(rng, -1, 1), gsl_ran_flat(rng, 0, 1));
	hs_vec3 dir = gauss_dir(rng), ha = hs_scale(sa, 0.5), hb = hs_scale(sb, 0.5);
	double size = p.a->radius + p.b->radius;
	p.pb = hs_add(p.pa, hs_scale(dir, place_at(ha, p.pa, p.qa, hb, p.qb, dir, rel * size, 2 * size)));
	p.sep = sat_separation(ha, p.pa, p.qa, hb, p.pb, p.qb);
	return p;
}

static void test_sat_random_near_contact(void **state) {
	(void)state;
	gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
	gsl_rng_set(rng, 2027);
	enum { N = 4000 };
	int counts[3] = {0, 0, 0}, parallel_decided = 0;
	for (int trial = 0; trial < N; trial++) {
		// separations from 1e-9 to 1e-2 of the size, either side; a third with nearly parallel edges
		double rel = (gsl_rng_uniform(rng) < 0.5 ? -1 : 1) * pow(10, gsl_ran_flat(rng, -9, -2));
		double turn = trial % 3 == 0 ? pow(10, gsl_ran_flat(rng, -14, -2)) : 0;
		near_pair p = random_near_pair(rng, trial % 2 ? 1.0 : 0.05, rel, turn);
		bool got = hs_shapes_overlap(p.a, p.pa, p.qa, p.b, p.pb, p.qb);
		bool gjk = hs_shapes_overlap_gjk(p.a, p.pa, p.qa, p.b, p.pb, p.qb);
		if (got != gjk)
			print_error("trial %d: separation %.3g of the size, turn %.3g: %d, libccd %d\n", trial, rel, turn, got, gjk);
		assert_int_equal(got, gjk);
		hs_box_verdict v = verdict(p.a, p.pa, p.qa, p.b, p.pb, p.qb);
		counts[v]++;
		parallel_decided += turn > 0 && v != HS_BOXES_CLOSE;
		if (turn == 0 && v != HS_BOXES_CLOSE) // and a clear answer is the exact one
			assert_int_equal(v == HS_BOXES_OVERLAP, p.sep < 0);
		hs_shape_destroy(p.a);
		hs_shape_destroy(p.b);
	}
	gsl_rng_free(rng);
	print_message("apart %d, overlap %d, close %d, parallel decided %d\n", counts[1], counts[0], counts[2], parallel_decided);
	// most pairs decided either way, the nearest left to libccd
	assert_true(counts[HS_BOXES_APART] > N / 5 && counts[HS_BOXES_OVERLAP] > N / 5);
	assert_true(counts[HS_BOXES_CLOSE] > N / 20);
	assert_true(parallel_decided > N / 10);
}

// libccd's GJK counts shapes as touching when its simplex comes within sqrt(DBL_EPSILON) ≈ 1.5e-8
// of the origin in the pair's normalised coordinates: most boxes apart by 1.2e-8 of their radii
// sum overlap for it. The box test leaves them to it (a slack of 1e-8 alone would say apart).
static void test_gjk_touching_band(void **state) {
	(void)state;
	gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
	gsl_rng_set(rng, 7);
	enum { N = 400 };
	int gjk_overlaps = 0;
	for (int trial = 0; trial < N; trial++) {
		near_pair p = random_near_pair(rng, trial % 2 ? 1.0 : 0.05, 1.2e-8, 0);
		assert_true(p.sep > 1e-8 * (p.a->radius + p.b->radius));
		bool gjk = hs_shapes_overlap_gjk(p.a, p.pa, p.qa, p.b, p.pb, p.qb);
		assert_int_equal(hs_shapes_overlap(p.a, p.pa, p.qa, p.b, p.pb, p.qb), gjk);
		assert_int_equal(verdict(p.a, p.pa, p.qa, p.b, p.pb, p.qb), HS_BOXES_CLOSE);
		gjk_overlaps += gjk;
		hs_shape_destroy(p.a);
		hs_shape_destroy(p.b);
	}
	gsl_rng_free(rng);
	print_message("gjk overlaps %d of %d\n", gjk_overlaps, N);
	assert_true(gjk_overlaps > N / 2);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_cubes),
	    cmocka_unit_test(test_small_cubes),
	    cmocka_unit_test(test_rotated_cube),
	    cmocka_unit_test(test_l_block_notch),
	    cmocka_unit_test(test_sphere_box),
	    cmocka_unit_test(test_ellipsoid_box),
	    cmocka_unit_test(test_penetration),
	    cmocka_unit_test(test_bad_input),
	    cmocka_unit_test(test_random_boxes_against_sat),
	    cmocka_unit_test(test_sat_faces),
	    cmocka_unit_test(test_sat_which_parts),
	    cmocka_unit_test(test_sat_edge_face),
	    cmocka_unit_test(test_sat_edge_edge),
	    cmocka_unit_test(test_sat_parallel_edges),
	    cmocka_unit_test(test_sat_random_near_contact),
	    cmocka_unit_test(test_gjk_touching_band),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
