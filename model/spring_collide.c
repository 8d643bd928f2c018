// spring_collide.c — object–object collisions of "Dynamics in Interaction on the Responsive
// Workbench" (§4.5: "collisions ... momentum and energy are conserved").
//
// Readings fixed here (DESIGN.md "Spring model" leaves them to us):
//  - After the step, each overlapping pair (array order) exchanges an impulse along the contact
//    normal, J = −(1 + e) v_n / (1/m_a + 1/m_b), then is pushed apart along the normal in
//    inverse-mass shares.
//  - "Physical contact of objects is intuitively equivalent with geometric intersection" (§4.5):
//    the true shapes meet. Spheres are exact (along the line of centres); a box is the box in its
//    own orientation: sphere–box along the nearest point, box–box along the separating-axis
//    test's axis of least overlap (15 axes); every other shape (pyramid, the L-block's parts,
//    ellipsoid, polyhedron) and any pair with one goes through libccd (hs_shapes_penetration:
//    MPR's depth and direction, deepest part pair). A box whose faces lie on its world-axis
//    bounding box uses the bounding-box formulas, the same bits as before turned boxes existed.
//    Objects do not turn (§4.2: no torque), so a collision changes velocities only.
//  - There is no resting contact between objects.
#include "spring_collide.h"

// A sphere (centre c, radius r) against the box lo..hi in the same frame: normal from the sphere
// to the box in that frame, depth; false when they do not meet.
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

// Contact of a (sphere) with b (box): normal from a to b, depth.
static bool sphere_box(hs_vec3 pa, double r, hs_vec3 pb, const hs_spring_geom *gb, hs_vec3 *n, double *depth) {
	return sphere_in_frame(pa, r, hs_add(pb, gb->lo), hs_add(pb, gb->hi), n, depth);
}

