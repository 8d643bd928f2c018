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
//  - No tunnelling: a pair apart at the frame's end whose paths through the frame met (exactly for
//    two spheres, by sub-steps no longer than the sum of their inner radii otherwise) is put back
//    where they met and answered there (first_meeting).
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

// Objects whose bounds may meet object i's box (its margin included), or its path through the frame
// grown by `reach` (the farthest any object moved: where another's path may cross it), in index
// order.
static int near_of(const hs_world *world, hs_spring_system *sys, int i, double reach) {
	if (sys->all_pairs) {
		for (int j = 0; j < world->object_count; ++j)
			sys->near[j] = j;
		return world->object_count;
	}
	const hs_spring_geom *g = &sys->geom[i];
	hs_vec3 p = world->bodies[i].pos, s = sys->saved_pos[i];
	double m = margin_of(g, p);
	hs_vec3 lo = hs_add(p, hs_sub(g->lo, hs_v3(m, m, m))), hi = hs_add(p, hs_add(g->hi, hs_v3(m, m, m)));
	if (reach > 0.0) {
		lo = hs_v3(fmin(lo.x, s.x + g->lo.x) - reach, fmin(lo.y, s.y + g->lo.y) - reach, fmin(lo.z, s.z + g->lo.z) - reach);
		hi = hs_v3(fmax(hi.x, s.x + g->hi.x) + reach, fmax(hi.y, s.y + g->hi.y) + reach, fmax(hi.z, s.z + g->hi.z) + reach);
	}
	return hs_hgrid_query(&sys->grid, lo, hi, sys->near);
}


// Object i at the fraction tau of the frame, for motion at constant acceleration through it (gravity,
// sliding friction): the position from the frame start's and end's velocities, p0 + dt (tau v0 +
// tau² (v1 - v0) / 2), when its end is the frame's end (the step was such); else the straight path.
static hs_vec3 path_at(const hs_world *world, const hs_spring_system *sys, int i, double tau) {
	const hs_body *b = &world->bodies[i];
	double dt = world->def.dt;
	hs_vec3 v0 = sys->saved_vel[i], dv = hs_sub(b->vel, v0), p0 = sys->saved_pos[i];
	hs_vec3 end = hs_add(p0, hs_scale(hs_mul_add(v0, 0.5, dv), dt));
	if (hs_length_sq(hs_sub(end, b->pos)) <= 1e-24)
		return hs_add(p0, hs_scale(hs_mul_add(hs_scale(v0, tau), 0.5 * tau * tau, dv), dt));
	return hs_mul_add(p0, tau, hs_sub(b->pos, p0));
}

// Object i put back to the fraction tau of the frame: on its path, the velocity between the frame
// start's and end's.
static void state_at(hs_world *world, const hs_spring_system *sys, int i, double tau) {
	hs_body *b = &world->bodies[i];
	hs_vec3 p = path_at(world, sys, i, tau);
	b->vel = hs_mul_add(sys->saved_vel[i], tau, hs_sub(b->vel, sys->saved_vel[i]));
	b->pos = p;
}

// No tunnelling (issue 11): two objects apart at the frame's start may meet on the way, whether or
// not they still overlap where the frame leaves them. The first fraction tau at which they meet, -1 when
// they do not: at sub-steps no longer than the sum of their inner radii (a sphere's radius, a box's
// smallest half extent) along their paths (path_at), so no pass through the other's inner ball is
// missed (a glancing overlap shallower than that may be), then by bisection to 1e-12 of the frame
// between the last sub-step apart and the first that meets.
#define HS_MAX_SWEEP_STEPS 4096
static bool meet_at(const hs_world *world, const hs_spring_system *sys, int i, int j, double t) {
	hs_vec3 n;
	double depth;
	return hs_spring_contact(world, &sys->geom[i], path_at(world, sys, i, t), &sys->geom[j], path_at(world, sys, j, t),
	                         &n, &depth);
}

// Two spheres: the gap |G_b - G_a| - (r_a + r_b) along their paths, a smooth function of tau.
static double sphere_gap(const hs_world *world, const hs_spring_system *sys, int i, int j, double t) {
	return hs_length(hs_sub(path_at(world, sys, j, t), path_at(world, sys, i, t))) - sys->geom[i].radius -
	       sys->geom[j].radius;
}

// The gap's root in [lo, hi] (apart at lo, meeting at hi) by regula falsi with the Illinois rule,
// to 1e-12 of the frame or a gap within 1e-15 m: a few steps where bisection takes forty.
static double sphere_root(const hs_world *world, const hs_spring_system *sys, int i, int j, double lo, double hi) {
	double flo = sphere_gap(world, sys, i, j, lo), fhi = sphere_gap(world, sys, i, j, hi);
	int side = 0;
	for (int it = 0; it < 100 && hi - lo > 1e-12; ++it) {
		double t = flo - fhi > 0.0 ? lo + (hi - lo) * flo / (flo - fhi) : 0.5 * (lo + hi);
		if (!(t > lo && t < hi))
			t = 0.5 * (lo + hi);
		double f = sphere_gap(world, sys, i, j, t);
		if (f <= 0.0) { // meeting at t
			hi = t;
			fhi = f;
			if (side == -1)
				flo *= 0.5;
			side = -1;
			if (f > -1e-15)
				break;
		} else {
			lo = t;
			flo = f;
			if (side == 1)
				fhi *= 0.5;
			side = 1;
		}
	}
	return hi;
}

