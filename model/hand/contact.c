// contact.c — contacts between hands and objects (1999 paper §3.1-3.2, Fig. 2, Fig. 4): which of
// the paper's tests run for each hand, part, check point and check line, in which order.
//
// Everything is computed in the object's body frame, whose origin is G, against each convex part:
//  (A) a check point that reached the part this frame touches the face it crossed along its path
//      relative to the object (also when it has come out again: swept detection, contact_swept.c);
//  (B) a check line crossing the part touches an edge when it enters and leaves through the two
//      faces that meet at that edge; the contact normal is the pseudo-normal from G to the edge.
//      A line through two faces that do not meet presses the face nearest to its middle; a line
//      that swept across the part during the frame touches where it first met it.
// A part already inside is drawn back to the surface (§3.2 rectification) when it touched last
// frame or the object came onto it, and touches nothing when it started inside (docs/model.md §3,
// "Swept detection, rectification and contact hysteresis"). paper_contacts keeps [H]'s letter.
// The rules themselves: contact_rules.c; the part queries: contact_part.h; the bounding tests that
// pass parts over before them: contact_cull.c; the grasp test: contact_grasp.c.
#include "contact.h"
#include "contact_cull.h"
#include "contact_rules.h"
#include "contact_swept.h"
#include "hand_sweep.h"

// The object did not move last frame (its pose equals the one before: asleep, or held still).
static bool same_pose(const hs_body *b) {
	return b->pos.x == b->prev.x && b->pos.y == b->prev.y && b->pos.z == b->prev.z && b->rot.w == b->rot_prev.w &&
	       b->rot.x == b->rot_prev.x && b->rot.y == b->rot_prev.y && b->rot.z == b->rot_prev.z;
}

