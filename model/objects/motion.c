// motion.c — free motion and the floor of the 1999 paper (§4.1, §4.2).
//
// Readings fixed here (the paper leaves them open; docs/model.md §5):
//  - Gm, the motion vector of eq. 4, is the displacement the Verlet step of eq. 3 proposes this
//    frame: P(t-dt) - P(t-2dt) + g dt². With the literal eq. 4 a resting object has Gm = 0 and
//    nothing could ever tip; adding this frame's gravity is what makes rule (1)-(3) fall.
//  - An object touching the floor is not translated (rules (1)-(3): "the contacting point does not
//    move"): it only rotates about its contact vertex or contact edge.
//  - A tipping rotation stops exactly where the next vertex reaches the floor (the smallest such
//    angle), and the object loses its inertia there: §4.1 "inertia is not conserved and an object
//    does not rebound after interfering with ... a floor".
#include "motion.h"

// Penetration below this depth (m) is rounding, not interference: lifting it again every frame
// would make resting objects creep.
#define HS_RECTIFY_SLOP 1e-12
// A tipping turn an object beside it stops within this angle (rad) is none: it leans there at rest.
#define HS_LEAN_REST 1e-6

double hs_motion_pose_vertices(const hs_world_model *model, hs_world_scratch *scratch, const hs_body *body) {
	const hs_shape *shape = &model->shapes[body->shape];
	double zmin = INFINITY;
	for (int i = 0; i < shape->vertex_count; ++i) {
		hs_vec3 p = hs_add(body->pos, hs_quat_rotate(body->rot, shape->vertices[i]));
		scratch->posed[i] = p;
		zmin = p.z < zmin ? p.z : zmin;
	}
	return zmin;
}

int hs_motion_floor_points(const hs_world_model *model, hs_world_scratch *scratch, const hs_body *body) {
	const hs_shape *shape = &model->shapes[body->shape];
	int n = 0;
	for (int i = 0; i < shape->vertex_count; ++i) {
		hs_vec3 p = scratch->posed[i];
		if (p.z <= model->def.floor_tolerance)
			scratch->points[n++] = (hs_vec2){p.x, p.y};
	}
	return n;
}

// §4.2: lift the object so the vertex that penetrated deepest is on the floor.
static void rectify(const hs_world_model *model, hs_world_scratch *scratch, hs_body *body, double zmin) {
	if (zmin >= -HS_RECTIFY_SLOP)
		return;
	body->pos.z -= zmin;
	const hs_shape *shape = &model->shapes[body->shape];
	for (int i = 0; i < shape->vertex_count; ++i)
		scratch->posed[i].z -= zmin;
}

void hs_motion_keep_above_floor(const hs_world_model *model, hs_world_scratch *scratch, hs_body *body) {
	// Its bounding sphere clear of the floor's tolerance (with a slack far above the rounding of a
	// posed vertex): no vertex lies below it, so there is nothing to rectify and no floor contact,
	// the answer of posing every vertex (O(V) a frame for a held many-faced object) without it.
	double clear = fmax(model->def.floor_tolerance, 0.0);
	if (body->pos.z - model->shapes[body->shape].radius * (1.0 + 1e-9) - 1e-12 > clear) {
		body->floor_contacts = 0;
		return;
	}
	rectify(model, scratch, body, hs_motion_pose_vertices(model, scratch, body));
	body->floor_contacts = hs_motion_floor_points(model, scratch, body);
}

static void stop(hs_body *body) {
	body->prev = body->pos;
	body->spin = hs_quat_identity();
	body->asleep = 1;
}

// Eq. 5: G' is G projected onto the contact plane z = height along Gm; a motion that does not
// point down projects straight down, the direction gravity will take it.
static hs_vec2 project_g(hs_vec3 g, hs_vec3 gm, double height) {
	if (gm.z < 0.0) {
		double s = (g.z - height) / -gm.z;
		return (hs_vec2){g.x + s * gm.x, g.y + s * gm.y};
	}
	return (hs_vec2){g.x, g.y};
}

