// spring_geom.c — the reach of an object in the spring model and point / ray queries on it.
//
// Reading fixed here: forces act at G only and objects keep their orientation (§4.2), so each
// object's reach relative to G is fixed. The floor and walls (spring_contact.c) and picking
// (spring_grab.c) use its world-axis bounding box (exact for the floor and the axis-aligned walls:
// the lowest / outermost vertex); collisions (spring_collide.c) use the true shape.
#include <string.h>

#include "spring_geom.h"

// A box whose every turned vertex is a corner of its world-axis bounding box IS that box: it
// collides through the bounding-box formulas (bit for bit as before turned boxes existed).
static bool axis_aligned(const hs_shape *shape, hs_quat rot, hs_vec3 lo, hs_vec3 hi) {
	for (int i = 0; i < shape->vertex_count; ++i) {
		hs_vec3 v = hs_quat_rotate(rot, shape->vertices[i]);
		if ((v.x != lo.x && v.x != hi.x) || (v.y != lo.y && v.y != hi.y) || (v.z != lo.z && v.z != hi.z))
			return false;
	}
	return true;
}

hs_spring_geom hs_spring_geom_of(const hs_shape *shape, const hs_body *body) {
	hs_spring_geom g;
	memset(&g, 0, sizeof g);
	g.shape = body->shape;
	g.rot = body->rot;
	if (shape->kind == HS_SHAPE_SPHERE) {
		double r = shape->sphere_radius;
		g.sphere = true;
		g.form = HS_FORM_SPHERE;
		g.radius = r;
		g.lo = hs_v3(-r, -r, -r);
		g.hi = hs_v3(r, r, r);
		g.inner = r;
		return g;
	}
	g.lo = hs_v3(INFINITY, INFINITY, INFINITY);
	g.hi = hs_v3(-INFINITY, -INFINITY, -INFINITY);
	for (int i = 0; i < shape->vertex_count; ++i) {
		hs_vec3 v = hs_quat_rotate(body->rot, shape->vertices[i]);
		g.lo = hs_v3(fmin(g.lo.x, v.x), fmin(g.lo.y, v.y), fmin(g.lo.z, v.z));
		g.hi = hs_v3(fmax(g.hi.x, v.x), fmax(g.hi.y, v.y), fmax(g.hi.z, v.z));
		g.half = hs_v3(fmax(g.half.x, fabs(shape->vertices[i].x)), fmax(g.half.y, fabs(shape->vertices[i].y)),
		               fmax(g.half.z, fabs(shape->vertices[i].z)));
	}
	g.form = shape->kind != HS_SHAPE_BOX ? HS_FORM_CONVEX : axis_aligned(shape, body->rot, g.lo, g.hi) ? HS_FORM_AXIS_BOX : HS_FORM_BOX;
	hs_vec3 h = hs_scale(hs_sub(g.hi, g.lo), 0.5);
	double r = fmin(h.x, fmin(h.y, h.z));
	g.inner = g.form == HS_FORM_BOX ? fmin(g.half.x, fmin(g.half.y, g.half.z)) : g.form == HS_FORM_AXIS_BOX ? r : r / 8.0;
	return g;
}

bool hs_spring_geom_inside(const hs_spring_geom *g, hs_vec3 p, hs_vec3 s) {
	if (g->sphere)
		return hs_length_sq(hs_sub(s, p)) <= g->radius * g->radius;
	return s.x >= p.x + g->lo.x && s.x <= p.x + g->hi.x && s.y >= p.y + g->lo.y && s.y <= p.y + g->hi.y &&
	       s.z >= p.z + g->lo.z && s.z <= p.z + g->hi.z;
}

double hs_spring_geom_distance(const hs_spring_geom *g, hs_vec3 p, hs_vec3 s) {
	if (g->sphere)
		return hs_distance(s, p) - g->radius;
	hs_vec3 lo = hs_add(p, g->lo), hi = hs_add(p, g->hi);
	hs_vec3 q = hs_v3(fmin(fmax(s.x, lo.x), hi.x), fmin(fmax(s.y, lo.y), hi.y), fmin(fmax(s.z, lo.z), hi.z));
	return hs_distance(s, q);
}

// the sphere: the nearer root of |o + t d − p|² = r², 0 when o is inside
static double sphere_ray(const hs_spring_geom *g, hs_vec3 p, hs_vec3 o, hs_vec3 d, double range) {
	hs_vec3 oc = hs_sub(o, p);
	double b = hs_dot(oc, d), cc = hs_dot(oc, oc) - g->radius * g->radius, disc = b * b - cc;
	if (disc < 0.0)
		return -1.0;
	if (cc <= 0.0)
		return 0.0; // the origin is inside
	double t = -b - sqrt(disc);
	return t >= 0.0 && t <= range ? t : -1.0;
}

double hs_spring_geom_ray(const hs_spring_geom *g, hs_vec3 p, hs_vec3 o, hs_vec3 d, double range) {
	if (g->sphere)
		return sphere_ray(g, p, o, d, range);
	double tmin = 0.0, tmax = range; // the box: slabs
	double os[3] = {o.x, o.y, o.z}, ds[3] = {d.x, d.y, d.z};
	double los[3] = {p.x + g->lo.x, p.y + g->lo.y, p.z + g->lo.z}, his[3] = {p.x + g->hi.x, p.y + g->hi.y, p.z + g->hi.z};
	for (int k = 0; k < 3; ++k) {
		if (ds[k] == 0.0) {
			if (os[k] < los[k] || os[k] > his[k])
				return -1.0;
			continue;
		}
		double t1 = (los[k] - os[k]) / ds[k], t2 = (his[k] - os[k]) / ds[k];
		if (t1 > t2) {
			double tmp = t1;
			t1 = t2;
			t2 = tmp;
		}
		tmin = t1 > tmin ? t1 : tmin;
		tmax = t2 < tmax ? t2 : tmax;
		if (tmin > tmax)
			return -1.0;
	}
	return tmin;
}
