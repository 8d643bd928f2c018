// fault_soak.c — the randomized fault soak (make stress, make check-soak): no numeric fault is ever a
// normal outcome. Seeded random scenes, driven through the library's API as the tests drive it.
//
//   fault_soak FRAMES [SEED]    scenes from SEED (default 1) until FRAMES frames have run in all
//   fault_soak --scene S        only the scene whose own seed is S (as a fault's message names it)
//
// Each scene (GSL's mt19937: every run the same) runs 3-8 s at a frame rate drawn from
// 12-144 frames/s, three in four with the input noise on, the rest with the exact inputs as a
// catalog's nominal run has them (exact zeros arise there: a box dragged square into a block that
// stops it dead, which the noise never gives):
//  - a spring world (walled or open; some lined up along x) of 2-8 spheres, cubes and boxes of
//    random sizes and densities (a heavy block first), some dropped onto others; the stylus, with
//    the tracker's noise (0.03 inch and 0.15° RMS), drags objects into walls and other objects
//    (often the block, often along an axis, the spring level with G or from above) at 0.1-2 m/s,
//    lifts them and drops them onto others, throws them and follows them to catch them in flight;
//  - a hand world (paper or support stacking) of 3-8 cubes, boxes, pyramids, L-blocks and
//    ellipsoids; one hand with the glove's and tracker's noise (±4 units, 0.762 mm, 0.15°) pushes
//    them, grasps, carries and puts them down, and throws them.
// Each move is planned from where the objects lie when the last one ends. Before the fix of a
// dragged box stopped dead while it still counted as sliding (docs/model.md §8), 1,000,000 frames
// from seeds 1, 2 and 3 faulted in 3, 2 and 1 scenes.
// A fault: a step that returns an error, a non-finite value the world caught (it freezes the
// object and counts it), or any non-finite position, orientation, velocity, stylus or spring
// value. Prints frames, scenes, faults and the first fault (scene seed, frame rate, frame,
// object, quantity); exit status 1 on any fault. Nothing is allocated per frame: each scene
// allocates its world, its generators and its shapes when it starts.
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <gsl/gsl_rng.h>

#include "handspring.h"
#include "noise.h"

#define MAX_OBJECTS 8
#define MAX_KEYS 12
#define MAX_FAULT 400

typedef struct key {
	double t;     // s
	hs_vec3 p;    // pen (spring) or grip point (hand); ignored when `follow`
	double value; // spring: the button from this key on (> 0.5 down); hand: -1 open flat, 0 the
	              // widest grasp, 1 closed, blended to the next key
	int mode;     // how the way to this key goes: AT p, FOLLOW the object's G (a catch), STAY put
} key;

enum { AT, FOLLOW, STAY };

typedef struct scene {
	unsigned long seed;
	gsl_rng *rng;
	hs_noise *noise;
	hs_noise_options noise_options;
	hs_world *world;
	bool spring, noisy; // a spring or a hand world; with the input noise or the exact inputs
	bool row;           // objects on the floor lined up along x (drags along x meet them face on)
	double dt, reach; // frame time; how far from the middle objects are moved (the walls, if any)
	long frames;
	int count;
	hs_object_id id[MAX_OBJECTS];
	hs_vec3 half[MAX_OBJECTS]; // half extents of the bounding box at the start
	hs_object_state now[MAX_OBJECTS];
	key keys[MAX_KEYS];
	int key_count, segment, follow; // the keys of the move, the one last passed, the object followed
	hs_vec3 at, from; // where the pen or the grip point was last put, and where the segment began
	double value;     // its button or posture then
	// the hand
	hs_hand_id hand;
	hs_hand_def hand_def;
	hs_quat yaw;
	uint8_t open[HS_GLOVE_SENSORS], wide[HS_GLOVE_SENSORS], grasp[HS_GLOVE_SENSORS];
	hs_vec3 grip; // the grasp posture's grip centre, wrist frame
	// what has happened: the spring's last attach and release, each object's last contact state
	hs_attach_kind attach;
	double release_time;
	uint8_t contact[MAX_OBJECTS];
} scene;

