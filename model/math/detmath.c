// detmath.c — deterministic elementary functions (hs_math.h): sin, cos, tan, atan, atan2, asin,
// acos here; exp, log, pow, cbrt in detmath_exp.c; the exact building blocks in detmath.h.
// glibc's libm takes different paths with and without FMA, so its last bits differ between CPUs;
// these are built from + − × ÷, sqrt, floor and bit operations only (no FMA, no long double), so
// every IEEE-754 binary64 machine gives the same bits. Errors are below 1 ulp over the whole domain
// (measured: `make ulp`, docs/determinism.md). Tables and polynomial coefficients were derived with
// mpmath (Remez minimax, coefficients rounded one by one with the rest refitted).
#include "detmath.h"

// ---- tables (generated with mpmath) ----

// 2/pi in 32-bit words, most significant first: enough for any double exponent (Payne–Hanek)
static const uint32_t two_over_pi[40] = {
	0xa2f9836e, 0x4e441529, 0xfc2757d1, 0xf534ddc0, 0xdb629599, 0x3c439041,
	0xfe5163ab, 0xdebbc561, 0xb7246e3a, 0x424dd2e0, 0x06492eea, 0x09d1921c,
	0xfe1deb1c, 0xb129a73e, 0xe88235f5, 0x2ebb4484, 0xe99c7026, 0xb45f7e41,
	0x3991d639, 0x835339f4, 0x9c845f8b, 0xbdf9283b, 0x1ff897ff, 0xde05980f,
	0xef2f118b, 0x5a0a6d1f, 0x6d367ecf, 0x27cb09b7, 0x4f463f66, 0x9e5fea2d,
	0x7527bac7, 0xebe5f17b, 0x3d0739f7, 0x8a5292ea, 0x6bfb5fb1, 0x1f8d5d08,
	0x56033046, 0xfc7b6bab, 0xf0cfbc20, 0x9af4361d,
};
// pi/2 = P1 + P2 + P3 + P3T, 33 bits each but the last: n*Pk is exact for |n| < 2^20
#define PIO2_1 0x1.921fb54400000p+0
#define PIO2_2 0x1.0b4611a600000p-34
#define PIO2_3 0x1.3198a2e000000p-69
#define PIO2_3T 0x1.b839a252049c1p-104
// pi/2 and pi as hi + lo; 2/pi rounded
#define PIO2_HI 0x1.921fb54442d18p+0
#define PIO2_LO 0x1.1a62633145c07p-54
#define PI_HI 0x1.921fb54442d18p+1
#define PI_LO 0x1.1a62633145c07p-53
#define INV_PIO2 0x1.45f306dc9c883p-1
// atan(i/8) as hi, lo
static const double atan_tab[2 * 9] = {
	0x0.0p+0, 0x0.0p+0,
	0x1.fd5ba9aac2f6ep-4, -0x1.cd37686760c17p-59,
	0x1.f5b75f92c80ddp-3, 0x1.8ab6e3cf7afbdp-57,
	0x1.6f61941e4def1p-2, -0x1.c63aae6f6e918p-56,
	0x1.dac670561bb4fp-2, 0x1.a2b7f222f65e2p-56,
	0x1.1e00babdefeb4p-1, -0x1.928df287a668fp-58,
	0x1.4978fa3269ee1p-1, 0x1.2419a87f2a458p-56,
	0x1.700a7c5784634p-1, -0x1.8c34d25aadef6p-56,
	0x1.921fb54442d18p-1, 0x1.1a62633145c07p-55,
};

// ---- sin, cos, tan ----

// sin(x) = x + x^3 S(x^2) and cos(x) = 1 - x^2/2 + x^4 C(x^2) on |x| <= pi/4 + 0.002
// (relative errors 2^-63.2 and 2^-63.8)
static const double S0 = -0x1.5555555555555p-3, S1 = 0x1.1111111111069p-7, S2 = -0x1.a01a019ffe57fp-13,
                    S3 = 0x1.71de3a33b62dfp-19, S4 = -0x1.ae642c7393a9ap-26, S5 = 0x1.6109da7403777p-33,
                    S6 = -0x1.a00f479550b43p-41;
static const double C0 = 0x1.555555555554ap-5, C1 = -0x1.6c16c16c14e00p-10, C2 = 0x1.a01a019c5c392p-16,
                    C3 = -0x1.27e4f7cd31882p-22, C4 = 0x1.1ee9c3356fde3p-29, C5 = -0x1.8f99cb785236ep-37;

