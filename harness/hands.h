// hands.h — the hands of a scenario: their scripts, definitions and joint-recording fits, read from
// the `hands` section and driven per frame (hands.c).
#ifndef HS_HARNESS_HANDS_H
#define HS_HARNESS_HANDS_H

#include "hand_script.h"
#include "handspring.h"
#include "noise.h"

// What loading a hand's joint recording found (hs_scenario_hand_fit; scenarios/README.md,
// "Recorded joint positions").
typedef struct hs_hand_fit {
	bool joints;   // the hand is driven by a joint recording
	char *record;  // the file as the scenario names it
	long samples;  // tracked samples
	double rms_mm; // the fit's RMS distance over their recorded check points
} hs_hand_fit;

// The hands of a scenario and their scripts.
typedef struct hs_hands {
	int count;
	char **names;
	hs_hand_id *ids;
	hs_hand_script *scripts;
	hs_hand_def *defs; // as added to the world
	hs_hand_fit *fits;
	hs_thrower thrower; // a campaign's throw error (inactive: none)
} hs_hands;

// Gives every hand its pose and glove at time t (the end of the coming frame), with the input
// noise of `options` when `noise` is not NULL, and whether it is tracked (an untracked hand gets
// the pose its script holds).
void hs_hands_drive(hs_world *world, const hs_hands *hands, double t, hs_noise *noise,
                    const hs_noise_options *options);
void hs_hands_free(hs_hands *hands);

#endif