// Where a part that lies in, or passed through, a convex part of the object now got there
// (docs/model.md §3, "Rectification and swept detection"):
//  - entered this frame (its path relative to the object crosses the surface): C where it
//    crossed, B where it is now - also when it has come out again (swept detection: a fast
//    fingertip at 12 frames/s does not pass through an object);
//  - already inside a frame ago and touching then: sunk in, drawn back to the surface;
//  - already inside and not touching: it started inside (or the object came onto it) and
//    touches nothing: no flinging, no grabbing.
// `grow` > 0: against the part grown by that much (the grasp's release margin, docs/model.md §3);
// swept detection runs for the part itself only. `moved`: the object moved since the last frame
// (a held object): points are culled where they end (their motion relative to it is small).
// `model` is cp->model passed on its own, as in detect_lines: held in a register rather than read
// through cp after every call (cp's other parts are read seldom); culls run when model->skip_work.
static void detect_points(const hs_contact_pass *cp, const hs_world_model *model, int object, int h, const hs_part *part, const hs_part_cache *pc,
                          const hs_frame *body, const hs_frame *before, const hs_body_points *bp, bool moved, double grow, unsigned far) {
	const hs_shape *shape = &model->shapes[cp->bodies[object].shape];
	const hs_hand *hand = &cp->hands[h];
	hs_vec3 center = to_world(body, part->center); // cull before the transform
	double r = part->radius + pc->grow_reach * grow, r_sq = r * r; // grown: its corners reach further
	bool paper = model->def.paper_contacts, swept = grow == 0.0 && !paper;
	int steps = moved ? 1 : hand->cache.path_steps; // a held object moves with the hand: chords suffice
	bool still = !moved && same_pose(&cp->bodies[object]);
	// passed over: far fingers' points (far_fingers), and those beyond the sphere now unless paths count
	uint32_t todo = ((1u << HS_HAND_POINTS) - 1u) & ~hs_finger_parts(far, 4);
	uint32_t near = model->skip_work ? hs_contact_points_near_part(hand, pc->grow_reach, center, r, swept, hs_contact_keep(model, hand)) : todo;
	double margin = model->def.grasp_release_mm * 1e-3;
	if (!swept || moved)
		todo &= near;
	for (; todo; todo &= todo - 1u) {
		int i = hs_lowest_bit(todo);
		if (!(near >> i & 1u) && !hs_contact_path_near(hand, i, steps, center, r_sq))
			continue;
		hs_vec3 b = hs_body_point(bp, hand, body, i);
		bool inside = inside_part_with(model, shape, part, pc, b, grow);
		if (paper) {
			if (inside)
				hs_contact_paper_point(cp, object, h, i, part, body, to_body(before, hand->cache.prev_points[i]), b, grow);
			continue;
		}
		bool touched = swept && (hand->state.touch_points >> i & 1u);
		if (swept && (hand->state.embed_points >> i & 1u)) { // started inside: touches nothing until clear
			if (inside_part_with(model, shape, part, pc, b, 2.0 * margin))
				cp->hands[h].scratch.embed_points_next |= 1u << i;
			continue;
		}
		if (!inside && touched && inside_part_with(model, shape, part, pc, b, margin)) {
			cp->hands[h].scratch.near_points |= 1u << i; // off the surface, within the margin: still touching
			if (moved)
				continue;
			const hs_face *f = &shape->faces[nearest_face_with(model, shape, part, pc, b)];
			hs_vec3 on = hs_mul_add(b, f->offset - hs_dot(f->normal, b), f->normal);
			// on an object that moved, only beside a part of its hand that pushes it (keep_hovering)
			hs_contact_push(cp, object, h, i, false, (int)(f - shape->faces), body, on, f->normal, on, still ? 0.0 : -1.0);
			continue;
		}
		if (!inside && (!swept || moved))
			continue; // a held object moves with the hand: nothing passes through it unseen
		hs_vec3 a = to_body(before, hand->cache.prev_points[i]); // where it was
		hs_clip c;
		hs_vec3 from = a, to = b; // (path_enters sets them when it enters: read only then)
		bool entered = false;
		double when = 0.0;
		if (touched) {
			// the entry is read only for a point that did not touch: not sought
		} else if (grow > 0.0 || steps == 1) {
			c = clip_part_with(model, shape, part, pc, a, b, grow);
			from = a;
			to = b;
			entered = c.face_in >= 0 && c.hit && (inside || c.t_in < c.t_out);
			when = c.t_in;
		} else {
			entered = hs_contact_path_enters(model, shape, part, hand, i, steps, body, a, inside, &c, &from, &to, &when);
		}
		if (entered && !touched) { // reached the surface this frame
			hs_contact_push(cp, object, h, i, false, c.face_in, body, hs_lerp(from, to, c.t_in),
			                shape->faces[c.face_in].normal, b, when);
		} else if (inside && !touched && !inside_part_with(model, shape, part, pc, a, grow)) { // from on the surface (the clip's t = 0)
			int face = nearest_face_with(model, shape, part, pc, a);
			hs_contact_push(cp, object, h, i, false, face, body, a, shape->faces[face].normal, b, 0.0);
		} else if (inside && (grow > 0.0 || touched || hs_contact_came_onto(cp, object, part, hand->cache.prev_points[i], grow))) {
			// sunk in (or back in, within the margin), or the object came onto it; or within the grown
			// part (the margin counts every part)
			int face = nearest_face_with(model, shape, part, pc, a);
			const hs_face *f = &shape->faces[face];
			hs_vec3 point = hs_mul_add(a, f->offset - hs_dot(f->normal, a), f->normal);
			hs_vec3 start = inside_part_with(model, shape, part, pc, a, grow) ? a : point; // back in: from the surface
			hs_contact_push(cp, object, h, i, false, face, body, point, f->normal,
			                hs_add(point, hs_sub(b, start)), 0.0);
		} else if (inside && swept) { // in it since before it touched anything: started inside
			cp->hands[h].scratch.embed_points_next |= 1u << i;
		}
	}
}

// A free object's finger segment whose lines find nothing through the frame, seen from its axis
// (contact_cull.h): a path of several pieces beyond a box face at every pose; one piece beyond a
// face of the scan (a box's too: that scan's early exit costs less than the box's coordinates).
static HS_FORCE_INLINE bool segment_clear(const hs_contact_pass *cp, int h, int a, const hs_frame *body, const hs_frame *before,
                                          const hs_shape *shape, const hs_part *part, const hs_part_cache *pc, int steps) {
	int box = steps > 1 && hs_part_is_box(pc) ? hs_contact_segment_path_clear_of_a_box_face(cp, h, a, body, before, pc, steps) : -1;
	if (box >= 0)
		return box == 1;
	return steps == 1 && hs_contact_segment_clear_of_a_face(cp, h, a, body, before, shape, part);
}

