// hs_math.h — vectors and quaternions for handspring.
// Conventions: parameters and results by value, double precision, SI units,
// angles in radians, right-handed frame with z up, unit quaternions w + xi + yj + zk.
// Every function is a plain sequence of IEEE operations (no fused multiply-add:
// build with -ffp-contract=off) so results are bit-identical across compilers.
#ifndef HS_MATH_H
#define HS_MATH_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

// Deterministic elementary functions (detmath.c, detmath_exp.c): built from + − × ÷ and sqrt only, so they give
// the same bits on every CPU and compiler (glibc's libm does not: its code paths differ with and
// without FMA). Every value that enters a world's state goes through these, never through libm's
// sin, cos, atan2, exp, pow... Worst errors in ulps are measured by `make ulp` (docs/determinism.md).
double hs_sin(double x);
double hs_cos(double x);
double hs_tan(double x);
double hs_asin(double x);
double hs_acos(double x);
double hs_atan(double x);
double hs_atan2(double y, double x);
double hs_exp(double x);
double hs_log(double x);
double hs_pow(double x, double y);
double hs_cbrt(double x);

typedef struct hs_vec3 {
	double x, y, z;
} hs_vec3;

typedef struct hs_quat {
	double w, x, y, z;
} hs_quat;

#define HS_PI 3.14159265358979323846

