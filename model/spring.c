// spring.c — the spring model of "Dynamics in Interaction on the Responsive Workbench" (§4–§5).
//
// A tracked stylus moves objects through a critically damped spring attached at the centre of mass
// (§4.2, §4.4). Forces act at G only (no torque, objects keep their orientation): gravity, the
// spring, its damper, the ground's normal force, friction (§4.2), the walls (§4.5).
//
// Readings fixed here (DESIGN.md "Spring model" leaves them to us):
//  - Rest length (§4.2: "calculated automatically from the mass ... for heavy objects a stronger
//    and longer spring"): x0(m) = x0_ref (m / m_ref)^p, default 0.10 m · (m / 1 kg)^(1/3), clamped to
//    [0.01 m, 1.0 m]. The cube root makes the spring grow like the object's size at fixed density;
//    the clamp spans exactly 1 g (1 cm) to 1000 kg (1 m). k = m g / (0.2 x0) (§4.2: hanging
//    stretches the spring by 20 % of x0), so ω = √(k/m) = √(g / 0.2 x0) (22 rad/s at 1 kg) and
//    c = 2 √(k m) (§4.3, critical). g is |world gravity| (9.81 m/s² in a world without gravity).
//  - The spring is a 3D spring of rest length x0 between the stylus point S and G. Within a frame
//    it is linearised about its state at the frame start (direction u = (G − S)/|G − S|, length L):
//    along u it has stiffness k and damping c (exactly the paper's m ẍ + c ẋ + k x = f, eq. of
//    §4.3); across u the linearisation's stiffness is the tension over the length,
//    k⊥ = k (1 − x0 / L) (the pendulum of §4.4, ω⊥ = √(g / L) when hanging), damped critically by
//    c⊥ = 2 √(k⊥ m): "both linear and pendulum oscillations are damped critically" (§4.4).
//    A slack or compressed spring (L ≤ x0) pushes along u only (k⊥ = 0; it does not buckle).
//    The damper acts on the relative velocity v − w (w = stylus velocity).
//  - The stylus moves linearly within a frame, S(t) = S0 + w t. In the relative coordinate
//    e = G − S(t) − x0 u every mode obeys ë + 2 ω ė + ω² e = a (a = the mode's share of the constant
//    acceleration: gravity, normal force, sliding friction). HS_INTEGRATOR_EXACT uses its closed
//    form, e(t) = e^{−ωt} (e0 + (ė0 + ω e0) t) + a (1 − e^{−ωt}(1 + ωt)) / ω², exact for any dt
//    and any ω (free flight is the case ω = 0: the parabola). The other integrators take one step
//    of their scheme on the same equation.
//  - Constraints after the unconstrained step (splitting): the normal force N and the friction
//    force are evaluated once per stretch of a frame with the object held where it is and the
//    stylus at the frame end (the force the ground must supply to keep it still), then enter the
//    step as constant forces; afterwards the floor and the walls are projections (the position
//    is clamped and the velocity into the constraint removed: ground and walls absorb the impact,
//    the paper's drop ends on the ground). An object on the floor does not slide while the
//    horizontal force ≤ μ N (with a 1e-9 relative tolerance, so exactly μ N holds on every
//    compiler); a sliding object feels μ_sliding N against its velocity and stops when the velocity
//    along its initial direction crosses zero — the crossing is found by bisection, the rest of
//    the frame starts from there (stuck again, or breaking away the other way). A critically
//    damped pull against sliding friction need not cross zero: it creeps toward the point where
//    the spring force equals μ_sliding N and, with μ_sliding = μ, would never quite stop. So an
//    object slower than 1 µm/s whose excess force over μ N would stretch the spring by less than
//    1 nm (k · 1e-9 m) counts as held — the same rule at rest, where it means a pull that would
//    move the object by less than a nanometre does not break it away. A wall takes the
//    force and velocity components pushing into it (frictionless walls), so a pulled object stays
//    at the wall while the spring stretches (Fig. 4).
//  - Object–object collisions (§4.5, momentum and energy conserved): after the step, each
//    overlapping pair (array order) exchanges an impulse along the contact normal,
//    J = −(1 + e) v_n / (1/m_a + 1/m_b), then is pushed apart along the normal in inverse-mass shares.
//    Spheres collide as exact spheres, other shapes as their world-axis bounding box (no rotation
//    in this model): sphere–sphere along the line of centres, sphere–box along the nearest point,
//    box–box along the axis of least overlap. There is no resting contact between objects.
//  - Button and selection at the end of each frame (the sample that carries them): a release
//    while the tracker says 'at rest' is a drop, otherwise a throw (the object takes the tracker's
//    velocity estimate, §4.4); a press attaches, in this order, the object the stylus is inside
//    (direct picking, §3), the nearest flying object within catch_radius (catch), or the selection
//    candidate within grab_range (a press inside a flying object counts as a catch). The candidate
//    ('I want this one', §3) is the object the stylus is inside, else — while the hand moves — the
//    first object hit by a ray from the stylus along the hand's heading (its path over the tracker's
//    fit window, up to select_range; none when the ray hits nothing), else — the hand at rest —
//    the previous candidate.
#include <gsl/gsl_rng.h>
#include <stdlib.h>
#include <string.h>

#include "spring_internal.h"

#define HS_HANG_EXTENSION 0.2       // §4.2: a hanging object stretches its spring by 0.2 x0
#define HS_STANDARD_GRAVITY 9.81    // m/s²: sizes k in a world without gravity
#define HS_FRICTION_TOLERANCE 1e-9  // relative: a force within this of μ N does not break away
#define HS_STICK_SPEED 1e-6         // m/s: slower than this an object may stick (creep has ended)
#define HS_STICK_TRAVEL 1e-9        // m: a pull that would move a held object less than this is held
#define HS_MAX_SEGMENTS 4           // stop / break-away stretches per object and frame
#define HS_STOP_BISECTIONS 60       // halvings of the stretch when locating a stop
#define HS_SERIES_LIMIT 0.5         // ω t below which (1 − e^{−x}(1 + x)) / x² is summed as a series