static double first_meeting(const hs_world *world, const hs_spring_system *sys, int i, int j, bool end_meets) {
	const hs_spring_geom *ga = &sys->geom[i], *gb = &sys->geom[j];
	hs_vec3 rel = hs_sub(hs_sub(world->bodies[j].pos, sys->saved_pos[j]), hs_sub(world->bodies[i].pos, sys->saved_pos[i]));
	double step = ga->inner + gb->inner, len = hs_length(rel);
	if (!(step > 0.0) || !(len > 0.0) || (!end_meets && !(len > step)))
		return -1.0; // no relative motion, or slower: a pass through the inner balls shows at an end
	bool spheres = ga->sphere && gb->sphere && ga->form != HS_FORM_BOX && gb->form != HS_FORM_BOX;
	if (spheres ? sphere_gap(world, sys, i, j, 0.0) <= 0.0 : meet_at(world, sys, i, j, 0.0))
		return -1.0; // met already at the start: a contact going on, not a first meeting
	double n = ceil(len / step);
	int steps = n > HS_MAX_SWEEP_STEPS ? HS_MAX_SWEEP_STEPS : n < 1.0 ? 1 : (int)n;
	int k = 1;
	while (k < steps && !(spheres ? sphere_gap(world, sys, i, j, (double)k / steps) <= 0.0
	                              : meet_at(world, sys, i, j, (double)k / steps)))
		++k;
	if (k == steps && !end_meets)
		return -1.0;
	double lo = (double)(k - 1) / steps, hi = (double)k / steps;
	if (spheres)
		return sphere_root(world, sys, i, j, lo, hi);
	while (hi - lo > 1e-12) {
		double mid = 0.5 * (lo + hi);
		if (meet_at(world, sys, i, j, mid))
			hi = mid;
		else
			lo = mid;
	}
	return hi;
}


void hs_spring_collide(hs_world *world, hs_spring_system *sys) {
	// Pairs in ascending (i, j), as the full double loop met them, so the bits are the same: for
	// each i the broad phase lists the j near it now; when a pair moved i, the list is taken again
	// from where i is now and resumes after j (only i and j move within i's turn).
	const hs_spring_geom *geom = sys->geom;
	double e = sys->def.restitution, reach = 0.0, inner = INFINITY;
	for (int i = 0; i < world->object_count; ++i) { // the farthest any object moved this frame
		reach = fmax(reach, hs_length(hs_sub(world->bodies[i].pos, sys->saved_pos[i])));
		inner = fmin(inner, geom[i].inner);
	}
	// no two objects moved apart by more than the sum of any two inner radii: a pass through shows
	// at the frame's end (first_meeting), so the queries need not cover the paths
	if (2.0 * reach <= 2.0 * inner)
		reach = 0.0;
	file_all(world, sys);
	for (int i = 0; i < world->object_count; ++i) {
		hs_body *a = &world->bodies[i];
		const hs_spring_geom *ga = &geom[i];
		int count = near_of(world, sys, i, reach);
		for (int k = 0; k < count; ++k) {
			int j = sys->near[k];
			if (j <= i)
				continue;
			hs_body *b = &world->bodies[j];
			const hs_spring_geom *gb = &geom[j];
			hs_vec3 n;
			double depth;
			bool end_meets = boxes_meet(ga, a->pos, gb, b->pos, margin_of(ga, a->pos) + margin_of(gb, b->pos)) &&
			                 hs_spring_contact(world, ga, a->pos, gb, b->pos, &n, &depth);
			// where they first met on the way; an object answered already this frame has left the
			// path its frame-start state describes: such pairs meet at the frame's end only
			double tau = sys->separated[i] || sys->separated[j] ? -1.0 : first_meeting(world, sys, i, j, end_meets);
			if (!end_meets && tau < 0.0)
				continue;
			if (tau >= 0.0 && tau < 1.0) {
				state_at(world, sys, i, tau); // both back to where they met (the rest of the frame's
				state_at(world, sys, j, tau); // motion is lost: a delay, no energy)
				if (!hs_spring_contact(world, ga, a->pos, gb, b->pos, &n, &depth)) { // just touching
					n = hs_normalize(hs_sub(b->pos, a->pos));
					depth = 0.0;
				}
			}
			respond(a, b, n, depth, e);
			if (tau > 0.0 && tau < 1.0) { // the rest of the frame, from where they met (on the spring: lost)
				double rest = (1.0 - tau) * world->def.dt;
				if (i != sys->attached)
					hs_spring_advance(world, sys, i, rest);
				if (j != sys->attached)
					hs_spring_advance(world, sys, j, rest);
			}
			sys->separated[i] = sys->separated[j] = 1;
			hs_hgrid_file(&sys->grid, i, box_centre(ga, a->pos));
			hs_hgrid_file(&sys->grid, j, box_centre(gb, b->pos));
			count = near_of(world, sys, i, reach);
			for (k = 0; k < count && sys->near[k] <= j; ++k)
				;
			--k; // the loop's ++k lands on the first object after j
		}
	}
}