// Smallest angle in (0, limit] at which a vertex above the contact plane reaches it when the
// posed vertices turn about the unit `axis` through `c`; `limit` when none does. The plane is the
// floor z = 0, or on supports (`sup`) the face they rest on (eq. 7's first touch against the
// support; a vertex only lands where it is over a support, not past its edge).
static double first_touch(const hs_motion_pass *pass, const hs_body *body, hs_vec3 c, hs_vec3 axis,
                          double limit, const hs_settle_supports *sup) {
	const hs_shape *shape = &pass->model->shapes[body->shape];
	hs_vec3 n = sup ? sup->normal : hs_v3(0, 0, 1);
	double off = sup ? sup->offset : 0.0;
	double best = limit;
	for (int i = 0; i < shape->vertex_count; ++i) {
		hs_vec3 p = pass->scratch->posed[i];
		if (hs_dot(n, p) <= off + pass->model->def.floor_tolerance)
			continue; // pivot vertices stay, other contact vertices lift (rule (3))
		// height over the plane h(θ) = h0 + A cos θ + B sin θ = h0 + M cos(θ - φ)
		hs_vec3 r = hs_sub(p, c);
		hs_vec3 r_par = hs_scale(axis, hs_dot(r, axis));
		hs_vec3 r_perp = hs_sub(r, r_par);
		double h0 = hs_dot(n, c) + hs_dot(n, r_par);
		double a = hs_dot(n, r_perp), b = hs_dot(n, hs_cross(axis, r_perp));
		double m = sqrt(a * a + b * b);
		if (m <= 0.0 || (off - h0) / m < -1.0 || (off - h0) / m > 1.0)
			continue; // its circle never reaches the plane
		double phi = hs_atan2(b, a), alpha = hs_acos((off - h0) / m);
		double roots[2] = {phi - alpha, phi + alpha};
		for (int k = 0; k < 2; ++k) {
			double t = roots[k];
			while (t <= 0.0)
				t += 2.0 * HS_PI;
			while (t > 2.0 * HS_PI)
				t -= 2.0 * HS_PI;
			if (t < best && sup &&
			    !sup->over(pass, sup, hs_add(c, hs_quat_rotate(hs_quat_from_axis_angle(axis, t), r))))
				continue; // it passes beyond the support's edge
			best = t < best ? t : best;
		}
	}
	return best;
}

// A turn about one vertex (rule (1)) that brings a second one down keeps turning about the edge
// they make: the impulse at the new vertex, on that edge, leaves the turn about it alone. A flicked
// pyramid yawed by a degree stands on one corner of its front edge, and stopping it there rocked
// it back onto its base. G keeps its motion across the edge (its part along the edge is stopped:
// a thrown cube kept it and tumbled on) and rule (2) turns it about the edge next frame
// (docs/model.md §5); a landing on a face stops it, as before.
static void keep_turning_about_edge(const hs_world_model *model, hs_world_scratch *scratch, hs_body *body, hs_vec3 motion) {
	if (hs_motion_floor_points(model, scratch, body) != 2)
		return;
	const hs_vec2 *f = scratch->points;
	hs_vec3 e = hs_v3(f[1].x - f[0].x, f[1].y - f[0].y, 0.0);
	double len = hs_length(e);
	if (!(len > 0.0))
		return;
	e = hs_scale(e, 1.0 / len);
	body->prev = hs_sub(body->pos, hs_mul_add(motion, -hs_dot(motion, e), e));
}