// sin(x + y) as hi + lo for |x| <= pi/4, y the tail of the reduced argument. S0 x^3 is up to a
// tenth of the result, so it is carried exactly: rounding it would cost up to 0.2 ulp.
static dd sin_dd(double x, double y) {
	dd z = two_prod(x, x), v = two_prod(z.hi, x), w = two_prod(v.hi, S0);
	double zh = z.hi;
	double r = S1 + zh * (S2 + zh * (S3 + zh * (S4 + zh * (S5 + zh * S6))));
	// sin(x + y) ~ sin x + y cos x ~ x + S0 x^3 + x^3 z r + y (1 - z/2)
	double tail = (w.lo + S0 * (v.lo + z.lo * x)) + (y + zh * (v.hi * r - 0.5 * y));
	dd s = fast_two_sum(x, w.hi);
	return fast_two_sum(s.hi, s.lo + tail);
}
static double sin_k(double x, double y) {
	dd s = sin_dd(x, y);
	return s.hi + s.lo;
}
// cos(x + y) as hi + lo; x^2 exactly, since its rounding error alone would cost 0.25 ulp
static dd cos_dd(double x, double y) {
	dd z = two_prod(x, x);
	double zh = z.hi;
	double r = zh * zh * (C0 + zh * (C1 + zh * (C2 + zh * (C3 + zh * (C4 + zh * C5)))));
	double hz = 0.5 * zh, w = 1.0 - hz;
	// ((1 - w) - hz) is the exact rounding error of w; cos(x + y) ~ cos x - x y
	double corr = ((1.0 - w) - hz) + (r - (x * y + 0.5 * z.lo));
	return fast_two_sum(w, corr);
}

// Cody–Waite for |x| < 2^20 pi/2: n pi/2 in three exact 33-bit pieces, errors tracked exactly
static unsigned reduce_medium(double x, double *y0, double *y1) {
	double fn = (x * INV_PIO2 + SHIFT) - SHIFT;
	double r = x - fn * PIO2_1; // exact: fn PIO2_1 is exact and close to x
	dd a = two_sum(r, -(fn * PIO2_2));
	dd b = two_sum(a.hi, -(fn * PIO2_3));
	dd y = two_sum(b.hi, (a.lo + b.lo) - fn * PIO2_3T);
	*y0 = y.hi;
	*y1 = y.lo;
	return (unsigned)(int)fn & 3u;
}

// 32 bits of the little-endian multiword p starting at bit pos
static uint32_t bits_at(const uint32_t *p, int pos) {
	int l = pos >> 5, sh = pos & 31;
	return sh ? (p[l] >> sh) | (p[l + 1] << (32 - sh)) : p[l];
}

// Payne–Hanek for |x| >= 2^20 pi/2: only the words of 2/pi that reach the last two integer bits
// and 138 fraction bits of x 2/pi are used, in exact integer arithmetic (valid up to DBL_MAX).
static unsigned reduce_large(double x, double *y0, double *y1) {
	uint64_t ix = bits_of(x);
	int e = (int)((ix >> 52) & 0x7ff) - 1075; // |x| = m 2^e
	uint64_t m = (ix & MANT_MASK) | (1ULL << 52);
	int w0 = e >= 2 ? (e - 2) / 32 : 0; // earlier words add multiples of 4 to x 2/pi
	uint32_t p[10] = {0}, ml[2] = {(uint32_t)m, (uint32_t)(m >> 32)};
	for (int i = 0; i < 2; i++) {
		uint64_t carry = 0;
		for (int j = 0; j < 7; j++) {
			uint64_t t = (uint64_t)ml[i] * two_over_pi[w0 + 6 - j] + p[i + j] + carry;
			p[i + j] = (uint32_t)t;
			carry = t >> 32;
		}
		p[i + 7] = (uint32_t)carry;
	}
	int s = 32 * (w0 + 7) - e; // |x| 2/pi = p 2^-s (mod 4), 191 <= s <= 256
	unsigned q = bits_at(p, s) & 3u;
	uint32_t g[8] = {0}; // fraction, most significant word first
	for (int k = 0; k < 5; k++)
		g[k] = bits_at(p, s - 32 * (k + 1));
	int neg = (int)(g[0] >> 31);
	if (neg) { // fraction >= 1/2: take fraction - 1, whose magnitude is the two's complement
		q++;
		uint32_t c = 1;
		for (int k = 4; k >= 0; k--) {
			uint32_t v = ~g[k] + c;
			c = (c && v == 0) ? 1u : 0u;
			g[k] = v;
		}
	}
	int z = 0;
	while (z < 3 && g[z] == 0) // doubles never come closer than 2^-62 to a multiple of pi/2
		z++;
	static const double scale[4] = {0x1p-64, 0x1p-96, 0x1p-128, 0x1p-160};
	dd f = two_sum((double)g[z] * 0x1p32, (double)g[z + 1]);
	double fh = f.hi * scale[z], fl = (f.lo + ((double)g[z + 2] * 0x1p-32 + (double)g[z + 3] * 0x1p-64)) * scale[z];
	dd pr = two_prod(fh, PIO2_HI); // times pi/2
	dd y = fast_two_sum(pr.hi, pr.lo + (fh * PIO2_LO + fl * PIO2_HI));
	double sg = (neg ? -1.0 : 1.0) * (x < 0 ? -1.0 : 1.0);
	*y0 = sg * y.hi;
	*y1 = sg * y.lo;
	return x < 0 ? (0u - q) & 3u : q & 3u;
}