typedef struct totals {
	long frames, scenes, faults, spring_scenes, hand_scenes, faulted_scenes;
	long picks, catches, throws, drops, grasps, pushes; // what the moves did (the soak's reach)
	unsigned long first_seed; // the first fault's scene
	char first[MAX_FAULT];
} totals;

static double uniform(gsl_rng *r, double lo, double hi) { return lo + (hi - lo) * gsl_rng_uniform(r); }
static int pick(gsl_rng *r, int n) { return (int)gsl_rng_uniform_int(r, (unsigned long)n); }
static double log_uniform(gsl_rng *r, double lo, double hi) { return lo * pow(hi / lo, gsl_rng_uniform(r)); }
static hs_vec3 flat(hs_vec3 v) { return hs_v3(v.x, v.y, 0.0); }

static void need(bool ok, const char *what) {
	if (!ok) {
		fprintf(stderr, "fault_soak: setup failed: %s\n", what);
		exit(2);
	}
}

// A horizontal unit direction at a random angle.
static hs_vec3 direction(gsl_rng *r) {
	double a = uniform(r, 0.0, 2.0 * HS_PI);
	return hs_v3(cos(a), sin(a), 0.0);
}

// ---------------------------------------------------------------------------------------------
// objects

static int add_object(scene *sc, hs_shape *shape, hs_vec3 half, hs_vec3 pos, hs_quat rot, double density) {
	need(shape != NULL, "shape");
	hs_status st = HS_OK;
	hs_shape_id sid = hs_world_add_shape(sc->world, shape, &st);
	hs_shape_destroy(shape);
	need(sid.index1 != 0, "add shape");
	hs_object_def od = hs_default_object_def();
	od.shape = sid;
	od.position = pos;
	od.orientation = rot;
	od.density = density;
	hs_object_id id = hs_world_add_object(sc->world, &od, &st);
	need(id.index1 != 0, "add object");
	sc->id[sc->count] = id;
	sc->half[sc->count] = half;
	return sc->count++;
}

// A spot on the floor (or, with `stack`, above another object) clear of the objects placed so far
// by their bounding spheres; false when none was found.
static bool find_spot(scene *sc, double reach, hs_vec3 half, bool stack, hs_vec3 *out) {
	double r = hs_length(half);
	for (int tries = 0; tries < 200; ++tries) {
		hs_vec3 p = hs_v3(uniform(sc->rng, -reach, reach), uniform(sc->rng, -reach, reach), half.z);
		if (sc->row && sc->count > 0) // lined up with the first object along x
			p.y = sc->now[0].position.y;
		if (stack && sc->count > 0) { // over another object, off centre, dropped from up to 0.5 m
			int j = pick(sc->rng, sc->count);
			hs_vec3 g = sc->now[j].position;
			p = hs_v3(g.x + uniform(sc->rng, -0.5, 0.5) * sc->half[j].x, g.y + uniform(sc->rng, -0.5, 0.5) * sc->half[j].y,
			          g.z + sc->half[j].z + r + uniform(sc->rng, 0.01, 0.5));
		}
		bool clear = true;
		for (int k = 0; k < sc->count && clear; ++k)
			clear = hs_distance(p, sc->now[k].position) > r + hs_length(sc->half[k]) + 0.002;
		if (clear) {
			*out = p;
			return true;
		}
	}
	return false;
}

static void spring_objects(scene *sc, double reach) {
	int n = 2 + pick(sc->rng, 7);
	for (int k = 0; k < n; ++k) {
		int kind = k == 0 ? 3 : pick(sc->rng, 3); // the first a heavy block
		hs_vec3 half;
		hs_shape *shape;
		double density = log_uniform(sc->rng, 50.0, 2000.0);
		if (kind == 0) {
			double r = uniform(sc->rng, 0.03, 0.12);
			half = hs_v3(r, r, r);
			shape = hs_shape_sphere(r, NULL);
		} else if (kind == 1 || kind == 3) {
			double s = kind == 3 ? uniform(sc->rng, 0.3, 0.5) : uniform(sc->rng, 0.05, 0.25);
			half = hs_v3(0.5 * s, 0.5 * s, 0.5 * s);
			shape = hs_shape_box(hs_scale(half, 2.0), NULL);
			density = kind == 3 ? uniform(sc->rng, 1000.0, 3000.0) : density;
		} else {
			half = hs_v3(uniform(sc->rng, 0.025, 0.2), uniform(sc->rng, 0.025, 0.2), uniform(sc->rng, 0.025, 0.1));
			shape = hs_shape_box(hs_scale(half, 2.0), NULL);
		}
		hs_vec3 p;
		if (!find_spot(sc, reach - hs_length(half), half, k > 0 && gsl_rng_uniform(sc->rng) < 0.3, &p)) {
			hs_shape_destroy(shape);
			continue;
		}
		int i = add_object(sc, shape, half, p, hs_quat_identity(), density);
		sc->now[i].position = p;
	}
}

