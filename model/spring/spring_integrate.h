// spring_integrate.h — one object moved through a stretch of a frame by the linearised spring,
// gravity and constant forces: the exact critically damped step and the comparison integrators.
#ifndef HS_SPRING_INTEGRATE_H
#define HS_SPRING_INTEGRATE_H

#include "spring_params.h"

// One stretch of a frame with constant coefficients.
typedef struct hs_spring_segment {
	bool spring;    // attached: the linearised spring acts
	hs_vec3 axis;   // u, unit
	double x0;      // m
	double omega;   // rad/s along u
	double omega_t; // rad/s across u
	hs_vec3 s0;     // stylus at the stretch start
	hs_vec3 w;      // stylus velocity
	hs_vec3 accel;  // constant acceleration: gravity, normal force, friction
	// a frictionless wall holds G's x (bit 0) and/or y (bit 1) at `pinned_at`: the step moves it
	// in the other directions only, under the linearised spring restricted to them
	unsigned pinned;
	hs_vec3 pinned_at;
} hs_spring_segment;

// Linearises the spring about G at p with the stylus at sg->s0: sets u (in *axis too; *axis is
// kept when G and S coincide), x0, ω and ω⊥.
void hs_spring_linearise(hs_spring_segment *sg, const hs_spring_params *sp, hs_vec3 p, hs_vec3 *axis);
// Moves (p0, v0) through t seconds of the segment into (p1, v1).
void hs_spring_integrate(hs_integrator integrator, const hs_spring_segment *sg, hs_vec3 p0, hs_vec3 v0, double t,
                         hs_vec3 *p1, hs_vec3 *v1);
// A frame of dt in the air from the segment's start (sg->accel set): sub-steps of ω h ≤ 0.5 for the
// stable schemes on the spring, each linearised again (updating sg and *axis).
void hs_spring_fly(hs_integrator integrator, hs_spring_segment *sg, const hs_spring_params *sp, double dt,
                   hs_vec3 *axis, hs_vec3 *p, hs_vec3 *v);

#endif