// x = n pi/2 + y0 + y1 with |y0 + y1| <= pi/4 (about); returns n mod 4. x finite.
static unsigned reduce_pio2(double x, double *y0, double *y1) {
	if (fabs(x) < 0x1.921fb54442d18p+20)
		return reduce_medium(x, y0, y1);
	return reduce_large(x, y0, y1);
}

#define PIO4 0x1.921fb54442d18p-1

double hs_sin(double x) {
	double ax = fabs(x), y0, y1;
	if (ax < PIO4) {
		if (ax < 0x1p-26) // x^3/6 is below a third of an ulp; keeps -0
			return x;
		return sin_k(x, 0.0);
	}
	if (!(ax < INFINITY))
		return x - x; // NaN for NaN and ±inf
	unsigned n = reduce_pio2(x, &y0, &y1);
	dd c;
	switch (n) {
	case 0: return sin_k(y0, y1);
	case 1: c = cos_dd(y0, y1); return c.hi + c.lo;
	case 2: return -(sin_k(y0, y1));
	default: c = cos_dd(y0, y1); return -(c.hi + c.lo);
	}
}

double hs_cos(double x) {
	double ax = fabs(x), y0 = x, y1 = 0.0;
	unsigned n = 0;
	if (ax < 0x1p-27) // x^2/2 is below half an ulp of 1
		return 1.0;
	if (!(ax < INFINITY))
		return x - x;
	if (ax >= PIO4)
		n = reduce_pio2(x, &y0, &y1);
	dd c;
	switch (n) {
	case 0: c = cos_dd(y0, y1); return c.hi + c.lo;
	case 1: return -(sin_k(y0, y1));
	case 2: c = cos_dd(y0, y1); return -(c.hi + c.lo);
	default: return sin_k(y0, y1);
	}
}

// (a.hi + a.lo) / (b.hi + b.lo), one rounding plus a tiny error
static double dd_div(dd a, dd b) {
	double q = a.hi / b.hi;
	dd p = two_prod(q, b.hi);
	double r = ((a.hi - p.hi) - p.lo) + (a.lo - q * b.lo);
	return q + r / b.hi;
}

double hs_tan(double x) {
	double ax = fabs(x), y0 = x, y1 = 0.0;
	unsigned n = 0;
	if (ax < 0x1p-27) // x^3/3 is below a third of an ulp; keeps -0
		return x;
	if (!(ax < INFINITY))
		return x - x;
	if (ax >= PIO4)
		n = reduce_pio2(x, &y0, &y1);
	// sin / cos both carried to ~2^-60, so the quotient is rounded about once
	dd s = sin_dd(y0, y1), c = cos_dd(y0, y1);
	if (n & 1u) {
		dd mc = {-c.hi, -c.lo};
		return dd_div(mc, s);
	}
	return dd_div(s, c);
}

// ---- atan, atan2, asin, acos ----

// atan(t) = t + t^3 A(t^2) on |t| <= 1/16 (relative error 2^-62.6)
static const double A0 = -0x1.5555555555537p-2, A1 = 0x1.99999999637c5p-3, A2 = -0x1.2492482a7fceap-3,
                    A3 = 0x1.c7188204dbebfp-4, A4 = -0x1.70c2fc908f081p-4;