// Hand-model objects of graspable size, on the floor, turned about z.
static void hand_objects(scene *sc) {
	int n = 3 + pick(sc->rng, 6);
	for (int k = 0; k < n; ++k) {
		double s = uniform(sc->rng, 0.035, 0.08);
		hs_vec3 half = hs_v3(0.5 * s, 0.5 * s, 0.5 * s);
		hs_shape *shape;
		switch (pick(sc->rng, 5)) {
		case 0: shape = hs_shape_box(hs_v3(s, s, s), NULL); break;
		case 1:
			half = hs_v3(0.5 * s, 0.35 * s, 0.4 * s);
			shape = hs_shape_box(hs_scale(half, 2.0), NULL);
			break;
		case 2: shape = hs_shape_pyramid(s, s, NULL); break;
		case 3:
			half = hs_v3(0.5 * s, 0.5 * s, 0.5 * s);
			shape = hs_shape_l_block(hs_v3(s, 0.5 * s, s), 0.3 * s, NULL);
			break;
		default:
			half = hs_v3(0.5 * s, 0.4 * s, 0.3 * s);
			shape = hs_shape_ellipsoid(half, NULL);
		}
		hs_vec3 p;
		if (!find_spot(sc, 0.3, half, false, &p)) {
			hs_shape_destroy(shape);
			continue;
		}
		p.z += 0.001; // 1 mm up (a pyramid or an L-block, whose G is not the box's centre, may drop further)
		int i = add_object(sc, shape, half, p, hs_quat_from_axis_angle(hs_v3(0, 0, 1), uniform(sc->rng, 0, HS_PI)), 500);
		sc->now[i].position = p;
	}
}

// ---------------------------------------------------------------------------------------------
// moves: a few keys from where the pen or hand is now, planned when the last move ends

static void add_key(scene *sc, double t, hs_vec3 p, double value, int mode) {
	if (sc->key_count < MAX_KEYS)
		sc->keys[sc->key_count++] = (key){t, p, value, mode};
}

// An object to move: one within reach (a thrown one may lie far away), or -1.
static int target(scene *sc, double reach) {
	for (int tries = 0; tries < 20; ++tries) {
		int i = pick(sc->rng, sc->count);
		hs_vec3 g = sc->now[i].position;
		if (fabs(g.x) < reach && fabs(g.y) < reach && g.z < 1.0)
			return i;
	}
	return -1;
}

