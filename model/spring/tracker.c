// tracker.c — the tracker daemon of the Responsive Workbench (§3, §5.1).
//
// "A Tracker daemon reads periodically at a rate of 50Hz the tracking data and stores them in a
// buffer. Velocity and acceleration vectors of the user's hand are calculated." (§5.1) and "It can
// detect when the user is at rest, the start and the end of user's motion." (§3)
//
// Readings fixed here:
//  - Resampling: the world runs at its own dt; sample k is due at time k / rate. A step from t0 to
//    t1 takes every sample due in (t0, t1] (a sample within 1e-9 periods of t1 counts as due), with
//    the stylus interpolated between its poses at t0 and t1 — the stylus moves linearly within a
//    frame, as the spring model assumes. The button of a sample is the button of its frame.
//  - Estimates: least-squares fit of p(τ) = c0 + c1 τ + c2 τ² to the newest `window` samples
//    (default 9 = 0.16 s at 50 Hz), velocity c1 and acceleration 2 c2 at the newest sample (no lag
//    on a path of constant acceleration, exact on linear and quadratic paths). With the Fastrak's
//    0.762 mm RMS noise per axis this gives a velocity noise of 0.018 m/s RMS per axis for
//    window 9 at 50 Hz (0.026 for window 7, 0.042 for window 5) and 0.22 m/s² for the acceleration.
//  - No motion against the path: the fit's end-point derivative weighs the window's samples by
//    17/55, 73/660, −83/2310, −201/1540, −40/231, −757/4620, −79/770, 7/660, 29/165 (newest first,
//    window 9): negative weights in the middle, so after an abrupt stop from speed V it reads
//    V, 0.691 V, 0.271 V, −0.113 V, −0.366 V, −0.446 V, −0.362 V, −0.176 V, 0 at 0..8 samples after
//    the stop — a hand that stopped seemed to move backwards at 45 % of its speed, and a release
//    0.1 s after a stop threw the object back. Once the window is full, the part of the
//    velocity that points against the heading (the chord below) is removed: a hand's recent path
//    and its velocity cannot disagree in direction except at such a kink. The stop response is
//    then V, 0.691 V, 0.271 V, 0, 0, ...: the hand is at rest at most 3 samples (60 ms) after the
//    stop whatever its speed (2 below 0.369 m/s, 1 below 0.145 m/s: rest_speed 0.10). The cost: a
//    real reversal reads 0 along the old path until the chord turns, i.e. until the hand is back
//    where the window began (≤ 8 samples). A ramp from rest (constant acceleration a) reads
//    a h (0.1545, 0.6735, 1.594, 2.833, 4.239, 5.643, 6.912) at samples 1-7 (true: a h k): it
//    lags until the window lies on it (at 10 m/s² motion starts at sample 3 instead of 1).
//    test_tracker checks all three responses against these closed forms.
//    A start from rest still overshoots: 0, 0.309 V, 0.729 V, 1.113 V, 1.366 V, 1.446 V, 1.362 V,
//    1.176 V, V (a throw 0.1 s after the hand set off leaves 45 % too fast); the quadratic fit is
//    exact on every constant-acceleration path once the window lies on it.
//  - Heading: the unit direction of the chord from the oldest sample of the fit window to the newest,
//    the hand's recent path (§3: "the path information and current direction of the movement ...
//    are combined"). Unlike the end-point velocity it does not swing backwards when a hand stops
//    abruptly (a quadratic fit overshoots at such a kink), so the selection ray uses it.
//  - Events with hysteresis (judged once the fit window is full): a hand at rest starts moving
//    when its speed exceeds motion_speed (default 0.20 m/s, 11 σ of the noise above); a moving hand
//    comes to rest when its speed falls below rest_speed (default 0.10 m/s, 5.5 σ). Between the two
//    the state does not change, so noise cannot make it flicker.
//  - Noise is input, not physics (docs/model.md "Noise is input"): the tracker records exactly
//    the stylus poses it is given. A caller simulating the Fastrak (0.03 inch = 0.762 mm RMS per
//    axis, 0.15° RMS: its static accuracy) adds that noise to the poses it passes to
//    hs_world_set_stylus — so the spring's anchor sees it too, as §5.1 computes the spring from
//    the tracker data.
#include <string.h>

