// contact_rules.c — the contact rules of the 1999 paper §3.1-3.2 written plainly: where a contact's
// C and B lie and how B drives C (eq. 1-2, Fig. 3, with the fingertip's friction), a face's normal
// or an edge's pseudo-normal from G (Fig. 4), a check point in a face ((A)) and a check line across
// an edge ((B)); handspring's own rules beside them (docs/model.md §3).
#include "contact_rules.h"
#include "push.h"

// Where a part touching the surface at C with normal n drives C (B, eq. 1-2), when its own
// position, or its motion since it touched (a part drawn back to the surface, §3.2
// rectification), would take C to C + d. The fingertip holds the surface by Coulomb friction
// (docs/model.md §3, "Friction at the fingertip"): it pushes by how far it goes in along -n and
// drags C sideways by at most μ times that, as a finger sliding over the face; a part not going
// in (leaving, or moving along the face) drives nothing. [H]'s eq. 1-2 take C to the finger
// wherever it went (a sticky contact): under glove noise a fingertip resting on a face dragged
// it by its jitter. How deep a part sank never moves the object (d is its motion, not its depth).
static hs_vec3 friction_finger(hs_vec3 c, hs_vec3 d, hs_vec3 n) {
	double in = -hs_dot(d, n);
	if (!(in > 0.0))
		return c;
	hs_vec3 tan = hs_mul_add(d, in, n);
	double t = hs_length(tan), cap = HS_PUSH_FRICTION * in;
	return hs_add(c, hs_mul_add(t > cap ? hs_scale(tan, cap / t) : tan, -in, n));
}

// A contact found in the body frame `f`: C = `point` on the surface, B = `finger` where the part
// drives it (eq. 1-2), `normal` the face normal or the edge's pseudo-normal.
void hs_contact_push(const hs_contact_pass *cp, int object, int hand, int part, bool edge, int feature, const hs_frame *f,
                     hs_vec3 point, hs_vec3 normal, hs_vec3 finger, double t) {
	if (cp->out->contact_count >= cp->out->contact_capacity) {
		cp->counters->dropped_contacts++;
		return;
	}
	hs_contact *c = &cp->out->contacts[cp->out->contact_count++];
	c->object = hs_object_handle(cp->model, object);
	c->hand = hs_hand_handle(cp->model, hand);
	c->part = part;
	c->edge = edge;
	c->feature = feature;
	c->point = to_world(f, point);
	c->normal = hs_mat3_mul(f->rot, normal);
	if (!cp->model->def.paper_contacts)
		finger = friction_finger(point, hs_sub(finger, point), normal);
	c->finger = to_world(f, finger);
	c->t = t;
}

// The pseudo-normal of edge e: the unit vector from G (the body origin) to the foot of the
// perpendicular from G onto the edge line.
hs_vec3 hs_contact_edge_normal(const hs_shape *shape, int e) {
	hs_vec3 ea = shape->vertices[shape->edges[e].a], eb = shape->vertices[shape->edges[e].b];
	hs_vec3 dir = hs_normalize(hs_sub(eb, ea));
	return hs_normalize(hs_mul_add(ea, -hs_dot(ea, dir), dir));
}

// The part's first edge (in index order) between faces f1 and f2, or -1: among f1's own edges
// (hs_face_edges), a cost that does not grow with the part's face count.
static int edge_between(const hs_world_model *model, int shape_index, const hs_part *part, int f1, int f2) {
	const hs_shape *shape = &model->shapes[shape_index];
	const hs_face_edges *index = &model->face_edges[shape_index];
	for (int k = index->first[f1]; k < index->first[f1 + 1]; ++k) {
		int e = index->edges[k];
		const hs_edge *edge = &shape->edges[e];
		if (e >= part->first_edge && e < part->first_edge + part->edge_count &&
		    ((edge->faces[0] == f1 && edge->faces[1] == f2) || (edge->faces[0] == f2 && edge->faces[1] == f1)))
			return e;
	}
	return -1;
}

// Closest point on segment a-b to segment c-d (both in the same frame).
static hs_vec3 closest_on_first(hs_vec3 a, hs_vec3 b, hs_vec3 c, hs_vec3 d) {
	hs_vec3 u = hs_sub(b, a), v = hs_sub(d, c), w = hs_sub(a, c);
	double uu = hs_dot(u, u), uv = hs_dot(u, v), vv = hs_dot(v, v), uw = hs_dot(u, w), vw = hs_dot(v, w);
	double den = uu * vv - uv * uv;
	double s = den > 0.0 ? (uv * vw - vv * uw) / den : 0.0;
	s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
	return hs_mul_add(a, s, u);
}

