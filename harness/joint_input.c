// joint_input.c — hands driven by recorded joint positions instead of glove angles: the 21
// landmarks of MediaPipe Hands and the 26 joints of OpenXR's XR_EXT_hand_tracking, turned at load
// time into the glove model's own input — a wrist pose and 18 sensor values per sample — so that
// a joint recording drives exactly the hand a glove would ([H] §3.1: the check points are the
// joints and the fingertips). The format and every rule here: scenarios/README.md, "Recorded
// joint positions". A load:
//  1. reads the file (joint_file.c) and places every point in the scene (joint_frame.c);
//  2. decides which samples are tracked: not `tracked` 0, a confidence not below the minimum, and
//     the three points the wrist fit needs recorded;
//  3. fits each tracked sample's wrist pose (joint_pose.c) and refuses a wrist under the floor or
//     far away (joint_plausible.c);
//  4. takes the hand's size from the recording unless the scenario says fit_hand: false
//     (joint_fit.c), the definition the world's hand is built with, fits the wrist poses again for
//     it, then the sensors (joint_pose.c), in time order;
//  5. gives each untracked sample the last tracked pose and sensors (the first tracked one's
//     before any): the script holds them (hand_script.c).
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "joint_file.h"
#include "joint_fit.h"
#include "joint_input.h"
#include "joint_plausible.h"
#include "joint_pose.h"

hs_joint_options hs_joint_options_default(void) {
	hs_joint_options o;
	memset(&o, 0, sizeof o);
	o.scenario = o.hand = "";
	o.frame.value = o.units.value = -1;
	o.rot = hs_quat_identity();
	o.min_confidence = 0.5;
	o.fit_hand = true;
	return o;
}

// A sample's check points in the scene (the ones not recorded: zero).
static void scene_points(const hs_joint_place *place, const hs_joint_sample *s, hs_vec3 out[HS_HAND_POINTS]) {
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		out[i] = s->present >> i & 1u ? hs_joint_place_point(place, s->points[i]) : hs_v3(0.0, 0.0, 0.0);
}

// Which samples are tracked; none is an error that says why.
static bool classify(const char *path, hs_joint_file *f, double min_confidence, long *tracked, hs_error *err) {
	long off = 0, unsure = 0, lost = 0, n = 0;
	for (long k = 0; k < f->count; ++k) {
		hs_joint_sample *s = &f->samples[k];
		bool said_off = s->tracked_cell == 0, low = s->confidence < min_confidence; // NaN: not said
		bool gone = (s->present & HS_JOINT_RIGID_MASK) != HS_JOINT_RIGID_MASK;
		s->tracked = !said_off && !low && !gone;
		off += said_off;
		unsure += !said_off && low;
		lost += !said_off && !low && gone;
		n += s->tracked;
	}
	*tracked = n;
	if (n == 0)
		return hs_set_error(err, path, (unsigned long)f->samples[0].line,
		                    "no tracked sample: of %ld, %ld say tracked 0, %ld have a confidence below %g, %ld lack a "
		                    "joint the wrist fit needs (thumb CMC, index or middle MCP)",
		                    f->count, off, unsure, min_confidence, lost);
	return true;
}

// The wrist pose of every tracked sample (key k for sample k).
static bool fit_wrists(const char *path, const hs_joint_file *f, const hs_hand_def *def, hs_hand_key *keys,
                       hs_error *err) {
	for (long k = 0; k < f->count; ++k) {
		const hs_joint_sample *s = &f->samples[k];
		keys[k].t = s->t;
		keys[k].tracked = s->tracked;
		if (!s->tracked)
			continue;
		hs_vec3 world[HS_HAND_POINTS];
		scene_points(&f->place, s, world);
		if (!hs_joint_fit_wrist(def, world, &keys[k].rot, &keys[k].wrist))
			return hs_set_error(err, path, (unsigned long)s->line,
			                    "cannot fit the wrist: the thumb CMC and the index and middle MCPs are in one line");
	}
	return true;
}

