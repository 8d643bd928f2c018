// contact.c — contacts between hands and objects (1999 paper §3.1-3.2, Fig. 2, Fig. 4).
//
// Everything is computed in the object's body frame, whose origin is G, against each convex part:
//  (A) a check point inside the part touches the face it entered through along its motion
//      relative to the object (the face nearest to it when it was already inside);
//  (B) a check line crossing the part touches an edge when it enters and leaves through the two
//      faces that meet at that edge; the contact normal is the pseudo-normal from G to the edge.
//      A line through two faces that do not meet presses the face nearest to its middle.
#include "clip.h"
#include "contact.h"

// Grasp when n_i · n_j <= cos(threshold) + eps: with a bare comparison rounding would decide the
// 90 deg case (two adjoining cube faces) and two builds could disagree (DESIGN.md).
#define HS_GRASP_EPS 1e-9

// An object's pose as a position and a rotation matrix: detection moves up to 140 hand points
// into each object's frame every frame.
typedef struct frame {
	hs_vec3 pos;
	hs_mat3 rot;
} frame;

static frame frame_of(const hs_body *body) {
	frame f = {body->pos, hs_mat3_from_quat(body->rot)};
	return f;
}
static hs_vec3 to_body(const frame *f, hs_vec3 p) { return hs_mat3_tmul(f->rot, hs_sub(p, f->pos)); }
static hs_vec3 to_world(const frame *f, hs_vec3 p) { return hs_add(f->pos, hs_mat3_mul(f->rot, p)); }

// Inside the part grown by `grow` (m; 0: the part itself).
static bool inside_part(const hs_shape *shape, const hs_part *part, hs_vec3 p, double grow) {
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f)
		if (hs_dot(shape->faces[f].normal, p) >= shape->faces[f].offset + grow)
			return false;
	return true;
}

static int nearest_face(const hs_shape *shape, const hs_part *part, hs_vec3 p) {
	int best = part->first_face;
	double best_depth = INFINITY;
	for (int f = part->first_face; f < part->first_face + part->face_count; ++f) {
		double depth = shape->faces[f].offset - hs_dot(shape->faces[f].normal, p);
		if (depth < best_depth) {
			best_depth = depth;
			best = f;
		}
	}
	return best;
}