// atan(a + al) as hi + lo for 0 <= a <= 1, al a tail (|al| <= ulp(a)): atan(c) from the table,
// c = i/8 the nearest, plus atan((a - c)/(1 + a c)) with that quotient carried exactly, since it
// is not small next to the result.
static dd atan_dd(double a, double al) {
	int i = (int)(a * 8.0 + 0.5);
	double c = 0.125 * i;
	double num = a - c; // exact (Sterbenz)
	dd p = two_prod(c, a);
	dd d = two_sum(1.0, p.hi);
	double dl = d.lo + (p.lo + c * al);
	double t = num / d.hi;
	dd m = two_prod(t, d.hi);
	double tl = (((num - m.hi) - m.lo) + (al - t * dl)) / d.hi;
	double z = t * t;
	double corr = t * z * (A0 + z * (A1 + z * (A2 + z * (A3 + z * A4))));
	dd h = two_sum(atan_tab[2 * i], t);
	return fast_two_sum(h.hi, h.lo + (atan_tab[2 * i + 1] + (tl + corr)));
}

// k - (h + l) for the double-double constant k = kh + kl (pi/2 or pi) and 0 <= h <= k/2
static dd sub_from(double kh, double kl, dd v) {
	dd s = two_sum(kh, -v.hi);
	dd r = {s.hi, s.lo + (kl - v.lo)};
	return r;
}

double hs_atan(double x) {
	double ax = fabs(x);
	if (!(ax <= 0x1p54)) { // |x| > 2^54, inf, NaN: pi/2 - 1/|x| rounds to pi/2
		if (x != x)
			return x + x;
		return x < 0 ? -PIO2_HI : PIO2_HI;
	}
	if (ax < 0x1p-27) // x^3/3 is below a third of an ulp; keeps -0
		return x;
	dd r;
	if (ax <= 1.0) {
		r = atan_dd(ax, 0.0);
	} else { // pi/2 - atan(1/|x|), 1/|x| carried exactly
		double q = 1.0 / ax;
		dd m = two_prod(q, ax);
		r = sub_from(PIO2_HI, PIO2_LO, atan_dd(q, ((1.0 - m.hi) - m.lo) / ax));
	}
	double v = r.hi + r.lo;
	return x < 0 ? -v : v;
}

// atan2 for the special operands of C99 Annex F (a zero, an infinity or a NaN)
static double atan2_special(double y, double x) {
	if (x != x || y != y)
		return x + y;
	double sy = y < 0 || (y == 0 && bits_of(y) >> 63) ? -1.0 : 1.0;
	int xneg = x < 0 || (x == 0 && bits_of(x) >> 63);
	if (y == 0)
		return xneg ? sy * PI_HI : y;
	if (x == 0)
		return sy * PIO2_HI;
	if (fabs(y) == INFINITY) {
		if (fabs(x) == INFINITY)
			return sy * (xneg ? 0x1.2d97c7f3321d2p+1 : 0x1.921fb54442d18p-1); // 3pi/4, pi/4
		return sy * PIO2_HI;
	}
	return xneg ? sy * PI_HI : sy * 0.0; // x = ±inf, y finite
}

double hs_atan2(double y, double x) {
	double ax = fabs(x), ay = fabs(y);
	if (!(ax < INFINITY && ay < INFINITY) || ax == 0 || ay == 0)
		return atan2_special(y, x);
	int swap = ay > ax; // atan(ay/ax) or pi/2 - atan(ax/ay), the quotient <= 1
	double num = swap ? ax : ay, den = swap ? ay : ax;
	double a = num / den, al = 0.0;
	if (a >= 0x1p-60) { // the tail of the quotient matters: exact remainder on scaled copies
		double k = den > 0x1p400 ? 0x1p-600 : den < 0x1p-400 ? 0x1p600 : 1.0;
		double ns = num * k, ds = den * k; // exact: both stay normal
		dd m = two_prod(a, ds);
		al = ((ns - m.hi) - m.lo) / ds;
	}
	dd r = atan_dd(a, al);
	if (swap)
		r = sub_from(PIO2_HI, PIO2_LO, r);
	if (x < 0)
		r = sub_from(PI_HI, PI_LO, r);
	double v = r.hi + r.lo;
	return y < 0 ? -v : v;
}