// Support mode: the smallest angle in [0, limit] at which the body, turned about the unit `axis`
// through `c`, meets another object it is clear of now (bisected on libccd's overlap test to
// 1e-6 rad, the angle just short of touching: libccd's own builds differ by a few ulps between
// architectures, so a finer bisection's last probes, next to the touch, went either way on i386
// and aarch64); `limit` when it meets none. A tall box tipping
// over onto a cube beside it stops where it leans on the cube's edge, as the floor stops a turn
// (eq. 7's first touch), instead of turning into the cube and being lifted out of it, off the
// floor, frame after frame.
static double first_touch_neighbour(const hs_world_model *model, const hs_body *bodies, const hs_body *body, hs_vec3 c,
                                    hs_vec3 axis, double limit) {
	const hs_shape *shape = &model->shapes[body->shape];
	double reach = shape->radius + hs_length(hs_sub(body->pos, c)) * limit;
	double best = limit;
	for (int j = 0; j < model->object_count; ++j) {
		const hs_body *b = &bodies[j];
		const hs_shape *sb = &model->shapes[b->shape];
		double r = reach + sb->radius;
		if (b == body || hs_length_sq(hs_sub(b->pos, body->pos)) > r * r)
			continue;
		hs_quat q = hs_quat_from_axis_angle(axis, best);
		hs_vec3 at = hs_add(c, hs_quat_rotate(q, hs_sub(body->pos, c)));
		if (!hs_shapes_overlap(shape, at, hs_quat_normalize(hs_quat_mul(q, body->rot)), sb, b->pos, b->rot) ||
		    hs_shapes_overlap(shape, body->pos, body->rot, sb, b->pos, b->rot))
			continue; // clear of it at the end of the turn, or already touching it
		double lo = 0.0, hi = best;
		while (hi - lo > 1e-6) {
			double mid = 0.5 * (lo + hi);
			q = hs_quat_from_axis_angle(axis, mid);
			at = hs_add(c, hs_quat_rotate(q, hs_sub(body->pos, c)));
			if (hs_shapes_overlap(shape, at, hs_quat_normalize(hs_quat_mul(q, body->rot)), sb, b->pos, b->rot))
				hi = mid;
			else
				lo = mid;
		}
		best = lo;
	}
	return best;
}

