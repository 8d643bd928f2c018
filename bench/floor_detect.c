// floor_detect.c — the floor's contact check (bench/floor.c): the honest frame's check points and
// lines against its ten 5 cm cubes, written as plainly and as cheaply as the job allows, in
// structures of arrays, scalar with an SSE2 or AVX path for the transforms (same bits: the same
// products and sums in the same order, no fused operations).
//
// Its rules are handspring's end-of-frame ones (docs/model.md §2-3), and no more:
//  - a check point touches a cube when it lies in it and either touched last frame or lay outside
//    the cube a frame ago (it reached it); inside without either it started inside and touches
//    nothing until it is 2 margins clear; a touching point that came off by less than the margin
//    (grasp_release_mm) still touches (a contact on a still cube, none on a moving one);
//  - a check line touches a cube when it enters and leaves it through faces, touched last frame or
//    missed it a frame ago, is not beside a touching check point (an end within the margin of the
//    cube by a point that touches), and did not start inside (the same memory as the points).
// What it leaves out: swept paths through the frame, the trailing-part and hovering filters, the
// grasp decision, carrying, kinematics, the hash. floor.c checks, frame by frame, that on the honest
// frame's input it finds exactly handspring's contacts all the same.
#include <math.h>

#include "floor.h"

#if defined(__AVX__) || defined(__SSE2__)
#include <immintrin.h>
#endif

#define H (0.5 * BENCH_CUBE)

// The rotation of a unit quaternion as a matrix, rows r[0..2] (hs_mat3_from_quat's products).
static void matrix(double w, double x, double y, double z, double r[3][3]) {
	double xx = x * x, yy = y * y, zz = z * z, xy = x * y, xz = x * z, yz = y * z, wx = w * x, wy = w * y, wz = w * z;
	r[0][0] = 1.0 - 2.0 * (yy + zz), r[0][1] = 2.0 * (xy - wz), r[0][2] = 2.0 * (xz + wy);
	r[1][0] = 2.0 * (xy + wz), r[1][1] = 1.0 - 2.0 * (xx + zz), r[1][2] = 2.0 * (yz - wx);
	r[2][0] = 2.0 * (xz - wy), r[2][1] = 2.0 * (yz + wx), r[2][2] = 1.0 - 2.0 * (xx + yy);
}

typedef struct cube_frame {
	double c[3], r[3][3];
} cube_frame;

static cube_frame frame_of(const floor_poses *p, int i) {
	cube_frame f = {{p->x[i], p->y[i], p->z[i]}, {{0}}};
	matrix(p->qw[i], p->qx[i], p->qy[i], p->qz[i], f.r);
	return f;
}

// Body coordinates of n points (b = Rᵀ(p − c)) and three masks: bit i set when point i lies within
// H + g of the centre on every axis, for g = 0, the margin and twice it.
typedef struct masks {
	uint64_t in, near, near2;
} masks;

static void to_body(const cube_frame *f, const double *x, const double *y, const double *z, int n, double *bx,
                    double *by, double *bz, double margin, masks *m) {
	int i = 0;
	m->in = m->near = m->near2 = 0;
#if defined(__AVX__)
	const __m256d cx = _mm256_set1_pd(f->c[0]), cy = _mm256_set1_pd(f->c[1]), cz = _mm256_set1_pd(f->c[2]);
	const __m256d h0 = _mm256_set1_pd(H), h1 = _mm256_set1_pd(H + margin), h2 = _mm256_set1_pd(H + 2.0 * margin);
	const __m256d sign = _mm256_set1_pd(-0.0);
	for (; i + 4 <= n; i += 4) {
		__m256d dx = _mm256_sub_pd(_mm256_loadu_pd(x + i), cx), dy = _mm256_sub_pd(_mm256_loadu_pd(y + i), cy),
		        dz = _mm256_sub_pd(_mm256_loadu_pd(z + i), cz);
		__m256d b[3];
		for (int k = 0; k < 3; ++k) { // column k of R: (r0k, r1k, r2k)
			__m256d s = _mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(f->r[0][k]), dx), _mm256_mul_pd(_mm256_set1_pd(f->r[1][k]), dy));
			b[k] = _mm256_add_pd(s, _mm256_mul_pd(_mm256_set1_pd(f->r[2][k]), dz));
		}
		_mm256_storeu_pd(bx + i, b[0]), _mm256_storeu_pd(by + i, b[1]), _mm256_storeu_pd(bz + i, b[2]);
		__m256d a = _mm256_max_pd(_mm256_max_pd(_mm256_andnot_pd(sign, b[0]), _mm256_andnot_pd(sign, b[1])),
		                          _mm256_andnot_pd(sign, b[2]));
		m->in |= (uint64_t)_mm256_movemask_pd(_mm256_cmp_pd(a, h0, _CMP_LE_OQ)) << i;
		m->near |= (uint64_t)_mm256_movemask_pd(_mm256_cmp_pd(a, h1, _CMP_LE_OQ)) << i;
		m->near2 |= (uint64_t)_mm256_movemask_pd(_mm256_cmp_pd(a, h2, _CMP_LE_OQ)) << i;
	}
