// collide.c — interference of posed shapes: bounding spheres, then libccd on convex part pairs.
//
// libccd compares against absolute epsilons (DBL_EPSILON on squared lengths), so each pair is
// handed to it in normalised coordinates, (x - origin) / (r_a + r_b): its tolerances become
// relative to the size of the pair, the same for a 5 cm block as for a 1 m box.
// Nothing here allocates: support points are posed on the fly from the body-frame vertices.
#include <ccd/ccd.h>

#include "collide.h"

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

// World-axis box around a part posed at (pos, rot): its body-frame box (c, h) turned (|R| times
// the half extents); an exact sphere (sphere_radius > 0) about `center` (world).
static void box_of(hs_vec3 pos, hs_quat rot, hs_vec3 c, hs_vec3 h, double sphere_radius, hs_vec3 center,
                   hs_vec3 *centre, hs_vec3 *half) {
	if (sphere_radius > 0.0) {
		*centre = center;
		*half = hs_v3(sphere_radius, sphere_radius, sphere_radius);
		return;
	}
	// hs_quat_rotate of the three axes with its products by 0 and 1 left out: only the signs of
	// zeros can differ, and only magnitudes are read
	double x = rot.x, y = rot.y, z = rot.z, w = rot.w, a = 2.0 * x, b = 2.0 * y, d = 2.0 * z;
	hs_vec3 ux = hs_v3(1.0 + (y * -b - z * d), d * w - x * -b, -b * w + x * d);
	hs_vec3 uy = hs_v3(-d * w + y * a, 1.0 + (z * -d - x * a), a * w - y * -d);
	hs_vec3 uz = hs_v3(b * w - z * -a, -a * w + z * b, 1.0 + (x * -a - y * b));
	*centre = hs_add(pos, hs_quat_rotate(rot, c));
	*half = hs_v3(fabs(ux.x) * h.x + fabs(uy.x) * h.y + fabs(uz.x) * h.z,
	              fabs(ux.y) * h.x + fabs(uy.y) * h.y + fabs(uz.y) * h.z,
	              fabs(ux.z) * h.x + fabs(uy.z) * h.y + fabs(uz.z) * h.z);
}

static void part_box(const posed_part *p, hs_vec3 *centre, hs_vec3 *half) {
	box_of(p->pos, p->rot, p->box_center, p->box_half, p->sphere_radius, p->center, centre, half);
}

// Cheap rejection before libccd: the parts' world boxes are apart by more than 1e-8 of the pair's
// size (far beyond libccd's 1e-10 and the touch margins), so GJK and MPR would find no contact
// either and no result changes. A small part beside a huge one (a 5 cm cube within the bounding
// sphere of a 400 m box) no longer costs a GJK run. `margin`: each part's (posed_part).
static bool boxes_apart_by(hs_vec3 ca, hs_vec3 ha, double ra, hs_vec3 cb, hs_vec3 hb, double rb, double margin) {
	double m = 1e-8 * (ra + rb) + 4.0 * HS_TOUCH_MARGIN + (margin - HS_TOUCH_MARGIN) * 2.0;
	return fabs(cb.x - ca.x) > ha.x + hb.x + m || fabs(cb.y - ca.y) > ha.y + hb.y + m ||
	       fabs(cb.z - ca.z) > ha.z + hb.z + m;
}

static bool boxes_apart(const posed_part *a, const posed_part *b) {
	hs_vec3 ca, ha, cb, hb;
	part_box(a, &ca, &ha);
	part_box(b, &cb, &hb);
	return boxes_apart_by(ca, ha, a->radius, cb, hb, b->radius, a->margin);
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

bool hs_shapes_overlap(const hs_shape *a, hs_vec3 pos_a, hs_quat rot_a, const hs_shape *b, hs_vec3 pos_b,
                       hs_quat rot_b) {
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
			if (!spheres_meet(pa.center, pa.radius, pb.center, pb.radius) || boxes_apart(&pa, &pb))
				continue;
			normalise_pair(&pa, &pb);
			if (ccdGJKIntersect(&pa, &pb, &ccd))
				return true;
		}
	}
	return false;
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
