// part_box.h — the hand check's face loops for a part that is a box with axis-aligned faces
// (hs_part_cache.box_face), the commonest object (a cube): its inside test coordinate by coordinate
// instead of six dot products, and the misses of its Cyrus-Beck clip found by comparisons.
//
// For a face of normal +x, dot(normal, p) = 1 p.x + 0 p.y + 0 p.z is p.x exactly when p is finite
// (up to the sign of a zero, which comparisons do not see), and -p.x for -x: the inside test
// returns what the scan of the faces returns. A point with a coordinate that is not finite (or
// whose sum overflows) goes to the scan, whose NaN dots decide as they always did.
#ifndef HS_PART_BOX_H
#define HS_PART_BOX_H

#include <stdbool.h>

#include "clip.h"
#include "handspring.h"
#include "part_cache.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

// Fills pc->box_face and pc->box_offset for the part (box_face[0] = -1 when it is no such box).
void hs_part_box_find(const hs_shape *shape, const hs_part *part, hs_part_cache *pc);

static inline bool hs_part_is_box(const hs_part_cache *pc) { return pc->box_face[0] >= 0; }

// Whether p takes the box's path: its coordinates are finite and so is their sum.
static inline bool hs_part_box_takes(hs_vec3 p) {
	double s = p.x + p.y + p.z;
	return s - s == 0.0;
}

// scan_inside (contact_part.h): no face has dot(normal, p) >= offset + grow.
static inline bool hs_part_box_inside(const hs_part_cache *pc, hs_vec3 p, double grow) {
	const double *o = pc->box_offset;
#if defined(__SSE2__)
	// without a branch (the points are noisy input): each lane one face's comparison, the same
	// operands (negation flips the sign bit alone, as unary minus does) and the same NaN answers
	__m128d g = _mm_set1_pd(grow), neg = _mm_set_pd(-0.0, 0.0);
	__m128d out = _mm_or_pd(
	    _mm_or_pd(_mm_cmpge_pd(_mm_xor_pd(_mm_set1_pd(p.x), neg), _mm_add_pd(_mm_loadu_pd(o), g)),
	              _mm_cmpge_pd(_mm_xor_pd(_mm_set1_pd(p.y), neg), _mm_add_pd(_mm_loadu_pd(o + 2), g))),
	    _mm_cmpge_pd(_mm_xor_pd(_mm_set1_pd(p.z), neg), _mm_add_pd(_mm_loadu_pd(o + 4), g)));
	return _mm_movemask_pd(out) == 0;
#else
	return !(p.x >= o[0] + grow) && !(-p.x >= o[1] + grow) && !(p.y >= o[2] + grow) && !(-p.y >= o[3] + grow) &&
	       !(p.z >= o[4] + grow) && !(-p.z >= o[5] + grow);
#endif
}

// scan_nearest (contact_part.h) of a point that takes the box's path: the first face in face order of
// the least depth offset - dot(normal, p). With an axis normal the dot is the coordinate or its
// negation (up to the sign of a zero, which the subtraction from the offset does not keep), so each
// depth is o[k] - p.c or o[k] - (-p.c), as there; the least found without a branch (the points
// are noisy input), a tie settled by the face index.
static inline int hs_part_box_nearest(const hs_part_cache *pc, hs_vec3 p) {
	const double *o = pc->box_offset;
	unsigned least = 0;
#if defined(__SSE2__)
	__m128d neg = _mm_set_pd(-0.0, 0.0);
	__m128d dx = _mm_sub_pd(_mm_loadu_pd(o), _mm_xor_pd(_mm_set1_pd(p.x), neg));
	__m128d dy = _mm_sub_pd(_mm_loadu_pd(o + 2), _mm_xor_pd(_mm_set1_pd(p.y), neg));
	__m128d dz = _mm_sub_pd(_mm_loadu_pd(o + 4), _mm_xor_pd(_mm_set1_pd(p.z), neg));
	__m128d m = _mm_min_pd(_mm_min_pd(dx, dy), dz);
	m = _mm_min_pd(m, _mm_shuffle_pd(m, m, 1));
	least = (unsigned)_mm_movemask_pd(_mm_cmpeq_pd(dx, m)) | (unsigned)_mm_movemask_pd(_mm_cmpeq_pd(dy, m)) << 2 |
	        (unsigned)_mm_movemask_pd(_mm_cmpeq_pd(dz, m)) << 4;
#else
	const double d[6] = {o[0] - p.x, o[1] - -p.x, o[2] - p.y, o[3] - -p.y, o[4] - p.z, o[5] - -p.z};
	double m = d[0];
	for (int k = 1; k < 6; ++k)
		m = d[k] < m ? d[k] : m;
	for (int k = 0; k < 6; ++k)
		least |= (unsigned)(d[k] == m) << k;
#endif
	int best = -1;
	for (; least; least &= least - 1u) {
		int f = pc->box_face[__builtin_ctz(least)];
		best = best < 0 || f < best ? f : best;
	}
	return best;
}

// True when a and b both lie beyond one face of the box grown by `grow` by more than `slack`: then
// hs_clip_segment misses (that face's t lies outside [0, 1] whatever the rounding, for a slack far
// above it), found with 12 comparisons instead of its dots and divisions.
static inline bool hs_part_box_apart(const hs_part_cache *pc, hs_vec3 a, hs_vec3 b, double grow, double slack) {
	const double *o = pc->box_offset;
	double g = grow + slack;
	return (a.x > o[0] + g && b.x > o[0] + g) || (-a.x > o[1] + g && -b.x > o[1] + g) ||
	       (a.y > o[2] + g && b.y > o[2] + g) || (-a.y > o[3] + g && -b.y > o[3] + g) ||
	       (a.z > o[4] + g && b.z > o[4] + g) || (-a.z > o[5] + g && -b.z > o[5] + g);
}