#elif defined(__SSE2__)
	const __m128d cx = _mm_set1_pd(f->c[0]), cy = _mm_set1_pd(f->c[1]), cz = _mm_set1_pd(f->c[2]);
	const __m128d h0 = _mm_set1_pd(H), h1 = _mm_set1_pd(H + margin), h2 = _mm_set1_pd(H + 2.0 * margin);
	const __m128d sign = _mm_set1_pd(-0.0);
	for (; i + 2 <= n; i += 2) {
		__m128d dx = _mm_sub_pd(_mm_loadu_pd(x + i), cx), dy = _mm_sub_pd(_mm_loadu_pd(y + i), cy),
		        dz = _mm_sub_pd(_mm_loadu_pd(z + i), cz);
		__m128d b[3];
		for (int k = 0; k < 3; ++k) {
			__m128d s = _mm_add_pd(_mm_mul_pd(_mm_set1_pd(f->r[0][k]), dx), _mm_mul_pd(_mm_set1_pd(f->r[1][k]), dy));
			b[k] = _mm_add_pd(s, _mm_mul_pd(_mm_set1_pd(f->r[2][k]), dz));
		}
		_mm_storeu_pd(bx + i, b[0]), _mm_storeu_pd(by + i, b[1]), _mm_storeu_pd(bz + i, b[2]);
		__m128d a = _mm_max_pd(_mm_max_pd(_mm_andnot_pd(sign, b[0]), _mm_andnot_pd(sign, b[1])), _mm_andnot_pd(sign, b[2]));
		m->in |= (uint64_t)_mm_movemask_pd(_mm_cmple_pd(a, h0)) << i;
		m->near |= (uint64_t)_mm_movemask_pd(_mm_cmple_pd(a, h1)) << i;
		m->near2 |= (uint64_t)_mm_movemask_pd(_mm_cmple_pd(a, h2)) << i;
	}
#endif
	for (; i < n; ++i) {
		double dx = x[i] - f->c[0], dy = y[i] - f->c[1], dz = z[i] - f->c[2], b[3];
		for (int k = 0; k < 3; ++k)
			b[k] = f->r[0][k] * dx + f->r[1][k] * dy + f->r[2][k] * dz;
		bx[i] = b[0], by[i] = b[1], bz[i] = b[2];
		double a = fabs(b[0]) > fabs(b[1]) ? fabs(b[0]) : fabs(b[1]);
		a = fabs(b[2]) > a ? fabs(b[2]) : a;
		m->in |= (uint64_t)(a <= H) << i;
		m->near |= (uint64_t)(a <= H + margin) << i;
		m->near2 |= (uint64_t)(a <= H + 2.0 * margin) << i;
	}
}

// One point in body coordinates, within H + g on every axis.
static bool point_in(const cube_frame *f, double x, double y, double z, double g) {
	double d[3] = {x - f->c[0], y - f->c[1], z - f->c[2]};
	for (int k = 0; k < 3; ++k)
		if (fabs(f->r[0][k] * d[0] + f->r[1][k] * d[1] + f->r[2][k] * d[2]) > H + g)
			return false;
	return true;
}

// The segment a → b (body coordinates) against the box grown by g: the slabs' clip.
static bool segment_hits(const double a[3], const double b[3], double g) {
	double t0 = 0.0, t1 = 1.0, h = H + g;
	for (int k = 0; k < 3; ++k) {
		double d = b[k] - a[k];
		if (d == 0.0) {
			if (fabs(a[k]) > h)
				return false;
			continue;
		}
		double ta = (-h - a[k]) / d, tb = (h - a[k]) / d;
		if (ta > tb) {
			double t = ta;
			ta = tb, tb = t;
		}
		t0 = ta > t0 ? ta : t0;
		t1 = tb < t1 ? tb : t1;
		if (t0 > t1)
			return false;
	}
	return true;
}

static void line_in_body(const cube_frame *f, const floor_hand *hand, int j, double a[3], double b[3]) {
	double da[3] = {hand->lx[j] - f->c[0], hand->ly[j] - f->c[1], hand->lz[j] - f->c[2]};
	double db[3] = {hand->lx[60 + j] - f->c[0], hand->ly[60 + j] - f->c[1], hand->lz[60 + j] - f->c[2]};
	for (int k = 0; k < 3; ++k) {
		a[k] = f->r[0][k] * da[0] + f->r[1][k] * da[1] + f->r[2][k] * da[2];
		b[k] = f->r[0][k] * db[0] + f->r[1][k] * db[1] + f->r[2][k] * db[2];
	}
}

