// noise.h — input noise: what a real tracker and glove add to the pose and sensors they report.
// Noise is input, not physics (docs/model.md "Noise is input"): the harness draws it from its own seeded
// generator and gives the world the noisy readings, so the model holds no random generator.
#ifndef HS_HARNESS_NOISE_H
#define HS_HARNESS_NOISE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "handspring.h"

// The Fastrak's static accuracy (workbench paper §5.1, [13]): RMS per axis of each reading.
#define HS_STYLUS_NOISE_POSITION (0.03 * 0.0254)        // m: 0.03 inch
#define HS_STYLUS_NOISE_ROTATION (0.15 * HS_PI / 180.0) // rad: 0.15° per component of the rotation vector
// An optical hand tracker's jitter on each joint of a hand it holds still (docs/model.md §1
// "Joint-driven hands"): ±1 mm per coordinate, uniform, the realistic noise's default.
#define HS_JOINT_NOISE 0.001

// What a scenario asks for (model.spring.noise_seed, model.input_noise).
typedef struct hs_noise_options {
	bool stylus;     // Gaussian tracker noise on the stylus pose, every frame
	int glove_units; // hands: each sensor ± this many units, uniform, every frame (0: none)
	double wrist;    // m, hands: each wrist coordinate ± this, uniform, every frame (0: none)
	double wrist_rotation; // rad, hands: each component of a rotation vector ± this, uniform (0: none)
	double joint;    // m, joint-driven hands: each joint coordinate ± this, uniform, every frame (0: none)
} hs_noise_options;

typedef struct hs_noise hs_noise;

// A generator (GSL's mt19937) seeded explicitly; NULL when out of memory.
hs_noise *hs_noise_create(unsigned long seed);
void hs_noise_destroy(hs_noise *noise);
// The stylus's noise is its RMS times `scale` from now on (1 when created).
void hs_noise_set_stylus_scale(hs_noise *noise, double scale);
// A draw in [0, 1) (an integer over 2^32: exact everywhere).
double hs_noise_uniform(hs_noise *noise);
// Two independent N(0, 1) draws (Box–Muller through hs_log, hs_cos, hs_sin: the same on every machine).
void hs_noise_gaussian_pair(hs_noise *noise, double *a, double *b);

// Adds tracker noise to a stylus reading: position + N(0, σp²) per axis, then a rotation whose
// rotation vector is N(0, σr²) per axis, applied before the reading (world frame). Six draws in a
// fixed order: x, y, z, then the rotation vector's x, y, z.
void hs_noise_stylus(hs_noise *noise, hs_vec3 *position, hs_quat *orientation);
// Adds uniform noise to a hand reading: the wrist (x, y, z) ± options->wrist, then a rotation whose
// rotation vector is ± options->wrist_rotation per axis (world frame, before the reading), then each
// sensor in order ± options->glove_units, clamped to 0..255. Nothing is drawn for a zero amplitude.
void hs_noise_hand(hs_noise *noise, const hs_noise_options *options, hs_vec3 *wrist, hs_quat *rotation,
                   uint8_t sensors[HS_GLOVE_SENSORS]);
// Adds uniform noise to a joint-driven hand's joints (wrist frame): each coordinate of each joint,
// in order, ± options->joint. Nothing is drawn for a zero amplitude.
void hs_noise_joints(hs_noise *noise, const hs_noise_options *options, hs_vec3 joints[HS_HAND_POINTS]);

// The generator's state as HS_NOISE_WORDS portable words (state files: scenario_state.c): GSL's
// mt19937 624 words of 32 bits, then the position of the next one (0 to 624). Saving fails when
// this GSL keeps its state otherwise; loading fails (the generator untouched) on a state that
// hs_noise_check refuses.
enum { HS_NOISE_WORDS = 625 };
bool hs_noise_save(const hs_noise *noise, uint64_t words[HS_NOISE_WORDS]);
bool hs_noise_load(hs_noise *noise, const uint64_t words[HS_NOISE_WORDS]);
// NULL for a state a draw can use, else why not, with *field the word at fault (its index).
const char *hs_noise_check(const uint64_t words[HS_NOISE_WORDS], int *field);

#endif
