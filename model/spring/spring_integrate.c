// spring_integrate.c — one object through a stretch of a frame: the linearised spring of
// "Dynamics in Interaction on the Responsive Workbench" (§4.3, §4.4) with gravity and constant
// forces, integrated exactly (the default) or by a comparison scheme.
//
// Readings fixed here (the paper leaves them open; docs/model.md §8):
//  - Within a frame the spring (spring_params.c) is linearised about its state at the frame start
//    (direction u = (G − S)/|G − S|, length L): along u it has stiffness k and damping c (exactly
//    the paper's m ẍ + c ẋ + k x = f, eq. of §4.3); across u the linearisation's stiffness is the
//    tension over the length, k⊥ = k (1 − x0 / L) (the pendulum of §4.4, ω⊥ = √(g / L) when
//    hanging), damped critically by c⊥ = 2 √(k⊥ m): "both linear and pendulum oscillations are
//    damped critically" (§4.4). A slack or compressed spring (L ≤ x0) pushes along u only (k⊥ = 0;
//    it does not buckle). The damper acts on the relative velocity v − w (w = stylus velocity).
//  - The stylus moves linearly within a frame, S(t) = S0 + w t. In the relative coordinate
//    e = G − S(t) − x0 u every mode obeys ë + 2 ω ė + ω² e = a (a = the mode's share of the constant
//    acceleration: gravity, normal force, sliding friction). HS_INTEGRATOR_EXACT uses its closed
//    form, e(t) = e^{−ωt} (e0 + (ė0 + ω e0) t) + a (1 − e^{−ωt}(1 + ωt)) / ω², exact for any dt
//    and any ω (free flight is the case ω = 0: the parabola). The other integrators take one step
//    of their scheme on the same equation.
//  - The step must be stable at any frame rate (docs/model.md §8, "Integration"): the exact and
//    implicit schemes are the model's; semi-implicit Euler and RK4 stay only as the speed-vs-error
//    benchmark's comparison.
#include "spring_integrate.h"

#define HS_SERIES_LIMIT 0.5 // ω t below which (1 − e^{−x}(1 + x)) / x² is summed as a series
#define HS_SUBSTEP_OMEGA_H 0.5 // largest ω h of one sub-step in the air
#define HS_MAX_SUBSTEPS 256

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

// classic Runge–Kutta on (e, u)' = (u, a − ω² e − 2 ω u)
static void rk4_step(double omega, double e0, double u0, double a, double t, double *e1, double *u1) {
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
}