// The sensors of every tracked sample, from the first tracked sample on; returns the fit's RMS
// distance (mm) over the recorded check points of the tracked samples.
static double fit_sensors(const hs_joint_file *f, const hs_hand_def *def, hs_hand_key *keys) {
	uint8_t s[HS_GLOVE_SENSORS];
	hs_hand_posture(def, HS_POSTURE_OPEN, 0.0, s);
	bool first = true;
	double sum = 0.0;
	long points = 0;
	for (long k = 0; k < f->count; ++k) {
		const hs_joint_sample *sample = &f->samples[k];
		if (!sample->tracked)
			continue;
		hs_vec3 world[HS_HAND_POINTS], local[HS_HAND_POINTS], fitted[HS_HAND_POINTS];
		scene_points(&f->place, sample, world);
		for (int i = 0; i < HS_HAND_POINTS; ++i)
			local[i] = hs_quat_inv_rotate(keys[k].rot, hs_sub(world[i], keys[k].wrist));
		hs_joint_fit_sensors(def, sample->present, local, first, s);
		first = false;
		for (int i = 0; i < HS_GLOVE_SENSORS; ++i)
			keys[k].sensors[i] = s[i];
		hs_hand_kinematics(def, keys[k].wrist, keys[k].rot, s, fitted, NULL);
		if (def->joint_driven) { // the recorded joints, the fitted hand's where one is missing
			hs_hand_kinematics(def, hs_v3(0, 0, 0), hs_quat_identity(), s, keys[k].joints, NULL);
			for (int i = 0; i < HS_HAND_POINTS; ++i)
				if (sample->present >> i & 1u)
					keys[k].joints[i] = local[i];
		}
		for (int i = 0; i < HS_HAND_POINTS; ++i)
			if (sample->present >> i & 1u) {
				points++;
				if (!def->joint_driven)
					sum += hs_length_sq(hs_sub(fitted[i], world[i]));
			}
	}
	return points > 0 ? sqrt(sum / (double)points) * 1000.0 : 0.0;
}

// Untracked samples hold the last tracked pose and sensors; before the first tracked sample, its.
static void hold_untracked(const hs_joint_file *f, hs_hand_key *keys) {
	long held = 0;
	while (!f->samples[held].tracked)
		held++;
	for (long k = 0; k < f->count; ++k) {
		if (f->samples[k].tracked) {
			held = k;
			continue;
		}
		keys[k] = keys[held];
		keys[k].t = f->samples[k].t;
		keys[k].tracked = false;
	}
}

bool hs_joint_record_load(const char *path, const hs_joint_options *options, hs_hand_def *def,
                          hs_hand_script *script, hs_joint_report *report, hs_error *err) {
	script->key_count = 0;
	script->keys = NULL;
	memset(report, 0, sizeof *report);
	hs_joint_file f;
	if (!hs_joint_file_read(path, options, def->left, &f, err))
		return false;
	def->joint_driven = options->drive_joints;
	long tracked = 0;
	bool ok = classify(path, &f, options->min_confidence, &tracked, err);
	hs_hand_key *keys = ok ? calloc((size_t)f.count, sizeof *keys) : NULL;
	if (ok && !keys)
		ok = hs_set_error(err, path, f.header_line, "out of memory");
	// where the hand is, judged with the definition as given; then its size, and the poses again
	// (the wrist fit carries the definition's bases onto the recorded ones)
	ok = ok && fit_wrists(path, &f, def, keys, err) && hs_joint_check_plausible(path, &f, def, keys, tracked, err);
	ok = ok && (!options->fit_hand || (hs_joint_fit_size(path, &f, def, err) && fit_wrists(path, &f, def, keys, err)));
	if (ok) {
		report->rms_mm = fit_sensors(&f, def, keys);
		hold_untracked(&f, keys);
		script->keys = keys;
		script->key_count = (int)f.count;
		report->samples = tracked;
		report->frame_assumed = f.frame_assumed;
		report->units_assumed = f.units_assumed;
		report->header_line = f.header_line;
	} else {
		free(keys);
	}
	hs_joint_file_free(&f);
	return ok;
}