// The first check point of finger segment s (s / 3 · 4 + s % 3); its line j runs beside it and the next.
static int segment_point(int s) { return s / 3 * 4 + s % 3; }


// The check points against cube c: contacts into *found, the memory into *next.
// `before`: the cube where the frame began (a still cube: `now`); `last`: where the frame before began.
// True when segment s's two check points lie beyond one face of the box of half-width r.
static bool segment_clear(const double *bx, const double *by, const double *bz, int s, double r) {
	int a = segment_point(s), b = a + 1;
	return (bx[a] > r && bx[b] > r) || (bx[a] < -r && bx[b] < -r) || (by[a] > r && by[b] > r) ||
	       (by[a] < -r && by[b] < -r) || (bz[a] > r && bz[b] > r) || (bz[a] < -r && bz[b] < -r);
}

// The finger segments some of whose lines may reach the cube, bit s for segment s: a segment's
// lines lie within finger_radius of its axis, so when both its check points lie beyond one face by
// more than finger_radius, so do its four lines. For the segments in `wide` (a line of theirs
// started inside), by finger_radius + `grow`.
static uint32_t segments_near(const double *bx, const double *by, const double *bz, double finger_radius, double grow,
                              uint32_t wide) {
	uint32_t near = 0;
	for (int s = 0; s < 15; ++s)
		near |= (uint32_t)!segment_clear(bx, by, bz, s, H + finger_radius + (wide >> s & 1u ? grow : 0.0)) << s;
	return near;
}

// *segments: the finger segments whose lines need testing (segments_near).
static uint32_t detect_points(const floor_state *st, floor_state *next, const floor_input *in, const floor_hand *prev,
                              int c, const cube_frame *now, const cube_frame *before, const cube_frame *last,
                              uint32_t *segments) {
	double bx[HS_HAND_POINTS], by[HS_HAND_POINTS], bz[HS_HAND_POINTS];
	masks m;
	to_body(now, in->hand.px, in->hand.py, in->hand.pz, HS_HAND_POINTS, bx, by, bz, st->margin, &m);
	// a line that did not start inside touches only the cube itself; one that did, within 2 margins
	uint32_t embedded_segments = 0;
	for (uint64_t e = st->forget ? 0u : st->embed_lines; e; e &= e - 1u)
		embedded_segments |= 1u << (__builtin_ctzll(e) / 4);
	*segments = segments_near(bx, by, bz, st->finger_radius, 2.0 * st->margin, embedded_segments);
	uint32_t embedded = st->forget ? 0u : st->embed_points, found = 0;
	next->embed_points |= embedded & (uint32_t)m.near2; // started inside: nothing until 2 margins clear
	for (uint32_t todo = (uint32_t)m.in & ~embedded; todo; todo &= todo - 1u) {
		int i = __builtin_ctz(todo);
		double x = prev->px[i], y = prev->py[i], z = prev->pz[i];
		if ((st->touch_points >> i & 1u) || !point_in(before, x, y, z, 0.0) || !point_in(last, x, y, z, 0.0))
			found |= 1u << i; // touching, reached it this frame, or the cube came onto it
		else if (!st->forget)
			next->embed_points |= 1u << i;
	}
	uint32_t off = (uint32_t)m.near & ~(uint32_t)m.in & st->touch_points & ~embedded; // came off by < margin
	next->touch_points |= off;
	return found | (in->held >> c & 1u ? 0u : off); // on a moving cube it drives nothing

}

// Check line j's ends now (pa, pb) against cube c as handspring orders its tests.
static bool line_touches(const floor_state *st, floor_state *next, const floor_hand *prev, int j, const double pa[3],
                         const double pb[3], bool ends_out, const cube_frame *before, const cube_frame *last) {
	int a = segment_point(j / 4);
	bool embedded = !st->forget && (st->embed_lines >> j & 1u);
	bool hit = segment_hits(pa, pb, 0.0);
	if (!embedded && !hit)
		return false;
	for (int k = 0; k < 2; ++k) // the line a frame ago beside a point touching then
		if ((st->touch_points >> (a + k) & 1u) &&
		    point_in(before, prev->lx[60 * k + j], prev->ly[60 * k + j], prev->lz[60 * k + j], st->margin))
			return false;
	if (embedded) {
		if (segment_hits(pa, pb, 2.0 * st->margin))
			next->embed_lines |= (uint64_t)1 << j;
		return false;
	}
	if (!ends_out)
		return false; // an end inside: the check points' business
	double qa[3], qb[3], ra[3], rb[3];
	line_in_body(before, prev, j, qa, qb);
	if (!segment_hits(qa, qb, 0.0) || (st->touch_lines >> j & 1u))
		return true; // reached it this frame, or sunk in
	line_in_body(last, prev, j, ra, rb);
	if (!segment_hits(ra, rb, 0.0))
		return true; // the cube came onto it
	if (!st->forget)
		next->embed_lines |= (uint64_t)1 << j;
	return false;
}