// asin(s) = s + s^3 B(s^2) on |s| <= 1/2 (relative error 2^-59)
static const double B[13] = {
	0x1.5555555555577p-3, 0x1.333333332e131p-4, 0x1.6db6db7212680p-5, 0x1.f1c71a94f2db6p-6,
	0x1.6e8bdee042f30p-6, 0x1.1c49f05c8c7dep-6, 0x1.ca1f8d7a77e9bp-7, 0x1.7585893bc3243p-7,
	0x1.613c8f8c07e94p-7, 0x1.e5f5461007570p-9, 0x1.639c9099e0fb1p-6, -0x1.57fdbf98788c8p-6,
	0x1.0b46df1e2795dp-5,
};
// B(z) - B[0] over z
static double asin_poly1(double z) {
	double z2 = z * z; // two Horner chains in z^2 halve the latency
	double odd = B[2] + z2 * (B[4] + z2 * (B[6] + z2 * (B[8] + z2 * (B[10] + z2 * B[12]))));
	double even = B[1] + z2 * (B[3] + z2 * (B[5] + z2 * (B[7] + z2 * (B[9] + z2 * B[11]))));
	return even + z * odd;
}

// asin(s) - s = s z B(z) (z = s^2 + zl) as hi + lo; s z B[0] is up to a tenth of the result, so it
// is carried exactly, as in sin_dd.
static dd asin_tail(double s, double z, double zl) {
	dd v = two_prod(s, z), w = two_prod(v.hi, B[0]);
	double lo = w.lo + (B[0] * (v.lo + s * zl) + v.hi * z * asin_poly1(z));
	return fast_two_sum(w.hi, lo);
}

// For 1/2 <= |x| <= 1: asin(s + sl) - s as hi + lo, with s + sl = sqrt((1 - |x|)/2) and the
// sqrt tail exact, since 2 asin(s) is not small next to the result.
static dd asin_half(double ax, double *s_out) {
	double z = 0.5 * (1.0 - ax); // exact
	double s = sqrt(z), sl = 0.0;
	if (s > 0) {
		dd m = two_prod(s, s);
		sl = ((z - m.hi) - m.lo) / (s + s);
	}
	*s_out = s;
	dd t = asin_tail(s, z, 0.0);
	// d asin/ds ~ 1 + z/2, less the z/3 sl that asin_tail already took in through z = (s + sl)^2
	t.lo += sl * (1.0 + z * 0x1.5555555555555p-3);
	return t;
}

// kh + kl - (a + t.hi + t.lo), rounded once (about): kh + kl = pi/2 or pi, the rest smaller
static double sub3(double kh, double kl, double a, dd t) {
	dd u = two_sum(kh, -a), v = two_sum(u.hi, -t.hi);
	return v.hi + ((u.lo + v.lo) + (kl - t.lo));
}

double hs_asin(double x) {
	double ax = fabs(x), v;
	if (!(ax <= 1.0))
		return (x - x) / (x - x); // NaN, also for NaN
	if (ax < 0x1p-26) // x^3/6 is below a third of an ulp; keeps -0
		return x;
	if (ax < 0.5) {
		dd z = two_prod(x, x), t = asin_tail(x, z.hi, z.lo), s = fast_two_sum(x, t.hi);
		return s.hi + (s.lo + t.lo);
	}
	double s;
	dd c = asin_half(ax, &s);
	dd c2 = {2.0 * c.hi, 2.0 * c.lo};
	v = sub3(PIO2_HI, PIO2_LO, 2.0 * s, c2); // pi/2 - 2 asin(sqrt((1 - x)/2))
	return x < 0 ? -v : v;
}

double hs_acos(double x) {
	double ax = fabs(x);
	if (!(ax <= 1.0))
		return (x - x) / (x - x);
	if (ax < 0.5) { // pi/2 - asin(x)
		dd z = two_prod(x, x);
		return sub3(PIO2_HI, PIO2_LO, x, asin_tail(x, z.hi, z.lo));
	}
	double s;
	dd c = asin_half(ax, &s);
	if (x > 0) { // 2 asin(sqrt((1 - x)/2))
		dd a = fast_two_sum(s, c.hi);
		return 2.0 * (a.hi + (a.lo + c.lo));
	}
	dd c2 = {2.0 * c.hi, 2.0 * c.lo};
	return sub3(PI_HI, PI_LO, 2.0 * s, c2); // pi - 2 asin(sqrt((1 + x)/2))
}
