// detmath.c — deterministic elementary functions (hs_math.h).
// PLACEHOLDER: forwards to libm until the own implementations land.
#include "hs_math.h"

double hs_sin(double x) { return sin(x); }
double hs_cos(double x) { return cos(x); }
double hs_tan(double x) { return tan(x); }
double hs_asin(double x) { return asin(x); }
double hs_acos(double x) { return acos(x); }
double hs_atan(double x) { return atan(x); }
double hs_atan2(double y, double x) { return atan2(y, x); }
double hs_exp(double x) { return exp(x); }
double hs_log(double x) { return log(x); }
double hs_pow(double x, double y) { return pow(x, y); }
double hs_cbrt(double x) { return cbrt(x); }
