// spring_params.h — the spring model's definition (validation) and the spring of each object
// (Responsive Workbench paper §4.2, §4.3): mass, rest length x0, stiffness k, damping c, ω.
#ifndef HS_SPRING_PARAMS_H
#define HS_SPRING_PARAMS_H

#include <stdbool.h>

#include "handspring.h"

// One object's spring, derived from the definition and the object's mass (never state).
typedef struct hs_spring_params {
	double mass;  // kg
	double x0;    // m: rest length
	double k;     // N/m
	double c;     // N s/m: critical damping along the spring
	double omega; // rad/s: √(k / m)
} hs_spring_params;

// True when every field of the definition is finite and within its range (handspring.h).
bool hs_spring_def_valid(const hs_spring_def *def);
// x0, k, c and ω of an object of `mass` kg in a world of that gravity (§4.2, §4.3).
hs_spring_params hs_spring_params_of(const hs_spring_def *def, hs_vec3 gravity, double mass);
// The spring + damper force (N) on G at p moving at v, the stylus at s moving at w: the nonlinear
// spring, for the friction test and the reports. `fallback_axis` is its direction when G = S.
hs_vec3 hs_spring_force(const hs_spring_params *sp, hs_vec3 fallback_axis, hs_vec3 p, hs_vec3 v, hs_vec3 s,
                        hs_vec3 w);

#endif