#include "tracker.h"

// a sample within this fraction of a period of the frame end is taken in that frame
#define HS_TICK_SLOP 1e-9

void hs_tracker_init(hs_tracker *tracker, const hs_spring_def *def, double t) {
	memset(tracker, 0, sizeof *tracker);
	tracker->period = 1.0 / def->tracker_rate;
	tracker->window = def->tracker_window;
	tracker->rest_speed = def->rest_speed;
	tracker->motion_speed = def->motion_speed;
	tracker->next_tick = (long)ceil(t / tracker->period - HS_TICK_SLOP);
	tracker->head = HS_TRACKER_CAPACITY - 1;
	tracker->at_rest = true;
	tracker->last_event = HS_TRACKER_EVENT_NONE;
}

// the sample of the given age, 0 ≤ age < stored samples
static const hs_tracker_sample *ring_at(const hs_tracker *tracker, int age) {
	return &tracker->ring[(tracker->head - age + HS_TRACKER_CAPACITY) % HS_TRACKER_CAPACITY];
}

bool hs_tracker_sample_at(const hs_tracker *tracker, int age, hs_tracker_sample *out) {
	long stored = tracker->count < HS_TRACKER_CAPACITY ? tracker->count : HS_TRACKER_CAPACITY;
	if (age < 0 || age >= stored)
		return false;
	*out = *ring_at(tracker, age);
	return true;
}

// y = c0 + c1 τ + c2 τ² by least squares, τ in periods relative to the newest sample and y relative
// to the newest position (small numbers: no cancellation against large coordinates).
void hs_tracker_estimate(const hs_tracker *tracker, hs_vec3 *velocity, hs_vec3 *acceleration) {
	long stored = tracker->count < HS_TRACKER_CAPACITY ? tracker->count : HS_TRACKER_CAPACITY;
	int n = (int)(stored < tracker->window ? stored : tracker->window);
	*velocity = hs_v3(0.0, 0.0, 0.0);
	*acceleration = hs_v3(0.0, 0.0, 0.0);
	if (n < 2)
		return;
	const hs_tracker_sample *newest = ring_at(tracker, 0);
	if (n == 2) { // two samples: a difference quotient, no acceleration
		const hs_tracker_sample *older = ring_at(tracker, 1);
		double dt = newest->time - older->time;
		if (dt > 0.0)
			*velocity = hs_scale(hs_sub(newest->position, older->position), 1.0 / dt);
		return;
	}
	double h = tracker->period;
	double m0 = 0, m1 = 0, m2 = 0, m3 = 0, m4 = 0; // Σ τ^k
	hs_vec3 r0 = {0, 0, 0}, r1 = {0, 0, 0}, r2 = {0, 0, 0}; // Σ y τ^k
	for (int age = 0; age < n; ++age) {
		const hs_tracker_sample *s = ring_at(tracker, age);
		double tau = (s->time - newest->time) / h, tau2 = tau * tau;
		hs_vec3 y = hs_sub(s->position, newest->position);
		m0 += 1.0;
		m1 += tau;
		m2 += tau2;
		m3 += tau2 * tau;
		m4 += tau2 * tau2;
		r0 = hs_add(r0, y);
		r1 = hs_mul_add(r1, tau, y);
		r2 = hs_mul_add(r2, tau2, y);
	}
	// inverse of the symmetric normal matrix [[m0 m1 m2] [m1 m2 m3] [m2 m3 m4]] by cofactors;
	// only its rows for c1 and c2 are needed
	double a11 = m2 * m4 - m3 * m3, a12 = m2 * m3 - m1 * m4, a13 = m1 * m3 - m2 * m2;
	double a22 = m0 * m4 - m2 * m2, a23 = m1 * m2 - m0 * m3, a33 = m0 * m2 - m1 * m1;
	double det = m0 * a11 + m1 * a12 + m2 * a13;
	if (!(det > 0.0))
		return; // repeated sample times: no estimate
	double inv = 1.0 / det;
	// c1 = (a12 r0 + a22 r1 + a23 r2) / det, c2 = (a13 r0 + a23 r1 + a33 r2) / det
	hs_vec3 c1 = hs_scale(hs_add(hs_add(hs_scale(r0, a12), hs_scale(r1, a22)), hs_scale(r2, a23)), inv);
	hs_vec3 c2 = hs_scale(hs_add(hs_add(hs_scale(r0, a13), hs_scale(r1, a23)), hs_scale(r2, a33)), inv);
	*velocity = hs_scale(c1, 1.0 / h);
	*acceleration = hs_scale(c2, 2.0 / (h * h));
}