// Contact of two boxes: along the axis of least overlap, normal from a to b.
static bool box_box(const hs_spring_geom *ga, hs_vec3 pa, const hs_spring_geom *gb, hs_vec3 pb, hs_vec3 *n,
                    double *depth) {
	hs_vec3 alo = hs_add(pa, ga->lo), ahi = hs_add(pa, ga->hi), blo = hs_add(pb, gb->lo), bhi = hs_add(pb, gb->hi);
	double ov[3] = {fmin(ahi.x, bhi.x) - fmax(alo.x, blo.x), fmin(ahi.y, bhi.y) - fmax(alo.y, blo.y),
	                fmin(ahi.z, bhi.z) - fmax(alo.z, blo.z)};
	if (ov[0] <= 0.0 || ov[1] <= 0.0 || ov[2] <= 0.0)
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
static bool sphere_obox(hs_vec3 pa, double r, hs_vec3 pb, const hs_spring_geom *gb, hs_vec3 *n, double *depth) {
	hs_vec3 c = hs_quat_inv_rotate(gb->rot, hs_sub(pa, pb)), h = gb->half;
	if (!sphere_in_frame(c, r, hs_scale(h, -1.0), h, n, depth))
		return false;
	*n = hs_quat_rotate(gb->rot, *n);
	return true;
}

// Half-width of a box (axes u[3], half extents h) along the unit direction l.
static double box_reach(const hs_vec3 u[3], hs_vec3 h, hs_vec3 l) {
	return h.x * fabs(hs_dot(u[0], l)) + h.y * fabs(hs_dot(u[1], l)) + h.z * fabs(hs_dot(u[2], l));
}

// Two boxes in their own orientations: the separating-axis test over the 6 face normals and the
// 9 edge-edge cross products; contact along the axis of least overlap, normal from a to b. An
// edge axis must beat the best face axis by 5 % (a face normal is the stabler answer at a tie).
static bool obox_obox(const hs_spring_geom *ga, hs_vec3 pa, const hs_spring_geom *gb, hs_vec3 pb, hs_vec3 *n,
                      double *depth) {
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
		if (!(overlap > 0.0))
			return false; // a separating axis
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
                        hs_vec3 pb, hs_vec3 *n, double *depth) {
	return hs_shapes_penetration(&world->shapes[ga->shape], pa, ga->rot, &world->shapes[gb->shape], pb, gb->rot,
	                             depth, n);
}

bool hs_spring_contact(const hs_world *world, const hs_spring_geom *ga, hs_vec3 pa, const hs_spring_geom *gb,
                       hs_vec3 pb, hs_vec3 *n, double *depth) {
	if (ga->form == HS_FORM_CONVEX || gb->form == HS_FORM_CONVEX)
		return convex_pair(world, ga, pa, gb, pb, n, depth);
	if (ga->form == HS_FORM_BOX || gb->form == HS_FORM_BOX) { // a turned box
		if (ga->sphere)
			return sphere_obox(pa, ga->radius, pb, gb, n, depth);
		if (gb->sphere) {
			if (!sphere_obox(pb, gb->radius, pa, ga, n, depth))
				return false;
			*n = hs_neg(*n);
			return true;
		}
		return obox_obox(ga, pa, gb, pb, n, depth);
	}
	if (ga->sphere && gb->sphere) {
		hs_vec3 d = hs_sub(pb, pa);
		double dist = hs_length(d), reach = ga->radius + gb->radius;
		if (dist >= reach)
			return false;
		*n = dist > 0.0 ? hs_scale(d, 1.0 / dist) : hs_v3(0.0, 0.0, 1.0);
		*depth = reach - dist;
		return true;
	}
	if (ga->sphere)
		return sphere_box(pa, ga->radius, pb, gb, n, depth);
	if (gb->sphere) {
		if (!sphere_box(pb, gb->radius, pa, ga, n, depth))
			return false;
		*n = hs_neg(*n);
		return true;
	}
	return box_box(ga, pa, gb, pb, n, depth);
}

// The impulse of restitution e along n (from a to b) when approaching, then the separation by
// depth in inverse-mass shares (velocities untouched by it: momentum stays exact).
static void respond(hs_body *a, hs_body *b, hs_vec3 n, double depth, double e) {
	double wa = 1.0 / a->mass, wb = 1.0 / b->mass, wsum = wa + wb;
	double vn = hs_dot(hs_sub(b->vel, a->vel), n);
	if (vn < 0.0) { // approaching: impulse along the normal
		double impulse = -(1.0 + e) * vn / wsum;
		a->vel = hs_mul_add(a->vel, -impulse * wa, n);
		b->vel = hs_mul_add(b->vel, impulse * wb, n);
	}
	a->pos = hs_mul_add(a->pos, -depth * wa / wsum, n);
	b->pos = hs_mul_add(b->pos, depth * wb / wsum, n);
}

// m added around each bounding box in the broad phase: far above rounding and libccd's touch
// margins, so it only ever lets through pairs the exact test then rejects.
static double margin_of(const hs_spring_geom *g, hs_vec3 p) {
	return 1e-6 + 1e-9 * (fabs(p.x) + fabs(p.y) + fabs(p.z) + g->hi.x - g->lo.x + g->hi.y - g->lo.y + g->hi.z - g->lo.z);
}

static bool boxes_meet(const hs_spring_geom *ga, hs_vec3 pa, const hs_spring_geom *gb, hs_vec3 pb, double m) {
	return pa.x + ga->lo.x - m <= pb.x + gb->hi.x && pb.x + gb->lo.x <= pa.x + ga->hi.x + m &&
	       pa.y + ga->lo.y - m <= pb.y + gb->hi.y && pb.y + gb->lo.y <= pa.y + ga->hi.y + m &&
	       pa.z + ga->lo.z - m <= pb.z + gb->hi.z && pb.z + gb->lo.z <= pa.z + ga->hi.z + m;
}

static hs_vec3 box_centre(const hs_spring_geom *g, hs_vec3 p) {
	return hs_add(p, hs_scale(hs_add(g->lo, g->hi), 0.5));
}

// Files every object in the broad phase by its bounding box's centre; levels from the boxes'
// half-extents, assigned again when objects were added (or the geometry was rebuilt).
static void file_all(hs_world *world, hs_spring_system *sys) {
	int n = world->object_count;
	if (sys->grid_count != n) {
		for (int i = 0; i < n; ++i) {
			hs_vec3 w = hs_sub(sys->geom[i].hi, sys->geom[i].lo);
			sys->grid.half[i] = 0.5 * fmax(w.x, fmax(w.y, w.z));
		}
		hs_hgrid_build(&sys->grid, n);
		sys->grid_count = n;
	}
	for (int i = 0; i < n; ++i)
		hs_hgrid_file(&sys->grid, i, box_centre(&sys->geom[i], world->bodies[i].pos));
}

// Objects whose bounds may meet object i's box (its margin included), in index order.
static int near_of(const hs_world *world, hs_spring_system *sys, int i) {
	const hs_spring_geom *g = &sys->geom[i];
	hs_vec3 p = world->bodies[i].pos;
	double m = margin_of(g, p);
	hs_vec3 lo = hs_add(p, hs_sub(g->lo, hs_v3(m, m, m))), hi = hs_add(p, hs_add(g->hi, hs_v3(m, m, m)));
	return hs_hgrid_query(&sys->grid, lo, hi, sys->near);
}

void hs_spring_collide(hs_world *world, hs_spring_system *sys) {
	// Pairs in ascending (i, j), as the full double loop met them, so the bits are the same: for
	// each i the broad phase lists the j near it now; when a pair moved i, the list is taken again
	// from where i is now and resumes after j (only i and j move within i's turn).
	const hs_spring_geom *geom = sys->geom;
	double e = sys->def.restitution;
	file_all(world, sys);
	for (int i = 0; i < world->object_count; ++i) {
		hs_body *a = &world->bodies[i];
		const hs_spring_geom *ga = &geom[i];
		int count = near_of(world, sys, i);
		for (int k = 0; k < count; ++k) {
			int j = sys->near[k];
			if (j <= i)
				continue;
			hs_body *b = &world->bodies[j];
			const hs_spring_geom *gb = &geom[j];
			hs_vec3 n;
			double depth;
			if (!boxes_meet(ga, a->pos, gb, b->pos, margin_of(ga, a->pos) + margin_of(gb, b->pos)) ||
			    !hs_spring_contact(world, ga, a->pos, gb, b->pos, &n, &depth))
				continue;
			respond(a, b, n, depth, e);
			sys->separated[i] = sys->separated[j] = 1;
			hs_hgrid_file(&sys->grid, i, box_centre(ga, a->pos));
			hs_hgrid_file(&sys->grid, j, box_centre(gb, b->pos));
			count = near_of(world, sys, i);
			for (k = 0; k < count && sys->near[k] <= j; ++k)
				;
			--k; // the loop's ++k lands on the first object after j
		}
	}
}