// Spring moves: pick an object (the pen into its G, a press), then drag it into another object
// or a wall (or past where one would be), lift it over another and drop it there, or lift and
// throw it, sometimes following it to catch it in flight.
static void plan_spring(scene *sc, double t, double reach) {
	gsl_rng *r = sc->rng;
	sc->key_count = 0;
	sc->follow = -1;
	add_key(sc, t, sc->at, sc->value, AT);
	add_key(sc, t + 0.1, sc->at, 0.0, AT); // whatever hangs on the spring is let go first
	int i = target(sc, reach);
	if (i < 0) {
		add_key(sc, t + 0.5, sc->at, 0.0, AT);
		return;
	}
	hs_vec3 g = sc->now[i].position;
	add_key(sc, t + uniform(r, 0.2, 0.5), g, 0.0, AT);
	double t0 = sc->keys[sc->key_count - 1].t;
	add_key(sc, t0 + 0.1, g, 1.0, AT); // a direct pick
	t0 += 0.1;
	int j = gsl_rng_uniform(r) < 0.5 ? 0 : pick(r, sc->count), kind = pick(r, 3); // often the heavy block
	hs_vec3 other = sc->now[j].position;
	if (kind == 0) { // drag: into the other object, or along a random direction (a wall, if any)
		hs_vec3 d = j != i && gsl_rng_uniform(r) < 0.7 ? flat(hs_sub(other, g)) : direction(r);
		double len = hs_length(d) + uniform(r, 0.1, 0.6), v = uniform(r, 0.1, 2.0);
		if (gsl_rng_uniform(r) < 0.5) // along an axis: exactly into a face of an unturned box
			d = fabs(d.x) >= fabs(d.y) ? hs_v3(d.x < 0.0 ? -1.0 : 1.0, 0, 0) : hs_v3(0, d.y < 0.0 ? -1.0 : 1.0, 0);
		d = hs_length(d) > 1e-9 ? hs_scale(d, 1.0 / hs_length(d)) : hs_v3(1, 0, 0);
		hs_vec3 end = hs_mul_add(g, len, d);
		if (gsl_rng_uniform(r) < 0.5) { // the pen lowered by x0 first: the spring lies level with G
			hs_spring_object so;
			need(hs_world_spring_object(sc->world, sc->id[i], &so) == HS_OK, "spring object");
			hs_vec3 low = hs_v3(g.x, g.y, g.z - so.rest_length);
			add_key(sc, t0 + 0.3, hs_mul_add(low, so.rest_length, d), 1.0, AT);
			end = hs_mul_add(low, len, d);
			t0 += 0.3;
		}
		add_key(sc, t0 + len / v, end, 1.0, AT);
		add_key(sc, t0 + len / v + uniform(r, 0.2, 1.0), end, 1.0, AT);
	} else if (kind == 1) { // lift it over the other and drop it
		hs_vec3 up = hs_v3(g.x, g.y, g.z + uniform(r, 0.2, 0.6));
		hs_vec3 over = hs_v3(other.x, other.y, other.z + sc->half[j].z + uniform(r, 0.3, 0.8));
		add_key(sc, t0 + 0.5, up, 1.0, AT);
		add_key(sc, t0 + 0.5 + hs_distance(up, over) / uniform(r, 0.3, 1.5), over, 1.0, AT);
		double t1 = sc->keys[sc->key_count - 1].t + uniform(r, 0.2, 0.6);
		add_key(sc, t1, over, 1.0, AT);
		add_key(sc, t1 + 0.05, over, 0.0, AT);
		add_key(sc, t1 + 0.5, over, 0.0, AT);
	} else { // throw: lift, swing, let go while moving; then maybe follow it and press (a catch)
		hs_vec3 up = hs_v3(g.x, g.y, g.z + uniform(r, 0.3, 0.7)), d = direction(r);
		double v = uniform(r, 0.8, 4.0), swing = uniform(r, 0.2, 0.5);
		add_key(sc, t0 + 0.5, up, 1.0, AT);
		add_key(sc, t0 + 0.8, up, 1.0, AT);
		add_key(sc, t0 + 0.8 + swing / v, hs_mul_add(up, swing, d), 1.0, AT);
		add_key(sc, t0 + 0.8 + 2.0 * swing / v, hs_mul_add(up, 2.0 * swing, d), 0.0, AT);
		double t1 = sc->keys[sc->key_count - 1].t;
		if (gsl_rng_uniform(r) < 0.6) { // after it, then pressed inside it, then where it hangs
			sc->follow = i;
			add_key(sc, t1 + uniform(r, 0.05, 0.3), up, 1.0, FOLLOW);
			add_key(sc, sc->keys[sc->key_count - 1].t + uniform(r, 0.1, 0.4), up, 1.0, FOLLOW);
			add_key(sc, sc->keys[sc->key_count - 1].t + 0.5, up, 1.0, STAY);
		} else {
			add_key(sc, t1 + 0.5, hs_mul_add(up, 2.0 * swing, d), 0.0, AT);
		}
	}
}

// The grasp posture for an object `width` across, and its grip centre.
static void hand_width(scene *sc, double width) {
	need(hs_hand_posture(&sc->hand_def, HS_POSTURE_GRASP, width, sc->grasp) == HS_OK, "grasp posture");
	hs_vec3 axis;
	hs_hand_grip(&sc->hand_def, sc->grasp, &sc->grip, &axis);
}

