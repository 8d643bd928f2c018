// test_contact.c — hand contacts (A) and (B), classification (Fig. 2) and the motions of §3.2,
// with check points placed by hand (no kinematics) and expectations computed by hand.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "broadphase.h"
#include "contact.h"
#include "manipulate.h"
#include "world_internal.h"
#include "push.h"
#include "test_rig.h"

#define FAR RIG_FAR

// The contact tests' parts of w (made at each call: its frame number is the world's now).
static const hs_contact_pass *contacts_of(hs_world *w) {
	static hs_contact_pass cp;
	cp = hs_contact_pass_of(w);
	return &cp;
}

// A unit cube (faces at ±0.5 about G) with G at (0, 0, 2), out of the floor's reach, and one hand
// whose parts are all far away until a test puts some of them somewhere.
static hs_world *cube_world_dt(double dt) {
	hs_world_def def = hs_default_world_def();
	def.dt = dt;
	return rig_world(&def, hs_shape_box(hs_v3(1, 1, 1), NULL), hs_v3(0, 0, 2), hs_v3(0, 0, 2));
}

static hs_world *cube_world(void) { return cube_world_dt(1.0 / 60); }

static void move_point(hs_world *w, int i, hs_vec3 from, hs_vec3 to) {
	w->state.hands[0].cache.prev_points[i] = from;
	w->state.hands[0].cache.points[i] = to;
	hs_hand_points_moved(&w->state.hands[0]);
}

static hs_contact contact(const hs_world *w, int k) { return w->out.contacts[k]; }

// (A) a check point that entered through the top face touches it where it crossed.
static void test_point_enters_face(void **state) {
	(void)state;
	hs_world *w = cube_world();
	move_point(w, 3, hs_v3(0.1, 0.2, 2.7), hs_v3(0.1, 0.2, 2.3));
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	hs_contact c = contact(w, 0);
	assert_false(c.edge);
	assert_int_equal(c.part, 3);
	assert_vec3_near(c.normal, hs_v3(0, 0, 1), 1e-15);
	assert_vec3_near(c.point, hs_v3(0.1, 0.2, 2.5), 1e-15);
	hs_world_destroy(w);
}

// (A) a point that was already inside a frame ago: touching then, it has sunk in and is drawn back
// to the face nearest to where it was (§3.2 rectification): C there, B = C + its motion since.
// Not touching then, it started inside and touches nothing.
static void test_point_inside_nearest_face(void **state) {
	(void)state;
	hs_world *w = cube_world();
	move_point(w, 0, hs_v3(-0.45, 0, 2.1), hs_v3(-0.44, 0, 2.1));
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 0);
	w->state.hands[0].state.touch_points = 1u;
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	assert_vec3_near(contact(w, 0).normal, hs_v3(-1, 0, 0), 1e-15);
	assert_vec3_near(contact(w, 0).point, hs_v3(-0.5, 0, 2.1), 1e-15);
	assert_vec3_near(contact(w, 0).finger, hs_v3(-0.49, 0, 2.1), 1e-15);
	w->out.contact_count = 0;
	move_point(w, 0, hs_v3(-0.45, 0, 2.1), hs_v3(-0.46, 0.01, 2.1)); // coming out: it drives nothing
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	assert_vec3_near(contact(w, 0).finger, hs_v3(-0.5, 0, 2.1), 1e-15);
	hs_world_destroy(w);
}

// Friction at the fingertip (docs/model.md §3): a part drives C in by how far it went in along -n
// and sideways by at most μ (HS_PUSH_FRICTION, 1) times that; inside that cone B is where it went,
// as eq. 1-2; a part not going in drives nothing.
static void test_fingertip_friction_cone(void **state) {
	(void)state;
	assert_true(HS_PUSH_FRICTION == 1.0); // the closed forms below
	hs_world *w = cube_world();
	// reaching the top: crosses z = 2.5 at 0.8 of its path, C = (0.34, 0.2, 2.5); CB = (0.06, 0, -0.05)
	// goes in 0.05 and sideways 0.06 > 0.05: B = C + (0.05, 0, -0.05)
	move_point(w, 3, hs_v3(0.1, 0.2, 2.7), hs_v3(0.4, 0.2, 2.45));
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	assert_vec3_near(contact(w, 0).point, hs_v3(0.34, 0.2, 2.5), 1e-12);
	assert_vec3_near(contact(w, 0).finger, hs_v3(0.39, 0.2, 2.45), 1e-12);
	// sunk in the -x face (touching): in 0.01 and sideways 0.03 -> 0.01; sideways 0.005 stays whole
	w->out.contact_count = 0;
	w->state.hands[0].cache.points[3] = w->state.hands[0].cache.prev_points[3] = RIG_FAR;
	w->state.hands[0].state.touch_points = 1u;
	move_point(w, 0, hs_v3(-0.45, 0, 2.1), hs_v3(-0.44, 0.03, 2.1));
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	assert_vec3_near(contact(w, 0).point, hs_v3(-0.5, 0, 2.1), 1e-15);
	assert_vec3_near(contact(w, 0).finger, hs_v3(-0.49, 0.01, 2.1), 1e-15);
	w->out.contact_count = 0;
	move_point(w, 0, hs_v3(-0.45, 0, 2.1), hs_v3(-0.44, 0.005, 2.1));
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	assert_vec3_near(contact(w, 0).finger, hs_v3(-0.49, 0.005, 2.1), 1e-15);
	w->out.contact_count = 0;
	move_point(w, 0, hs_v3(-0.45, 0, 2.1), hs_v3(-0.45, 0.02, 2.1)); // along the face only
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	assert_vec3_near(contact(w, 0).finger, hs_v3(-0.5, 0, 2.1), 1e-15);
	hs_world_destroy(w);
}