// Where an object reaches, relative to G in world axes: its world-axis bounding box, or a sphere.
typedef struct body_geom {
	hs_vec3 lo, hi; // m: offsets of the box corners from G
	double radius;  // m, spheres only
	bool sphere;
} body_geom;

typedef struct spring_params {
	double mass, x0, k, c, omega;
} spring_params;

struct hs_spring_system {
	hs_spring_def def;
	gsl_rng *rng;
	hs_tracker tracker;
	int geom_count; // bodies whose geometry is cached
	body_geom *geom;
	uint8_t *on_floor;
	uint8_t *sliding;
	uint8_t *separated; // pushed apart from a neighbour this frame: moved without a velocity
	hs_vec3 *saved_pos; // frame-start state for the numeric guard
	hs_vec3 *saved_vel;
	// the stylus: pose at the end of the coming frame and at its start
	bool has_stylus;
	hs_vec3 stylus, stylus_prev;
	hs_quat rot, rot_prev;
	bool button, button_prev;
	hs_vec3 stylus_velocity; // m/s during the last frame
	// the spring
	int attached; // body index, -1 when none
	hs_attach_kind attach_kind;
	hs_vec3 axis; // unit direction S → G used when they coincide
	int candidate; // body index, -1 when none
	hs_release release;
};

// ---------------------------------------------------------------------------------------------
// Definition

hs_spring_def hs_default_spring_def(void) {
	hs_spring_def def;
	memset(&def, 0, sizeof def);
	def.integrator = HS_INTEGRATOR_EXACT;
	def.friction_static = 0.5;
	def.friction_sliding = 0.5; // §4.2: "At small speeds μ is constant"
	def.restitution = 1.0;
	def.walls.enabled = false;
	def.walls.x_min = -1.0;
	def.walls.x_max = 1.0;
	def.walls.y_min = -0.6;
	def.walls.y_max = 0.6;
	def.rest_length_ref = 0.10;
	def.rest_mass_ref = 1.0;
	def.rest_exponent = 1.0 / 3.0;
	def.rest_length_min = 0.01;
	def.rest_length_max = 1.0;
	def.tracker_rate = 50.0; // §5.1
	def.tracker_window = 9;
	def.rest_speed = 0.10;
	def.motion_speed = 0.20;
	def.catch_radius = 0.05;
	def.grab_range = 0.5;
	def.select_range = 2.0;
	def.noise = false;
	def.noise_seed = 1;
	def.noise_position = 0.03 * 0.0254;          // 0.03 inch (Fastrak static accuracy, [13])
	def.noise_orientation = 0.15 * HS_PI / 180.0; // 0.15°
	return def;
}

static bool finite_nonneg(double x) { return isfinite(x) && x >= 0.0; }
static bool finite_pos(double x) { return isfinite(x) && x > 0.0; }

static bool valid_spring_def(const hs_spring_def *d) {
	if (!d)
		return false;
	if (d->integrator != HS_INTEGRATOR_EXACT && d->integrator != HS_INTEGRATOR_IMPLICIT_EULER &&
	    d->integrator != HS_INTEGRATOR_SEMI_IMPLICIT_EULER && d->integrator != HS_INTEGRATOR_RK4)
		return false;
	if (!finite_nonneg(d->friction_static) || !finite_nonneg(d->friction_sliding) ||
	    d->friction_sliding > d->friction_static)
		return false;
	if (!finite_nonneg(d->restitution) || d->restitution > 1.0)
		return false;
	if (d->walls.enabled && !(isfinite(d->walls.x_min) && isfinite(d->walls.x_max) && isfinite(d->walls.y_min) &&
	                          isfinite(d->walls.y_max) && d->walls.x_min < d->walls.x_max &&
	                          d->walls.y_min < d->walls.y_max))
		return false;
	if (!finite_pos(d->rest_length_ref) || !finite_pos(d->rest_mass_ref) || !isfinite(d->rest_exponent) ||
	    !finite_pos(d->rest_length_min) || !finite_pos(d->rest_length_max) ||
	    d->rest_length_min > d->rest_length_max)
		return false;
	if (!finite_pos(d->tracker_rate) || d->tracker_rate > 1e6 || d->tracker_window < 3 ||
	    d->tracker_window > HS_TRACKER_CAPACITY)
		return false;
	if (!finite_nonneg(d->rest_speed) || !isfinite(d->motion_speed) || d->motion_speed <= d->rest_speed)
		return false;
	if (!finite_nonneg(d->catch_radius) || !finite_nonneg(d->grab_range) || !finite_pos(d->select_range))
		return false;
	if (!finite_nonneg(d->noise_position) || !finite_nonneg(d->noise_orientation))
		return false;
	return true;
}

// ---------------------------------------------------------------------------------------------
// Per-object spring (§4.2) and geometry

static double gravity_magnitude(const hs_world *world) {
	double g = hs_length(world->def.gravity);
	return g > 0.0 ? g : HS_STANDARD_GRAVITY;
}

static spring_params params_of(const hs_spring_def *def, const hs_world *world, double mass) {
	spring_params sp;
	sp.mass = mass;
	double x0 = def->rest_length_ref * hs_pow(mass / def->rest_mass_ref, def->rest_exponent);
	x0 = x0 < def->rest_length_min ? def->rest_length_min : x0;
	x0 = x0 > def->rest_length_max ? def->rest_length_max : x0;
	sp.x0 = x0;
	sp.k = mass * gravity_magnitude(world) / (HS_HANG_EXTENSION * x0); // §4.2
	sp.omega = sqrt(sp.k / mass);
	sp.c = 2.0 * sqrt(sp.k * mass); // §4.3: critical damping
	return sp;
}

