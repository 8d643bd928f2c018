// soak_gen.c — writes the randomized determinism soak (scripts/determinism.sh): two scenario files
// generated from a fixed seed with GSL's mt19937, so every run writes the same text.
//
//   soak_gen OUTDIR [SEED [SECONDS]]   writes OUTDIR/hand.yaml and OUTDIR/spring.yaml, each at least
//                                      SECONDS long (default 62, at least 60) from seed SEED
//                                      (default 1999)
//
// hand.yaml: a dozen objects of every built-in hand-model shape (cube, box, pyramid, L-block,
//   ellipsoid, polyhedron: two of each) on the floor, and one hand that pokes them for SECONDS:
//   fingertip pushes and flicks from random directions and speeds (states 1 and 3), grasps that
//   carry an object to a free spot and put it down (state 2), and grasps that end in a throw.
// spring.yaml: a spring world (walls, tracker noise on: model.spring.noise_seed) with spheres,
//   cubes, boxes and a pyramid; the stylus picks objects (pen inside them), lifts and drops them,
//   drags them along the floor, throws them and sometimes catches them again in flight, for
//   SECONDS.
// The generator keeps an estimate of where each object is (its own closed forms: a pushed object
// moves by about the push, a placed or dropped one lands under the hand, a caught one is where
// the parabola says), so the pokes really reach objects; an object whose landing it cannot
// predict (a hand throw, a spring throw that is not caught) is not targeted again.
// No expectations: the soak is for per-frame hash comparison between builds, not for physics.
//
// Determinism of the text itself: the random numbers are mt19937's 32-bit integers (gsl_rng_get
// and gsl_rng_uniform, an exact scaling), the arithmetic is + - * / and sqrt (exactly rounded),
// directions come from a table of exact literals, and every number is printed rounded (%.6f
// or fewer digits), so the text does not depend on the compiler, its flags or libm.
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <math.h>

#include <gsl/gsl_rng.h>

#define G 9.81

static gsl_rng *rng;

static double uniform(double lo, double hi) { return lo + (hi - lo) * gsl_rng_uniform(rng); }
static int pick(int n) { return (int)gsl_rng_uniform_int(rng, (unsigned long)n); }
static bool chance(double p) { return gsl_rng_uniform(rng) < p; }
static double clampd(double x, double lo, double hi) { return x < lo ? lo : x > hi ? hi : x; }

// cos and sin of k * 15 deg, k = 0..23 (exact literals: no libm in the generator)
static const double COS15[24] = {1.0,
                                 0.96592582628906831,
                                 0.86602540378443865,
                                 0.70710678118654752,
                                 0.5,
                                 0.25881904510252076,
                                 0.0,
                                 -0.25881904510252076,
                                 -0.5,
                                 -0.70710678118654752,
                                 -0.86602540378443865,
                                 -0.96592582628906831,
                                 -1.0,
                                 -0.96592582628906831,
                                 -0.86602540378443865,
                                 -0.70710678118654752,
                                 -0.5,
                                 -0.25881904510252076,
                                 0.0,
                                 0.25881904510252076,
                                 0.5,
                                 0.70710678118654752,
                                 0.86602540378443865,
                                 0.96592582628906831};
static double cos15(int k) { return COS15[((k % 24) + 24) % 24]; }
static double sin15(int k) { return COS15[(((k - 6) % 24) + 24) % 24]; }

// the cube root by Newton's method (x > 0): + - * / only
static double cube_root(double x) {
	double y = x > 1.0 ? x : 1.0;
	for (int i = 0; i < 200; ++i) {
		double next = (2.0 * y + x / (y * y)) / 3.0;
		if (next >= y)
			break;
		y = next;
	}
	return y;
}

// ---------------------------------------------------------------------------------------------
// output

static FILE *out;
static const char *out_path;