// Contact hysteresis: a touching check point off the surface by less than grasp_release_mm still
// touches; on an object that did not move last frame it is a contact that drives nothing (C = B,
// the point moved onto the nearest face), so a fingertip trembling on a still object stays one
// push (state 1). On an object it moved it is none: the object goes on by eq. 3.
static void test_touching_point_within_margin(void **state) {
	(void)state;
	hs_world *w = cube_world();
	hs_body *b = &w->state.bodies[0];
	b->prev = b->pos;
	b->rot_prev = b->rot;
	w->state.hands[0].state.touch_points = 1u << 3;
	move_point(w, 3, hs_v3(0.1, 0.2, 2.499), hs_v3(0.1, 0.2, 2.503));
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	assert_vec3_near(contact(w, 0).point, hs_v3(0.1, 0.2, 2.5), 1e-15);
	assert_vec3_near(contact(w, 0).finger, contact(w, 0).point, 0.0);
	assert_int_equal(w->state.hands[0].scratch.near_points, 1u << 3);
	w->out.contact_count = 0;
	w->state.hands[0].scratch.near_points = 0;
	b->prev.x -= 0.001; // moved last frame: no contact, still touching
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 0);
	assert_int_equal(w->state.hands[0].scratch.near_points, 1u << 3);
	w->out.contact_count = 0; // ... unless another part of the hand pushes it this frame: 3
	move_point(w, 7, hs_v3(0.0, 0.2, 2.6), hs_v3(0.0, 0.2, 2.49));
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 2);
	assert_int_equal(hs_contact_classify(w->out.contacts, 2, w->model.grasp_limit, false), HS_CONTACT_PUSH_MANY);
	assert_true(w->out.contacts[0].t == 0.0 || w->out.contacts[1].t == 0.0);
	w->out.contact_count = 0;
	w->state.hands[0].cache.points[7] = w->state.hands[0].cache.prev_points[7] = RIG_FAR;
	b->prev = b->pos;
	w->state.hands[0].scratch.near_points = 0;
	move_point(w, 3, hs_v3(0.1, 0.2, 2.499), hs_v3(0.1, 0.2, 2.506)); // beyond the margin: let go
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 0);
	assert_int_equal(w->state.hands[0].scratch.near_points, 0u);
	hs_world_destroy(w);
}

// A part reaching a face this frame behind a part of the same finger that touched that face
// already and drives it further in is set aside (the face, pushed by the leading part, is still
// ahead of it); going in further, or on another finger, it touches.
static void test_trailing_part_set_aside(void **state) {
	(void)state;
	hs_world *w = cube_world();
	w->state.hands[0].state.touch_points = 1u << 7;                           // finger 1's tip touched the -x face
	move_point(w, 7, hs_v3(-0.45, 0, 2.1), hs_v3(-0.43, 0, 2.1)); // sunk: drives it in 0.02
	move_point(w, 6, hs_v3(-0.6, 0, 2.2), hs_v3(-0.49, 0, 2.2));  // its DIP reaches it, 0.01 in
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	assert_int_equal(contact(w, 0).part, 7);
	w->out.contact_count = 0;
	move_point(w, 6, hs_v3(-0.6, 0, 2.2), hs_v3(-0.47, 0, 2.2)); // 0.03 in: ahead of the tip
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 2);
	w->out.contact_count = 0;
	move_point(w, 6, hs_v3(-0.6, 0, 2.2), hs_v3(-0.49, 0, 2.2));
	move_point(w, 11, hs_v3(-0.6, 0.2, 2.2), hs_v3(-0.49, 0.2, 2.2)); // another finger: touches
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 2);
	hs_world_destroy(w);
}

// Both reach the face this frame: the part that reached it later (swept detection's t) and less
// deep trails the one that got there first; reaching it first, it touches.
static void test_trailing_part_same_frame(void **state) {
	(void)state;
	hs_world *w = cube_world();
	move_point(w, 7, hs_v3(-0.6, 0, 2.1), hs_v3(-0.47, 0, 2.1));  // the tip: in at t = 0.77, 0.03 deep
	move_point(w, 6, hs_v3(-0.62, 0, 2.2), hs_v3(-0.49, 0, 2.2)); // the DIP: in at t = 0.92, 0.01 deep
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	assert_int_equal(contact(w, 0).part, 7);
	w->out.contact_count = 0;
	move_point(w, 6, hs_v3(-0.52, 0, 2.2), hs_v3(-0.49, 0, 2.2)); // the DIP first (t = 0.67): touches
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 2);
	hs_world_destroy(w);
}

// A check line whose end lies within grasp_release_mm of the part at a touching check point is
// that point's business, as a line with an end inside: the side of a fingertip resting near an
// edge does not push the edge. Line 8 runs beside check points 2 and 3 (finger 0, segment 2).
static void test_line_beside_touching_point(void **state) {
	(void)state;
	hs_world *w = cube_world();
	hs_hand *hand = &w->state.hands[0];
	hand->cache.lines[8][0] = hs_v3(0.3, 0, 2.7); // enters the top, leaves +x; its end 3 mm off the +x face
	hand->cache.lines[8][1] = hs_v3(0.503, 0, 2.45);
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	assert_true(contact(w, 0).edge);
	w->out.contact_count = 0;
	hand->state.touch_points = 1u << 3;
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 0);
	hand->state.touch_points = 1u << 1; // another point of that finger: the line still touches
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	w->out.contact_count = 0;
	hand->state.touch_points = 0; // point 3 reaching the top this frame: the line is its business too
	move_point(w, 3, hs_v3(0.45, 0, 2.6), hs_v3(0.45, 0, 2.49));
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	assert_int_equal(contact(w, 0).part, 3);
	hs_world_destroy(w);
}

// (A) a point on the surface is not inside; entering exactly through an edge picks one of the two
// faces, the same one every time (array order), never both.
static void test_point_at_edge_and_surface(void **state) {
	(void)state;
	hs_world *w = cube_world();
	move_point(w, 0, hs_v3(-0.6, 0, 2), hs_v3(-0.5, 0, 2)); // exactly on the face plane
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 0);
	w->out.contact_count = 0;
	move_point(w, 0, hs_v3(0.6, 0, 2.6), hs_v3(0.4, 0, 2.4)); // crosses the edge x = z - 2 = 0.5
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	hs_vec3 n = contact(w, 0).normal;
	assert_true((n.x == 1 && n.z == 0) || (n.x == 0 && n.z == 1));
	assert_vec3_near(contact(w, 0).point, hs_v3(0.5, 0, 2.5), 1e-15);
	hs_world_destroy(w);
}