// Rules (1)-(3) of §4.2 for an unstable object: pick the contact vertex or edge and turn about it.
static void tip(const hs_motion_pass *m, hs_body *body, const hs_vec2 *hull, int hull_count, double height,
                hs_vec2 g_proj, hs_vec3 gm, const hs_settle_supports *sup) {
	hs_vec3 g = body->pos;
	hs_vec3 c, line = hs_v3(0, 0, 0);
	bool about_line = false;
	if (hull_count == 1) {
		c = hs_v3(hull[0].x, hull[0].y, height); // rule (1)
	} else {
		// rule (3) renames the hull edge nearest G' as V1 V2 and follows rule (2)
		int i = hull_count == 2 ? 0 : hs_hull_nearest_edge(hull, hull_count, g_proj);
		hs_vec2 v1 = hull[i], v2 = hull[(i + 1) % hull_count];
		double dx = v2.x - v1.x, dy = v2.y - v1.y;
		double u = ((g_proj.x - v1.x) * dx + (g_proj.y - v1.y) * dy) / (dx * dx + dy * dy);
		if (u < 0.0) { // rule (2)-a: G' beyond the line through V1: turn about V1 by rule (1)
			c = hs_v3(v1.x, v1.y, height);
		} else if (u > 1.0) {
			c = hs_v3(v2.x, v2.y, height);
		} else { // rule (2)-b: turn about the line V1 V2
			about_line = true;
			line = hs_normalize(hs_v3(dx, dy, 0.0));
			hs_vec3 v1_3 = hs_v3(v1.x, v1.y, height);
			c = hs_mul_add(v1_3, hs_dot(hs_sub(g, v1_3), line), line); // foot of G on the line
		}
	}
	// eq. 6: Gm = T + R, T ∥ CG, T ⊥ R; T is dropped (no slide, no rebound)
	hs_vec3 cg = hs_sub(g, c);
	double cg_len = hs_length(cg);
	hs_vec3 cg_unit = hs_scale(cg, 1.0 / cg_len);
	hs_vec3 r = hs_mul_add(gm, -hs_dot(gm, cg_unit), cg_unit);
	if (about_line)
		r = hs_mul_add(r, -hs_dot(r, line), line); // a hinge only turns G across the line
	double r_len = hs_length(r);
	if (!(r_len > 0.0) || !(cg_len > 0.0)) {
		stop(body); // Gm ∥ CG: "the well-balanced state, and does not move"
		return;
	}
	hs_vec3 axis = hs_normalize(hs_cross(cg, r)); // G moves along R
	if (about_line)
		axis = hs_dot(line, axis) >= 0.0 ? line : hs_neg(line);
	double theta = hs_atan(r_len / cg_len); // eq. 7
	double touch = first_touch(m, body, c, axis, theta, sup);
	if (!sup) { // on the floor alone: an object beside it can stop the turn too
		double lean = first_touch_neighbour(m->model, m->bodies, body, c, axis, touch);
		if (lean < touch && lean <= HS_LEAN_REST) { // leaning on it already: it rests there (§4.1)
			stop(body);
			m->counters->object_steps++;
			return;
		}
		touch = lean;
	}
	bool landed = touch < theta;
	if (landed)
		theta = touch;
	hs_quat q = hs_quat_from_axis_angle(axis, theta);
	hs_vec3 old = body->pos, motion = hs_sub(body->pos, body->prev);
	body->pos = hs_add(c, hs_quat_rotate(q, cg));
	body->rot = hs_quat_normalize(hs_quat_mul(q, body->rot));
	body->prev = landed ? body->pos : old;
	rectify(m->model, m->scratch, body, hs_motion_pose_vertices(m->model, m->scratch, body));
	// on the floor alone, in paper mode: support mode's step of an object on the floor and a
	// support read the kept motion as a turn over both and sank a cube 5 µm into the floor
	if (landed && hull_count == 1 && !sup && height == 0.0 && m->model->def.stacking == HS_STACKING_PAPER &&
	    !m->model->def.paper_tipping)
		keep_turning_about_edge(m->model, m->scratch, body, motion);
	m->counters->object_steps++;
}

bool hs_motion_settle(const hs_motion_pass *m, hs_body *body, int count, double height, hs_vec3 gm, bool may_tip,
                      const hs_settle_supports *sup) {
	int hull_count = hs_hull_build(m->scratch->points, count, m->scratch->hull);
	hs_vec2 g_proj = project_g(body->pos, gm, height);
	if (hs_hull_contains(m->scratch->hull, hull_count, g_proj, HS_RECTIFY_SLOP)) {
		stop(body);
		return true;
	}
	body->asleep = 0;
	if (may_tip)
		tip(m, body, m->scratch->hull, hull_count, height, g_proj, gm, sup);
	return false;
}

// Stability with the hull of the floor contacts and G' (eq. 4-5, Fig. 5); tip when unstable.
static void settle_or_tip(const hs_motion_pass *m, hs_body *body, hs_vec3 gm, bool may_tip) {
	body->floor_contacts = hs_motion_floor_points(m->model, m->scratch, body);
	if (!hs_motion_settle(m, body, body->floor_contacts, 0.0, gm, may_tip, NULL) && may_tip)
		body->floor_contacts = hs_motion_floor_points(m->model, m->scratch, body);
}

// Eq. 3: P(t) = 2P(t - dt) - P(t - 2dt) + g dt², and the carried-over relative rotation.
// True when another object's bounding sphere comes within `reach` of this one's centre (a landing
// is rare: a pass over the objects costs nothing a frame).
static bool near_another(const hs_world_model *model, const hs_body *bodies, const hs_body *body, double reach) {
	for (int j = 0; j < model->object_count; ++j) {
		const hs_body *b = &bodies[j];
		if (b == body)
			continue;
		double r = reach + model->shapes[b->shape].radius;
		hs_vec3 d = hs_sub(b->pos, body->pos);
		if (hs_dot(d, d) < r * r)
			return true;
	}
	return false;
}