// One critically damped mode ë + 2 ω ė + ω² e = a over a time t.
static void mode_step(hs_integrator integrator, double omega, double e0, double u0, double a, double t,
                      double *e1, double *u1) {
	switch (integrator) {
	case HS_INTEGRATOR_EXACT: {
		if (omega == 0.0) { // no spring on this mode (gravity, friction): e^0 = 1 and φ2(0) = 1/2
			double b = u0 + omega * e0; // the general case's operations with those values: the same bits
			*e1 = 1.0 * (e0 + b * t) + a * t * t * 0.5;
			*u1 = 1.0 * (u0 - omega * b * t) + a * t * 1.0;
			return;
		}
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
	case HS_INTEGRATOR_RK4:
		rk4_step(omega, e0, u0, a, t, e1, u1);
		return;
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

void hs_spring_linearise(hs_spring_segment *sg, const hs_spring_params *sp, hs_vec3 p, hs_vec3 *axis) {
	hs_vec3 d = hs_sub(p, sg->s0);
	double len = hs_length(d);
	if (len > 1e-9 * sp->x0)
		*axis = hs_scale(d, 1.0 / len);
	sg->axis = *axis;
	sg->x0 = sp->x0;
	sg->omega = sp->omega;
	sg->omega_t = len > sp->x0 ? sp->omega * sqrt(1.0 - sp->x0 / len) : 0.0; // ω⊥ = √(k⊥ / m)
}

static double comp(hs_vec3 v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }
static void set_comp(hs_vec3 *v, int k, double x) {
	if (k == 0)
		v->x = x;
	else if (k == 1)
		v->y = x;
	else
		v->z = x;
}

// The spring against a frictionless wall (sg->pinned): G moves in the free axes only (z, and x or y).
// The linearised stiffness per mass K = ω² u uᵀ + ω⊥² (I − u uᵀ) restricted to them is split into
// its eigenmodes (at most 2 × 2, closed form), each damped critically as the free spring's modes
// are (§4.4); the pinned axes' share of e (at the middle of the stretch: exact for a still stylus)
// is a constant force. At rest the step stands exactly where the spring's force along the wall
// vanishes, whatever t: the free modes' different ω⊥ and ω otherwise left a rest point that moved
// with dt (1.6 cm between 1/12 and 1/1000 s for a hanging cube pulled into a wall).
static void integrate_pinned(hs_integrator integrator, const hs_spring_segment *sg, hs_vec3 p0, hs_vec3 v0, double t,
                             hs_vec3 *p1, hs_vec3 *v1) {
	hs_vec3 u = sg->axis;
	double w2 = sg->omega * sg->omega, t2 = sg->omega_t * sg->omega_t;
	hs_vec3 s_mid = hs_mul_add(sg->s0, 0.5 * t, sg->w), s1 = hs_mul_add(sg->s0, t, sg->w);
	hs_vec3 e0 = hs_sub(hs_sub(p0, sg->s0), hs_scale(u, sg->x0));
	hs_vec3 e_mid = hs_sub(hs_sub(p0, s_mid), hs_scale(u, sg->x0)); // the pinned axes' e mid-stretch
	int free_axes[3], nf = 0;
	for (int k = 0; k < 3; ++k)
		if (!(sg->pinned >> k & 1u))
			free_axes[nf++] = k;
	double K[2][2], b[2], e[2], r[2];
	for (int i = 0; i < nf; ++i) {
		int a = free_axes[i];
		double ua = comp(u, a);
		for (int j = 0; j < nf; ++j) {
			int c = free_axes[j];
			K[i][j] = (w2 - t2) * ua * comp(u, c) + (a == c ? t2 : 0.0);
		}
		b[i] = comp(sg->accel, a);
		for (int c = 0; c < 3; ++c) // the pinned axes push through the stiffness's coupling
			if (sg->pinned >> c & 1u)
				b[i] -= (w2 - t2) * ua * comp(u, c) * comp(e_mid, c);
		e[i] = comp(e0, a);
		r[i] = comp(v0, a) - comp(sg->w, a);
	}
	// eigenvectors of the symmetric K: q0 = (cos θ, sin θ), q1 = (−sin θ, cos θ)
	double th = nf == 2 ? 0.5 * hs_atan2(2.0 * K[0][1], K[0][0] - K[1][1]) : 0.0;
	double cs = hs_cos(th), sn = hs_sin(th);
	double q[2][2] = {{cs, sn}, {-sn, cs}};
	double ef[2] = {0.0, 0.0}, rf[2] = {0.0, 0.0};
	for (int m = 0; m < nf; ++m) {
		double lam = nf == 1 ? K[0][0]
		                     : q[m][0] * (K[0][0] * q[m][0] + K[0][1] * q[m][1]) + q[m][1] * (K[1][0] * q[m][0] + K[1][1] * q[m][1]);
		double om = lam > 0.0 ? sqrt(lam) : 0.0;
		double em = 0.0, rm = 0.0, am = 0.0;
		for (int i = 0; i < nf; ++i) {
			double qi = nf == 1 ? 1.0 : q[m][i];
			em += qi * e[i];
			rm += qi * r[i];
			am += qi * b[i];
		}
		double em1, rm1;
		mode_step(integrator, om, em, rm, am, t, &em1, &rm1);
		for (int i = 0; i < nf; ++i) {
			double qi = nf == 1 ? 1.0 : q[m][i];
			ef[i] += qi * em1;
			rf[i] += qi * rm1;
		}
	}
	*p1 = sg->pinned_at;
	*v1 = hs_v3(0.0, 0.0, 0.0);
	for (int i = 0; i < nf; ++i) {
		int a = free_axes[i];
		set_comp(p1, a, comp(s1, a) + sg->x0 * comp(u, a) + ef[i]);
		set_comp(v1, a, rf[i] + comp(sg->w, a));
	}
}

void hs_spring_integrate(hs_integrator integrator, const hs_spring_segment *sg, hs_vec3 p0, hs_vec3 v0, double t,
                         hs_vec3 *p1, hs_vec3 *v1) {
	if (sg->spring && sg->pinned) {
		integrate_pinned(integrator, sg, p0, v0, t, p1, v1);
		return;
	}
	if (!sg->spring) {
		mode_step3(integrator, 0.0, p0, v0, sg->accel, t, p1, v1);
		return;
	}
	// split e and the relative velocity into the mode along u and the two across it
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

void hs_spring_fly(hs_integrator integrator, hs_spring_segment *sg, const hs_spring_params *sp, double dt,
                   hs_vec3 *axis, hs_vec3 *p, hs_vec3 *v) {
	// the linearisation holds the spring's direction for a whole step: with omega dt large the
	// object would fall across it unrestrained and gain energy. Sub-steps of omega h <= 0.5,
	// each linearised again, keep it a spring (one step when omega dt <= 0.5). The explicit
	// schemes keep their single step: they are the benchmark's unstable comparison.
	bool stable = integrator == HS_INTEGRATOR_EXACT || integrator == HS_INTEGRATOR_IMPLICIT_EULER;
	int steps = sg->spring && stable ? (int)ceil(sp->omega * dt / HS_SUBSTEP_OMEGA_H) : 1;
	steps = steps < 1 ? 1 : (steps > HS_MAX_SUBSTEPS ? HS_MAX_SUBSTEPS : steps);
	double h = dt / steps;
	hs_vec3 start = sg->s0; // the stylus at the frame start
	for (int k = 0; k < steps; ++k) {
		if (k > 0) {
			sg->s0 = hs_mul_add(start, (double)k * h, sg->w);
			hs_spring_linearise(sg, sp, *p, axis);
		}
		hs_spring_integrate(integrator, sg, *p, *v, h, p, v);
	}
}