// (B) a check line cutting the corner wedge of an edge touches that edge; its pseudo-normal
// points from G to the edge (Fig. 4).
static void test_line_crosses_edge(void **state) {
	(void)state;
	hs_world *w = cube_world();
	hs_hand *hand = &w->state.hands[0];
	hand->cache.lines[7][0] = hs_v3(0.25, 0, 2.6); // enters the top at t = 0.25, leaves +x at t = 0.625
	hand->cache.lines[7][1] = hs_v3(0.65, 0, 2.2);
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	hs_contact c = contact(w, 0);
	assert_true(c.edge);
	assert_int_equal(c.part, HS_HAND_POINTS + 7);
	assert_vec3_near(c.normal, hs_v3(sqrt(0.5), 0, sqrt(0.5)), 1e-15);
	assert_vec3_near(c.point, hs_v3(0.5, 0, 2.5), 1e-15);
	hs_world_destroy(w);
}

// (B) a line through two opposite faces presses the face nearest its middle; a line ending inside
// is left to the check points.
static void test_line_across_and_line_ending_inside(void **state) {
	(void)state;
	hs_world *w = cube_world();
	hs_hand *hand = &w->state.hands[0];
	hand->cache.lines[0][0] = hs_v3(-1, 0, 2.45);
	hand->cache.lines[0][1] = hs_v3(1, 0, 2.45);
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 1);
	assert_false(contact(w, 0).edge);
	assert_vec3_near(contact(w, 0).normal, hs_v3(0, 0, 1), 1e-15);
	assert_vec3_near(contact(w, 0).point, hs_v3(0, 0, 2.5), 1e-15);
	w->out.contact_count = 0;
	hand->cache.lines[0][1] = hs_v3(0, 0, 2.45);
	assert_int_equal(hs_contact_detect(contacts_of(w), 0, NULL), 0);
	hs_world_destroy(w);
}

// The release margin's question (hs_contact_hand_within): a check point inside the cube grown by
// 2 cm, or a check line across it with both ends outside, answers yes; a part beyond the margin,
// or a line with an end inside the grown cube (the check points' business), no. The answer is the
// grown test's: it gives that hand a contact exactly then.
static void test_hand_within_margin(void **state) {
	(void)state;
	const double grow = 0.02;
	struct {
		int kind; // 0: check point 3 at a, 1: check line 0 from a to b
		hs_vec3 a, b;
		bool within;
	} cases[] = {
	    {0, {0.1, 0.2, 2.515}, {0, 0, 0}, true},    // 1.5 cm above the top face
	    {0, {0.1, 0.2, 2.53}, {0, 0, 0}, false},    // 3 cm above it
	    {0, {0.515, 0.515, 2.0}, {0, 0, 0}, true},  // beside a vertical edge, 1.5 cm off two faces
	    {1, {-1, 0, 2.51}, {1, 0, 2.51}, true},     // across the grown cube, 1 cm above the top
	    {1, {-1, 0, 2.53}, {1, 0, 2.53}, false},    // above it
	    {1, {-1, 0, 2.51}, {0, 0, 2.51}, false},    // ends inside the grown cube: no contact of its own
	};
	for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
		hs_world *w = cube_world();
		hs_hand *hand = &w->state.hands[0];
		if (cases[k].kind == 0) {
			move_point(w, 3, cases[k].a, cases[k].a);
		} else {
			hand->cache.lines[0][0] = hand->cache.prev_lines[0][0] = cases[k].a;
			hand->cache.lines[0][1] = hand->cache.prev_lines[0][1] = cases[k].b;
		}
		bool within = hs_contact_hand_within(contacts_of(w), 0, 0, grow);
		assert_int_equal(within, cases[k].within);
		assert_int_equal(within, hs_contact_detect_grown(contacts_of(w), 0, NULL, grow) > 0);
		assert_false(hs_contact_hand_within(contacts_of(w), 0, 0, 0.0)); // asked with a margin only
		hs_world_destroy(w);
	}
}

static hs_contact with_normal(hs_vec3 n) {
	hs_contact c;
	memset(&c, 0, sizeof c);
	c.normal = n;
	return c;
}

// Fig. 2: none / one point / grasp (two normals >= threshold apart) / several points; the paper's
// rule (any two contacts) first, then the default (two fingers or hands).
static void test_classification(void **state) {
	(void)state;
	hs_contact cs[3] = {with_normal(hs_v3(1, 0, 0)), with_normal(hs_v3(0, 1, 0)), with_normal(hs_v3(1, 0, 0))};
	assert_int_equal(hs_contact_classify(cs, 0, hs_grasp_limit(90), true), HS_CONTACT_NONE);
	assert_int_equal(hs_contact_classify(cs, 1, hs_grasp_limit(90), true), HS_CONTACT_PUSH_ONE);
	assert_int_equal(hs_contact_classify(cs, 2, hs_grasp_limit(90), true), HS_CONTACT_GRASP); // adjoining faces: exactly 90
	assert_int_equal(hs_contact_classify(cs, 2, hs_grasp_limit(91), true), HS_CONTACT_PUSH_MANY);
	hs_contact same[2] = {cs[0], cs[2]};
	assert_int_equal(hs_contact_classify(same, 2, hs_grasp_limit(90), true), HS_CONTACT_PUSH_MANY);
	// 90 deg reached through rounding (cos(pi/2) is 6e-17, not 0): the tolerance decides, not the ulp
	hs_vec3 n = hs_quat_rotate(hs_quat_from_axis_angle(hs_v3(0, 0, 1), HS_PI / 2 + 1e-12), hs_v3(1, 0, 0));
	hs_contact rounded[2] = {cs[0], with_normal(n)};
	assert_int_equal(hs_contact_classify(rounded, 2, hs_grasp_limit(90), true), HS_CONTACT_GRASP);
	hs_vec3 m = hs_quat_rotate(hs_quat_from_axis_angle(hs_v3(0, 0, 1), 89.0 * HS_PI / 180), hs_v3(1, 0, 0));
	hs_contact short_of[2] = {cs[0], with_normal(m)};
	assert_int_equal(hs_contact_classify(short_of, 2, hs_grasp_limit(90), true), HS_CONTACT_PUSH_MANY);
	// three contacts: any pair at the threshold makes a grasp (Fig. 4)
	hs_contact three[3] = {cs[0], cs[2], with_normal(hs_v3(-1, 0, 0))};
	assert_int_equal(hs_contact_classify(three, 3, hs_grasp_limit(90), true), HS_CONTACT_GRASP);
	// the default rule: the pair must lie on different fingers (point i: i / 4; line j: j / 12) or hands
	hs_contact pair[2] = {cs[0], cs[1]};
	const int parts[][2] = {{3, 7}, {3, 2}, {3, HS_HAND_POINTS + 0}, {3, HS_HAND_POINTS + 12}, {7, HS_HAND_POINTS + 23}};
	const hs_contact_state want[] = {HS_CONTACT_GRASP, HS_CONTACT_PUSH_MANY, HS_CONTACT_PUSH_MANY, HS_CONTACT_GRASP,
	                                 HS_CONTACT_PUSH_MANY};
	for (int k = 0; k < 5; ++k) {
		pair[0].part = parts[k][0];
		pair[1].part = parts[k][1];
		assert_int_equal(hs_contact_classify(pair, 2, hs_grasp_limit(90), false), want[k]);
		assert_int_equal(hs_contact_classify(pair, 2, hs_grasp_limit(90), true), HS_CONTACT_GRASP);
	}
	pair[0].part = pair[1].part = 3; // one finger of each of two hands
	pair[0].hand.index1 = 1;
	pair[1].hand.index1 = 2;
	assert_int_equal(hs_contact_classify(pair, 2, hs_grasp_limit(90), false), HS_CONTACT_GRASP);
}