static body_geom geometry_of(const hs_world *world, const hs_body *body) {
	const hs_shape *shape = &world->shapes[body->shape];
	body_geom g;
	memset(&g, 0, sizeof g);
	if (shape->kind == HS_SHAPE_SPHERE) {
		double r = shape->sphere_radius;
		g.sphere = true;
		g.radius = r;
		g.lo = hs_v3(-r, -r, -r);
		g.hi = hs_v3(r, r, r);
		return g;
	}
	g.lo = hs_v3(INFINITY, INFINITY, INFINITY);
	g.hi = hs_v3(-INFINITY, -INFINITY, -INFINITY);
	for (int i = 0; i < shape->vertex_count; ++i) {
		hs_vec3 v = hs_quat_rotate(body->rot, shape->vertices[i]);
		g.lo = hs_v3(fmin(g.lo.x, v.x), fmin(g.lo.y, v.y), fmin(g.lo.z, v.z));
		g.hi = hs_v3(fmax(g.hi.x, v.x), fmax(g.hi.y, v.y), fmax(g.hi.z, v.z));
	}
	return g;
}

// The spring + damper force on G (the nonlinear spring, for the friction test and reports).
static hs_vec3 spring_force(const spring_params *sp, hs_vec3 fallback_axis, hs_vec3 p, hs_vec3 v, hs_vec3 s,
                            hs_vec3 w) {
	hs_vec3 d = hs_sub(p, s);
	double len = hs_length(d);
	hs_vec3 u = len > 1e-9 * sp->x0 ? hs_scale(d, 1.0 / len) : fallback_axis;
	hs_vec3 rel = hs_sub(v, w);
	double ra = hs_dot(rel, u);
	hs_vec3 rp = hs_mul_add(rel, -ra, u);
	double kt = len > sp->x0 ? sp->k * (1.0 - sp->x0 / len) : 0.0;
	double ct = 2.0 * sqrt(kt * sp->mass);
	return hs_sub(hs_scale(u, -(sp->k * (len - sp->x0) + sp->c * ra)), hs_scale(rp, ct));
}

// ---------------------------------------------------------------------------------------------
// Integration of one critically damped mode ë + 2 ω ė + ω² e = a over a time t

// (1 − e^{−x}(1 + x)) / x², x ≥ 0: Σ_{n≥2} (−1)^n (n − 1) x^{n−2} / n! for small x (no cancellation)
static double phi2(double x) {
	if (x < HS_SERIES_LIMIT) {
		double sum = 0.0, fact_ratio = 0.5; // x^{n-2} / n! at n = 2
		for (int n = 2; n < 24; ++n) {
			double term = (double)(n - 1) * fact_ratio;
			sum += (n % 2 == 0) ? term : -term;
			fact_ratio = fact_ratio * x / (double)(n + 1);
		}
		return sum;
	}
	return (1.0 - hs_exp(-x) * (1.0 + x)) / (x * x);
}

static void mode_step(hs_integrator integrator, double omega, double e0, double u0, double a, double t,
                      double *e1, double *u1) {
	switch (integrator) {
	case HS_INTEGRATOR_EXACT: {
		double x = omega * t, decay = hs_exp(-x), b = u0 + omega * e0;
		*e1 = decay * (e0 + b * t) + a * t * t * phi2(x);
		*u1 = decay * (u0 - omega * b * t) + a * t * decay;
		return;
	}
	case HS_INTEGRATOR_IMPLICIT_EULER: { // u1 = u0 + t (a − ω² e1 − 2 ω u1), e1 = e0 + t u1
		double x = omega * t;
		*u1 = (u0 + t * (a - omega * omega * e0)) / ((1.0 + x) * (1.0 + x));
		*e1 = e0 + t * *u1;
		return;
	}
	case HS_INTEGRATOR_SEMI_IMPLICIT_EULER: // velocity first, then position with the new velocity
		*u1 = u0 + t * (a - omega * omega * e0 - 2.0 * omega * u0);
		*e1 = e0 + t * *u1;
		return;
	case HS_INTEGRATOR_RK4: {
		double w2 = omega * omega, w = 2.0 * omega;
		double k1e = u0, k1u = a - w2 * e0 - w * u0;
		double e = e0 + 0.5 * t * k1e, u = u0 + 0.5 * t * k1u;
		double k2e = u, k2u = a - w2 * e - w * u;
		e = e0 + 0.5 * t * k2e;
		u = u0 + 0.5 * t * k2u;
		double k3e = u, k3u = a - w2 * e - w * u;
		e = e0 + t * k3e;
		u = u0 + t * k3u;
		double k4e = u, k4u = a - w2 * e - w * u;
		*e1 = e0 + t / 6.0 * (k1e + 2.0 * k2e + 2.0 * k3e + k4e);
		*u1 = u0 + t / 6.0 * (k1u + 2.0 * k2u + 2.0 * k3u + k4u);
		return;
	}
	}
	*e1 = e0;
	*u1 = u0;
}

// componentwise: an isotropic mode acting on a 3-vector
static void mode_step3(hs_integrator integrator, double omega, hs_vec3 e0, hs_vec3 u0, hs_vec3 a, double t,
                       hs_vec3 *e1, hs_vec3 *u1) {
	mode_step(integrator, omega, e0.x, u0.x, a.x, t, &e1->x, &u1->x);
	mode_step(integrator, omega, e0.y, u0.y, a.y, t, &e1->y, &u1->y);
	mode_step(integrator, omega, e0.z, u0.z, a.z, t, &e1->z, &u1->z);
}

// One stretch of a frame with constant coefficients.
typedef struct segment {
	bool spring;      // attached: the linearised spring acts
	hs_vec3 axis;     // u, unit
	double x0;        // m
	double omega;     // rad/s along u
	double omega_t;   // rad/s across u
	hs_vec3 s0;       // stylus at the stretch start
	hs_vec3 w;        // stylus velocity
	hs_vec3 accel;    // constant acceleration: gravity, normal force, friction
} segment;

