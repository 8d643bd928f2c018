// spring_touch.c — where two objects of the spring model meet (§4.5: "physical contact of
// objects is intuitively equivalent with geometric intersection"): the narrow phase of every kind
// of pair, exact for spheres and boxes, libccd for the rest (spring_collide.c's header gives the
// readings), and the list of the pairs touching where the objects are now (spring_rest.c's).
#include <string.h>

#include "collide.h"
#include "spring_near.h"
#include "spring_touch.h"

// A sphere (centre c, radius r) against the box lo..hi in the same frame: normal from the sphere
// to the box in that frame, depth; false when they do not meet. (r is grown by the gap of a
// touch test: the caller takes the gap off the depth.)
static bool sphere_in_frame(hs_vec3 c, double r, hs_vec3 lo, hs_vec3 hi, hs_vec3 *n, double *depth) {
	hs_vec3 q = hs_v3(fmin(fmax(c.x, lo.x), hi.x), fmin(fmax(c.y, lo.y), hi.y), fmin(fmax(c.z, lo.z), hi.z));
	hs_vec3 d = hs_sub(q, c);
	double dist2 = hs_length_sq(d);
	if (dist2 > 0.0) { // centre outside the box
		double dist = sqrt(dist2);
		if (dist >= r)
			return false;
		*n = hs_scale(d, 1.0 / dist);
		*depth = r - dist;
		return true;
	}
	// centre inside: leave through the nearest face
	double gaps[6] = {c.x - lo.x, hi.x - c.x, c.y - lo.y, hi.y - c.y, c.z - lo.z, hi.z - c.z};
	hs_vec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
	int best = 0;
	for (int k = 1; k < 6; ++k)
		if (gaps[k] < gaps[best])
			best = k;
	*n = dirs[best];
	*depth = gaps[best] + r;
	return true;
}

// Contact of a (sphere) with b (box) within gap: normal from a to b, depth (less the gap).
static bool sphere_box(hs_vec3 pa, double r, hs_vec3 pb, const hs_spring_geom *gb, double gap, hs_vec3 *n,
                       double *depth) {
	if (!sphere_in_frame(pa, r + gap, hs_add(pb, gb->lo), hs_add(pb, gb->hi), n, depth))
		return false;
	*depth -= gap;
	return true;
}

// Contact of two boxes: along the axis of least overlap, normal from a to b.
static bool box_box(const hs_spring_geom *ga, hs_vec3 pa, const hs_spring_geom *gb, hs_vec3 pb, double gap,
                    hs_vec3 *n, double *depth) {
	hs_vec3 alo = hs_add(pa, ga->lo), ahi = hs_add(pa, ga->hi), blo = hs_add(pb, gb->lo), bhi = hs_add(pb, gb->hi);
	double ov[3] = {fmin(ahi.x, bhi.x) - fmax(alo.x, blo.x), fmin(ahi.y, bhi.y) - fmax(alo.y, blo.y),
	                fmin(ahi.z, bhi.z) - fmax(alo.z, blo.z)};
	if (ov[0] <= -gap || ov[1] <= -gap || ov[2] <= -gap)
		return false;
	int axis = 0;
	for (int k = 1; k < 3; ++k)
		if (ov[k] < ov[axis])
			axis = k;
	double ca[3] = {alo.x + ahi.x, alo.y + ahi.y, alo.z + ahi.z}, cb[3] = {blo.x + bhi.x, blo.y + bhi.y, blo.z + bhi.z};
	double sign = cb[axis] >= ca[axis] ? 1.0 : -1.0;
	*n = hs_v3(axis == 0 ? sign : 0.0, axis == 1 ? sign : 0.0, axis == 2 ? sign : 0.0);
	*depth = ov[axis];
	return true;
}

// Contact of a (sphere) with b (turned box): as sphere_box in b's body frame, normal from a to b.
static bool sphere_obox(hs_vec3 pa, double r, hs_vec3 pb, const hs_spring_geom *gb, double gap, hs_vec3 *n,
                        double *depth) {
	hs_vec3 c = hs_quat_inv_rotate(gb->rot, hs_sub(pa, pb)), h = gb->half;
	if (!sphere_in_frame(c, r + gap, hs_scale(h, -1.0), h, n, depth))
		return false;
	*n = hs_quat_rotate(gb->rot, *n);
	*depth -= gap;
	return true;
}

// Half-width of a box (axes u[3], half extents h) along the unit direction l.
static double box_reach(const hs_vec3 u[3], hs_vec3 h, hs_vec3 l) {
	return h.x * fabs(hs_dot(u[0], l)) + h.y * fabs(hs_dot(u[1], l)) + h.z * fabs(hs_dot(u[2], l));
}

