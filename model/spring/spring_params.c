// spring_params.c — the spring model's definition and each object's spring, from "Dynamics in
// Interaction on the Responsive Workbench" (§4.2, §4.3).
//
// Readings fixed here (the paper leaves them open; docs/model.md §8):
//  - Rest length (§4.2: "calculated automatically from the mass ... for heavy objects a stronger
//    and longer spring"): x0(m) = x0_ref (m / m_ref)^p, default 0.10 m · (m / 1 kg)^(1/3), clamped to
//    [0.01 m, 1.0 m]. The cube root makes the spring grow like the object's size at fixed density;
//    the clamp spans exactly 1 g (1 cm) to 1000 kg (1 m). k = m g / (0.2 x0) (§4.2: hanging
//    stretches the spring by 20 % of x0), so ω = √(k/m) = √(g / 0.2 x0) (22 rad/s at 1 kg) and
//    c = 2 √(k m) (§4.3, critical). g is |world gravity| (9.81 m/s² in a world without gravity).
//  - The spring is a 3D spring of rest length x0 between the stylus point S and G: along
//    u = (G − S)/|G − S| it has stiffness k and damping c; across u the tension over the length,
//    k⊥ = k (1 − x0 / L), damped critically by c⊥ = 2 √(k⊥ m) (the pendulum of §4.4). A slack or
//    compressed spring (L ≤ x0) pushes along u only. The damper acts on the relative velocity
//    v − w (w = stylus velocity). spring_integrate.c integrates its linearisation.
#include <string.h>

#include "spring_params.h"

#define HS_HANG_EXTENSION 0.2    // §4.2: a hanging object stretches its spring by 0.2 x0
#define HS_STANDARD_GRAVITY 9.81 // m/s²: sizes k in a world without gravity

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
	def.select_speed = 0.05;
	return def;
}

static bool finite_nonneg(double x) { return isfinite(x) && x >= 0.0; }
static bool finite_pos(double x) { return isfinite(x) && x > 0.0; }

bool hs_spring_def_valid(const hs_spring_def *d) {
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
	if (!finite_nonneg(d->catch_radius) || !finite_nonneg(d->grab_range) || !finite_pos(d->select_range) ||
	    !finite_nonneg(d->select_speed))
		return false;
	return true;
}

static double gravity_magnitude(hs_vec3 gravity) {
	double g = hs_length(gravity);
	return g > 0.0 ? g : HS_STANDARD_GRAVITY;
}

hs_spring_params hs_spring_params_of(const hs_spring_def *def, hs_vec3 gravity, double mass) {
	hs_spring_params sp;
	sp.mass = mass;
	double x0 = def->rest_length_ref * hs_pow(mass / def->rest_mass_ref, def->rest_exponent);
	x0 = x0 < def->rest_length_min ? def->rest_length_min : x0;
	x0 = x0 > def->rest_length_max ? def->rest_length_max : x0;
	sp.x0 = x0;
	sp.k = mass * gravity_magnitude(gravity) / (HS_HANG_EXTENSION * x0); // §4.2
	sp.omega = mass > 0.0 ? sqrt(sp.k / mass) : 0.0; // massless (k = 0): no spring to speak of
	sp.c = 2.0 * sqrt(sp.k * mass); // §4.3: critical damping
	return sp;
}

hs_vec3 hs_spring_force(const hs_spring_params *sp, hs_vec3 fallback_axis, hs_vec3 p, hs_vec3 v, hs_vec3 s,
                        hs_vec3 w) {
	hs_vec3 d = hs_sub(p, s);
	double len = hs_length(d);
	hs_vec3 u = len > 1e-9 * sp->x0 ? hs_scale(d, 1.0 / len) : fallback_axis;
	hs_vec3 rel = hs_sub(v, w);
	double ra = hs_dot(rel, u);
	hs_vec3 rp = hs_mul_add(rel, -ra, u);
	double kt = len > sp->x0 ? sp->k * (1.0 - sp->x0 / len) : 0.0; // k⊥: the pendulum of §4.4
	double ct = 2.0 * sqrt(kt * sp->mass);
	return hs_sub(hs_scale(u, -(sp->k * (len - sp->x0) + sp->c * ra)), hs_scale(rp, ct));
}