// Hand moves, turned about z at random: a push through an object (the open hand or the widest
// grasp, 0.1-1 m/s), or a grasp from above that carries it to a free spot and puts it down, or
// one that lifts it, swings it at 1-3 m/s and opens while swinging (a throw).
static void plan_hand(scene *sc, double t) {
	gsl_rng *r = sc->rng;
	sc->key_count = 0;
	sc->follow = -1;
	sc->yaw = hs_quat_from_axis_angle(hs_v3(0, 0, 1), uniform(r, 0.0, 2.0 * HS_PI));
	add_key(sc, t, sc->at, sc->value, AT);
	int i = target(sc, 0.8);
	if (i < 0) {
		add_key(sc, t + 0.5, hs_add(sc->at, hs_v3(0, 0, 0.1)), -1.0, AT);
		return;
	}
	hs_vec3 g = sc->now[i].position, up = hs_v3(0, 0, 0.15), d = direction(r);
	double reach = hs_length(flat(sc->half[i]));
	hand_width(sc, fmin(0.1, 2.0 * fmax(sc->half[i].x, sc->half[i].y)));
	int kind = pick(r, 3);
	if (kind == 0) { // a push from beside it, on through it
		double posture = gsl_rng_uniform(r) < 0.5 ? -1.0 : 0.0, v = uniform(r, 0.1, 1.0), len = reach + uniform(r, 0.1, 0.3);
		hs_vec3 start = hs_mul_add(g, -(reach + 0.1), d);
		add_key(sc, t + 0.5, hs_add(start, up), posture, AT);
		add_key(sc, t + 0.8, start, posture, AT);
		add_key(sc, t + 0.8 + (len + 0.1) / v, hs_mul_add(g, len, d), posture, AT);
		add_key(sc, t + 1.2 + (len + 0.1) / v, hs_add(hs_mul_add(g, len, d), up), -1.0, AT);
		return;
	}
	add_key(sc, t + 0.5, hs_add(g, up), -1.0, AT); // above it, open
	add_key(sc, t + 0.7, hs_add(g, up), 0.0, AT);  // the widest grasp
	add_key(sc, t + 1.2, g, 0.0, AT);              // around it
	add_key(sc, t + 1.7, g, 1.0, AT);              // closed
	if (kind == 1) { // carry it to a free spot and put it down
		hs_vec3 to = hs_v3(uniform(r, -0.3, 0.3), uniform(r, -0.3, 0.3), g.z);
		add_key(sc, t + 2.7, hs_add(to, up), 1.0, AT);
		add_key(sc, t + 3.2, to, 1.0, AT);
		add_key(sc, t + 3.6, to, -1.0, AT);
		add_key(sc, t + 4.2, hs_add(to, up), -1.0, AT);
	} else { // lift, swing and open while swinging
		double v = uniform(r, 1.0, 3.0);
		hs_vec3 lift = hs_add(g, up);
		add_key(sc, t + 2.2, lift, 1.0, AT);
		add_key(sc, t + 2.2 + 0.3 / v, hs_mul_add(lift, 0.3, d), 1.0, AT);
		add_key(sc, t + 2.2 + 0.5 / v, hs_mul_add(lift, 0.5, d), -1.0, AT);
		add_key(sc, t + 2.7 + 0.5 / v, hs_add(hs_mul_add(lift, 0.5, d), up), -1.0, AT);
	}
}

// The pen or grip point and the button or posture at time t (the frame's end): along the move's
// keys, a new move planned when they are over.
static void input_at(scene *sc, double t, double reach) {
	if (sc->key_count == 0 || t >= sc->keys[sc->key_count - 1].t) {
		if (sc->spring)
			plan_spring(sc, t, reach);
		else
			plan_hand(sc, t);
		sc->segment = 0;
		sc->from = sc->at;
	}
	while (sc->segment + 1 < sc->key_count - 1 && t >= sc->keys[sc->segment + 1].t) {
		sc->segment++;
		sc->from = sc->at;
	}
	const key *a = &sc->keys[sc->segment], *b = &sc->keys[sc->segment + 1];
	double u = fmin(1.0, fmax(0.0, (t - a->t) / (b->t - a->t)));
	if (b->mode == FOLLOW) { // the object where it will be at the frame's end
		const hs_object_state *o = &sc->now[sc->follow];
		sc->at = hs_mul_add(o->position, sc->dt, o->velocity);
	} else if (b->mode == AT) {
		sc->at = hs_add(hs_scale(sc->from, 1.0 - u), hs_scale(b->p, u));
	}
	sc->value = sc->spring ? a->value : a->value + u * (b->value - a->value);
}

