// stylus_script.h — the spring model's input (workbench paper §3–§5): stylus keyframes or a
// recorded tracker file, sampled per frame.
#ifndef HS_HARNESS_STYLUS_SCRIPT_H
#define HS_HARNESS_STYLUS_SCRIPT_H

#include <stdbool.h>

#include "error.h"
#include "handspring.h"
#include "noise.h"

// One stylus key (keyframes) or sample (recorded file).
typedef struct hs_stylus_key {
	double t;         // s
	hs_vec3 position; // m
	hs_quat rot;
	bool button;
	// the techniques (docs/techniques.md), a step like the button: what the key leaves out it keeps
	hs_technique technique;
	hs_release_mode release;
	bool magnet;
} hs_stylus_key;

typedef struct hs_stylus_script {
	int count;
	hs_stylus_key *keys; // strictly increasing t
	bool techniques;     // keys set the techniques (hs_world_spring_set_technique) every frame
	hs_technique_def gesture; // the magnet's body point and thresholds (the section's `gesture`)
} hs_stylus_script;

// The stylus at the end of a frame ending at time t: positions linear between keys, orientations
// slerped, the button a step from its key's time on (within a slop of 1e-9 s).
void hs_stylus_sample(const hs_stylus_script *script, double t, hs_vec3 *position, hs_quat *rot, bool *button);
// Reads a recorded stylus file (header t,x,y,z,qw,qx,qy,qz,button) into keys.
bool hs_stylus_record_load(const char *path, hs_stylus_script *script, hs_error *err);

// Sets the stylus for the frame that ends at time t, with tracker noise when `noise` is not NULL
// (the spring's anchor then follows the noisy reading, as the tracker daemon's does, §5.1).
// Never allocates.
void hs_stylus_drive(hs_world *world, const hs_stylus_script *script, double t, hs_noise *noise);

#endif