// Where the path through the frame met the floor (docs/model.md §5 "Landing"): an object clear of
// the floor when the frame began goes back along the frame's motion gm, in x and y, by the part of
// its lowest vertex's fall that lay below the floor; §4.2's lift (rectify) then puts it on the
// floor as before. Lifted straight up from the frame's end instead, a throw at 12 frames/s landed
// up to v_x dt = 0.2 m further on, and where depended on where the frames fell on its flight.
static void back_to_floor(const hs_motion_pass *m, hs_body *body, hs_vec3 gm, double zmin) {
	const hs_shape *shape = &m->model->shapes[body->shape];
	int low = 0;
	for (int i = 1; i < shape->vertex_count; ++i)
		low = m->scratch->posed[i].z < m->scratch->posed[low].z ? i : low;
	double was = body->prev.z + hs_quat_rotate(body->rot_prev, shape->vertices[low]).z;
	if (!(was > 0.0) || !(was > zmin)) // touching already, or not falling onto the floor
		return;
	double f = zmin / (was - zmin); // in [-1, 0): minus the part of its fall below the floor
	double dx = f * gm.x, dy = f * gm.y;
	if (near_another(m->model, m->bodies, body, shape->radius + sqrt(dx * dx + dy * dy)))
		return; // moved back it could meet that object: lifted straight up, as §4.2
	body->pos.x += dx;
	body->pos.y += dy;
	for (int i = 0; i < shape->vertex_count; ++i) {
		m->scratch->posed[i].x += dx;
		m->scratch->posed[i].y += dy;
	}
}

static void fly(const hs_motion_pass *m, hs_body *body) {
	double dt = m->model->def.dt;
	bool touching = body->floor_contacts > 0; // when the frame began
	hs_vec3 gm = hs_add(hs_sub(body->pos, body->prev), hs_scale(m->model->def.gravity, dt * dt));
	body->prev = body->pos;
	body->pos = hs_add(body->pos, gm);
	body->rot = hs_quat_normalize(hs_quat_mul(body->spin, body->rot));
	m->counters->object_steps++;

	const hs_shape *shape = &m->model->shapes[body->shape];
	if (m->model->skip_work && body->pos.z - shape->radius > m->model->def.floor_tolerance) {
		body->floor_contacts = 0; // the bounding sphere is clear of the floor
		return;
	}
	m->counters->floor_checks++;
	double zmin = hs_motion_pose_vertices(m->model, m->scratch, body);
	if (zmin > m->model->def.floor_tolerance) {
		body->floor_contacts = 0;
		return;
	}
	if (!m->model->def.paper_landing && !touching && zmin < 0.0)
		back_to_floor(m, body, gm, zmin);
	rectify(m->model, m->scratch, body, zmin);
	body->spin = hs_quat_identity(); // §4.1: rotation inertia ends at the floor
	body->grounded = 1;
	settle_or_tip(m, body, gm, false); // landing: tipping starts next frame
}

// In floor contact: no translation; stable → rest, otherwise rules (1)-(3).
static void on_floor(const hs_motion_pass *m, hs_body *body) {
	double dt = m->model->def.dt;
	hs_vec3 gm = hs_add(hs_sub(body->pos, body->prev), hs_scale(m->model->def.gravity, dt * dt));
	m->counters->floor_checks++;
	double zmin = hs_motion_pose_vertices(m->model, m->scratch, body);
	if (zmin > m->model->def.floor_tolerance) { // lifted off (moved by a hand): fly again
		body->grounded = 0;
		fly(m, body);
		return;
	}
	rectify(m->model, m->scratch, body, zmin);
	settle_or_tip(m, body, gm, true);
}

void hs_motion_step(const hs_motion_pass *m, hs_body *body) {
	if (body->grounded)
		on_floor(m, body);
	else
		fly(m, body);
}