static void emit(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static void emit(const char *fmt, ...) {
	va_list ap;
	va_start(ap, fmt);
	if (vfprintf(out, fmt, ap) < 0) {
		fprintf(stderr, "soak_gen: cannot write %s\n", out_path);
		exit(1);
	}
	va_end(ap);
}

static char *body;
static size_t body_size;

// The body (objects and keys) is written first, into memory: the duration, which goes before it,
// is known only when the keys are.
static void open_out(const char *dir, const char *name) {
	static char path[4096];
	if (snprintf(path, sizeof path, "%s/%s", dir, name) >= (int)sizeof path) {
		fprintf(stderr, "soak_gen: path too long\n");
		exit(2);
	}
	out_path = path;
	out = open_memstream(&body, &body_size);
	if (!out) {
		perror("open_memstream");
		exit(1);
	}
}

// writes the file: `header`, `duration: D`, then the body
static void close_out(const char *header, double duration) {
	if (fclose(out) != 0) {
		perror("open_memstream");
		exit(1);
	}
	out = fopen(out_path, "w");
	if (!out) {
		perror(out_path);
		exit(1);
	}
	emit("%sduration: %.2f\n", header, duration);
	if (fwrite(body, 1, body_size, out) != body_size || fclose(out) != 0) {
		perror(out_path);
		exit(1);
	}
	free(body);
	body = NULL;
}

// ---------------------------------------------------------------------------------------------
// objects and their estimated places

enum { MAX_OBJECTS = 16 };

typedef struct object {
	char name[32];
	double x, y;     // estimated G on the floor
	double z;        // G height at rest
	double half_min; // smallest horizontal half-extent (m)
	double half_max; // largest horizontal half-extent, any yaw (m)
	double height;   // full height (m)
	double grasp;    // grasp width for the hand, 0: not grasped
	double x0;       // spring rest length (spring world)
	bool lost;       // landing not predicted: not targeted again
} object;

static object objs[MAX_OBJECTS];
static int n_objs;

static bool spot_free(double x, double y, double clearance, int except) {
	for (int i = 0; i < n_objs; ++i) {
		if (i == except || objs[i].lost)
			continue;
		double dx = objs[i].x - x, dy = objs[i].y - y;
		if (dx * dx + dy * dy < clearance * clearance)
			return false;
	}
	return true;
}

// a free spot within [-xr, xr] x [-yr, yr], at least `clearance` from every other object
static void free_spot(double xr, double yr, double clearance, int except, double *x, double *y) {
	for (int tries = 0; tries < 1000; ++tries) {
		*x = uniform(-xr, xr);
		*y = uniform(-yr, yr);
		if (spot_free(*x, *y, clearance, except))
			return;
	}
	// crowded: accept the last draw (the soak stays valid, the poke may touch two objects)
}

static int live_target(void) {
	int live[MAX_OBJECTS], n = 0;
	for (int i = 0; i < n_objs; ++i)
		if (!objs[i].lost)
			live[n++] = i;
	return n ? live[pick(n)] : -1;
}

static int live_count(void) {
	int n = 0;
	for (int i = 0; i < n_objs; ++i)
		n += !objs[i].lost;
	return n;
}

// ---------------------------------------------------------------------------------------------
// hand.yaml

static double t_now;
static double soak_seconds = 62.0; // each soak runs at least this long (s)

// wrist from the index tip for the `point` posture at rpy [0, 30, yaw]: tip - Rz(yaw) (0.15588457,
// 0.025, -0.09) (scenarios/hand/push_off_centre.yaml: the tip sits there in the wrist frame)
static void point_key(double t, double tx, double ty, double tz, int k) {
	double ox = 0.15588457, oy = 0.025, oz = -0.09;
	double wx = tx - (cos15(k) * ox - sin15(k) * oy);
	double wy = ty - (sin15(k) * ox + cos15(k) * oy);
	emit("      - { t: %.4f, wrist: [%.6f, %.6f, %.6f], rpy_deg: [0, 30, %d], posture: point }\n", t, wx, wy, tz - oz,
	     15 * k);
}

static void hand_push(int i, bool flick) {
	object *o = &objs[i];
	int k = pick(24);
	double ux = cos15(k), uy = sin15(k);
	double lateral = uniform(-0.6, 0.6) * o->half_min;
	double nx = -uy * lateral, ny = ux * lateral;
	// tip height: within the object's lower part, clear of the floor by the finger radius
	double tz = clampd(uniform(0.3, 0.8) * o->height, 0.012, o->height - 0.005);
	double push = flick ? uniform(0.005, 0.02) : uniform(0.02, 0.07);
	double speed = flick ? uniform(0.8, 1.6) : uniform(0.1, 0.5);
	double start = o->half_max + 0.05;
	double sx = o->x - start * ux + nx, sy = o->y - start * uy + ny;
	double ex = o->x + (push - o->half_min) * ux + nx, ey = o->y + (push - o->half_min) * uy + ny;
	double travel = start + push - o->half_min;
	emit("      # %s %s from %d deg, %.3f m at %.2f m/s\n", flick ? "flick" : "push", o->name, 15 * k, push, speed);
	point_key(t_now += uniform(0.4, 0.8), sx, sy, tz + 0.2, k);   // above the start
	point_key(t_now += uniform(0.3, 0.5), sx, sy, tz, k);         // down
	point_key(t_now += travel / speed, ex, ey, tz, k);            // the stroke
	if (flick) // the tip rises away at the end of a flick
		point_key(t_now += 0.1, ex + 0.02 * ux, ey + 0.02 * uy, tz + 0.12, k);
	else {
		point_key(t_now += uniform(0.05, 0.3), ex, ey, tz, k);                // hold
		point_key(t_now += 0.3, ex - 0.08 * ux, ey - 0.08 * uy, tz + 0.02, k); // draw back
	}
	point_key(t_now += 0.3, ex - 0.08 * ux, ey - 0.08 * uy, tz + 0.25, k);     // up
	// open the hand up there: a grasp the stroke made by chance ends (the object drops)
	emit("      - { t: %.4f, posture: open }\n", t_now += 0.1);
	o->x += push * ux;
	o->y += push * uy;
}

#define OPEN (-1.0) // grip_key's width for the open hand

// the grip centre at (x, y, z) with the wrist unrotated: thumb on -x, fingertips on +x
static void grip_key(double t, double x, double y, double z, double width) {
	if (width == OPEN)
		emit("      - { t: %.4f, grip: [%.6f, %.6f, %.6f], rpy_deg: [0, 0, 0], posture: open }\n", t, x, y, z);
	else
		emit("      - { t: %.4f, grip: [%.6f, %.6f, %.6f], rpy_deg: [0, 0, 0], posture: { grasp: %.4f } }\n", t, x, y, z,
		     width);
}

static void hand_grasp(int i, bool do_throw) {
	object *o = &objs[i];
	double w = o->grasp;
	emit("      # grasp %s (width %.4f) and %s\n", o->name, w, do_throw ? "throw it" : "put it down elsewhere");
	grip_key(t_now += uniform(0.4, 0.8), o->x, o->y, o->z + 0.2, 0.12); // above, open wide
	grip_key(t_now += uniform(0.4, 0.6), o->x, o->y, o->z + 0.01, 0.12); // down around it
	grip_key(t_now += 0.1, o->x, o->y, o->z + 0.01, 0.12);
	grip_key(t_now += 0.01, o->x, o->y, o->z, w); // close within one frame
	grip_key(t_now += 0.1, o->x, o->y, o->z, w);
	double lx = o->x, ly = o->y, lz = o->z + uniform(0.1, 0.2);
	grip_key(t_now += uniform(0.3, 0.6), lx, ly, lz, w); // lift
	if (!do_throw) {
		double x, y;
		free_spot(0.55, 0.4, 0.2, i, &x, &y);
		double d = sqrt((x - lx) * (x - lx) + (y - ly) * (y - ly));
		grip_key(t_now += d / uniform(0.2, 0.6) + 0.05, x, y, lz, w); // carry
		grip_key(t_now += 0.4, x, y, o->z, w);                        // put down
		grip_key(t_now += 0.2, x, y, o->z, w);                        // hold still: a release at rest
		// open in place (a key without `grip` keeps the wrist; with it, the open hand's other grip
		// centre would move the wrist and the fingers could close on the object again)
		emit("      - { t: %.4f, posture: open }\n", t_now += 0.01);
		emit("      - { t: %.4f }\n", t_now += 0.1);
		grip_key(t_now += 0.3, x, y, o->z + 0.25, OPEN); // away, up
		o->x = x;
		o->y = y;
		return;
	}
	// wind up against the throw direction, swing at 2 to 3.5 m/s and open while moving
	int k = pick(24);
	double ux = cos15(k), uy = sin15(k);
	double speed = uniform(2.0, 3.5), up = uniform(0.4, 1.0);
	double norm = sqrt(1.0 + up * up);
	double vx = speed * ux / norm, vy = speed * uy / norm, vz = speed * up / norm;
	double ax = lx - 0.12 * ux, ay = ly - 0.12 * uy, az = lz;
	grip_key(t_now += 0.3, ax, ay, az, w); // wind up
	grip_key(t_now += 0.1, ax, ay, az, w);
	double ts = 0.12;
	double rx = ax + vx * ts, ry = ay + vy * ts, rz = az + vz * ts;
	emit("      # throw toward %d deg at %.2f m/s\n", 15 * k, speed);
	grip_key(t_now += ts, rx, ry, rz, w);                                               // swing
	emit("      - { t: %.4f, posture: open }\n", t_now += 0.01); // open (the wrist stops in place)
	grip_key(t_now += 0.15, rx + 0.16 * vx, ry + 0.16 * vy, rz + 0.16 * vz + 0.05, OPEN); // follow through
	grip_key(t_now += 0.3, rx + 0.2 * vx, ry + 0.2 * vy, rz + 0.3, OPEN);              // stop
	o->lost = true;
}

static void add_hand_object(const char *shape, int serial) {
	object *o = &objs[n_objs];
	snprintf(o->name, sizeof o->name, "%s%d", shape, serial);
	o->grasp = 0;
	o->lost = false;
	// a 4 x 3 grid, 0.3 m apart, jittered
	int cell = n_objs;
	o->x = -0.45 + 0.3 * (cell % 4) + uniform(-0.03, 0.03);
	o->y = -0.3 + 0.3 * (cell / 4) + uniform(-0.03, 0.03);
	double yaw = uniform(0, 90);
	emit("  - { name: %s, shape: %s, ", o->name, shape);
	if (strcmp(shape, "cube") == 0) {
		double s = uniform(0.04, 0.07);
		emit("size: %.4f, ", s);
		o->z = s / 2;
		o->height = s;
		o->half_min = s / 2;
		o->half_max = s * 0.7072;
		o->grasp = 0.8 * s;
	} else if (strcmp(shape, "box") == 0) {
		double a = uniform(0.04, 0.08), b = uniform(0.04, 0.09), c = uniform(0.03, 0.08);
		emit("size: [%.4f, %.4f, %.4f], ", a, b, c);
		o->z = c / 2;
		o->height = c;
		o->half_min = (a < b ? a : b) / 2;
		o->half_max = sqrt(a * a + b * b) / 2 + 1e-4;
		o->grasp = 0.8 * (a < b ? a : b);
	} else if (strcmp(shape, "pyramid") == 0) {
		double b = uniform(0.05, 0.08), h = uniform(0.04, 0.08);
		emit("size: [%.4f, %.4f], ", b, h);
		o->z = h / 4;
		o->height = h;
		o->half_min = 0.375 * b; // the section at G's height
		o->half_max = b * 0.7072;
		o->grasp = 0.8 * 0.75 * b;
	} else if (strcmp(shape, "l_block") == 0) {
		double x = uniform(0.06, 0.09), y = uniform(0.04, 0.07), z = uniform(0.06, 0.09), th = uniform(0.02, 0.03);
		emit("size: [%.4f, %.4f, %.4f], thickness: %.4f, ", x, y, z, th);
		double vf = x * y * th, vu = th * y * (z - th);
		o->z = (vf * th / 2 + vu * (th + (z - th) / 2)) / (vf + vu);
		o->height = z;
		o->half_min = (x < y ? x : y) / 2;
		o->half_max = sqrt(x * x + y * y) / 2 + 0.03; // G is off the box centre
		o->grasp = 0;                                   // pushed only
	} else if (strcmp(shape, "ellipsoid") == 0) {
		double a = uniform(0.025, 0.04), b = uniform(0.025, 0.04), c = uniform(0.02, 0.035);
		emit("size: [%.4f, %.4f, %.4f], ", a, b, c);
		o->z = c;
		o->height = 2 * c;
		o->half_min = 0.9 * (a < b ? a : b);
		o->half_max = a > b ? a : b;
		o->grasp = 0.8 * 2 * (a < b ? a : b);
	} else { // polyhedron: a prism over a random convex n-gon (the vertices on a circle)
		int n = 3 + pick(6);
		double r = uniform(0.025, 0.045), h = uniform(0.03, 0.07);
		emit("\n      vertices: [");
		// corner angles: multiples of 15 deg, as evenly spread as 24 allows (the object's yaw turns it)
		int k[8];
		for (int j = 0; j < n; ++j)
			k[j] = (24 * j) / n;
		for (int layer = 0; layer < 2; ++layer)
			for (int j = 0; j < n; ++j)
				emit("%s[%.6f, %.6f, %.6f]", layer + j ? ", " : "", r * cos15(k[j]), r * sin15(k[j]), layer ? h : 0.0);
		emit("],\n      faces: [[");
		for (int j = n - 1; j >= 0; --j)
			emit("%s%d", j == n - 1 ? "" : ", ", j); // bottom
		emit("], [");
		for (int j = 0; j < n; ++j)
			emit("%s%d", j ? ", " : "", n + j); // top
		emit("]");
		for (int j = 0; j < n; ++j)
			emit(", [%d, %d, %d, %d]", j, (j + 1) % n, n + (j + 1) % n, n + j); // sides
		emit("],\n      ");
		o->z = h / 2;
		o->height = h;
		o->half_min = 0.5 * r; // an inscribed circle of a triangle
		o->half_max = r;
		o->grasp = 0.8 * r;
	}
	if (o->grasp > 0)
		o->grasp = clampd(o->grasp, 0.01, 0.12);
	emit("position: [%.6f, %.6f, %.6f], rpy_deg: [0, 0, %.3f] }\n", o->x, o->y, o->z, yaw);
	++n_objs;
}

static void write_hand(const char *dir, unsigned long seed) {
	char header[1024];
	snprintf(header, sizeof header,
	         "# Generated by tests/soak_gen.c (seed %lu): the randomized determinism soak of the hand model.\n"
	         "# Do not edit: scripts/determinism.sh regenerates it. No expectations: the builds' per-frame\n"
	         "# state hashes are compared instead.\n"
	         "description: randomized soak, a hand pushes, flicks, grasps, carries and throws a dozen objects\n"
	         "dt: 1/60\n",
	         seed);
	open_out(dir, "hand.yaml");
	n_objs = 0;
	t_now = 0;
	emit("model: { grasp_threshold_deg: 90, stacking: paper }\n");
	emit("objects:\n");
	static const char *const shapes[6] = {"cube", "box", "pyramid", "l_block", "ellipsoid", "polyhedron"};
	for (int i = 0; i < 12; ++i)
		add_hand_object(shapes[i % 6], i / 6 + 1);
	emit("hands:\n  - name: right\n    keys:\n");
	grip_key(0.0, 0, -0.6, 0.3, 0.12);
	while (t_now < soak_seconds) {
		int i = live_target();
		if (i < 0)
			break;
		double r = gsl_rng_uniform(rng);
		if (objs[i].grasp > 0 && r < 0.3)
			hand_grasp(i, chance(0.35) && live_count() > 8); // at most four throws
		else
			hand_push(i, r > 0.8);
	}
	grip_key(t_now += 0.5, 0, -0.6, 0.3, 0.12);
	close_out(header, t_now + 1.0);
}

// ---------------------------------------------------------------------------------------------
// spring.yaml

static void stylus_key(double t, double x, double y, double z, const char *button) {
	emit("    - { t: %.4f, position: [%.6f, %.6f, %.6f]%s%s }\n", t, x, y, z, button ? ", button: " : "", button ? button : "");
}

#define WALL_X 1.0
#define WALL_Y 0.6

static void spring_release_spot(int except, double *x, double *y) { free_spot(WALL_X - 0.25, WALL_Y - 0.2, 0.25, except, x, y); }

static double sx, sy, sz; // where the stylus is

static void stylus_to(double x, double y, double z, double speed, const char *button) {
	double d = sqrt((x - sx) * (x - sx) + (y - sy) * (y - sy) + (z - sz) * (z - sz));
	t_now += d / speed + 0.05;
	stylus_key(t_now, x, y, z, button);
	sx = x;
	sy = y;
	sz = z;
}

static void stylus_hold(double seconds, const char *button) {
	t_now += seconds;
	stylus_key(t_now, sx, sy, sz, button);
}

// hanging below the stylus at rest: G = stylus - 1.2 x0 (a hanging object stretches its spring by
// 20 % of x0); the drop lands right below
static void spring_drop_at(int i, double x, double y) {
	object *o = &objs[i];
	double hz = clampd(o->z + 1.2 * o->x0 + uniform(0.05, 0.25), 0.25, 0.6);
	stylus_to(sx, sy, hz, uniform(0.3, 0.6), NULL);                 // lift
	stylus_to(x, y, hz, uniform(0.3, 0.8), NULL);                   // carry
	stylus_hold(uniform(1.2, 1.8), NULL);                           // the swing dies out
	stylus_hold(0.02, "false");                                     // at rest: a drop
	stylus_to(x, y, hz + 0.1, 0.5, NULL);
	o->x = x;
	o->y = y;
}

static void spring_action(int i) {
	object *o = &objs[i];
	double r = gsl_rng_uniform(rng);
	if (r >= 0.6 && live_count() <= 5)
		r *= 0.5; // keep most objects in play: no throws once three may be lost
	emit("    # %s %s\n", r < 0.35 ? "pick, lift, carry and drop" : r < 0.6 ? "drag along the floor" : "pick and throw", o->name);
	stylus_to(o->x, o->y, 0.4, uniform(0.5, 1.0), NULL);   // above it
	stylus_to(o->x, o->y, o->z, uniform(0.3, 0.6), NULL);  // into it
	stylus_hold(uniform(0.2, 0.4), "true");                // press: direct pick
	if (r < 0.35) {
		double x, y;
		spring_release_spot(i, &x, &y);
		spring_drop_at(i, x, y);
		return;
	}
	if (r < 0.6) { // drag: the pen stays at the object's height and pulls it across the floor
		double x, y;
		spring_release_spot(i, &x, &y);
		stylus_hold(0.3, NULL);
		stylus_to(x, y, o->z, uniform(0.1, 0.4), NULL);
		stylus_hold(uniform(1.0, 1.5), NULL);
		stylus_hold(0.02, "false");
		stylus_to(x, y, 0.4, 0.5, NULL);
		o->x = x;
		o->y = y;
		return;
	}
	// throw: lift, wind up, a straight 0.4-0.6 s swing released on arrival (the tracker's fit is
	// exact on a straight line at constant speed), then, most of the time, a catch in flight
	double hz = 0.25;
	stylus_to(sx, sy, hz, 0.5, NULL);
	double ax = clampd(sx, -0.5, 0.5), ay = clampd(sy, -0.3, 0.3);
	stylus_to(ax, ay, hz, 0.5, NULL);
	stylus_hold(uniform(0.8, 1.2), NULL);
	int k = pick(24);
	double vh = uniform(0.2, 0.6), vz = uniform(0.8, 1.3), ts = uniform(0.4, 0.6);
	double vx = vh * cos15(k), vy = vh * sin15(k);
	double rx = ax + vx * ts, ry = ay + vy * ts, rz = hz + vz * ts;
	t_now += ts;
	stylus_key(t_now, rx, ry, rz, "false"); // released while moving: a throw
	sx = rx;
	sy = ry;
	sz = rz;
	// free flight from G0 = R - 1.2 x0 (the hanging object, to within its lag) at v
	double gz = rz - 1.2 * o->x0;
	double tau = uniform(0.3, 0.45);
	double cx = rx + vx * tau, cy = ry + vy * tau, cz = gz + vz * tau - 0.5 * G * tau * tau;
	if (cz > o->z + 0.1 && chance(0.7)) {
		emit("    # catch %s in flight\n", o->name);
		t_now += tau - 0.1;
		stylus_key(t_now, cx, cy, cz, NULL);
		t_now += 0.1;
		stylus_key(t_now, cx, cy, cz, "true"); // press as it passes: a catch
		sx = cx;
		sy = cy;
		sz = cz;
		stylus_hold(uniform(1.0, 1.5), NULL);
		double x, y;
		spring_release_spot(i, &x, &y);
		spring_drop_at(i, x, y);
		return;
	}
	stylus_to(sx, sy, 0.45, 0.8, NULL);
	o->lost = true;
}

static void add_spring_object(const char *shape, int serial) {
	object *o = &objs[n_objs];
	snprintf(o->name, sizeof o->name, "%s%d", shape, serial);
	o->lost = false;
	int cell = n_objs;
	o->x = -0.6 + 0.4 * (cell % 4) + uniform(-0.05, 0.05);
	o->y = -0.25 + 0.5 * (cell / 4) + uniform(-0.05, 0.05);
	double density = uniform(300, 1500), volume;
	emit("  - { name: %s, shape: %s, ", o->name, shape);
	if (strcmp(shape, "sphere") == 0) {
		double r = uniform(0.03, 0.06);
		emit("size: %.4f, ", r);
		o->z = r;
		volume = 4.0 / 3.0 * 3.14159265358979324 * r * r * r;
	} else if (strcmp(shape, "cube") == 0) {
		double s = uniform(0.05, 0.1);
		emit("size: %.4f, ", s);
		o->z = s / 2;
		volume = s * s * s;
	} else if (strcmp(shape, "box") == 0) {
		double a = uniform(0.05, 0.12), b = uniform(0.05, 0.12), c = uniform(0.04, 0.08);
		emit("size: [%.4f, %.4f, %.4f], ", a, b, c);
		o->z = c / 2;
		volume = a * b * c;
	} else { // pyramid
		double b = uniform(0.06, 0.1), h = uniform(0.05, 0.09);
		emit("size: [%.4f, %.4f], ", b, h);
		o->z = h / 4;
		volume = b * b * h / 3;
	}
	// the printed size is rounded: the mass (and x0) differ from these by 1e-4 relative at most
	double mass = density * volume;
	o->x0 = clampd(0.1 * cube_root(mass), 0.01, 1.0); // README: x0 = 0.10 m (m / 1 kg)^(1/3)
	emit("density: %.1f, position: [%.6f, %.6f, %.6f] }\n", density, o->x, o->y, o->z);
	++n_objs;
}

static void write_spring(const char *dir, unsigned long seed) {
	char header[1024];
	snprintf(header, sizeof header,
	         "# Generated by tests/soak_gen.c (seed %lu): the randomized determinism soak of the spring model.\n"
	         "# Do not edit: scripts/determinism.sh regenerates it. No expectations: the builds' per-frame\n"
	         "# state hashes are compared instead.\n"
	         "description: randomized soak, the stylus picks, drags, drops, throws and catches objects, tracker noise on\n"
	         "dt: 1/60\n",
	         seed);
	open_out(dir, "spring.yaml");
	n_objs = 0;
	t_now = 0;
	emit("model: { spring: { walls: [%.1f, %.1f, %.1f, %.1f], noise_seed: %lu } }\n", -WALL_X, WALL_X, -WALL_Y, WALL_Y,
	     gsl_rng_get(rng) % 1000000);
	emit("objects:\n");
	static const char *const shapes[8] = {"sphere", "cube", "box", "sphere", "pyramid", "box", "sphere", "cube"};
	for (int i = 0; i < 8; ++i)
		add_spring_object(shapes[i], i + 1);
	emit("stylus:\n  keys:\n");
	sx = 0;
	sy = 0;
	sz = 0.45;
	stylus_key(0.0, sx, sy, sz, NULL);
	while (t_now < soak_seconds) {
		int i = live_target();
		if (i < 0)
			break;
		spring_action(i);
	}
	stylus_hold(0.5, NULL);
	close_out(header, t_now + 1.0);
}

static bool read_number(const char *text, const char *what, unsigned long *value) {
	char *end;
	*value = strtoul(text, &end, 10);
	if (*text == '\0' || *text == '-' || *end != '\0') {
		fprintf(stderr, "soak_gen: the %s must be a decimal integer, got %s\n", what, text);
		return false;
	}
	return true;
}

int main(int argc, char **argv) {
	if (argc < 2 || argc > 4) {
		fprintf(stderr, "usage: soak_gen OUTDIR [SEED [SECONDS]]\n");
		return 2;
	}
	unsigned long seed = 1999, seconds = 62;
	if (argc >= 3 && !read_number(argv[2], "seed", &seed))
		return 2;
	if (argc >= 4 && (!read_number(argv[3], "length in seconds", &seconds) || seconds < 60 || seconds > 100000)) {
		fprintf(stderr, "soak_gen: the length must be within [60, 100000] s, got %s\n", argv[3]);
		return 2;
	}
	soak_seconds = (double)seconds;
	rng = gsl_rng_alloc(gsl_rng_mt19937);
	if (!rng) {
		fprintf(stderr, "soak_gen: out of memory\n");
		return 1;
	}
	gsl_rng_set(rng, seed);
	write_hand(argv[1], seed);
	gsl_rng_set(rng, seed + 1);
	write_spring(argv[1], seed);
	gsl_rng_free(rng);
	return 0;
}