// A check line across the part now (entering and leaving through two faces): an edge contact
// when the faces meet at an edge (§3.2 (B)), else the face nearest its middle. `d`: NULL when
// the line reached the object this frame (B = the line's point nearest C), else its motion
// relative to the object since it touched last frame (sunk in).
void hs_contact_line_across(const hs_contact_pass *cp, int object, int h, int j, const hs_part *part, const hs_frame *body,
                            hs_vec3 p0, hs_vec3 p1, hs_clip c, const hs_vec3 *d) {
	const hs_shape *shape = &cp->model->shapes[cp->bodies[object].shape];
	int feature = edge_between(cp->model, cp->bodies[object].shape, part, c.face_in, c.face_out);
	bool edge = feature >= 0;
	hs_vec3 point, normal;
	if (edge) {
		point = closest_on_first(shape->vertices[shape->edges[feature].a], shape->vertices[shape->edges[feature].b],
		                         p0, p1);
		normal = hs_contact_edge_normal(shape, feature);
	} else {
		hs_vec3 mid = hs_lerp(p0, p1, 0.5 * (c.t_in + c.t_out));
		feature = nearest_face(cp->model, shape, part, mid);
		const hs_face *f = &shape->faces[feature];
		point = hs_mul_add(mid, f->offset - hs_dot(f->normal, mid), f->normal);
		normal = f->normal;
	}
	hs_vec3 finger = d ? hs_add(point, *d) : hs_segment_closest(p0, p1, point);
	hs_contact_push(cp, object, h, HS_HAND_POINTS + j, edge, feature, body, point, normal, finger, 0.0);
}

// [H]'s letter (paper_contacts): a check point inside the part where it ends the frame touches the
// face it entered through along its motion, or the nearest face when it was inside already, and
// drives C to where it is.
void hs_contact_paper_point(const hs_contact_pass *cp, int object, int h, int i, const hs_part *part, const hs_frame *body,
                            hs_vec3 a, hs_vec3 b, double grow) {
	const hs_shape *shape = &cp->model->shapes[cp->bodies[object].shape];
	hs_clip c = hs_clip_segment_all(shape, part, a, b, grow); // face_in read on a miss too
	if (c.face_in >= 0) {
		hs_contact_push(cp, object, h, i, false, c.face_in, body, hs_lerp(a, b, c.t_in), shape->faces[c.face_in].normal,
		                b, c.t_in);
		return;
	}
	int face = nearest_face(cp->model, shape, part, b);
	const hs_face *f = &shape->faces[face];
	hs_contact_push(cp, object, h, i, false, face, body, hs_mul_add(b, f->offset - hs_dot(f->normal, b), f->normal),
	                f->normal, b, 0.0);
}

// How far contact c drives C in along its normal (friction_finger: the depth it pushes).
static double push_depth(const hs_contact *c) { return -hs_dot(hs_sub(c->finger, c->point), c->normal); }

static bool touched_before(const hs_contact_pass *cp, const hs_contact *c) {
	const hs_hand *hand = &cp->hands[c->hand.index1 - 1];
	return c->part < HS_HAND_POINTS ? (hand->state.touch_points >> c->part & 1u)
	                                : (hand->state.touch_lines >> (c->part - HS_HAND_POINTS) & 1u);
}

// A part that reached a face this frame behind a part of the same finger that already touched
// that face, or reached it earlier in this frame (swept detection's t), and drives it further in
// is set aside: the face, pushed by the leading part, is still ahead of it. Detection tests the parts against the object's pose at the start of the frame; at
// 12 frames/s a fingertip pushing at 0.3 m/s moves the face 2.5 cm a frame and its DIP, 1.7 cm
// behind the tip, "reached" the face the tip was pushing away (`hand/push_off_centre`: state 3,
// no more turn). A finger that curls or lies down onto the face goes in further than the part
// already there and still touches.
int hs_contact_drop_trailing(const hs_contact_pass *cp, int first) {
	int kept = first;
	for (int k = first; k < cp->out->contact_count; ++k) {
		const hs_contact *c = &cp->out->contacts[k];
		bool trails = false;
		for (int m = first; m < cp->out->contact_count && !trails && !c->edge && !touched_before(cp, c); ++m) {
			const hs_contact *l = &cp->out->contacts[m];
			trails = m != k && !l->edge && l->hand.index1 == c->hand.index1 &&
			         hs_contact_finger_of(l->part) == hs_contact_finger_of(c->part) &&
			         l->feature == c->feature && (touched_before(cp, l) || (l->t >= 0.0 && l->t < c->t)) &&
			         push_depth(l) > push_depth(c);
		}
		if (!trails && kept++ != k) // (kept in place: no copy)
			cp->out->contacts[kept - 1] = *c;
	}
	cp->out->contact_count = kept;
	return kept - first;
}

// A touching check point hovering within the margin over an object that moved last frame
// (marked t < 0 by detect_points) is a contact while another part of its hand drives the object
// this frame: two fingertips pushing a box, one of them lifted off by glove noise, still push at
// several points (3) rather than at one (1, which turns the box by eq. 2). Alone, it is none: the
// object goes on by eq. 3 (a finger drawn back after a push does not stop what it pushed).
int hs_contact_keep_hovering(const hs_contact_pass *cp, int first, int n) {
	int kept = first;
	for (int k = first; k < first + n; ++k) {
		const hs_contact *c = &cp->out->contacts[k];
		bool keep = !(c->t < 0.0);
		for (int m = first; m < first + n && !keep; ++m) {
			const hs_contact *l = &cp->out->contacts[m];
			keep = !(l->t < 0.0) && l->hand.index1 == c->hand.index1 && push_depth(l) > 0.0;
		}
		if (!keep)
			continue;
		hs_contact *to = &cp->out->contacts[kept++]; // a copy only when it moves (the one left behind
		if (to != c)                               // keeps its t for the later contacts' tests)
			*to = *c;
		to->t = to->t < 0.0 ? 0.0 : to->t;
	}
	cp->out->contact_count = kept;
	return kept - first;
}