static hs_body body_at(hs_vec3 g) {
	hs_body b;
	memset(&b, 0, sizeof b);
	b.pos = g;
	b.rot = hs_quat_identity();
	return b;
}

// Eq. 1-2 with R = 0 (CB ∥ CG): translation only.
static void test_push_r_zero(void **state) {
	(void)state;
	hs_body b = body_at(hs_v3(0, 0, 2));
	hs_push_at_one_point(&b, hs_v3(-0.5, 0, 2), hs_v3(-0.45, 0, 2));
	assert_vec3_near(b.pos, hs_v3(0.05, 0, 2), 1e-15);
	assert_near(hs_quat_angle(b.rot), 0, 0);
}

// Eq. 1-2 with T = 0 (CB ⟂ CG): rotation only, by atan(|R| / |CG|) about R × CG, C moving along R.
static void test_push_t_zero(void **state) {
	(void)state;
	hs_body b = body_at(hs_v3(0, 0, 2));
	hs_push_at_one_point(&b, hs_v3(-0.5, 0, 2), hs_v3(-0.5, 0.1, 2));
	assert_vec3_near(b.pos, hs_v3(0, 0, 2), 0);
	assert_near(hs_quat_angle(b.rot), atan(0.1 / 0.5), 1e-15);
	hs_vec3 c_now = hs_quat_rotate(b.rot, hs_v3(-0.5, 0, 0));
	assert_true(c_now.y > 0); // C went toward B
	assert_near(c_now.x, -0.5 * cos(atan(0.2)), 1e-15);
}

// Eq. 1-2 off-centre: T = (CB·ĉg) ĉg, R = CB - T, computed by hand for C = (-0.5, 0.3), CB = (0.05, 0).
static void test_push_off_centre(void **state) {
	(void)state;
	hs_body b = body_at(hs_v3(0, 0, 2));
	hs_push_at_one_point(&b, hs_v3(-0.5, 0.3, 2), hs_v3(-0.45, 0.3, 2));
	double cg = sqrt(0.34), tx = 0.05 * 0.25 / 0.34, ty = -0.05 * 0.15 / 0.34;
	assert_vec3_near(b.pos, hs_v3(tx, ty, 2), 1e-15);
	double rx = 0.05 - tx, ry = -ty;
	assert_near(hs_quat_angle(b.rot), atan(sqrt(rx * rx + ry * ry) / cg), 1e-15);
	assert_near(b.rot.z, -sin(0.5 * atan(sqrt(rx * rx + ry * ry) / cg)), 1e-15); // about -z: clockwise
}

// Push at several points: translate by the mean of the parts' motions while touching (from where
// each crossed the face: 0.05 and 0.1), no turn (§3.2 (3); docs/model.md §3).
static void test_push_many_translates(void **state) {
	(void)state;
	hs_world *w = cube_world();
	move_point(w, 3, hs_v3(-0.6, 0.2, 2), hs_v3(-0.45, 0.2, 2));
	move_point(w, 7, hs_v3(-0.6, -0.3, 2), hs_v3(-0.40, -0.3, 2));
	hs_manipulate(w);
	assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_PUSH_MANY);
	assert_vec3_near(w->state.bodies[0].pos, hs_v3(0.075, 0, 2), 1e-15);
	assert_near(hs_quat_angle(w->state.bodies[0].rot), 0, 0);
	hs_world_destroy(w);
}

