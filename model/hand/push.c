// push.c — a push at one point on an object lying on the floor (1999 paper eq. 1-2 under §4.2).
//
// Eq. 1-2 are written for a free object: CB = T + R, T ∥ CG translates, R turns about G along
// R × CG. On the floor that turn sinks one side into the floor and §4.2's rectification lifts it
// out again: a still fingertip 1 mm into the top of a box turned it by degrees every frame and
// stood it up on an edge. Reading fixed here (docs/model.md §4, "Pushing an object on the floor"):
//  - the floor supplies whatever points into it or out of it: the object translates along the
//    floor only (the vertical part of the push is dropped, never lifted, never sunk); T's
//    horizontal part slides it;
//  - eq. 2's turn splits into its part about the vertical through G (a yaw, harmless on the
//    floor, kept) and its part about a horizontal axis n_h (the swing, which tilts the object);
//    R = |R| (CG/|CG| × n) splits the same way into R_yaw + R_swing;
//  - the swing is replaced by a turn about the floor edge (or vertex) on the side it sinks, as
//    §4.2's rules (1)-(3) turn an unstable object about its floor edge, when the finger's push
//    lifts the object about that edge ((PC × CB) · a > 0, a = n_h / |n_h|, PC from the edge to C,
//    normal to it): θ = atan(|R'| / |PC|), eq. 2's form about the edge, = atan(((PC × R_swing) · a)
//    / |PC|²); the edge holds (T' along PC is dropped, as eq. 6 drops it);
//  - otherwise the swing is dropped and what it would have moved C horizontally slides the
//    object along the floor: it translates by CB's horizontal part less R_yaw's. A push below G's
//    height slides the object by the finger's horizontal motion, a push down on its top leaves
//    it where it is.
#include "push.h"
#include "motion.h"

// The object lies on the floor: a vertex, an edge or a face on it. One vertex is enough: a box
// that a first fingertip tipped onto a corner was lifted off the floor by the next frame's push
// at several points (its vertical part) and flew on by eq. 3 when the push ended.
static bool lies_on_floor(const hs_motion_pass *m, const hs_body *body, int *count) {
	hs_motion_pose_vertices(m->model, m->scratch, body);
	*count = hs_motion_floor_points(m->model, m->scratch, body);
	return *count >= 1;
}

// The push lies in the floor's friction cone: it presses the object into the floor at least as
// much as (1/μ times) it drives it sideways. The friction its press adds at the floor holds what
// the finger's own friction (the same μ, contact_rules.c) can drive; the object's weight, absent from
// eq. 1-2, is margin besides. A fingertip on a top face moves nothing however it trembles.
static bool held_by_floor(hs_vec3 d) {
	return d.z < 0.0 && sqrt(d.x * d.x + d.y * d.y) <= HS_PUSH_FRICTION * -d.z * (1.0 + 1e-9);
}

// The floor point furthest along the horizontal u: the side a turn along u sinks into the floor.
static hs_vec3 floor_point_along(const hs_world_scratch *scratch, int count, hs_vec3 u) {
	const hs_vec2 *p = scratch->points;
	int best = 0;
	for (int i = 1; i < count; ++i)
		if (p[i].x * u.x + p[i].y * u.y > p[best].x * u.x + p[best].y * u.y)
			best = i;
	return hs_v3(p[best].x, p[best].y, 0.0);
}

// The floor edge from p nearest in direction to the horizontal unit axis a, when it is within
// HS_PUSH_EDGE_DEG of it (oriented along a); else a, the turn about the vertex p. An object standing
// on a floor edge tips about that edge: turned about a line a degree off it, a flicked pyramid
// yawed by the tracker's noise stood on one corner and rocked back (docs/model.md §4).
#define HS_PUSH_EDGE_DEG 20.0
static hs_vec3 floor_edge_along(const hs_world_scratch *scratch, int count, hs_vec3 p, hs_vec3 a) {
	const hs_vec2 *f = scratch->points;
	double best = hs_cos(HS_PUSH_EDGE_DEG * (HS_PI / 180.0)); // the own cos: libm's may differ by a bit
	hs_vec3 axis = a;
	for (int i = 0; i < count; ++i) {
		hs_vec3 e = hs_v3(f[i].x - p.x, f[i].y - p.y, 0.0);
		double len = hs_length(e);
		if (!(len > 1e-9))
			continue; // p itself (or a vertex within a nanometre of it)
		double along = hs_dot(e, a) / len;
		if (fabs(along) > best) {
			best = fabs(along);
			axis = hs_scale(e, (along > 0.0 ? 1.0 : -1.0) / len);
		}
	}
	return axis;
}