// A line's sweep through one piece, q to p, beyond one face of the part by HS_CULL_SLACK
// (hs_contact_sweep_clear_of_a_face): for a box, from its coordinates (the same answer when they
// are finite: the dots are the coordinates); else, or when one is not, by the scan of its faces.
static HS_FORCE_INLINE bool sweep_clear(const hs_contact_pass *cp, const hs_shape *shape, const hs_part *part,
                                        const hs_part_cache *pc, const hs_vec3 q[2], const hs_vec3 p[2]) {
	const hs_vec3 ends[4] = {q[0], q[1], p[0], p[1]};
	int box = hs_part_is_box(pc) ? hs_part_box_beyond_n(pc, ends, 4, HS_CULL_SLACK) : -1;
	if (box >= 0) {
#if defined(HS_SELFCHECK)
		if ((box == 1) != hs_contact_sweep_clear_of_a_face(cp, shape, part, q, p)) {
			fprintf(stderr, "selfcheck: a box's sweep test differs from the scan's\n");
			abort();
		}
#endif
		return box == 1;
	}
	return hs_contact_sweep_clear_of_a_face(cp, shape, part, q, p);
}

static bool across(hs_clip c) {
	return c.hit && c.face_in >= 0 && c.face_out >= 0;
}

// (B) check lines against the part: across it now (reached it this frame, sunk in, or across it
// since before it touched anything, as the check points in detect_points), or swept across it
// during the frame. A line with an end inside is the check points' business.
static void detect_lines(const hs_contact_pass *cp, const hs_world_model *model, int object, int h, const hs_part *part, const hs_part_cache *pc,
                         const hs_frame *body, const hs_frame *before, const hs_body_points *bp, bool moved, double grow, uint32_t touching, unsigned far) {
	const hs_shape *shape = &model->shapes[cp->bodies[object].shape];
	const hs_hand *hand = &cp->hands[h];
	hs_vec3 center = to_world(body, part->center);
	double r = part->radius + pc->grow_reach * grow; // grown: its corners reach further
	bool paper = model->def.paper_contacts, swept = grow == 0.0 && !paper;
	int steps = moved ? 1 : hand->cache.path_steps; // a held object moves with the hand: chords suffice
	hs_segment_bounds sb = hs_contact_segment_bounds(model, hand, r);
	hs_deep_memo memo = {0, 0};
	hs_held_turn turn = {.ready = false};
	// passed over: far fingers' segments (far_fingers), and those beyond rs now unless paths count
	double d_axis[16]; // axes_near's AVX path fills a 16th
	uint32_t segments = HS_HAND_ALL_SEGMENTS & ~hs_finger_parts(far, 3);
	uint32_t near = (model->skip_work ? hs_contact_axes_near(hand, center, sb.rs * sb.rs, d_axis) : segments) | (swept ? hs_contact_segments_embedded(hand) : 0);
	if (!swept || moved)
		segments &= near;
	for (; segments; segments &= segments - 1u) {
		int s = hs_lowest_bit(segments), a = hs_segment_first_point(s); // a: the segment's first check point
		double d_sq = model->skip_work ? d_axis[s] : 0.0;
		bool plain = swept && !(hand->state.embed_lines >> (4 * s) & 0xFu); // none of its lines embedded
		if ((!(near >> s & 1u) && !hs_contact_axis_path_near(hand, a, steps, center, sb.rp)) ||
		    (swept && hs_contact_ends_deep(model, hand, touching, a, body, bp, shape, part, sb.deep, &memo)) ||
		    (plain && !moved && segment_clear(cp, h, a, body, before, shape, part, pc, steps)) ||
		    (plain && moved && hs_part_is_box(pc) && hs_contact_held_lines_clear(cp, h, s, a, body, bp, shape, part, touching, grow, &turn)))
			continue; // far, each line beside a touching point, or clear (seen before it is placed)
		hs_hand_ready_segment(&cp->hands[h], s); // its lines are read from here on
		bool all_near = (sb.ri > 0.0 && d_sq <= sb.ri * sb.ri) || (swept && !plain); // all within r now
		unsigned lines = model->skip_work && !all_near ? hs_contact_lines_near(hand, s, center, r * r) : 0xFu;
		for (int j = 4 * s; j < 4 * s + 4; ++j) {
			const hs_vec3 *l = hand->cache.lines[j], *m = hand->cache.prev_lines[j];
			if (!(lines >> (j - 4 * s) & 1u) && (!swept || moved || !hs_contact_line_path_near(hand, j, steps, center, r)))
				continue;
			hs_vec3 p[2];
			line_to_body(body, l, p);
			bool embedded = swept && (hand->state.embed_lines >> j & 1u);
			// where no path is swept (a held object; the grown and paper tests) a line that misses the part
			// now is done: clipped before the line a frame ago is transformed (most lines end here)
			bool miss_ends = (moved || !swept) && !embedded;
			if (swept && hs_contact_end_touches(model, touching, a, shape, part, p))
				continue; // beside a touching check point at the frame's end
			hs_clip c = miss_ends ? clip_part_with(model, shape, part, pc, p[0], p[1], grow) : (hs_clip){0.0, 1.0, -1, -1, false};
			if (miss_ends && !c.hit)
				continue;
			hs_vec3 q[2]; // the line a frame ago
			line_to_body(before, m, q);
			if (swept && !moved && !embedded && steps == 1 && sweep_clear(cp, shape, part, pc, q, p))
				continue; // missed it at both ends and swept nothing of it
			if (swept && hs_contact_end_touches(model, hand->state.touch_points, a, shape, part, q))
				continue; // or at its start
			if (embedded) { // started inside: touches nothing until clear
				if (clip_part_with(model, shape, part, pc, p[0], p[1], 2.0 * model->def.grasp_release_mm * 1e-3).hit)
					cp->hands[h].scratch.embed_lines_next |= (uint64_t)1 << j;
				continue;
			}
			if (!miss_ends)
				c = clip_part_with(model, shape, part, pc, p[0], p[1], grow);
			if (!c.hit) {
				if (swept && !moved) // a held object moves with the hand: nothing passes through it unseen
					hs_contact_swept_path(cp, object, h, j, part, body, steps, q, p);
				continue;
			}
			if (!across(c))
				continue; // an end is inside
			if (paper) { // [H]'s letter: across where it ends the frame
				hs_contact_line_across(cp, object, h, j, part, body, p[0], p[1], c, NULL);
				continue;
			}
			if (!clip_part_with(model, shape, part, pc, q[0], q[1], grow).hit) { // reached it this frame
				hs_contact_line_across(cp, object, h, j, part, body, p[0], p[1], c, NULL);
			} else if (grow > 0.0 || (hand->state.touch_lines >> j & 1u) || hs_contact_line_came_onto(cp, object, part, m, grow)) {
				// in it a frame ago too: sunk in (touching), or the object came onto it
				hs_vec3 d = hs_scale(hs_add(hs_sub(p[0], q[0]), hs_sub(p[1], q[1])), 0.5);
				hs_contact_line_across(cp, object, h, j, part, body, p[0], p[1], c, &d);
			} else if (swept) { // in it since before it touched anything: started inside, touches nothing
				cp->hands[h].scratch.embed_lines_next |= (uint64_t)1 << j;
			}
		}
	}
}