// Grasp: the pose in the wrist frame is kept; open the hand and it flies on with the hand's motion.
static void test_grasp_follow_release(void **state) {
	(void)state;
	hs_world *w = cube_world();
	hs_hand *hand = &w->state.hands[0];
	move_point(w, 3, hs_v3(-0.6, 0, 2), hs_v3(-0.45, 0, 2)); // two opposite faces: 180 deg
	move_point(w, 7, hs_v3(0.6, 0, 2), hs_v3(0.45, 0, 2));
	hs_world_step(w);
	assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
	assert_vec3_near(w->state.bodies[0].pos, hs_v3(0, 0, 2), 0); // held where it was grasped
	for (int k = 1; k <= 3; ++k) { // the wrist and fingers rise 0.1 per frame and turn 10 deg about z
		hs_vec3 lift = hs_v3(0, 0, 0.1 * k);
		hand->state.wrist_pos = lift;
		hand->state.wrist_rot = hs_quat_from_axis_angle(hs_v3(0, 0, 1), k * 10 * HS_PI / 180);
		hs_vec3 tip3 = hs_add(hs_quat_rotate(hand->state.wrist_rot, hs_v3(-0.45, 0, 2)), hs_v3(0, 0, 0));
		hs_vec3 tip7 = hs_quat_rotate(hand->state.wrist_rot, hs_v3(0.45, 0, 2));
		hand->cache.points[3] = hs_add(tip3, lift);
		hand->cache.points[7] = hs_add(tip7, lift);
		hs_hand_points_moved(hand);
		hs_world_step(w);
		assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
		assert_vec3_near(w->state.bodies[0].pos, hs_add(hs_quat_rotate(hand->state.wrist_rot, hs_v3(0, 0, 2)), lift), 1e-14);
	}
	hand->cache.points[3] = hand->cache.points[7] = FAR; // the hand opens while it goes on rising and turning
	hs_hand_points_moved(hand);
	hand->state.wrist_pos = hs_v3(0, 0, 0.4);
	hand->state.wrist_rot = hs_quat_from_axis_angle(hs_v3(0, 0, 1), 40 * HS_PI / 180);
	hs_vec3 carried = hs_add(hs_quat_rotate(hand->state.wrist_rot, hs_v3(0, 0, 2)), hand->state.wrist_pos);
	hs_world_step(w);
	assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_NONE);
	// v = the hand's motion over the frame it let go in, (carried - last) / dt: let go in the
	// middle of that frame, it leaves the frame where the hand carried it
	assert_vec3_near(w->state.bodies[0].pos, carried, 1e-14);
	hs_vec3 v_dt = hs_sub(carried, w->state.bodies[0].prev); // prev: where the last held frame left it
	hs_world_step(w); // on the parabola of v + g dt / 2 at that frame's end: + v dt + g dt²
	assert_vec3_near(w->state.bodies[0].pos, hs_add(hs_add(carried, v_dt), hs_v3(0, 0, -9.81 / 3600)), 1e-14);
	assert_near(hs_quat_angle(w->state.bodies[0].spin), 10 * HS_PI / 180, 1e-12); // keeps turning
	hs_world_destroy(w);
}

// A held cube that the hand presses into the floor is lifted back by the floor (§4.2) and slides in
// the grip: lifted again, it rises from the floor's height, not from 0.1 below it.
static void test_grasp_slips_on_floor(void **state) {
	(void)state;
	hs_world_def def = hs_default_world_def();
	hs_world *w = rig_world(&def, hs_shape_box(hs_v3(1, 1, 1), NULL), hs_v3(0, 0, 0.5), hs_v3(0, 0, 0.5));
	hs_hand *hand = &w->state.hands[0];
	move_point(w, 3, hs_v3(-0.6, 0, 0.5), hs_v3(-0.45, 0, 0.5)); // two opposite faces: a grasp
	move_point(w, 7, hs_v3(0.6, 0, 0.5), hs_v3(0.45, 0, 0.5));
	hand->cache.points[0] = hand->cache.prev_points[0] = hs_v3(-0.45, 0, 5); // the fingers' bases, far above:
	hand->cache.points[4] = hand->cache.prev_points[4] = hs_v3(0.45, 0, 5);  // moved with the tips, no reach out
	hs_hand_points_moved(hand);
	hs_world_step(w);
	assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
	const double dz[2] = {-0.1, 0.3}; // the wrist and the tips press 0.1 down, then rise 0.3
	const double held[2] = {0.5, 0.8}; // G: kept on the floor, then 0.3 above it
	for (int k = 0; k < 2; ++k) {
		hand->state.wrist_pos = hs_v3(0, 0, hand->state.wrist_pos.z + dz[k]);
		move_point(w, 3, hand->cache.points[3], hs_add(hand->cache.points[3], hs_v3(0, 0, dz[k])));
		move_point(w, 7, hand->cache.points[7], hs_add(hand->cache.points[7], hs_v3(0, 0, dz[k])));
		move_point(w, 0, hand->cache.points[0], hs_add(hand->cache.points[0], hs_v3(0, 0, dz[k])));
		move_point(w, 4, hand->cache.points[4], hs_add(hand->cache.points[4], hs_v3(0, 0, dz[k])));
		hs_world_step(w);
		assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
		assert_vec3_near(w->state.bodies[0].pos, hs_v3(0, 0, held[k]), 1e-15);
	}
	hs_world_destroy(w);
}

// The thumb tip (3) and index tip (7) hold the cube at its ±x faces; the wrist and both tips move
// to u k + a k²/2 at frame k (u, a per frame), from frame 1 to `frames`, then the hand opens.
// Returns the release frame's index.
static int carry_path_and_release(hs_world *w, hs_vec3 u_dt, hs_vec3 a_dt2, int frames) {
	hs_hand *hand = &w->state.hands[0];
	move_point(w, 3, hs_v3(-0.6, 0, 2), hs_v3(-0.45, 0, 2));
	move_point(w, 7, hs_v3(0.6, 0, 2), hs_v3(0.45, 0, 2));
	hs_world_step(w);
	assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
	for (int k = 1; k <= frames; ++k) {
		hs_vec3 shift = hs_mul_add(hs_scale(u_dt, k), 0.5 * k * k, a_dt2);
		hand->state.wrist_pos = shift;
		hand->cache.points[3] = hs_add(hs_v3(-0.45, 0, 2), shift);
		hand->cache.points[7] = hs_add(hs_v3(0.45, 0, 2), shift);
		hs_hand_points_moved(hand);
		hand->cache.center = hs_add(hs_v3(0, 0, 2), shift);
		hs_world_step(w);
		assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
	}
	hand->cache.points[3] = hand->cache.points[7] = FAR; // the hand opens while it goes on moving
	hs_hand_points_moved(hand);
	hand->state.wrist_pos = hs_mul_add(hs_scale(u_dt, frames + 1), 0.5 * (frames + 1) * (frames + 1), a_dt2);
	return frames + 1;
}

static int carry_and_release(hs_world *w, hs_vec3 u_dt, int frames) {
	return carry_path_and_release(w, u_dt, hs_v3(0, 0, 0), frames);
}