static void integrate(hs_integrator integrator, const segment *sg, hs_vec3 p0, hs_vec3 v0, double t, hs_vec3 *p1,
                      hs_vec3 *v1) {
	if (!sg->spring) {
		mode_step3(integrator, 0.0, p0, v0, sg->accel, t, p1, v1);
		return;
	}
	hs_vec3 u = sg->axis;
	hs_vec3 e0 = hs_sub(hs_sub(p0, sg->s0), hs_scale(u, sg->x0));
	hs_vec3 r0 = hs_sub(v0, sg->w);
	double ea = hs_dot(e0, u), ra = hs_dot(r0, u), aa = hs_dot(sg->accel, u);
	hs_vec3 ep = hs_mul_add(e0, -ea, u), rp = hs_mul_add(r0, -ra, u), ap = hs_mul_add(sg->accel, -aa, u);
	double ea1, ra1;
	hs_vec3 ep1, rp1;
	mode_step(integrator, sg->omega, ea, ra, aa, t, &ea1, &ra1);
	mode_step3(integrator, sg->omega_t, ep, rp, ap, t, &ep1, &rp1);
	hs_vec3 s1 = hs_mul_add(sg->s0, t, sg->w);
	*p1 = hs_add(hs_add(s1, hs_scale(u, sg->x0 + ea1)), ep1);
	*v1 = hs_add(hs_mul_add(rp1, ra1, u), sg->w);
}

// ---------------------------------------------------------------------------------------------
// Constraints: floor (z = 0) and walls

// Removes the components of `vec` that push into a wall the object touches.
static void wall_block(const hs_spring_system *sys, const body_geom *g, hs_vec3 p, double tol, hs_vec3 *vec) {
	const hs_spring_walls *wl = &sys->def.walls;
	if (!wl->enabled)
		return;
	if (p.x + g->lo.x <= wl->x_min + tol && vec->x < 0.0)
		vec->x = 0.0;
	if (p.x + g->hi.x >= wl->x_max - tol && vec->x > 0.0)
		vec->x = 0.0;
	if (p.y + g->lo.y <= wl->y_min + tol && vec->y < 0.0)
		vec->y = 0.0;
	if (p.y + g->hi.y >= wl->y_max - tol && vec->y > 0.0)
		vec->y = 0.0;
}

// Projects the object inside the walls; with `vel`, removes the velocity into a wall it was stopped at.
static void wall_project(const hs_spring_system *sys, const body_geom *g, hs_vec3 *p, hs_vec3 *vel) {
	const hs_spring_walls *wl = &sys->def.walls;
	if (!wl->enabled)
		return;
	if (p->x + g->lo.x < wl->x_min) {
		p->x = wl->x_min - g->lo.x;
		if (vel && vel->x < 0.0)
			vel->x = 0.0;
	}
	if (p->x + g->hi.x > wl->x_max) {
		p->x = wl->x_max - g->hi.x;
		if (vel && vel->x > 0.0)
			vel->x = 0.0;
	}
	if (p->y + g->lo.y < wl->y_min) {
		p->y = wl->y_min - g->lo.y;
		if (vel && vel->y < 0.0)
			vel->y = 0.0;
	}
	if (p->y + g->hi.y > wl->y_max) {
		p->y = wl->y_max - g->hi.y;
		if (vel && vel->y > 0.0)
			vel->y = 0.0;
	}
}

// ---------------------------------------------------------------------------------------------
// One object through one frame

typedef struct frame_ctx {
	hs_world *world;
	hs_spring_system *sys;
	double dt;
	hs_vec3 gravity;
} frame_ctx;

// The force on an object held still at p with the stylus at the frame end: gravity, spring, and
// the damper (which then sees the stylus velocity only).
static hs_vec3 hold_force(const frame_ctx *fx, const spring_params *sp, bool attached, hs_vec3 p) {
	hs_vec3 f = hs_scale(fx->gravity, sp->mass);
	if (attached)
		f = hs_add(f, spring_force(sp, fx->sys->axis, p, hs_v3(0.0, 0.0, 0.0), fx->sys->stylus,
		                           fx->sys->stylus_velocity));
	return f;
}