// ---------------------------------------------------------------------------------------------
// scenes

// A scene from its own seed: its kind, frame rate, world, objects, input and noise all follow.
static void scene_create(scene *sc, unsigned long seed) {
	memset(sc, 0, sizeof *sc);
	sc->seed = seed;
	sc->rng = gsl_rng_alloc(gsl_rng_mt19937);
	need(sc->rng != NULL, "generator");
	gsl_rng_set(sc->rng, seed);
	sc->spring = gsl_rng_uniform(sc->rng) < 0.5;
	sc->noisy = gsl_rng_uniform(sc->rng) < 0.75;
	sc->dt = 1.0 / uniform(sc->rng, 12.0, 144.0);
	sc->frames = lround(uniform(sc->rng, 3.0, 8.0) / sc->dt);
	sc->noise = hs_noise_create(gsl_rng_get(sc->rng));
	need(sc->noise != NULL, "noise");
	hs_world_def def = hs_default_world_def();
	def.dt = sc->dt;
	def.max_objects = def.max_shapes = MAX_OBJECTS;
	def.max_hands = 1;
	def.stacking = gsl_rng_uniform(sc->rng) < 0.5 ? HS_STACKING_PAPER : HS_STACKING_SUPPORT;
	double reach = 0.0;
	if (sc->spring) { // drawn before the world is made, in the order they always were
		hs_spring_def sd = hs_default_spring_def();
		reach = sc->reach = uniform(sc->rng, 0.6, 1.2);
		sd.walls = (hs_spring_walls){gsl_rng_uniform(sc->rng) < 0.7, -reach, reach, -reach, reach};
		sd.restitution = gsl_rng_uniform(sc->rng) < 0.5 ? 1.0 : uniform(sc->rng, 0.0, 1.0); // elastic: the default
		def.kind = HS_WORLD_SPRING;
		def.spring = sd;
	}
	hs_status st = HS_OK;
	sc->world = hs_world_create(&def, &st);
	need(sc->world != NULL, "world");
	if (sc->spring) {
		sc->row = gsl_rng_uniform(sc->rng) < 0.3;
		spring_objects(sc, reach);
		sc->noise_options = (hs_noise_options){.stylus = sc->noisy};
		sc->at = hs_v3(0.0, 0.0, 1.0);
		return;
	}
	hand_objects(sc);
	sc->hand_def = hs_default_hand_def();
	sc->hand = hs_world_add_hand(sc->world, &sc->hand_def, &st);
	need(sc->hand.index1 != 0, "hand");
	need(hs_hand_posture(&sc->hand_def, HS_POSTURE_OPEN, 0.0, sc->open) == HS_OK, "open posture");
	need(hs_hand_posture(&sc->hand_def, HS_POSTURE_GRASP, 0.12, sc->wide) == HS_OK, "wide posture");
	hand_width(sc, 0.05);
	if (sc->noisy)
		sc->noise_options = (hs_noise_options){.glove_units = 4, .wrist = 0.762e-3, .wrist_rotation = 0.15 * HS_PI / 180.0};
	sc->at = hs_v3(0.0, 0.0, 0.4);
	sc->reach = 0.8;
	sc->value = -1.0;
	sc->yaw = hs_quat_identity();
}

static void scene_destroy(scene *sc) {
	hs_world_destroy(sc->world);
	hs_noise_destroy(sc->noise);
	gsl_rng_free(sc->rng);
	memset(sc, 0, sizeof *sc);
}