// Release on a parabola, let go mid-frame: a cube carried at constant velocity u = (2, 0, 1) m/s
// by a hand that opens while moving on leaves the release frame where the hand carried it, at
// u + g dt / 2, so P(n + k) = P(n) + u k dt + g dt² (k - 1) k / 2 from its last held position
// P(n). That parabola peaks u_z²/(2g) + g dt²/8 above P(n) + u dt / 2, where the hand let it go
// half a frame into the release frame (the g dt²/8, 8.5 mm at 12 frames/s and 0.3 mm at 60, is
// the height it did not fall while the hand still held it; the last two held positions alone gave
// v_z - g dt/2: 0.0428 m at 60 frames/s). The peak is the vertex of the parabola through the three
// highest frames (exact for samples of a parabola).
static void test_release_on_exact_parabola(void **state) {
	(void)state;
	const double rates[] = {12, 17, 30, 60, 120}, g = 9.81;
	for (int r = 0; r < 5; ++r) {
		double dt = 1.0 / rates[r];
		hs_world *w = cube_world_dt(dt);
		hs_vec3 u = hs_v3(2, 0, 1);
		carry_and_release(w, hs_scale(u, dt), 6);
		hs_vec3 pn = w->state.bodies[0].pos; // the last held position: (0, 0, 2) + 6 u dt
		assert_vec3_near(pn, hs_add(hs_v3(0, 0, 2), hs_scale(u, 6 * dt)), 1e-14);
		double z[64];
		int n = (int)(0.3 / dt) + 2;
		for (int k = 1; k <= n; ++k) {
			hs_world_step(w);
			assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_NONE);
			double t = k * dt;
			hs_vec3 exact = hs_v3(pn.x + u.x * t, pn.y, pn.z + u.z * t - 0.5 * g * dt * dt * (k - 1) * k);
			assert_vec3_near(w->state.bodies[0].pos, exact, 1e-13);
			z[k] = w->state.bodies[0].pos.z;
		}
		int top = 1;
		for (int k = 2; k < n; ++k)
			top = z[k] > z[top] ? k : top;
		assert_true(top > 0 && top < n);
		double zm = top > 1 ? z[top - 1] : pn.z, zp = z[top + 1];
		double curve = zp - 2.0 * z[top] + zm, slope = 0.5 * (zp - zm);
		double peak = z[top] - slope * slope / (2.0 * curve) - (pn.z + 0.5 * u.z * dt);
		double expected = u.z * u.z / (2.0 * g) + g * dt * dt / 8.0;
		assert_near(peak, expected, 1e-9 * expected);
		hs_world_destroy(w);
	}
}

// The release estimators (hs_world_def.release_window_s, release_fit; docs/model.md §4 "Release").
// The cube carried by a wrist at u t + a t²/2 (t = k dt, k = 0 at the grasp) through frame
// `frames`, then let go in frame K = frames + 1, flies off with v: its position after the release
// step is P(K - 1) + v dt, where the hand carried it (let go mid-frame, at v + g dt / 2).
static hs_vec3 release_velocity(double dt, double window_s, hs_release_fit fit, hs_vec3 u, hs_vec3 a, int frames) {
	hs_world_def def = hs_default_world_def();
	def.dt = dt;
	def.release_window_s = window_s;
	def.release_fit = fit;
	hs_world *w = rig_world(&def, hs_shape_box(hs_v3(1, 1, 1), NULL), hs_v3(0, 0, 2), hs_v3(0, 0, 2));
	carry_path_and_release(w, hs_scale(u, dt), hs_scale(a, dt * dt), frames);
	hs_vec3 before = w->state.bodies[0].pos;
	assert_int_equal(hs_world_step(w), HS_OK);
	assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_NONE);
	hs_vec3 moved = hs_sub(w->state.bodies[0].pos, before);
	hs_world_destroy(w);
	return hs_scale(moved, 1.0 / dt);
}

// The window's frames as the library counts them: the nearest whole number, 1 to 64.
static int window_frames(double window_s, double dt) {
	double n = floor(window_s / dt + 0.5);
	return n < 1.0 ? 1 : n > HS_MAX_RELEASE_FRAMES ? HS_MAX_RELEASE_FRAMES : (int)n;
}

static const double release_rates[] = {12, 17, 30, 60, 120};
static const double release_windows[] = {0.0, 0.05, 0.1, 0.16}; // 0: one frame

// A hand at constant velocity releases with exactly that velocity, by either fit over any window.
static void test_release_constant_velocity(void **state) {
	(void)state;
	hs_vec3 u = hs_v3(2, -0.5, 1);
	for (int r = 0; r < 5; ++r)
		for (int k = 0; k < 4; ++k)
			for (int fit = HS_RELEASE_FIT_MEAN; fit <= HS_RELEASE_FIT_QUADRATIC; ++fit) {
				double dt = 1.0 / release_rates[r];
				int n = window_frames(release_windows[k], dt);
				hs_vec3 v = release_velocity(dt, release_windows[k], (hs_release_fit)fit, u, hs_v3(0, 0, 0), n + 2);
				assert_vec3_near(v, u, 1e-9);
			}
}

// A hand at constant acceleration a: the quadratic fit releases with the hand's velocity at the
// end of the release frame, u + a K dt, exactly (over 3 frames or more; the mean below that); the
// mean over n frames lags it by a n dt / 2, its velocity half a window before. A 0.5 s window at
// 240 frames/s is clamped to HS_MAX_RELEASE_FRAMES (64) frames: the hand keeps 63 older poses.
static void check_constant_acceleration(double dt, double window_s) {
	hs_vec3 u = hs_v3(2, -0.5, 1), a = hs_v3(3, 1, 2);
	int n = window_frames(window_s, dt), frames = n + 2, release = frames + 1;
	hs_vec3 exact = hs_mul_add(u, release * dt, a), mean = hs_mul_add(exact, -0.5 * n * dt, a);
	hs_vec3 v_mean = release_velocity(dt, window_s, HS_RELEASE_FIT_MEAN, u, a, frames);
	hs_vec3 v_quad = release_velocity(dt, window_s, HS_RELEASE_FIT_QUADRATIC, u, a, frames);
	assert_vec3_near(v_mean, mean, 1e-9);
	assert_vec3_near(v_quad, n >= 2 ? exact : mean, 1e-9);
}