// §4.2-style tipping in place of eq. 2's swing about the horizontal n_h, which moves C by r_swing:
// the turn about the floor edge (or vertex) on the side the swing sinks, along n_h, by eq. 2's
// form about that line, θ = atan(|R'| / |PC|) = atan(((PC × r_swing) · a) / |PC|²), when the
// push's torque about that line, (PC × CB) · a, lifts the object. False (nothing done) otherwise.
// The floor points are those of the pose eq. 2's yaw turned and T slid: the edge it stands on.
static bool tip_about_floor_edge(const hs_motion_pass *m, hs_body *body, hs_vec3 c, hs_vec3 cb, hs_vec3 n_h,
                                 hs_vec3 r_swing, hs_vec3 slid) {
	hs_motion_pose_vertices(m->model, m->scratch, body);
	int count = hs_motion_floor_points(m->model, m->scratch, body);
	if (count < 1)
		return false;
	hs_vec3 a = hs_normalize(n_h);
	hs_vec3 p = floor_point_along(m->scratch, count, hs_cross(a, hs_v3(0, 0, 1)));
	a = floor_edge_along(m->scratch, count, p, a);
	hs_vec3 pc = hs_sub(hs_add(c, slid), p); // C where T took it
	pc = hs_mul_add(pc, -hs_dot(pc, a), a); // from the edge to C, normal to the edge
	double lever_sq = hs_length_sq(pc);
	double torque = hs_dot(hs_cross(pc, cb), a);        // > 0: the finger turns the free side up
	double swing = hs_dot(hs_cross(pc, r_swing), a);    // = |PC| |R'|
	if (!(torque > 0.0) || !(swing > 0.0) || !(lever_sq > 0.0))
		return false;
	hs_quat q = hs_quat_from_axis_angle(a, hs_atan(swing / lever_sq));
	body->pos = hs_add(p, hs_quat_rotate(q, hs_sub(body->pos, p)));
	body->rot = hs_quat_normalize(hs_quat_mul(q, body->rot));
	return true;
}

// The yaw of eq. 2's turn q about its unit axis n: q itself when n is vertical, else the twist
// about z of q's swing-twist split.
static hs_quat yaw_part(hs_quat q, hs_vec3 n) {
	if (n.x == 0.0 && n.y == 0.0)
		return q;
	return hs_quat_normalize(hs_q(q.w, 0.0, 0.0, q.z));
}

bool hs_push_on_floor(const hs_motion_pass *m, hs_body *body, hs_vec3 c, hs_vec3 b) {
	int count = 0;
	if (!lies_on_floor(m, body, &count))
		return false;
	hs_vec3 cb = hs_sub(b, c), cg = hs_sub(body->pos, c);
	if (held_by_floor(cb))
		return true;
	double cg_len = hs_length(cg);
	if (!(cg_len > 0.0)) { // C at G: nothing to turn about, slide
		body->pos = hs_add(body->pos, hs_v3(cb.x, cb.y, 0.0));
		return true;
	}
	hs_vec3 cg_unit = hs_scale(cg, 1.0 / cg_len);
	hs_vec3 t = hs_scale(cg_unit, hs_dot(cb, cg_unit)); // eq. 1
	hs_vec3 r = hs_sub(cb, t);
	double r_len = hs_length(r);
	hs_vec3 n = r_len > 0.0 ? hs_normalize(hs_cross(r, cg)) : hs_v3(0, 0, 0);
	if (r_len > 0.0 && n.z != 0.0) { // the yaw of eq. 2 about the vertical through G
		hs_quat q = hs_quat_from_axis_angle(n, hs_atan(r_len / cg_len));
		body->rot = hs_quat_normalize(hs_quat_mul(yaw_part(q, n), body->rot));
	}
	// T slides along the floor; R = |R| (CG/|CG| × n) = the yaw's share |R| n_z (CG/|CG| × z) + the swing's
	hs_vec3 pos = body->pos, slid = hs_v3(t.x, t.y, 0.0);
	body->pos = hs_add(pos, slid);
	if (n.x == 0.0 && n.y == 0.0)
		return true; // no swing
	hs_vec3 n_h = hs_v3(n.x, n.y, 0.0);
	hs_vec3 r_swing = hs_scale(hs_cross(cg_unit, n_h), r_len);
	if (tip_about_floor_edge(m, body, c, cb, n_h, r_swing, slid))
		return true;
	// no tip: the swing slides instead, and T + R's swing share is CB less R's yaw share
	hs_vec3 r_yaw = hs_scale(hs_cross(cg_unit, hs_v3(0, 0, 1)), r_len * n.z);
	body->pos = hs_add(pos, hs_v3(cb.x - r_yaw.x, cb.y - r_yaw.y, 0.0));
	return true;
}

void hs_push_many(const hs_motion_pass *m, hs_body *body, hs_vec3 d) {
	int count = 0;
	if (!m->model->def.paper_floor_push && lies_on_floor(m, body, &count)) {
		if (held_by_floor(d))
			return;
		d.z = 0.0;
	} // the floor supplies whatever points into it or out of it, as for one point
	body->pos = hs_add(body->pos, d);
}


// §4.1-4.2 when a push ends: an object lying on the floor with G' inside its floor hull (eq. 4-5,
// Gm the motion eq. 3 would carry on plus this frame's gravity) loses its inertia there, as an
// object landing does ([H] §4.1: no rebound, no sliding). Eq. 3 otherwise carried the push's last
// motion on for a frame, a dt-dependent slide (1.7 cm at 12 frames/s), and a rise from a noisy
// push above G's height launched the box. A push at several points only translates (§3.2 (3)): it
// leaves no turn for eq. 3 to carry on, so an object it leaves on the floor and not stable (a box
// a first fingertip tipped a hair onto its edge) tips there by rules (1)-(3) instead of sliding a
// frame on (1.3 cm at 17 frames/s). A one-point push's turn does carry on: a flick tips over so.
bool hs_push_release_on_floor(const hs_motion_pass *m, hs_body *body, bool many) {
	int count = 0;
	if (!lies_on_floor(m, body, &count))
		return false;
	double dt = m->model->def.dt;
	hs_vec3 gm = hs_add(hs_sub(body->pos, body->prev), hs_scale(m->model->def.gravity, dt * dt));
	bool stable = hs_motion_settle(m, body, count, 0.0, gm, many, NULL);
	if (!stable && !many)
		return false;
	body->rot_prev = body->rot;
	body->grounded = 1;
	body->floor_contacts = stable ? count : hs_motion_floor_points(m->model, m->scratch, body);
	return true;
}
