// hand_script.h — one hand's input (1999 paper §5.1: glove + tracker): keyframes or a recorded
// glove+tracker file, sampled per frame (hand_script.c).
#ifndef HS_HARNESS_HAND_SCRIPT_H
#define HS_HARNESS_HAND_SCRIPT_H

#include <stdbool.h>
#include <stdint.h>

#include "error.h"
#include "handspring.h"

typedef struct hs_hand_key {
	double t;      // s
	hs_vec3 wrist; // m
	hs_quat rot;
	double sensors[HS_GLOVE_SENSORS]; // sensor units, interpolated linearly, rounded when applied
	hs_vec3 joints[HS_HAND_POINTS];   // a joint-driven hand's check points, wrist frame, linear between keys
	bool tracked; // false: the tracker had lost the hand; pose and sensors are the last tracked ones
} hs_hand_key;

typedef struct hs_hand_script {
	int key_count;
	hs_hand_key *keys; // strictly increasing t
} hs_hand_script;

// The hand at time t: positions and sensors linear between keys, orientation by slerp; before
// the first key and after the last the nearest key holds. Returns whether the hand is tracked at t:
// not when the key at or before t is untracked, or t lies between a tracked key and an untracked
// one; the hand then holds that key's pose and sensors (no interpolation toward the next tracked
// key). Keyframes and glove files are always tracked.
bool hs_hand_script_sample(const hs_hand_script *script, double t, hs_vec3 *wrist, hs_quat *rot,
                           uint8_t sensors[HS_GLOVE_SENSORS]);
// A joint-driven hand's joints at time t (wrist frame), between the keys hs_hand_script_sample
// takes, held as it holds them.
void hs_hand_script_joints(const hs_hand_script *script, double t, hs_vec3 joints[HS_HAND_POINTS]);
// Frees a script's keys and leaves it empty (a load that failed half way).
void hs_hand_script_clear(hs_hand_script *script);
// Reads a recorded glove+tracker CSV (header t,x,y,z,qw,qx,qy,qz,s0..s17; any rate) into keys.
// Errors are "PATH:LINE: what is wrong".
bool hs_record_load(const char *path, hs_hand_script *script, hs_error *err);

// A thrower's error on one hand's script (set by throw_error.c from hs_throw_error): the script runs `delay`
// late; after `from` the wrist is at pivot + turn (scale (w - pivot)) for the script's w, and the
// glove reads the script at t - timing.
typedef struct hs_thrower {
	bool active;
	int hand;
	double delay, from, timing, scale; // s, s, s, 1 + speed
	hs_vec3 pivot;                     // m: the script's wrist at `from`
	hs_quat turn;
} hs_thrower;
// The thrower's hand at time t (hs_hand_script_sample with the errors); whether it is tracked.
bool hs_thrower_sample(const hs_thrower *thrower, const hs_hand_script *script, double t, hs_vec3 *wrist,
                       hs_quat *rot, uint8_t sensors[HS_GLOVE_SENSORS]);

#endif