static void test_release_constant_acceleration(void **state) {
	(void)state;
	for (int r = 0; r < 5; ++r)
		for (int k = 0; k < 4; ++k)
			check_constant_acceleration(1.0 / release_rates[r], release_windows[k]);
	assert_int_equal(window_frames(0.5, 1.0 / 240), HS_MAX_RELEASE_FRAMES);
	check_constant_acceleration(1.0 / 240, 0.5);
	assert_int_equal(hs_hand_older_capacity(0.5, 1.0 / 240), HS_MAX_RELEASE_FRAMES - 1);
	assert_int_equal(hs_hand_older_capacity(0.05, 1.0 / 120), HS_HAND_OLDER); // the default's 7
	assert_int_equal(hs_hand_older_capacity(0.16, 1.0 / 120), 18);             // 19 frames
}

// hs_world_create refuses a window outside [0, HS_MAX_RELEASE_WINDOW] and an unknown fit.
static void test_release_options_refused(void **state) {
	(void)state;
	const double bad[] = {-1e-9, HS_MAX_RELEASE_WINDOW * (1 + 1e-15), NAN, INFINITY};
	for (int k = 0; k < 4; ++k) {
		hs_world_def def = hs_default_world_def();
		def.release_window_s = bad[k];
		hs_status st = HS_OK;
		assert_null(hs_world_create(&def, &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	}
	const int fits[] = {-1, 3}; // below MEAN and past OBJECT
	for (int k = 0; k < 2; ++k) {
		hs_world_def def = hs_default_world_def();
		def.release_fit = (hs_release_fit)fits[k];
		hs_status st = HS_OK;
		assert_null(hs_world_create(&def, &st));
		assert_int_equal(st, HS_ERR_INVALID_ARGUMENT);
	}
	hs_world_def def = hs_default_world_def(); // the ends of the range are fine
	assert_true(def.release_window_s == 0.05 && def.release_fit == HS_RELEASE_FIT_MEAN);
	const double good[] = {0.0, HS_MAX_RELEASE_WINDOW};
	for (int k = 0; k < 2; ++k) {
		def.release_window_s = good[k];
		hs_world *w = hs_world_create(&def, NULL);
		assert_non_null(w);
		hs_world_destroy(w);
	}
}

// The catalog's pyramid (base 0.08, height 0.08: G 0.02 above the base) at (0, 0, 2), the grasp
// rule chosen, one hand far away (as cube_world).
static hs_world *pyramid_world(bool any_contacts) {
	hs_world_def def = hs_default_world_def();
	def.grasp_any_contacts = any_contacts;
	def.grasp_opposed = !any_contacts; // the paper's letter whole: no opposition asked either
	return rig_world(&def, hs_shape_pyramid(0.08, 0.08, NULL), hs_v3(0, 0, 2), hs_v3(0, 0, 2));
}

// docs/model.md §3 "Two fingers make a grasp": the DIP (6) and the tip (7) of one index finger sunk
// into the pyramid's +x side face (normal (2, 0, 1)/√5) and its base (normal -z), 116.6 deg apart
// (cos = -1/√5), do not grasp it by default: two contacts on one finger push at several points (3).
// With the paper's rule (grasp_any_contacts) they grasp it (2), and a rising wrist lifts it 0.2 m
// in two frames; by default the rising finger leaves it behind.
static void pyramid_by_one_finger(bool any_contacts) {
	hs_world *w = pyramid_world(any_contacts);
	hs_vec3 n = hs_scale(hs_v3(2, 0, 1), 1.0 / sqrt(5.0));
	hs_vec3 dip = hs_v3(0.025, 0, 2.0); // 4.5 mm inside the side face, 20 mm above the base
	move_point(w, 6, hs_mul_add(dip, 0.01, n), dip);
	move_point(w, 7, hs_v3(0.03, 0, 1.97), hs_v3(0.03, 0, 1.985)); // up through the base, 5 mm in
	hs_world_step(w);
	assert_int_equal(w->out.contact_count, 2);
	assert_near(hs_dot(w->out.contacts[0].normal, w->out.contacts[1].normal), -1.0 / sqrt(5.0), 1e-12);
	assert_int_equal(w->state.bodies[0].contact, any_contacts ? HS_CONTACT_GRASP : HS_CONTACT_PUSH_MANY);
	assert_int_equal(hs_contact_classify(w->out.contacts, 2, w->model.grasp_limit, any_contacts),
	                 any_contacts ? HS_CONTACT_GRASP : HS_CONTACT_PUSH_MANY);
	hs_hand *hand = &w->state.hands[0];
	hs_vec3 p0 = w->state.bodies[0].pos;
	for (int k = 1; k <= 2; ++k) { // the wrist and the finger rise 0.1 m a frame, out past the +x side
		hs_vec3 lift = hs_v3(0.1 * k, 0, 0.1 * k);
		hand->state.wrist_pos = lift;
		hand->cache.points[6] = hs_add(dip, lift);
		hand->cache.points[7] = hs_add(hs_v3(0.03, 0, 1.985), lift);
		hs_hand_points_moved(hand);
		hs_world_step(w);
		if (any_contacts) { // held: it follows the wrist
			assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
			assert_near(w->state.bodies[0].pos.z - p0.z, 0.1 * k, 1e-12);
			assert_near(w->state.bodies[0].pos.x - p0.x, 0.1 * k, 1e-12);
		} else { // shoved a few mm by the push, then left behind by the rising finger
			assert_int_not_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
			assert_true(w->state.bodies[0].pos.z - p0.z < 0.01);
		}
	}
	hs_world_destroy(w);
}

static void test_one_finger_does_not_grasp(void **state) {
	(void)state;
	pyramid_by_one_finger(false);
	pyramid_by_one_finger(true);
}

// Where a grasp continues the rule holds too: a held cube whose only contacts left are two
// points of one finger (the thumb's tip and IP joint, on faces 180 deg apart) is let go.
static void test_grasp_continues_on_two_fingers_only(void **state) {
	(void)state;
	hs_world *w = cube_world();
	move_point(w, 3, hs_v3(-0.6, 0, 2), hs_v3(-0.45, 0, 2)); // thumb tip in the -x face
	move_point(w, 7, hs_v3(0.6, 0, 2), hs_v3(0.45, 0, 2));   // index tip in the +x face
	hs_world_step(w);
	assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
	w->state.hands[0].cache.points[7] = FAR;
	hs_hand_points_moved(&w->state.hands[0]);
	w->state.hands[0].cache.prev_points[2] = hs_v3(0.6, 0.1, 2); // the thumb's IP joint in the +x face
	w->state.hands[0].cache.points[2] = hs_v3(0.45, 0.1, 2);
	hs_hand_points_moved(&w->state.hands[0]);
	hs_world_step(w);
	assert_int_not_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
	assert_int_equal(w->state.bodies[0].grasped_by, 0);
	hs_world_destroy(w);
}

// Hysteresis on the grasp's end (docs/model.md §3): the thumb tip (3) and index tip (7) 1 mm into
// the cube's -x and +x faces grasp it. The index tip 3 mm outside the +x face (the tips 4 mm
// further apart than at the grasp, within grasp_open_mm = 8; the thumb still touches): the grasp
// goes on, though only one contact is left. 11 mm apart: the hand has opened, the grasp ends,
// and the thumb that still touches does not push the cube (the release rule): state 0.
static void test_grasp_survives_a_contact_leaving(void **state) {
	(void)state;
	hs_world *w = cube_world();
	move_point(w, 3, hs_v3(-0.6, 0, 2), hs_v3(-0.499, 0, 2));
	move_point(w, 7, hs_v3(0.6, 0, 2), hs_v3(0.499, 0, 2));
	hs_world_step(w);
	assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
	move_point(w, 7, hs_v3(0.499, 0, 2), hs_v3(0.503, 0, 2));
	hs_world_step(w);
	assert_int_equal(w->out.contact_count, 1); // the thumb's
	assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
	assert_int_equal(w->state.bodies[0].grasped_by, 1);
	move_point(w, 7, hs_v3(0.503, 0, 2), hs_v3(0.510, 0, 2));
	hs_world_step(w);
	assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_NONE);
	assert_int_equal(w->state.bodies[0].grasped_by, 0);
	assert_int_equal(w->state.bodies[0].released_by, 1);
	for (int k = 0; k < 3; ++k) { // the thumb stays in the face: set aside, nothing pushes
		move_point(w, 7, hs_v3(0.510, 0, 2), hs_v3(0.510, 0, 2));
		hs_world_step(w);
		assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_NONE);
	}
	hs_world_destroy(w);
}