int hs_contact_detect(const hs_contact_pass *cp, int object, const hs_pose *before) {
	return hs_contact_detect_grown(cp, object, before, 0.0);
}

int hs_contact_detect_grown(const hs_contact_pass *cp, int object, const hs_pose *before, double grow) {
	const hs_world_model *model = cp->model; // in locals: read once, not through cp after each call
	hs_world_output *out = cp->out;
	hs_hand *hands = cp->hands;
	int first = out->contact_count;
	const hs_body *body = &cp->bodies[object];
	const hs_shape *shape = &model->shapes[body->shape];
	int h = 0; // the first hand near the object: only then are its poses made matrices
	while (h < model->hand_count && !hs_contact_hand_near(model, body, &hands[h], grow))
		++h;
	if (h == model->hand_count)
		return 0;
	hs_frame now = frame_of(body), then = now;
	if (before)
		then = (hs_frame){before->pos, hs_mat3_from_quat(before->rot)};
	for (; h < model->hand_count; ++h) {
		const hs_hand *hand = &hands[h];
		if (!hs_contact_hand_near(model, body, hand, grow))
			continue; // bounding-volume rejection before the narrow tests (Fig. 2)
		if (grow == 0.0) // the grown test repeats a held object's: counted once
			cp->counters->hand_tests++;
		// finger by finger for an object the hand did not carry, in the ungrown test (a carried one
		// has them all near, and its points and lines are passed over by cheaper tests)
		bool fingers = model->skip_work && !before && grow == 0.0;
		if (fingers)
			hs_hand_finger_spheres(&hands[h]);
		// a moved (held) object reads most check points, each several times: in its frame once
		hs_body_points rows, *bp = before ? &rows : NULL;
		if (bp)
			hs_contact_points_to_body(hand, &now, bp);
		for (int p = 0; p < shape->part_count; ++p) {
			const hs_part *part = &shape->parts[p];
			const hs_part_cache *pc = &model->part_cache[body->shape][p];
			unsigned far = 0;
			if (model->skip_work) {
				hs_vec3 c = to_world(&now, part->center);
				if (!hs_contact_sphere_near(model, hand, c, part->radius, pc->grow_reach, grow))
					continue;
				if (fingers) {
					far = hs_contact_far_fingers(hand, pc->grow_reach, c, part->radius + HS_CULL_SLACK, hs_contact_keep(model, hand));
				}
			}
			int from = out->contact_count;
			detect_points(cp, model, object, h, part, pc, &now, &then, bp, before != NULL, grow, far);
			uint32_t touching = hand->state.touch_points; // touched last frame, or touch this part now
			for (int k = from; k < out->contact_count; ++k)
				touching |= 1u << out->contacts[k].part;
			detect_lines(cp, model, object, h, part, pc, &now, &then, bp, before != NULL, grow, touching, far);
		}
	}
	if (grow == 0.0 && !model->def.paper_contacts)
		return hs_contact_keep_hovering(cp, first, hs_contact_drop_trailing(cp, first));
	return out->contact_count - first;
}