static inline hs_vec3 hs_v3(double x, double y, double z) {
	hs_vec3 r = {x, y, z};
	return r;
}
static inline hs_vec3 hs_add(hs_vec3 a, hs_vec3 b) { return hs_v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline hs_vec3 hs_sub(hs_vec3 a, hs_vec3 b) { return hs_v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline hs_vec3 hs_scale(hs_vec3 a, double s) { return hs_v3(a.x * s, a.y * s, a.z * s); }
static inline hs_vec3 hs_neg(hs_vec3 a) { return hs_v3(-a.x, -a.y, -a.z); }
static inline double hs_dot(hs_vec3 a, hs_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline hs_vec3 hs_cross(hs_vec3 a, hs_vec3 b) {
	return hs_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double hs_length_sq(hs_vec3 a) { return hs_dot(a, a); }
static inline double hs_length(hs_vec3 a) { return sqrt(hs_dot(a, a)); }
static inline double hs_distance(hs_vec3 a, hs_vec3 b) { return hs_length(hs_sub(a, b)); }
// r = a + s b
static inline hs_vec3 hs_mul_add(hs_vec3 a, double s, hs_vec3 b) {
	return hs_v3(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z);
}
static inline hs_vec3 hs_lerp(hs_vec3 a, hs_vec3 b, double t) {
	return hs_v3(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z));
}
// unit vector along a; the zero vector stays zero (callers test the length first)
static inline hs_vec3 hs_normalize(hs_vec3 a) {
	double len = hs_length(a);
	return len > 0.0 ? hs_scale(a, 1.0 / len) : a;
}
static inline int hs_vec3_is_finite(hs_vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

static inline hs_quat hs_q(double w, double x, double y, double z) {
	hs_quat r = {w, x, y, z};
	return r;
}
static inline hs_quat hs_quat_identity(void) { return hs_q(1.0, 0.0, 0.0, 0.0); }
// Hamilton product: rotating by r = a * b applies b first, then a
static inline hs_quat hs_quat_mul(hs_quat a, hs_quat b) {
	return hs_q(a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
	            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
	            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
	            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w);
}
static inline hs_quat hs_quat_conj(hs_quat q) { return hs_q(q.w, -q.x, -q.y, -q.z); }
static inline double hs_quat_dot(hs_quat a, hs_quat b) { return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z; }
static inline hs_quat hs_quat_normalize(hs_quat q) {
	double len = sqrt(hs_quat_dot(q, q));
	return hs_q(q.w / len, q.x / len, q.y / len, q.z / len);
}
static inline int hs_quat_is_finite(hs_quat q) {
	return isfinite(q.w) && isfinite(q.x) && isfinite(q.y) && isfinite(q.z);
}
// rotation by angle (rad) about a unit axis
static inline hs_quat hs_quat_from_axis_angle(hs_vec3 unit_axis, double angle) {
	double s = hs_sin(0.5 * angle);
	return hs_q(hs_cos(0.5 * angle), unit_axis.x * s, unit_axis.y * s, unit_axis.z * s);
}
// v rotated by q: v + 2w (u × v) + 2 u × (u × v), u the vector part
static inline hs_vec3 hs_quat_rotate(hs_quat q, hs_vec3 v) {
	hs_vec3 u = hs_v3(q.x, q.y, q.z);
	hs_vec3 t = hs_scale(hs_cross(u, v), 2.0);
	return hs_add(hs_add(v, hs_scale(t, q.w)), hs_cross(u, t));
}
static inline hs_vec3 hs_quat_inv_rotate(hs_quat q, hs_vec3 v) { return hs_quat_rotate(hs_quat_conj(q), v); }
// The unit quaternion of the rotation whose matrix has columns x, y, z (orthonormal, right-handed):
// Shepperd's method, from the largest of the four squares (IEEE operations only: the same bits
// everywhere).
static inline hs_quat hs_quat_from_columns(hs_vec3 x, hs_vec3 y, hs_vec3 z) {
	double tr = x.x + y.y + z.z;
	hs_quat q;
	if (tr > 0.0) {
		double s = 2.0 * sqrt(1.0 + tr);
		q = hs_q(0.25 * s, (y.z - z.y) / s, (z.x - x.z) / s, (x.y - y.x) / s);
	} else if (x.x > y.y && x.x > z.z) {
		double s = 2.0 * sqrt(1.0 + x.x - y.y - z.z);
		q = hs_q((y.z - z.y) / s, 0.25 * s, (y.x + x.y) / s, (z.x + x.z) / s);
	} else if (y.y > z.z) {
		double s = 2.0 * sqrt(1.0 + y.y - x.x - z.z);
		q = hs_q((z.x - x.z) / s, (y.x + x.y) / s, 0.25 * s, (z.y + y.z) / s);
	} else {
		double s = 2.0 * sqrt(1.0 + z.z - x.x - y.y);
		q = hs_q((x.y - y.x) / s, (z.x + x.z) / s, (z.y + y.z) / s, 0.25 * s);
	}
	return hs_quat_normalize(q);
}
// roll about x, then pitch about y, then yaw about z (extrinsic), radians
static inline hs_quat hs_quat_from_rpy(double roll, double pitch, double yaw) {
	hs_quat qx = hs_quat_from_axis_angle(hs_v3(1, 0, 0), roll);
	hs_quat qy = hs_quat_from_axis_angle(hs_v3(0, 1, 0), pitch);
	hs_quat qz = hs_quat_from_axis_angle(hs_v3(0, 0, 1), yaw);
	return hs_quat_mul(qz, hs_quat_mul(qy, qx));
}
// angle of the rotation q in [0, pi]
static inline double hs_quat_angle(hs_quat q) {
	double v = sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
	return 2.0 * hs_atan2(v, fabs(q.w));
}
// spherical interpolation along the shorter arc, t in [0, 1]
static inline hs_quat hs_quat_slerp(hs_quat a, hs_quat b, double t) {
	double c = hs_quat_dot(a, b);
	if (c < 0.0) {
		b = hs_q(-b.w, -b.x, -b.y, -b.z);
		c = -c;
	}
	double wa, wb;
	if (c > 0.9995) { // nearly parallel: linear blend, renormalised below
		wa = 1.0 - t;
		wb = t;
	} else {
		double th = hs_acos(c), s = hs_sin(th);
		wa = hs_sin((1.0 - t) * th) / s;
		wb = hs_sin(t * th) / s;
	}
	return hs_quat_normalize(hs_q(wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z));
}

// A rotation as a 3×3 matrix (rows), for rotating many vectors by one orientation: half the
// operations of hs_quat_rotate per vector.
typedef struct hs_mat3 {
	hs_vec3 r0, r1, r2;
} hs_mat3;

static inline hs_mat3 hs_mat3_from_quat(hs_quat q) {
	double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
	double xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
	double wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
	hs_mat3 m = {{1.0 - 2.0 * (yy + zz), 2.0 * (xy - wz), 2.0 * (xz + wy)},
	             {2.0 * (xy + wz), 1.0 - 2.0 * (xx + zz), 2.0 * (yz - wx)},
	             {2.0 * (xz - wy), 2.0 * (yz + wx), 1.0 - 2.0 * (xx + yy)}};
	return m;
}
// m v
static inline hs_vec3 hs_mat3_mul(hs_mat3 m, hs_vec3 v) { return hs_v3(hs_dot(m.r0, v), hs_dot(m.r1, v), hs_dot(m.r2, v)); }
// mᵀ v: the inverse rotation
static inline hs_vec3 hs_mat3_tmul(hs_mat3 m, hs_vec3 v) {
	return hs_v3(m.r0.x * v.x + m.r1.x * v.y + m.r2.x * v.z, m.r0.y * v.x + m.r1.y * v.y + m.r2.y * v.z,
	             m.r0.z * v.x + m.r1.z * v.y + m.r2.z * v.z);
}

// Tolerance of a unit quaternion at the API boundary: | |q| - 1 | <= this. One value for every
// entry point (object orientation, wrist, stylus), loose enough for a quaternion written with
// a few decimals, tight enough that normalising it moves a vertex by less than a micrometre.
#define HS_UNIT_QUAT_TOLERANCE 1e-6

// True when q is finite and of unit length within HS_UNIT_QUAT_TOLERANCE.
static inline int hs_quat_is_unit(hs_quat q) {
	return hs_quat_is_finite(q) && fabs(sqrt(hs_quat_dot(q, q)) - 1.0) <= HS_UNIT_QUAT_TOLERANCE;
}

// The clamped parameter u in [0, 1] of the point of segment a-b nearest to p (0 for a point
// segment): written once for the hull edges, the hand's check lines and the contact culling.
static inline double hs_segment_param(hs_vec3 a, hs_vec3 b, hs_vec3 p) {
	hs_vec3 d = hs_sub(b, a);
	double len_sq = hs_length_sq(d);
	double u = len_sq > 0.0 ? hs_dot(hs_sub(p, a), d) / len_sq : 0.0;
	return u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
}

// The point of segment a-b nearest to p.
static inline hs_vec3 hs_segment_closest(hs_vec3 a, hs_vec3 b, hs_vec3 p) {
	return hs_mul_add(a, hs_segment_param(a, b, p), hs_sub(b, a));
}

#ifdef __cplusplus
}
#endif

#endif