// A fast hand keeps its grasp: the fingers' motion is judged relative to the held object, which
// moves with the wrist. Sideways by 0.1 m a frame (6 m/s) — twice the cube's size — for 5 frames.
static void test_grasp_holds_fast_hand(void **state) {
	(void)state;
	hs_world *w = cube_world();
	hs_hand *hand = &w->state.hands[0];
	hand->state.wrist_pos = hs_v3(0, 0, 2);
	move_point(w, 3, hs_v3(-0.6, 0, 2), hs_v3(-0.45, 0, 2));
	move_point(w, 7, hs_v3(0.6, 0, 2), hs_v3(0.45, 0, 2));
	hs_world_step(w);
	assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
	for (int k = 1; k <= 5; ++k) {
		hs_vec3 shift = hs_v3(2.0 * k, 0, 0);
		hand->state.wrist_pos = hs_add(hs_v3(0, 0, 2), shift);
		hand->cache.points[3] = hs_add(hs_v3(-0.45, 0, 2), shift);
		hand->cache.points[7] = hs_add(hs_v3(0.45, 0, 2), shift);
		hs_hand_points_moved(hand);
		hand->cache.center = hs_add(hs_v3(0, 0, 2), shift);
		hs_world_step(w);
		assert_int_equal(w->state.bodies[0].contact, HS_CONTACT_GRASP);
		assert_vec3_near(w->state.bodies[0].pos, hs_add(hs_v3(0, 0, 2), shift), 1e-12);
	}
	hs_world_destroy(w);
}

// §4.3 paper mode: an object interfering with a moved object is translated with it.
static void test_paper_mode_carries_interfering(void **state) {
	(void)state;
	hs_world *w = cube_world();
	hs_object_def od = hs_default_object_def();
	od.shape = (hs_shape_id){1, w->model.tag, HS_GENERATION};
	od.position = hs_v3(0.95, 0, 2); // overlaps the first cube by 0.05
	hs_world_add_object(w, &od, NULL);
	move_point(w, 3, hs_v3(-0.6, 0, 2), hs_v3(-0.45, 0, 2)); // push the first cube by 0.05 along x
	hs_world_step(w);
	assert_vec3_near(w->state.bodies[0].pos, hs_v3(0.05, 0, 2), 1e-15);
	assert_vec3_near(w->state.bodies[1].pos, hs_v3(1.0, 0, 2), 1e-15);
	assert_true(w->state.bodies[1].carried);
	hs_world_destroy(w);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_point_enters_face),
	    cmocka_unit_test(test_point_inside_nearest_face),
	    cmocka_unit_test(test_fingertip_friction_cone),
	    cmocka_unit_test(test_touching_point_within_margin),
	    cmocka_unit_test(test_line_beside_touching_point),
	    cmocka_unit_test(test_trailing_part_set_aside),
	    cmocka_unit_test(test_trailing_part_same_frame),
	    cmocka_unit_test(test_point_at_edge_and_surface),
	    cmocka_unit_test(test_line_crosses_edge),
	    cmocka_unit_test(test_line_across_and_line_ending_inside),
	    cmocka_unit_test(test_hand_within_margin),
	    cmocka_unit_test(test_classification),
	    cmocka_unit_test(test_push_r_zero),
	    cmocka_unit_test(test_push_t_zero),
	    cmocka_unit_test(test_push_off_centre),
	    cmocka_unit_test(test_push_many_translates),
	    cmocka_unit_test(test_grasp_follow_release),
	    cmocka_unit_test(test_grasp_slips_on_floor),
	    cmocka_unit_test(test_grasp_holds_fast_hand),
	    cmocka_unit_test(test_release_on_exact_parabola),
	    cmocka_unit_test(test_release_constant_velocity),
	    cmocka_unit_test(test_release_constant_acceleration),
	    cmocka_unit_test(test_release_options_refused),
	    cmocka_unit_test(test_one_finger_does_not_grasp),
	    cmocka_unit_test(test_grasp_continues_on_two_fingers_only),
	    cmocka_unit_test(test_grasp_survives_a_contact_leaving),
	    cmocka_unit_test(test_paper_mode_carries_interfering),
	};
	return cmocka_run_group_tests_name("contact", tests, NULL, NULL);
}