// Two boxes in their own orientations: the separating-axis test over the 6 face normals and the
// 9 edge-edge cross products; contact along the axis of least overlap, normal from a to b. An
// edge axis must beat the best face axis by 5 % (a face normal is the stabler answer at a tie).
static bool obox_obox(const hs_spring_geom *ga, hs_vec3 pa, const hs_spring_geom *gb, hs_vec3 pb, double gap,
                      hs_vec3 *n, double *depth) {
	hs_vec3 ua[3] = {hs_quat_rotate(ga->rot, hs_v3(1, 0, 0)), hs_quat_rotate(ga->rot, hs_v3(0, 1, 0)),
	                 hs_quat_rotate(ga->rot, hs_v3(0, 0, 1))};
	hs_vec3 ub[3] = {hs_quat_rotate(gb->rot, hs_v3(1, 0, 0)), hs_quat_rotate(gb->rot, hs_v3(0, 1, 0)),
	                 hs_quat_rotate(gb->rot, hs_v3(0, 0, 1))};
	hs_vec3 t = hs_sub(pb, pa), best_axis = ua[0];
	double best = INFINITY;
	for (int k = 0; k < 15; ++k) {
		hs_vec3 l = k < 3 ? ua[k] : k < 6 ? ub[k - 3] : hs_cross(ua[(k - 6) / 3], ub[(k - 6) % 3]);
		if (k >= 6) {
			double len = hs_length(l);
			if (!(len > 1e-9)) // parallel edges: the face axes decide
				continue;
			l = hs_scale(l, 1.0 / len);
		}
		double overlap = box_reach(ua, ga->half, l) + box_reach(ub, gb->half, l) - fabs(hs_dot(t, l));
		if (!(overlap > -gap))
			return false; // a separating axis (wider than the gap)
		if (k < 6 ? overlap < best : overlap < 0.95 * best) {
			best = overlap;
			best_axis = l;
		}
	}
	*n = hs_dot(t, best_axis) >= 0.0 ? best_axis : hs_neg(best_axis);
	*depth = best;
	return true;
}

// Any pair with a shape that is neither a sphere nor a box: libccd on the convex parts.
static bool convex_pair(const hs_world *world, const hs_spring_geom *ga, hs_vec3 pa, const hs_spring_geom *gb,
                        hs_vec3 pb, double gap, hs_vec3 *n, double *depth) {
	return hs_shapes_within(&world->model.shapes[ga->shape], pa, ga->rot, &world->model.shapes[gb->shape], pb, gb->rot, gap,
	                        depth, n);
}

bool hs_spring_contact(const hs_world *world, const hs_spring_geom *ga, hs_vec3 pa, const hs_spring_geom *gb,
                       hs_vec3 pb, hs_vec3 *n, double *depth) {
	return hs_spring_contact_within(world, ga, pa, gb, pb, 0.0, n, depth);
}

bool hs_spring_contact_within(const hs_world *world, const hs_spring_geom *ga, hs_vec3 pa, const hs_spring_geom *gb,
                     hs_vec3 pb, double gap, hs_vec3 *n, double *depth) {
	if (ga->form == HS_FORM_CONVEX || gb->form == HS_FORM_CONVEX)
		return convex_pair(world, ga, pa, gb, pb, gap, n, depth);
	if (ga->form == HS_FORM_BOX || gb->form == HS_FORM_BOX) { // a turned box
		if (ga->sphere)
			return sphere_obox(pa, ga->radius, pb, gb, gap, n, depth);
		if (gb->sphere) {
			if (!sphere_obox(pb, gb->radius, pa, ga, gap, n, depth))
				return false;
			*n = hs_neg(*n);
			return true;
		}
		return obox_obox(ga, pa, gb, pb, gap, n, depth);
	}
	if (ga->sphere && gb->sphere) {
		hs_vec3 d = hs_sub(pb, pa);
		double dist = hs_length(d), reach = ga->radius + gb->radius;
		if (dist >= reach + gap)
			return false;
		*n = dist > 0.0 ? hs_scale(d, 1.0 / dist) : hs_v3(0.0, 0.0, 1.0);
		*depth = reach - dist;
		return true;
	}
	if (ga->sphere)
		return sphere_box(pa, ga->radius, pb, gb, gap, n, depth);
	if (gb->sphere) {
		if (!sphere_box(pb, gb->radius, pa, ga, gap, n, depth))
			return false;
		*n = hs_neg(*n);
		return true;
	}
	return box_box(ga, pa, gb, pb, gap, n, depth);
}

void hs_spring_find_touches(hs_world *world, hs_spring_system *sys, double gap, double reach) {
	hs_spring_file_all(world, sys);
	sys->touch_count = 0;
	const hs_spring_geom *geom = sys->geom;
	for (int i = 0; i < world->model.object_count; ++i) {
		hs_vec3 pa = world->state.bodies[i].pos;
		const int *near;
		int count = hs_spring_near_grown(world, sys, i, reach, &near);
		for (int k = 0; k < count; ++k) {
			int j = near[k];
			hs_vec3 pb = world->state.bodies[j].pos, n;
			double depth;
			if (j <= i || !hs_spring_boxes_meet(&geom[i], pa, &geom[j], pb, reach + hs_spring_margin(&geom[i], pa) + hs_spring_margin(&geom[j], pb)) ||
			    !hs_spring_contact_within(world, &geom[i], pa, &geom[j], pb, reach, &n, &depth))
				continue;
			if (sys->touch_count == sys->touch_capacity) {
				world->counters.dropped_contacts++;
				continue;
			}
			hs_spring_touch *t = &sys->touch[sys->touch_count++];
			memset(t, 0, sizeof *t);
			t->a = i;
			t->b = j;
			t->n = n;
			t->depth = depth;
			t->ahead = depth < -gap;
		}
	}
}

bool hs_spring_touching(const hs_spring_system *sys, int a, int b) {
	int lo = 0, hi = sys->touch_count;
	while (lo < hi) { // touches are in ascending (a, b)
		int mid = lo + (hi - lo) / 2;
		const hs_spring_touch *t = &sys->touch[mid];
		if (t->a < a || (t->a == a && t->b < b))
			lo = mid + 1;
		else
			hi = mid;
	}
	if (lo == sys->touch_count || sys->touch[lo].a != a || sys->touch[lo].b != b)
		return false;
	return !sys->touch[lo].ahead || sys->touch[lo].normal > 0.0;
}