// Hands the world this frame's input (its end), with the noise a real tracker and glove add.
static void scene_input(scene *sc, long frame) {
	input_at(sc, (double)(frame + 1) * sc->dt, sc->reach);
	if (sc->spring) {
		hs_vec3 p = sc->at;
		hs_quat q = hs_quat_identity();
		if (sc->noisy)
			hs_noise_stylus(sc->noise, &p, &q);
		need(hs_world_set_stylus(sc->world, p, q, sc->value > 0.5) == HS_OK, "set stylus");
		return;
	}
	uint8_t s[HS_GLOVE_SENSORS];
	const uint8_t *a = sc->wide, *b = sc->value < 0.0 ? sc->open : sc->grasp;
	double u = fabs(sc->value);
	for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
		s[i] = (uint8_t)lround((double)a[i] + u * ((double)b[i] - (double)a[i]));
	hs_vec3 wrist = hs_sub(sc->at, hs_quat_rotate(sc->yaw, sc->grip));
	hs_quat rot = sc->yaw;
	hs_noise_hand(sc->noise, &sc->noise_options, &wrist, &rot, s);
	need(hs_world_set_hand(sc->world, sc->hand, wrist, rot, s) == HS_OK, "set hand");
}

// ---------------------------------------------------------------------------------------------
// faults

static const char *kind_name(const scene *sc) { return sc->spring ? "spring" : "hand"; }

// Counts a fault; the first one's message is kept.
static void fault(totals *tot, const scene *sc, long frame, const char *what) {
	if (tot->faults++ == 0) {
		tot->first_seed = sc->seed;
		snprintf(tot->first, sizeof tot->first, "scene seed %lu (%s world, %.4g frames/s, %d objects), frame %ld: %s",
		         sc->seed, kind_name(sc), 1.0 / sc->dt, sc->count, frame, what);
	}
}

// The first non-finite quantity of the spring model's stylus and spring, or NULL.
static const char *spring_nonfinite(const scene *sc) {
	hs_spring_state ss;
	need(hs_world_spring_state(sc->world, &ss) == HS_OK, "spring state");
	if (!hs_vec3_is_finite(ss.anchor) || !isfinite(ss.length) || !isfinite(ss.extension))
		return "the spring's anchor or length";
	if (!hs_vec3_is_finite(ss.force))
		return "the spring's force";
	if (!hs_vec3_is_finite(ss.stylus_velocity))
		return "the stylus's velocity";
	return NULL;
}

// Reads every object's state after a step and checks the frame: the step's status, the faults the
// world caught (its first: frame and object), every value finite.
static void check_frame(totals *tot, scene *sc, long frame, hs_status step, long *caught) {
	char what[200];
	if (step != HS_OK) {
		snprintf(what, sizeof what, "the step returned %s", hs_status_string(step));
		fault(tot, sc, frame, what);
	}
	long faults = hs_world_get_counters(sc->world).numeric_faults;
	if (faults > *caught) {
		long at = -1;
		hs_object_id id = {0};
		hs_world_first_fault(sc->world, &at, &id);
		int i = 0;
		while (i < sc->count && sc->id[i].index1 != id.index1)
			++i;
		snprintf(what, sizeof what, "the world caught %ld non-finite value%s (its first in the step from frame %ld, object %d, frozen)",
		         faults - *caught, faults - *caught == 1 ? "" : "s", at, i < sc->count ? i : -1);
		fault(tot, sc, frame, what);
		tot->faults += faults - *caught - 1; // each one counts
		*caught = faults;
	}
	for (int i = 0; i < sc->count; ++i) {
		hs_object_state *o = &sc->now[i];
		need(hs_world_object_state(sc->world, sc->id[i], o) == HS_OK, "object state");
		const char *q = !hs_vec3_is_finite(o->position)     ? "position"
		                : !hs_quat_is_finite(o->orientation) ? "orientation"
		                : !hs_vec3_is_finite(o->velocity)    ? "velocity"
		                                                     : NULL;
		if (q) {
			snprintf(what, sizeof what, "object %d's %s is not finite", i, q);
			fault(tot, sc, frame, what);
		}
	}
	const char *q = sc->spring ? spring_nonfinite(sc) : NULL;
	if (q) {
		snprintf(what, sizeof what, "%s is not finite", q);
		fault(tot, sc, frame, what);
	}
}