// The question hs_contact_detect_grown(cp, object, NULL, grow) answers for one hand, without
// making its contacts: with `grow` > 0 and no motion of the object, every check point inside a
// grown part and every check line across one (both ends outside) gives a contact there, and
// nothing else does (detect_points, detect_lines). The same culls pass the same parts over.
bool hs_contact_hand_within(const hs_contact_pass *cp, int object, int h, double grow) {
	const hs_world_model *model = cp->model;
	const hs_body *body = &cp->bodies[object];
	const hs_shape *shape = &model->shapes[body->shape];
	hs_hand *hand = &cp->hands[h];
	if (!(grow > 0.0) || !hs_contact_hand_near(model, body, hand, grow))
		return false;
	hs_frame now = frame_of(body);
	bool cull = model->skip_work;
	for (int p = 0; p < shape->part_count; ++p) {
		const hs_part *part = &shape->parts[p];
		const hs_part_cache *pc = &model->part_cache[body->shape][p];
		hs_vec3 center = to_world(&now, part->center);
		if (cull && !hs_contact_sphere_near(model, hand, center, part->radius, pc->grow_reach, grow))
			continue;
		double r = part->radius + pc->grow_reach * grow;
		uint32_t points = (1u << HS_HAND_POINTS) - 1u;
		if (cull)
			points &= hs_contact_points_near_part(hand, pc->grow_reach, center, r, false, hs_contact_keep(model, hand));
		for (; points; points &= points - 1u)
			if (inside_part_with(model, shape, part, pc, to_body(&now, hand->cache.points[hs_lowest_bit(points)]), grow))
				return true;
		hs_segment_bounds sb = hs_contact_segment_bounds(model, hand, r);
		double d_axis[16]; // axes_near's AVX path fills a 16th
		uint32_t segments = cull ? HS_HAND_ALL_SEGMENTS & hs_contact_axes_near(hand, center, sb.rs * sb.rs, d_axis) : HS_HAND_ALL_SEGMENTS;
		for (; segments; segments &= segments - 1u) {
			int s = hs_lowest_bit(segments);
			hs_hand_ready_segment(hand, s);
			bool all_near = !cull || (sb.ri > 0.0 && d_axis[s] <= sb.ri * sb.ri);
			unsigned lines = all_near ? 0xFu : hs_contact_lines_near(hand, s, center, r * r);
			for (int j = 4 * s; j < 4 * s + 4; ++j) {
				if (!(lines >> (j - 4 * s) & 1u))
					continue;
				hs_vec3 q[2];
				line_to_body(&now, hand->cache.lines[j], q);
				if (across(clip_part_with(model, shape, part, pc, q[0], q[1], grow)))
					return true;
			}
		}
	}
	return false;
}