// hs_clip_segment(shape, part, a, b, grow) of a box part (first_face: the part's), for a, b and
// b - a whose coordinates are finite (hs_part_box_takes): each face's dot is the coordinate or its
// negation (part_box.h's first comment), so its num and den are the clip's, and the faces are
// visited in face order with its tie rule and early exits: the same clip, every field.
static inline hs_clip hs_part_box_clip(const hs_part_cache *pc, int first_face, hs_vec3 a, hs_vec3 b, double grow) {
	hs_clip c = {0.0, 1.0, -1, -1, false};
	hs_vec3 d = hs_sub(b, a);
	const double pa[6] = {a.x, -a.x, a.y, -a.y, a.z, -a.z}, pd[6] = {d.x, -d.x, d.y, -d.y, d.z, -d.z};
	for (int i = 0; i < 6; ++i) {
		int k = pc->box_axis[i], f = first_face + i;
		double num = pc->box_offset[k] + grow - pa[k], den = pd[k];
		if (den == 0.0) {
			if (!(num > 0.0))
				return c; // parallel and outside this face's plane
			continue;
		}
		double t = num / den;
		if (den < 0.0) { // entering through this face
			if (t > c.t_in || (t == c.t_in && f < c.face_in)) {
				c.t_in = t;
				c.face_in = f;
			}
		} else if (t < c.t_out || (t == c.t_out && f < c.face_out)) {
			c.t_out = t;
			c.face_out = f;
		}
		if (c.t_in > c.t_out)
			return c; // misses
	}
	c.hit = c.t_in <= c.t_out;
	return c;
}

// 1 when the n points (n even, at least 2) are finite and all lie beyond one face of the box by
// more than `slack`: the segment between any two of them misses (hs_part_box_apart), and so does
// the surface a line sweeps between two of its positions (hs_face_beyond_by holds for that face:
// its dot is the coordinate); 0 when they are finite and do not (nor then do the face scans); -1
// when a coordinate is not finite (their sum is not): the caller's scan decides.
static inline int hs_part_box_beyond_n(const hs_part_cache *pc, const hs_vec3 *q, int n, double slack) {
	const double *o = pc->box_offset;
#if defined(__SSE2__)
	// lanes: points k and k + 1; lo/hi the least and greatest coordinate so far (all finite when the sum is)
	__m128d lx = _mm_set_pd(q[1].x, q[0].x), ly = _mm_set_pd(q[1].y, q[0].y), lz = _mm_set_pd(q[1].z, q[0].z);
	__m128d hx = lx, hy = ly, hz = lz, sum = _mm_add_pd(_mm_add_pd(lx, ly), lz);
	for (int k = 2; k + 1 < n; k += 2) {
		__m128d x = _mm_set_pd(q[k + 1].x, q[k].x), y = _mm_set_pd(q[k + 1].y, q[k].y), z = _mm_set_pd(q[k + 1].z, q[k].z);
		sum = _mm_add_pd(sum, _mm_add_pd(_mm_add_pd(x, y), z));
		lx = _mm_min_pd(lx, x), ly = _mm_min_pd(ly, y), lz = _mm_min_pd(lz, z);
		hx = _mm_max_pd(hx, x), hy = _mm_max_pd(hy, y), hz = _mm_max_pd(hz, z);
	}
	double s = _mm_cvtsd_f64(_mm_add_sd(sum, _mm_unpackhi_pd(sum, sum)));
	if (!(s - s == 0.0))
		return -1;
	// both lanes beyond: lo > o + slack for a + face, hi < -(o + slack) (-c > o + slack; negation is exact)
	const __m128d px = _mm_set1_pd(o[0] + slack), nx = _mm_set1_pd(-(o[1] + slack)), py = _mm_set1_pd(o[2] + slack),
	              ny = _mm_set1_pd(-(o[3] + slack)), pz = _mm_set1_pd(o[4] + slack), nz = _mm_set1_pd(-(o[5] + slack));
	return _mm_movemask_pd(_mm_cmpgt_pd(lx, px)) == 3 || _mm_movemask_pd(_mm_cmplt_pd(hx, nx)) == 3 ||
	       _mm_movemask_pd(_mm_cmpgt_pd(ly, py)) == 3 || _mm_movemask_pd(_mm_cmplt_pd(hy, ny)) == 3 ||
	       _mm_movemask_pd(_mm_cmpgt_pd(lz, pz)) == 3 || _mm_movemask_pd(_mm_cmplt_pd(hz, nz)) == 3;
#else
	double s = 0.0;
	for (int k = 0; k < n; ++k)
		s += q[k].x + q[k].y + q[k].z;
	if (!(s - s == 0.0))
		return -1;
	bool b[6] = {true, true, true, true, true, true};
	for (int k = 0; k < n; ++k) {
		b[0] = b[0] && q[k].x > o[0] + slack, b[1] = b[1] && -q[k].x > o[1] + slack;
		b[2] = b[2] && q[k].y > o[2] + slack, b[3] = b[3] && -q[k].y > o[3] + slack;
		b[4] = b[4] && q[k].z > o[4] + slack, b[5] = b[5] && -q[k].z > o[5] + slack;
	}
	return b[0] || b[1] || b[2] || b[3] || b[4] || b[5];
#endif
}

static inline bool hs_part_box_beyond4(const hs_part_cache *pc, const hs_vec3 q[4], double slack) {
	return hs_part_box_beyond_n(pc, q, 4, slack) == 1;
}

#endif
