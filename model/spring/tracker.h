// tracker.h — the tracker daemon of the spring model (tracker.c): what the spring system and the
// tests call.
#ifndef HS_TRACKER_H
#define HS_TRACKER_H

#include "handspring.h"

// The tracker daemon (§3, §5.1): stylus samples at a fixed rate in a ring buffer, velocity and
// acceleration estimates, rest / motion events with hysteresis. The first four fields come from
// the definition; every other one is state, an entry of spring_state.c's field table.
typedef struct hs_tracker {
	double period;        // s between samples (1 / rate)
	int window;           // samples in the least-squares fit
	double rest_speed;    // m/s: moving → rest below this
	double motion_speed;  // m/s: rest → moving above this
	long next_tick;       // index k of the next sample, due at k · period
	long count;           // samples taken
	int head;             // ring index of the newest sample
	hs_tracker_sample ring[HS_TRACKER_CAPACITY];
	hs_vec3 velocity, acceleration;
	hs_vec3 heading;      // unit direction of the path over the fit window (zero when unknown)
	bool at_rest;
	hs_tracker_event last_event;
	double last_event_time;
	long motion_starts, motion_ends;
} hs_tracker;

// Sets up an empty tracker whose first sample is due at or after time t (s).
void hs_tracker_init(hs_tracker *tracker, const hs_spring_def *def, double t);
// Records one sample exactly as given (noise is input: docs/model.md §10), then updates the estimates
// and events.
void hs_tracker_record(hs_tracker *tracker, double t, hs_vec3 position, hs_quat orientation, bool button);
// Takes every sample due in (t0, t1] (and at t0 if due), interpolating the stylus between its poses
// at t0 and t1 (position linearly, orientation by slerp). The button is the one of the frame.
void hs_tracker_advance(hs_tracker *tracker, double t0, double t1, hs_vec3 p0, hs_quat q0, hs_vec3 p1,
                        hs_quat q1, bool button);
// Lets every sample due up to t1 pass unrecorded (no stylus yet).
void hs_tracker_skip(hs_tracker *tracker, double t1);
// The stored sample of the given age (0 = newest); false when there is none.
bool hs_tracker_sample_at(const hs_tracker *tracker, int age, hs_tracker_sample *out);
// Least-squares quadratic fit over the newest `window` samples; derivatives at the newest sample.
void hs_tracker_estimate(const hs_tracker *tracker, hs_vec3 *velocity, hs_vec3 *acceleration);

#endif