static int edge_between(const hs_shape *shape, const hs_part *part, int f1, int f2) {
	for (int e = part->first_edge; e < part->first_edge + part->edge_count; ++e) {
		const hs_edge *edge = &shape->edges[e];
		if ((edge->faces[0] == f1 && edge->faces[1] == f2) || (edge->faces[0] == f2 && edge->faces[1] == f1))
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

static void push_contact(hs_world *world, int object, int hand, int part, bool edge, int feature, hs_vec3 point,
                         hs_vec3 normal) {
	if (world->contact_count >= world->contact_capacity) {
		world->counters.dropped_contacts++;
		return;
	}
	hs_contact *c = &world->contacts[world->contact_count++];
	c->object = hs_object_handle(world, object);
	c->hand = hs_hand_handle(world, hand);
	c->part = part;
	c->edge = edge;
	c->feature = feature;
	c->point = point;
	c->normal = normal;
}

// Squared distance from c to the segment p0-p1.
static double segment_distance_sq(hs_vec3 c, hs_vec3 p0, hs_vec3 p1) {
	return hs_length_sq(hs_sub(hs_segment_closest(p0, p1, c), c));
}

// `before` is the object's pose when the fingers were at their previous points: a point's
// motion is judged relative to the object.
// `grow` > 0: against the part grown by that much (the grasp's release margin, docs/model.md §3).
static void detect_part(hs_world *world, int object, int h, const hs_part *part, const frame *body,
                        const frame *before, bool cull, double grow) {
	const hs_shape *shape = &world->shapes[world->bodies[object].shape];
	const hs_hand *hand = &world->hands[h];
	// a finger part outside the part's bounding sphere cannot touch it: skip before the transform
	hs_vec3 center = to_world(body, part->center);
	double r_sq = (part->radius + grow) * (part->radius + grow);
	// (A) check points against faces
	for (int i = 0; i < HS_HAND_POINTS; ++i) {
		if (cull && hs_length_sq(hs_sub(hand->points[i], center)) > r_sq)
			continue;
		hs_vec3 b = to_body(body, hand->points[i]);
		if (!inside_part(shape, part, b, grow))
			continue;
		hs_vec3 a = to_body(before, hand->prev_points[i]);
		hs_clip c = hs_clip_segment(shape, part, a, b, grow);
		int face;
		hs_vec3 point;
		if (c.face_in >= 0) { // entered this frame: the face crossed along the motion
			face = c.face_in;
			point = hs_lerp(a, b, c.t_in);
		} else {
			face = nearest_face(shape, part, b);
			const hs_face *f = &shape->faces[face];
			point = hs_mul_add(b, f->offset - hs_dot(f->normal, b), f->normal);
		}
		push_contact(world, object, h, i, false, face, to_world(body, point),
		             hs_mat3_mul(body->rot, shape->faces[face].normal));
	}
	// (B) check lines against edges
	for (int j = 0; j < HS_HAND_LINES; ++j) {
		if (cull && segment_distance_sq(center, hand->lines[j][0], hand->lines[j][1]) > r_sq)
			continue;
		hs_vec3 p0 = to_body(body, hand->lines[j][0]), p1 = to_body(body, hand->lines[j][1]);
		hs_clip c = hs_clip_segment(shape, part, p0, p1, grow);
		if (!c.hit || c.face_in < 0 || c.face_out < 0)
			continue; // misses, or an end is inside: that is the check points' business
		int e = edge_between(shape, part, c.face_in, c.face_out);
		if (e >= 0) {
			hs_vec3 ea = shape->vertices[shape->edges[e].a], eb = shape->vertices[shape->edges[e].b];
			hs_vec3 point = closest_on_first(ea, eb, p0, p1);
			hs_vec3 dir = hs_normalize(hs_sub(eb, ea));
			hs_vec3 foot = hs_mul_add(ea, -hs_dot(ea, dir), dir); // foot of the perpendicular from G = 0
			push_contact(world, object, h, HS_HAND_POINTS + j, true, e, to_world(body, point),
			             hs_mat3_mul(body->rot, hs_normalize(foot)));
		} else {
			hs_vec3 mid = hs_lerp(p0, p1, 0.5 * (c.t_in + c.t_out));
			int face = nearest_face(shape, part, mid);
			const hs_face *f = &shape->faces[face];
			hs_vec3 point = hs_mul_add(mid, f->offset - hs_dot(f->normal, mid), f->normal);
			push_contact(world, object, h, HS_HAND_POINTS + j, false, face, to_world(body, point),
			             hs_mat3_mul(body->rot, f->normal));
		}
	}
}

bool hs_hand_near(const hs_world *world, const hs_hand *hand, int object) {
	const hs_body *body = &world->bodies[object];
	double r = world->shapes[body->shape].radius + hand->radius;
	return hs_length_sq(hs_sub(body->pos, hand->center)) <= r * r;
}

int hs_contact_detect(hs_world *world, int object, const hs_body *before) {
	return hs_contact_detect_grown(world, object, before, 0.0);
}

int hs_contact_detect_grown(hs_world *world, int object, const hs_body *before, double grow) {
	int first = world->contact_count;
	const hs_body *body = &world->bodies[object];
	const hs_shape *shape = &world->shapes[body->shape];
	frame now = frame_of(body), then = before ? frame_of(before) : now;
	for (int h = 0; h < world->hand_count; ++h) {
		const hs_hand *hand = &world->hands[h];
		double reach = world->shapes[body->shape].radius + grow + hand->radius;
		if (world->def.skip_work && hs_length_sq(hs_sub(body->pos, hand->center)) > reach * reach)
			continue; // bounding-volume rejection before the narrow tests (Fig. 2)
		if (grow == 0.0) // the grown test repeats a held object's: counted once
			world->counters.hand_tests++;
		for (int p = 0; p < shape->part_count; ++p) {
			const hs_part *part = &shape->parts[p];
			if (world->def.skip_work) {
				hs_vec3 c = to_world(&now, part->center);
				double r = part->radius + grow + hand->radius;
				if (hs_length_sq(hs_sub(c, hand->center)) > r * r)
					continue;
			}
			detect_part(world, object, h, part, &now, &then, world->def.skip_work, grow);
		}
	}
	return world->contact_count - first;
}

double hs_grasp_limit(double grasp_threshold_deg) {
	return hs_cos(grasp_threshold_deg * (HS_PI / 180.0)) + HS_GRASP_EPS;
}

hs_contact_state hs_contact_classify(const hs_contact *contacts, int count, double grasp_limit, bool any_contacts) {
	if (count == 0)
		return HS_CONTACT_NONE;
	if (count == 1)
		return HS_CONTACT_PUSH_ONE;
	return hs_contact_grasps(contacts, count, 0, grasp_limit, any_contacts) ? HS_CONTACT_GRASP : HS_CONTACT_PUSH_MANY;
}

// The finger of a contact's part: check point i is on finger i / 4, check line j on j / 12 (§3.1).
static int finger_of(int part) {
	return part < HS_HAND_POINTS ? part / 4 : (part - HS_HAND_POINTS) / 12;
}

// Two contacts may make a grasp when they lie on different hands or different fingers (DESIGN.md
// "Real input": two points of one finger sunk into an object are not a grasp), or with the
// paper's "any two contacts" rule (§3.2 (2)).
static bool may_grasp(const hs_contact *a, const hs_contact *b, bool any_contacts) {
	return any_contacts || a->hand.index1 != b->hand.index1 || finger_of(a->part) != finger_of(b->part);
}

bool hs_contact_grasps(const hs_contact *contacts, int count, uint32_t hand1, double grasp_limit, bool any_contacts) {
	for (int i = 0; i < count; ++i) {
		if (hand1 && contacts[i].hand.index1 != hand1)
			continue;
		for (int j = i + 1; j < count; ++j)
			if ((!hand1 || contacts[j].hand.index1 == hand1) && may_grasp(&contacts[i], &contacts[j], any_contacts) &&
			    hs_dot(contacts[i].normal, contacts[j].normal) <= grasp_limit)
				return true; // two normals at >= the threshold (§3.2 (2))
	}
	return false;
}