void hs_tracker_record(hs_tracker *tracker, double t, hs_vec3 position, hs_quat orientation, bool button) {
	tracker->head = (tracker->head + 1) % HS_TRACKER_CAPACITY;
	hs_tracker_sample *s = &tracker->ring[tracker->head];
	s->time = t;
	s->position = position;
	s->orientation = orientation;
	s->button = button;
	tracker->count++;

	hs_tracker_estimate(tracker, &tracker->velocity, &tracker->acceleration);
	if (tracker->count < tracker->window)
		return; // too few samples: a short fit is too noisy to call motion (σ_v × 5 at 3 samples)
	// the path over the fit window: from its oldest sample to the newest
	hs_vec3 chord = hs_sub(position, ring_at(tracker, tracker->window - 1)->position);
	double chord_len = hs_length(chord);
	tracker->heading = chord_len > 0.0 ? hs_scale(chord, 1.0 / chord_len) : hs_v3(0.0, 0.0, 0.0);
	// the fit does not run against the path it was fitted to: the part against the heading is the
	// quadratic's overshoot at a stop (a kink), not motion; drop it
	double back = hs_dot(tracker->velocity, tracker->heading);
	if (back < 0.0)
		tracker->velocity = hs_mul_add(tracker->velocity, -back, tracker->heading);
	double speed = hs_length(tracker->velocity);
	if (tracker->at_rest && speed > tracker->motion_speed) {
		tracker->at_rest = false;
		tracker->last_event = HS_TRACKER_EVENT_MOTION_START;
		tracker->last_event_time = t;
		tracker->motion_starts++;
	} else if (!tracker->at_rest && speed < tracker->rest_speed) {
		tracker->at_rest = true;
		tracker->last_event = HS_TRACKER_EVENT_MOTION_END;
		tracker->last_event_time = t;
		tracker->motion_ends++;
	}
}

static bool due(const hs_tracker *tracker, double t1) {
	return (double)tracker->next_tick * tracker->period <= t1 + HS_TICK_SLOP * tracker->period;
}

void hs_tracker_advance(hs_tracker *tracker, double t0, double t1, hs_vec3 p0, hs_quat q0, hs_vec3 p1,
                        hs_quat q1, bool button) {
	double span = t1 - t0;
	while (due(tracker, t1)) {
		double t = (double)tracker->next_tick * tracker->period;
		double f = span > 0.0 ? (t - t0) / span : 1.0;
		f = f < 0.0 ? 0.0 : (f > 1.0 ? 1.0 : f);
		hs_tracker_record(tracker, t, hs_lerp(p0, p1, f), hs_quat_slerp(q0, q1, f), button);
		tracker->next_tick++;
	}
}

void hs_tracker_skip(hs_tracker *tracker, double t1) {
	while (due(tracker, t1))
		tracker->next_tick++;
}