static void step_body(const frame_ctx *fx, int i) {
	hs_spring_system *sys = fx->sys;
	hs_body *body = &fx->world->bodies[i];
	const body_geom *g = &sys->geom[i];
	hs_integrator integrator = sys->def.integrator;
	double dt = fx->dt, tol = fx->world->def.floor_tolerance;
	bool attached = i == sys->attached;
	spring_params sp = params_of(&sys->def, fx->world, body->mass);
	hs_vec3 p = body->pos, v = body->vel;

	segment sg;
	memset(&sg, 0, sizeof sg);
	sg.spring = attached;
	sg.s0 = sys->stylus_prev;
	sg.w = sys->stylus_velocity;
	if (attached) { // linearise the spring about its state at the frame start
		hs_vec3 d = hs_sub(p, sys->stylus_prev);
		double len = hs_length(d);
		if (len > 1e-9 * sp.x0)
			sys->axis = hs_scale(d, 1.0 / len);
		sg.axis = sys->axis;
		sg.x0 = sp.x0;
		sg.omega = sp.omega;
		sg.omega_t = len > sp.x0 ? sp.omega * sqrt(1.0 - sp.x0 / len) : 0.0;
	}

	double floor_z = -g->lo.z; // height of G when the object lies on the floor
	bool on_floor = false, sliding = false;
	if (p.z <= floor_z + tol && v.z <= 0.0) {
		hs_vec3 f = hold_force(fx, &sp, attached, p);
		if (f.z <= 0.0) { // pressed onto the floor: it supplies N = −f_z (§4.5)
			on_floor = true;
			fx->world->counters.floor_checks++;
			p.z = floor_z;
			v.z = 0.0;
			double t = 0.0, mu_s = sys->def.friction_static, mu_k = sys->def.friction_sliding;
			for (int seg = 0; seg < HS_MAX_SEGMENTS && t < dt; ++seg) {
				if (seg > 0)
					f = hold_force(fx, &sp, attached, p);
				double normal = f.z < 0.0 ? -f.z : 0.0;
				hs_vec3 fh = hs_v3(f.x, f.y, 0.0), vh = hs_v3(v.x, v.y, 0.0);
				wall_block(sys, g, p, tol, &fh);
				wall_block(sys, g, p, tol, &vh);
				double speed = hs_length(vh), push = hs_length(fh);
				double hold = mu_s * normal * (1.0 + HS_FRICTION_TOLERANCE) + (attached ? sp.k * HS_STICK_TRAVEL : 0.0);
				if (speed <= HS_STICK_SPEED && push <= hold) {
					v = hs_v3(0.0, 0.0, 0.0); // static friction holds (§4.2)
					sliding = false;
					break;
				}
				hs_vec3 dir = speed > 0.0 ? hs_scale(vh, 1.0 / speed) : hs_scale(fh, 1.0 / push);
				sg.accel = hs_add(fx->gravity, hs_scale(hs_mul_add(hs_v3(0.0, 0.0, normal), -mu_k * normal, dir),
				                                        1.0 / sp.mass));
				sg.s0 = hs_mul_add(sys->stylus_prev, t, sys->stylus_velocity);
				double rest = dt - t;
				hs_vec3 p1, v1;
				integrate(integrator, &sg, p, v, rest, &p1, &v1);
				sliding = true;
				if (hs_dot(hs_v3(v1.x, v1.y, 0.0), dir) > 0.0) {
					p = p1;
					v = v1;
					break;
				}
				// the velocity along dir crossed zero within the stretch: find where, stop there
				double lo = 0.0, hi = rest;
				for (int k = 0; k < HS_STOP_BISECTIONS; ++k) {
					double mid = 0.5 * (lo + hi);
					integrate(integrator, &sg, p, v, mid, &p1, &v1);
					if (hs_dot(hs_v3(v1.x, v1.y, 0.0), dir) > 0.0)
						lo = mid;
					else
						hi = mid;
				}
				integrate(integrator, &sg, p, v, hi, &p1, &v1);
				p = hs_v3(p1.x, p1.y, floor_z);
				v = hs_v3(0.0, 0.0, 0.0);
				sliding = false;
				t += hi;
			}
			p.z = floor_z;
			v.z = 0.0;
		}
	}
	if (!on_floor) { // in the air: gravity and the spring
		sg.accel = fx->gravity;
		// the linearisation holds the spring's direction for a whole step: with omega dt large the
		// object would fall across it unrestrained and gain energy. Sub-steps of omega h <= 0.5,
		// each linearised again, keep it a spring (one step when omega dt <= 0.5). The explicit
		// schemes keep their single step: they are the benchmark's unstable comparison.
		bool stable = integrator == HS_INTEGRATOR_EXACT || integrator == HS_INTEGRATOR_IMPLICIT_EULER;
		int steps = attached && stable ? (int)ceil(sp.omega * dt / 0.5) : 1;
		steps = steps < 1 ? 1 : (steps > 256 ? 256 : steps);
		double h = dt / steps;
		for (int k = 0; k < steps; ++k) {
			if (k > 0) {
				sg.s0 = hs_mul_add(sys->stylus_prev, (double)k * h, sys->stylus_velocity);
				hs_vec3 d = hs_sub(p, sg.s0);
				double len = hs_length(d);
				if (len > 1e-9 * sp.x0)
					sys->axis = hs_scale(d, 1.0 / len);
				sg.axis = sys->axis;
				sg.omega_t = len > sp.x0 ? sp.omega * sqrt(1.0 - sp.x0 / len) : 0.0;
			}
			integrate(integrator, &sg, p, v, h, &p, &v);
		}
		if (p.z < floor_z) { // landed: the ground absorbs the normal velocity (§4.4 drop)
			p.z = floor_z;
			if (v.z < 0.0)
				v.z = 0.0;
			on_floor = true;
		}
	}
	wall_project(sys, g, &p, &v);
	body->pos = p;
	body->vel = v;
	sys->on_floor[i] = on_floor;
	sys->sliding[i] = sliding;
	fx->world->counters.object_steps++;
}

// ---------------------------------------------------------------------------------------------
// Object–object collisions (§4.5)

// Contact of a (sphere) with b (box): normal from a to b, depth.
static bool sphere_box(hs_vec3 pa, double r, hs_vec3 pb, const body_geom *gb, hs_vec3 *n, double *depth) {
	hs_vec3 lo = hs_add(pb, gb->lo), hi = hs_add(pb, gb->hi);
	hs_vec3 q = hs_v3(fmin(fmax(pa.x, lo.x), hi.x), fmin(fmax(pa.y, lo.y), hi.y), fmin(fmax(pa.z, lo.z), hi.z));
	hs_vec3 d = hs_sub(q, pa);
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
	double gaps[6] = {pa.x - lo.x, hi.x - pa.x, pa.y - lo.y, hi.y - pa.y, pa.z - lo.z, hi.z - pa.z};
	hs_vec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
	int best = 0;
	for (int k = 1; k < 6; ++k)
		if (gaps[k] < gaps[best])
			best = k;
	*n = dirs[best];
	*depth = gaps[best] + r;
	return true;
}