// The check lines of the segments in `segments` against the cube, four at a time (one segment's).
static uint64_t detect_lines(const floor_state *st, floor_state *next, const floor_input *in, const floor_hand *prev,
                             uint32_t touching, uint32_t segments, const cube_frame *now, const cube_frame *before,
                             const cube_frame *last) {
	const floor_hand *h = &in->hand;
	uint64_t found = 0;
	for (; segments; segments &= segments - 1u) {
		int s = __builtin_ctz(segments), j0 = 4 * s, a = segment_point(s);
		double ax[4], ay[4], az[4], bx[4], by[4], bz[4];
		masks ma, mb;
		to_body(now, h->lx + j0, h->ly + j0, h->lz + j0, 4, ax, ay, az, st->margin, &ma);
		to_body(now, h->lx + 60 + j0, h->ly + 60 + j0, h->lz + 60 + j0, 4, bx, by, bz, st->margin, &mb);
		for (int e = 0; e < 4; ++e) {
			if (((touching >> a & 1u) && (ma.near >> e & 1u)) || ((touching >> (a + 1) & 1u) && (mb.near >> e & 1u)))
				continue; // beside a touching check point
			// both ends beyond one face (by 2 margins for a line that started inside): it misses
			double far = !st->forget && (st->embed_lines >> (j0 + e) & 1u) ? H + 2.0 * st->margin : H;
			if ((ax[e] > far && bx[e] > far) || (ax[e] < -far && bx[e] < -far) || (ay[e] > far && by[e] > far) ||
			    (ay[e] < -far && by[e] < -far) || (az[e] > far && bz[e] > far) || (az[e] < -far && bz[e] < -far))
				continue;
			double pa[3] = {ax[e], ay[e], az[e]}, pb[3] = {bx[e], by[e], bz[e]};
			bool ends_out = !(ma.in >> e & 1u) && !(mb.in >> e & 1u);
			if (line_touches(st, next, prev, j0 + e, pa, pb, ends_out, before, last))
				found |= (uint64_t)1 << (j0 + e);
		}
	}
	return found;
}

void floor_detect(floor_state *st, const floor_input *in, const floor_input *prev_in, floor_found *out) {
	const floor_hand *prev = &prev_in->hand;
	floor_state next = *st;
	next.touch_points = next.embed_points = 0;
	next.touch_lines = next.embed_lines = 0;
	// the hand's box: the lines lie within finger_radius of the points' axes
	const floor_hand *h = &in->hand;
	double lo[3] = {h->px[0], h->py[0], h->pz[0]}, hi[3] = {h->px[0], h->py[0], h->pz[0]};
	for (int i = 1; i < HS_HAND_POINTS; ++i) {
		double p[3] = {h->px[i], h->py[i], h->pz[i]};
		for (int k = 0; k < 3; ++k) {
			lo[k] = p[k] < lo[k] ? p[k] : lo[k];
			hi[k] = p[k] > hi[k] ? p[k] : hi[k];
		}
	}
	double reach = H * 1.7320508075688772 + st->finger_radius + 2.0 * st->margin + 1e-9;
	for (int c = 0; c < BENCH_FLOOR_CUBES; ++c) {
		out->points[c] = 0;
		out->lines[c] = 0;
		double p[3] = {in->now.x[c], in->now.y[c], in->now.z[c]}, d2 = 0.0;
		for (int k = 0; k < 3; ++k) {
			double d = p[k] < lo[k] ? lo[k] - p[k] : p[k] > hi[k] ? p[k] - hi[k] : 0.0;
			d2 += d * d;
		}
		if (d2 > reach * reach)
			continue; // no part within reach of it
		cube_frame now = frame_of(&in->now, c), before = now, last = frame_of(&prev_in->before, c);
		if (in->held >> c & 1u)
			before = frame_of(&in->before, c);
		uint32_t segments;
		out->points[c] = detect_points(st, &next, in, prev, c, &now, &before, &last, &segments);
		out->lines[c] = detect_lines(st, &next, in, prev, st->touch_points | out->points[c], segments, &now, &before, &last);
		next.touch_points |= out->points[c];
		next.touch_lines |= out->lines[c];
	}
	*st = next;
}
