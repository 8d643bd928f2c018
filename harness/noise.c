// noise.c — input noise from GSL's mt19937, explicitly seeded. Determinism: the generator's
// integers and gsl_rng_uniform / gsl_rng_uniform_pos (an integer divided by 2^32) are exact on
// every machine; the Gaussian transform is Box–Muller through the library's own hs_log, hs_cos and
// hs_sin (hs_math.h) and sqrt, never libm's log, sin or cos, whose last bits differ across CPUs —
// which is also why gsl_ran_gaussian (it calls libm's log) is not used.
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "noise.h"

struct hs_noise {
	gsl_rng *rng;
	double stylus_scale; // the stylus's noise times this (a campaign's noise axis)
};

hs_noise *hs_noise_create(unsigned long seed) {
	hs_noise *noise = calloc(1, sizeof *noise);
	if (!noise)
		return NULL;
	noise->rng = gsl_rng_alloc(gsl_rng_mt19937);
	if (!noise->rng) {
		free(noise);
		return NULL;
	}
	gsl_rng_set(noise->rng, seed);
	noise->stylus_scale = 1.0;
	return noise;
}

void hs_noise_destroy(hs_noise *noise) {
	if (!noise)
		return;
	gsl_rng_free(noise->rng);
	free(noise);
}

void hs_noise_set_stylus_scale(hs_noise *noise, double scale) { noise->stylus_scale = scale; }

double hs_noise_uniform(hs_noise *noise) { return gsl_rng_uniform(noise->rng); }

// Two independent N(0, 1) draws (Box–Muller): u1, u2 in (0, 1], r = √(−2 ln u1), θ = 2π u2.
void hs_noise_gaussian_pair(hs_noise *noise, double *a, double *b) {
	double u1 = gsl_rng_uniform_pos(noise->rng), u2 = gsl_rng_uniform_pos(noise->rng);
	double r = sqrt(-2.0 * hs_log(u1)), theta = 2.0 * HS_PI * u2;
	*a = r * hs_cos(theta);
	*b = r * hs_sin(theta);
}

void hs_noise_stylus(hs_noise *noise, hs_vec3 *position, hs_quat *orientation) {
	double n[6]; // x, y, z of the position, then of the rotation vector
	for (int i = 0; i < 6; i += 2)
		hs_noise_gaussian_pair(noise, &n[i], &n[i + 1]);
	double k = noise->stylus_scale;
	*position = hs_add(*position, hs_scale(hs_v3(n[0], n[1], n[2]), HS_STYLUS_NOISE_POSITION * k));
	hs_vec3 rv = hs_scale(hs_v3(n[3], n[4], n[5]), HS_STYLUS_NOISE_ROTATION * k);
	double angle = hs_length(rv);
	if (angle > 0.0)
		*orientation = hs_quat_normalize(
		    hs_quat_mul(hs_quat_from_axis_angle(hs_scale(rv, 1.0 / angle), angle), *orientation));
}

// Three uniform draws in [-a, a), x then y then z.
static hs_vec3 uniform3(hs_noise *noise, double a) {
	double d[3];
	for (int i = 0; i < 3; ++i)
		d[i] = (2.0 * gsl_rng_uniform(noise->rng) - 1.0) * a;
	return hs_v3(d[0], d[1], d[2]);
}

void hs_noise_hand(hs_noise *noise, const hs_noise_options *options, hs_vec3 *wrist, hs_quat *rotation,
                   uint8_t sensors[HS_GLOVE_SENSORS]) {
	if (options->wrist > 0.0)
		*wrist = hs_add(*wrist, uniform3(noise, options->wrist));
	if (options->wrist_rotation > 0.0) { // drawn only when asked: older noisy runs keep their sequence
		hs_vec3 rv = uniform3(noise, options->wrist_rotation);
		double angle = hs_length(rv);
		if (angle > 0.0)
			*rotation = hs_quat_normalize(hs_quat_mul(hs_quat_from_axis_angle(hs_scale(rv, 1.0 / angle), angle), *rotation));
	}
	if (options->glove_units > 0) {
		unsigned long span = 2ul * (unsigned long)options->glove_units + 1ul;
		for (int i = 0; i < HS_GLOVE_SENSORS; ++i) { // integers: -units..+units, each equally likely
			long v = (long)sensors[i] + (long)gsl_rng_uniform_int(noise->rng, span) - options->glove_units;
			sensors[i] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
		}
	}
}

void hs_noise_joints(hs_noise *noise, const hs_noise_options *options, hs_vec3 joints[HS_HAND_POINTS]) {
	for (int i = 0; options->joint > 0.0 && i < HS_HAND_POINTS; ++i)
		joints[i] = hs_add(joints[i], uniform3(noise, options->joint));
}

// GSL's mt19937 state (gsl/rng/mt.c): 624 words of 32 bits, each kept in an unsigned long, and the
// position of the next word. Its size is checked against gsl_rng_size before it is used.
typedef struct mt_state {
	unsigned long mt[HS_NOISE_WORDS - 1];
	int mti;
} mt_state;

static mt_state *mt_of(const hs_noise *noise) {
	return noise && gsl_rng_size(noise->rng) == sizeof(mt_state) ? gsl_rng_state(noise->rng) : NULL;
}

bool hs_noise_save(const hs_noise *noise, uint64_t words[HS_NOISE_WORDS]) {
	const mt_state *m = mt_of(noise);
	if (!m)
		return false;
	for (int i = 0; i < HS_NOISE_WORDS - 1; ++i)
		words[i] = m->mt[i];
	words[HS_NOISE_WORDS - 1] = (uint64_t)(int64_t)m->mti;
	return true;
}

// A generator state a draw can use: 32-bit words (a higher bit made gsl_rng_uniform_int draw
// forever), a position within the words (beyond them a draw read outside the state), and not the
// one state whose 19937 bits are all zero (it draws zeros only: gsl_rng_uniform_pos never ends).
const char *hs_noise_check(const uint64_t words[HS_NOISE_WORDS], int *field) {
	bool zero = (words[0] & 0x80000000u) == 0; // only the top bit of the first word is used
	for (int i = 0; i < HS_NOISE_WORDS - 1; ++i) {
		*field = i;
		if (words[i] > 0xFFFFFFFFu)
			return "is not a 32-bit word";
		zero = zero && (i == 0 || words[i] == 0);
	}
	*field = HS_NOISE_WORDS - 1;
	if (words[HS_NOISE_WORDS - 1] > HS_NOISE_WORDS - 1)
		return "is not a position within the 624 words";
	*field = 0;
	return zero ? "is all zero (the generator would draw zeros for ever)" : NULL;
}

bool hs_noise_load(hs_noise *noise, const uint64_t words[HS_NOISE_WORDS]) {
	mt_state *m = mt_of(noise);
	int field;
	if (!m || hs_noise_check(words, &field))
		return false;
	for (int i = 0; i < HS_NOISE_WORDS - 1; ++i)
		m->mt[i] = (unsigned long)words[i];
	m->mti = (int)words[HS_NOISE_WORDS - 1];
	return true;
}