static bool contact_of(const body_geom *ga, hs_vec3 pa, const body_geom *gb, hs_vec3 pb, hs_vec3 *n, double *depth) {
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

static void collide_pairs(hs_world *world, hs_spring_system *sys) {
	double e = sys->def.restitution;
	for (int i = 0; i < world->object_count; ++i) {
		hs_body *a = &world->bodies[i];
		const body_geom *ga = &sys->geom[i];
		for (int j = i + 1; j < world->object_count; ++j) {
			hs_body *b = &world->bodies[j];
			const body_geom *gb = &sys->geom[j];
			hs_vec3 n;
			double depth;
			if (!contact_of(ga, a->pos, gb, b->pos, &n, &depth))
				continue;
			double wa = 1.0 / a->mass, wb = 1.0 / b->mass, wsum = wa + wb;
			double vn = hs_dot(hs_sub(b->vel, a->vel), n);
			if (vn < 0.0) { // approaching: impulse along the normal
				double impulse = -(1.0 + e) * vn / wsum;
				a->vel = hs_mul_add(a->vel, -impulse * wa, n);
				b->vel = hs_mul_add(b->vel, impulse * wb, n);
			}
			// separate in inverse-mass shares (velocities untouched: momentum stays exact)
			a->pos = hs_mul_add(a->pos, -depth * wa / wsum, n);
			b->pos = hs_mul_add(b->pos, depth * wb / wsum, n);
			sys->separated[i] = sys->separated[j] = 1;
		}
	}
}

// ---------------------------------------------------------------------------------------------
// Selection (§3), catch and release (§4.4)

static bool inside(const body_geom *g, hs_vec3 p, hs_vec3 s) {
	if (g->sphere)
		return hs_length_sq(hs_sub(s, p)) <= g->radius * g->radius;
	return s.x >= p.x + g->lo.x && s.x <= p.x + g->hi.x && s.y >= p.y + g->lo.y && s.y <= p.y + g->hi.y &&
	       s.z >= p.z + g->lo.z && s.z <= p.z + g->hi.z;
}

// m from s to the object's surface (≤ 0 inside)
static double surface_distance(const body_geom *g, hs_vec3 p, hs_vec3 s) {
	if (g->sphere)
		return hs_distance(s, p) - g->radius;
	hs_vec3 lo = hs_add(p, g->lo), hi = hs_add(p, g->hi);
	hs_vec3 q = hs_v3(fmin(fmax(s.x, lo.x), hi.x), fmin(fmax(s.y, lo.y), hi.y), fmin(fmax(s.z, lo.z), hi.z));
	return hs_distance(s, q);
}

// Ray o + t d (d unit) against the object: the entry t in [0, range], or -1.
static double ray_hit(const body_geom *g, hs_vec3 p, hs_vec3 o, hs_vec3 d, double range) {
	if (g->sphere) {
		hs_vec3 oc = hs_sub(o, p);
		double b = hs_dot(oc, d), cc = hs_dot(oc, oc) - g->radius * g->radius, disc = b * b - cc;
		if (disc < 0.0)
			return -1.0;
		if (cc <= 0.0)
			return 0.0; // the origin is inside
		double t = -b - sqrt(disc);
		return t >= 0.0 && t <= range ? t : -1.0;
	}
	double tmin = 0.0, tmax = range;
	double os[3] = {o.x, o.y, o.z}, ds[3] = {d.x, d.y, d.z};
	double los[3] = {p.x + g->lo.x, p.y + g->lo.y, p.z + g->lo.z}, his[3] = {p.x + g->hi.x, p.y + g->hi.y, p.z + g->hi.z};
	for (int k = 0; k < 3; ++k) {
		if (ds[k] == 0.0) {
			if (os[k] < los[k] || os[k] > his[k])
				return -1.0;
			continue;
		}
		double t1 = (los[k] - os[k]) / ds[k], t2 = (his[k] - os[k]) / ds[k];
		if (t1 > t2) {
			double tmp = t1;
			t1 = t2;
			t2 = tmp;
		}
		tmin = t1 > tmin ? t1 : tmin;
		tmax = t2 < tmax ? t2 : tmax;
		if (tmin > tmax)
			return -1.0;
	}
	return tmin;
}

// The object the stylus is inside (nearest centre first), -1 when none.
static int direct_pick(const hs_world *world, const hs_spring_system *sys, hs_vec3 s) {
	int best = -1;
	double best_d2 = INFINITY;
	for (int i = 0; i < world->object_count; ++i) {
		if (i == sys->attached || !inside(&sys->geom[i], world->bodies[i].pos, s))
			continue;
		double d2 = hs_length_sq(hs_sub(world->bodies[i].pos, s));
		if (d2 < best_d2) {
			best_d2 = d2;
			best = i;
		}
	}
	return best;
}

// 'I want this one' (§3): a ray along the hand's estimated velocity; first hit, -1 when none.
static int ray_pick(const hs_world *world, const hs_spring_system *sys, hs_vec3 o, hs_vec3 dir) {
	int best = -1;
	double best_t = INFINITY;
	for (int i = 0; i < world->object_count; ++i) {
		if (i == sys->attached)
			continue;
		double t = ray_hit(&sys->geom[i], world->bodies[i].pos, o, dir, sys->def.select_range);
		if (t >= 0.0 && t < best_t) {
			best_t = t;
			best = i;
		}
	}
	return best;
}

static void update_candidate(const hs_world *world, hs_spring_system *sys) {
	int pick = direct_pick(world, sys, sys->stylus);
	if (pick >= 0) {
		sys->candidate = pick;
		return;
	}
	hs_vec3 heading = sys->tracker.heading;
	if (!sys->tracker.at_rest && hs_length_sq(heading) > 0.0)
		sys->candidate = ray_pick(world, sys, sys->stylus, heading);
	if (sys->candidate == sys->attached)
		sys->candidate = -1;
}

static void attach(hs_world *world, hs_spring_system *sys, int i, hs_attach_kind kind) {
	sys->attached = i;
	sys->attach_kind = kind;
	hs_vec3 d = hs_sub(world->bodies[i].pos, sys->stylus);
	double len = hs_length(d);
	hs_vec3 down = hs_normalize(world->def.gravity);
	if (hs_length(down) == 0.0)
		down = hs_v3(0.0, 0.0, -1.0);
	sys->axis = len > 0.0 ? hs_scale(d, 1.0 / len) : down; // an object picked at G hangs below
	if (sys->candidate == i)
		sys->candidate = -1;
}

static void press(hs_world *world, hs_spring_system *sys) {
	if (sys->attached >= 0)
		return;
	hs_vec3 s = sys->stylus;
	int pick = direct_pick(world, sys, s);
	if (pick >= 0) { // inside a flying object is catching it too
		attach(world, sys, pick, sys->on_floor[pick] ? HS_ATTACH_PICK : HS_ATTACH_CATCH);
		return;
	}
	int best = -1;
	double best_d = INFINITY;
	for (int i = 0; i < world->object_count; ++i) { // catch: the nearest flying object in reach
		if (sys->on_floor[i])
			continue;
		double d = surface_distance(&sys->geom[i], world->bodies[i].pos, s);
		if (d <= sys->def.catch_radius && d < best_d) {
			best_d = d;
			best = i;
		}
	}
	if (best >= 0) {
		attach(world, sys, best, HS_ATTACH_CATCH);
		return;
	}
	int c = sys->candidate;
	if (c >= 0 && surface_distance(&sys->geom[c], world->bodies[c].pos, s) <= sys->def.grab_range)
		attach(world, sys, c, HS_ATTACH_SELECT);
}

static void detach(hs_world *world, hs_spring_system *sys, bool classify, double time) {
	int i = sys->attached;
	hs_body *body = &world->bodies[i];
	hs_release *r = &sys->release;
	r->object.index1 = (uint32_t)i + 1;
	r->time = time;
	r->hand_speed = hs_length(sys->tracker.velocity);
	if (classify && !sys->tracker.at_rest) { // §4.4 throw: the object takes the hand's velocity
		r->kind = HS_RELEASE_THROW;
		body->vel = sys->tracker.velocity;
	} else { // §4.4 drop: the object just loses the spring
		r->kind = HS_RELEASE_DROP;
	}
	r->velocity = body->vel;
	sys->attached = -1;
	sys->attach_kind = HS_ATTACH_NONE;
}

// ---------------------------------------------------------------------------------------------
// The frame

static int floor_contacts(hs_world *world, const hs_spring_system *sys, int i) {
	if (sys->geom[i].sphere)
		return 1;
	hs_body *body = &world->bodies[i];
	hs_motion_pose_vertices(world, body);
	return hs_motion_floor_points(world, body);
}

void hs_spring_step(hs_world *world) {
	hs_spring_system *sys = world->spring;
	int n = world->object_count;
	for (int i = sys->geom_count; i < n; ++i) // objects added since the last frame
		sys->geom[i] = geometry_of(world, &world->bodies[i]);
	sys->geom_count = n;

	frame_ctx fx = {world, sys, world->def.dt, world->def.gravity};
	double t0 = (double)world->frame * fx.dt, t1 = (double)(world->frame + 1) * fx.dt;
	sys->stylus_velocity = hs_scale(hs_sub(sys->stylus, sys->stylus_prev), 1.0 / fx.dt);

	for (int i = 0; i < n; ++i) {
		sys->saved_pos[i] = world->bodies[i].pos;
		sys->saved_vel[i] = world->bodies[i].vel;
	}
	for (int i = 0; i < n; ++i)
		step_body(&fx, i);
	memset(sys->separated, 0, (size_t)n);
	collide_pairs(world, sys);
	for (int i = 0; i < n; ++i) { // separation may have pushed an object through the floor or a wall
		hs_body *body = &world->bodies[i];
		if (body->pos.z < -sys->geom[i].lo.z)
			body->pos.z = -sys->geom[i].lo.z;
		wall_project(sys, &sys->geom[i], &body->pos, NULL);
	}

	// the tracker daemon (§5.1), then selection and the button at the frame end
	if (sys->has_stylus)
		hs_tracker_advance(&sys->tracker, t0, t1, sys->stylus_prev, sys->rot_prev, sys->stylus, sys->rot,
		                   sys->button);
	else
		hs_tracker_skip(&sys->tracker, t1);
	update_candidate(world, sys);
	if (sys->button && !sys->button_prev)
		press(world, sys);
	else if (!sys->button && sys->button_prev && sys->attached >= 0)
		detach(world, sys, true, t1);

	for (int i = 0; i < n; ++i) {
		hs_body *body = &world->bodies[i];
		if (!hs_vec3_is_finite(body->pos) || !hs_vec3_is_finite(body->vel)) {
			body->pos = sys->saved_pos[i]; // an explicit integrator blew up: freeze, count, go on
			body->vel = sys->saved_vel[i];
			world->counters.numeric_faults++;
		}
		body->prev = sys->saved_pos[i];
		bool still = body->vel.x == 0.0 && body->vel.y == 0.0 && body->vel.z == 0.0;
		body->grounded = sys->on_floor[i];
		body->asleep = sys->on_floor[i] && still && !sys->separated[i] && i != sys->attached;
		body->contact = (uint8_t)(i == sys->attached ? HS_CONTACT_GRASP : HS_CONTACT_NONE);
		body->floor_contacts = sys->on_floor[i] ? floor_contacts(world, sys, i) : 0;
	}
	sys->stylus_prev = sys->stylus;
	sys->rot_prev = sys->rot;
	sys->button_prev = sys->button;
}

// ---------------------------------------------------------------------------------------------
// Public API

void hs_spring_system_destroy(hs_spring_system *system) {
	if (!system)
		return;
	if (system->rng)
		gsl_rng_free(system->rng);
	free(system->geom);
	free(system->on_floor);
	free(system->sliding);
	free(system->separated);
	free(system->saved_pos);
	free(system->saved_vel);
	free(system);
}

hs_status hs_world_enable_springs(hs_world *world, const hs_spring_def *def) {
	if (!world || !valid_spring_def(def))
		return HS_ERR_INVALID_ARGUMENT;
	hs_spring_system *sys = calloc(1, sizeof *sys);
	if (!sys)
		return HS_ERR_NO_MEMORY;
	size_t cap = world->def.max_objects > 0 ? (size_t)world->def.max_objects : 1;
	sys->geom = calloc(cap, sizeof *sys->geom);
	sys->on_floor = calloc(cap, sizeof *sys->on_floor);
	sys->sliding = calloc(cap, sizeof *sys->sliding);
	sys->separated = calloc(cap, sizeof *sys->separated);
	sys->saved_pos = calloc(cap, sizeof *sys->saved_pos);
	sys->saved_vel = calloc(cap, sizeof *sys->saved_vel);
	if (def->noise) {
		sys->rng = gsl_rng_alloc(gsl_rng_mt19937);
		if (sys->rng)
			gsl_rng_set(sys->rng, def->noise_seed);
	}
	if (!sys->geom || !sys->on_floor || !sys->sliding || !sys->separated || !sys->saved_pos || !sys->saved_vel ||
	    (def->noise && !sys->rng)) {
		hs_spring_system_destroy(sys);
		return HS_ERR_NO_MEMORY;
	}
	sys->def = *def;
	hs_tracker_init(&sys->tracker, def, sys->rng, (double)world->frame * world->def.dt);
	sys->rot = sys->rot_prev = hs_quat_identity();
	sys->attached = -1;
	sys->candidate = -1;
	sys->axis = hs_v3(0.0, 0.0, -1.0);
	hs_spring_system_destroy(world->spring);
	world->spring = sys;
	return HS_OK;
}

bool hs_world_springs_enabled(const hs_world *world) { return world && world->spring; }

hs_status hs_world_set_stylus(hs_world *world, hs_vec3 position, hs_quat orientation, bool button) {
	if (!world || !world->spring || !hs_vec3_is_finite(position) || !hs_quat_is_finite(orientation) ||
	    fabs(sqrt(hs_quat_dot(orientation, orientation)) - 1.0) > 1e-6)
		return HS_ERR_INVALID_ARGUMENT;
	hs_spring_system *sys = world->spring;
	sys->stylus = position;
	sys->rot = hs_quat_normalize(orientation);
	sys->button = button;
	if (!sys->has_stylus) { // the first pose: the stylus has been there all along
		sys->has_stylus = true;
		sys->stylus_prev = sys->stylus;
		sys->rot_prev = sys->rot;
	}
	return HS_OK;
}

static int index_of(const hs_world *world, hs_object_id id) {
	if (!world || id.index1 < 1 || id.index1 > (uint32_t)world->object_count)
		return -1;
	return (int)id.index1 - 1;
}

hs_status hs_world_spring_attach(hs_world *world, hs_object_id id) {
	int i = index_of(world, id);
	if (i < 0 || !world->spring || !world->spring->has_stylus)
		return HS_ERR_INVALID_ARGUMENT;
	hs_spring_system *sys = world->spring;
	if (sys->attached >= 0 && sys->attached != i)
		detach(world, sys, false, hs_world_time(world));
	attach(world, sys, i, HS_ATTACH_API);
	return HS_OK;
}

hs_status hs_world_spring_detach(hs_world *world) {
	if (!world || !world->spring)
		return HS_ERR_INVALID_ARGUMENT;
	if (world->spring->attached >= 0)
		detach(world, world->spring, false, hs_world_time(world));
	return HS_OK;
}

static hs_object_id id_of(int i) {
	hs_object_id id = {i >= 0 ? (uint32_t)i + 1 : 0};
	return id;
}

hs_status hs_world_spring_state(const hs_world *world, hs_spring_state *out) {
	if (!world || !world->spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	const hs_spring_system *sys = world->spring;
	memset(out, 0, sizeof *out);
	out->attached = id_of(sys->attached);
	out->attach_kind = sys->attach_kind;
	out->candidate = id_of(sys->candidate);
	out->stylus = sys->stylus;
	out->stylus_orientation = sys->rot;
	out->button = sys->button;
	out->stylus_velocity = sys->stylus_velocity;
	if (sys->attached >= 0) {
		const hs_body *body = &world->bodies[sys->attached];
		spring_params sp = params_of(&sys->def, world, body->mass);
		out->length = hs_distance(body->pos, sys->stylus);
		out->extension = out->length - sp.x0;
		out->force = spring_force(&sp, sys->axis, body->pos, body->vel, sys->stylus, sys->stylus_velocity);
	}
	return HS_OK;
}

hs_status hs_world_spring_object(const hs_world *world, hs_object_id id, hs_spring_object *out) {
	int i = index_of(world, id);
	if (i < 0 || !world->spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	const hs_spring_system *sys = world->spring;
	const hs_body *body = &world->bodies[i];
	spring_params sp = params_of(&sys->def, world, body->mass);
	memset(out, 0, sizeof *out);
	out->mass = sp.mass;
	out->rest_length = sp.x0;
	out->stiffness = sp.k;
	out->damping = sp.c;
	out->omega = sp.omega;
	out->velocity = body->vel;
	out->on_floor = sys->on_floor[i] != 0;
	out->sliding = sys->sliding[i] != 0;
	out->attached = i == sys->attached;
	return HS_OK;
}

hs_status hs_world_tracker_state(const hs_world *world, hs_tracker_state *out) {
	if (!world || !world->spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	const hs_tracker *tr = &world->spring->tracker;
	memset(out, 0, sizeof *out);
	out->sample_count = tr->count;
	if (!hs_tracker_sample_at(tr, 0, &out->newest))
		out->newest.orientation = hs_quat_identity();
	out->velocity = tr->velocity;
	out->acceleration = tr->acceleration;
	out->speed = hs_length(tr->velocity);
	out->heading = tr->heading;
	out->at_rest = tr->at_rest;
	out->last_event = tr->last_event;
	out->last_event_time = tr->last_event_time;
	out->motion_starts = tr->motion_starts;
	out->motion_ends = tr->motion_ends;
	return HS_OK;
}

hs_status hs_world_tracker_sample(const hs_world *world, int age, hs_tracker_sample *out) {
	if (!world || !world->spring || !out || !hs_tracker_sample_at(&world->spring->tracker, age, out))
		return HS_ERR_INVALID_ARGUMENT;
	return HS_OK;
}

hs_status hs_world_spring_last_release(const hs_world *world, hs_release *out) {
	if (!world || !world->spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	*out = world->spring->release;
	return HS_OK;
}
