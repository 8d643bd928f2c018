// joint_fit.c — the hand's size from a joint recording (scenarios/README.md, "Recorded joint
// positions", fit_hand), so that a hand 20 % smaller or larger than the definition is modelled at
// its own size and its fingertips reach where the recording has them:
//  - each of the 15 finger segments (check point 4f + s to 4f + s + 1: docs/model.md §2) takes the
//    median of its recorded lengths;
//  - the palm — the thumb CMC and the four MCPs in the wrist frame, `base` — is scaled by the median
//    ratio of the recorded distances between bases to the definition's, over the five pairs that
//    no sensor changes: thumb CMC–index MCP, thumb CMC–middle MCP, index–middle, middle–ring and
//    middle–little (the palm arch rolls the ring and little bases about a line through the middle
//    MCP, docs/model.md §1, which keeps their distance to it but not to the others).
// Medians over the tracked samples of the first second: a tracker's outliers do not move them, and
// the hand has its size before it does anything. The fit comes before every pose is fitted (the
// wrist fit carries the definition's own bases onto the recorded ones, joint_pose.c: the poses are
// fitted again after it, joint_input.c).
#include <math.h>
#include <stdlib.h>

#include "joint_fit.h"

static const double WINDOW = 1.0;    // s
static const double SAME = 1e-6;     // m for a length, relative for the palm: nothing measurable
static const double MAX_FACTOR = 3.0; // a hand's size within [1/3, 3] times the definition's
static const int palm_pairs[5][2] = {{0, 4}, {0, 8}, {4, 8}, {8, 12}, {8, 16}}; // check points
static const char *const fingers[5] = {"thumb", "index finger", "middle finger", "ring finger", "little finger"};

static int by_value(const void *a, const void *b) {
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

// The median of n values (sorted in place); n > 0.
static double median(double *v, long n) {
	qsort(v, (size_t)n, sizeof *v, by_value);
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The recorded distance between check points a and b of every window sample recording both,
// divided by `per`, into v; how many.
static long distances(const hs_joint_file *f, long first, long last, int a, int b, double per, double *v) {
	long n = 0;
	for (long k = first; k <= last; ++k) {
		const hs_joint_sample *s = &f->samples[k];
		if (!s->tracked || !(s->present >> a & 1u) || !(s->present >> b & 1u))
			continue;
		hs_vec3 pa = hs_joint_place_point(&f->place, s->points[a]), pb = hs_joint_place_point(&f->place, s->points[b]);
		v[n++] = hs_distance(pa, pb) / per;
	}
	return n;
}

static bool within_factor(double fitted, double given) {
	return fitted >= given / MAX_FACTOR && fitted <= given * MAX_FACTOR;
}

// The median length of every segment recorded in the window, into def.
static bool fit_segments(const char *path, const hs_joint_file *f, long first, long last, hs_hand_def *def,
                         double *v, hs_error *err) {
	for (int finger = 0; finger < 5; ++finger)
		for (int s = 0; s < 3; ++s) {
			long n = distances(f, first, last, 4 * finger + s, 4 * finger + s + 1, 1.0, v);
			if (n == 0)
				continue;
			double *length = &def->segment_length[finger][s], m = median(v, n);
			if (!within_factor(m, *length))
				return hs_set_error(err, path, (unsigned long)f->samples[first].line,
				                    "fit_hand: the %s's segment %d is %.4g mm long (the median of %ld samples in "
				                    "the first second), the hand definition's %.4g mm: more than 3 times either way; are "
				                    "the units right (%s)?",
				                    fingers[finger], s + 1, m * 1000.0, n, *length * 1000.0,
				                    hs_joint_unit_names[f->place.units]);
			if (fabs(m - *length) > SAME)
				*length = m;
		}
	return true;
}

// The palm's scale: the median ratio of the recorded distances between bases to the definition's.
static bool fit_palm(const char *path, const hs_joint_file *f, long first, long last, hs_hand_def *def, double *v,
                     hs_error *err) {
	long n = 0;
	for (int p = 0; p < 5; ++p) {
		int a = palm_pairs[p][0], b = palm_pairs[p][1];
		n += distances(f, first, last, a, b, hs_distance(def->base[a / 4], def->base[b / 4]), v + n);
	}
	double scale = median(v, n); // n > 0: the wrist fit's three points are in every tracked sample
	if (!within_factor(scale, 1.0))
		return hs_set_error(err, path, (unsigned long)f->samples[first].line,
		                    "fit_hand: the recorded palm is %.3g times the hand definition's (the median of %ld "
		                    "distances between the knuckles in the first second): more than 3 times either way; are "
		                    "the units right (%s)?",
		                    scale, n, hs_joint_unit_names[f->place.units]);
	for (int b = 0; b < 5 && fabs(scale - 1.0) > SAME; ++b)
		def->base[b] = hs_scale(def->base[b], scale);
	return true;
}

bool hs_joint_fit_size(const char *path, const hs_joint_file *f, hs_hand_def *def, hs_error *err) {
	long first = 0, last;
	while (!f->samples[first].tracked) // there is one: the loader checked
		first++;
	for (last = first; last + 1 < f->count && f->samples[last + 1].t <= f->samples[first].t + WINDOW; ++last) {
	}
	double *v = malloc((size_t)(last - first + 1) * 5 * sizeof *v);
	if (!v)
		return hs_set_error(err, path, (unsigned long)f->samples[first].line, "out of memory");
	bool ok = fit_segments(path, f, first, last, def, v, err) && fit_palm(path, f, first, last, def, v, err);
	free(v);
	return ok;
}