// Counts what the frame's input did: attaches (picks, catches), releases (throws, drops), grasps
// and pushes begun.
static void count_events(totals *tot, scene *sc) {
	if (sc->spring) {
		hs_spring_state ss;
		hs_release rel;
		need(hs_world_spring_state(sc->world, &ss) == HS_OK && hs_world_spring_last_release(sc->world, &rel) == HS_OK,
		     "spring state");
		if (ss.attach_kind != sc->attach) {
			tot->picks += ss.attach_kind == HS_ATTACH_PICK;
			tot->catches += ss.attach_kind == HS_ATTACH_CATCH;
		}
		sc->attach = ss.attach_kind;
		if (rel.kind != HS_RELEASE_NONE && rel.time != sc->release_time) {
			tot->throws += rel.kind == HS_RELEASE_THROW;
			tot->drops += rel.kind == HS_RELEASE_DROP;
			sc->release_time = rel.time;
		}
		return;
	}
	for (int i = 0; i < sc->count; ++i) {
		uint8_t c = (uint8_t)sc->now[i].contact;
		if (c != sc->contact[i]) {
			tot->grasps += c == HS_CONTACT_GRASP;
			tot->pushes += c == HS_CONTACT_PUSH_ONE || c == HS_CONTACT_PUSH_MANY;
		}
		sc->contact[i] = c;
	}
}

// Runs one scene to its end; its frames and faults go to the totals.
static void run_scene(totals *tot, unsigned long seed) {
	scene sc;
	scene_create(&sc, seed);
	long caught = 0, before = tot->faults;
	check_frame(tot, &sc, 0, HS_OK, &caught); // the states the first move is planned from
	for (long f = 0; f < sc.frames; ++f) {
		scene_input(&sc, f);
		hs_status st = hs_world_step(sc.world);
		check_frame(tot, &sc, f + 1, st, &caught);
		count_events(tot, &sc);
	}
	tot->frames += sc.frames;
	tot->scenes++;
	tot->spring_scenes += sc.spring;
	tot->hand_scenes += !sc.spring;
	tot->faulted_scenes += tot->faults > before;
	scene_destroy(&sc);
}

int main(int argc, char **argv) {
	char *end = NULL;
	bool one = argc == 3 && strcmp(argv[1], "--scene") == 0;
	long frames = one ? 0 : argc >= 2 ? strtol(argv[1], &end, 10) : -1;
	unsigned long seed = one ? strtoul(argv[2], &end, 10) : argc == 3 ? strtoul(argv[2], &end, 10) : 1;
	if (argc < 2 || argc > 3 || (!one && frames <= 0) || (end && *end)) {
		fprintf(stderr, "usage: fault_soak FRAMES [SEED] | fault_soak --scene SCENE_SEED\n");
		return 2;
	}
	totals tot;
	memset(&tot, 0, sizeof tot);
	struct timespec t0, t1;
	clock_gettime(CLOCK_MONOTONIC, &t0);
	gsl_rng *master = gsl_rng_alloc(gsl_rng_mt19937);
	need(master != NULL, "generator");
	gsl_rng_set(master, seed);
	if (one)
		run_scene(&tot, seed);
	while (!one && tot.frames < frames)
		run_scene(&tot, gsl_rng_get(master));
	gsl_rng_free(master);
	clock_gettime(CLOCK_MONOTONIC, &t1);
	double seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
	printf("fault_soak (seed %lu): %ld frames, %ld scenes (%ld spring, %ld hand), %ld faults in %ld scenes, %.1f s\n", seed,
	       tot.frames, tot.scenes, tot.spring_scenes, tot.hand_scenes, tot.faults, tot.faulted_scenes, seconds);
	printf("  spring: %ld picks, %ld catches, %ld throws, %ld drops; hand: %ld grasps, %ld pushes begun\n", tot.picks,
	       tot.catches, tot.throws, tot.drops, tot.grasps, tot.pushes);
	if (tot.faults) {
		printf("fault_soak: first fault: %s\n", tot.first);
		printf("fault_soak: that scene alone: fault_soak --scene %lu\n", tot.first_seed);
		return 1;
	}
	return 0;
}
