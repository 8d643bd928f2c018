// hand_cmd.c — `handspring hand`: the default hand's check points in the wrist frame for a posture
// (so writing a scenario needs no hidden geometry).
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hand_cmd.h"

const char *const hs_hand_usage =
    "usage: handspring hand [--posture open|fist|pinch|point|grasp] [--amount A] [--side right|left]\n"
    "Prints the default hand's 20 check points in the wrist frame (m) for a posture, as CSV\n"
    "(point,name,x,y,z; the names a hand key can place, e.g. index_tip: [x, y, z]), after its\n"
    "dimensions as '#' lines. The wrist frame: x along the fingers, z up out of the back of a\n"
    "palm-down hand, y toward the thumb of a right hand. --amount: 0..1 for fist, pinch and point\n"
    "(default 1), the object's width in m for grasp (default 0.05).\n";

static const char *const finger[5] = {"thumb", "index", "middle", "ring", "little"};
static const char *const joint[4] = {"base", "joint1", "joint2", "tip"};
static const char *const postures[5] = {"open", "fist", "pinch", "point", "grasp"};

int hs_hand_main(int argc, char **argv) {
	int which = 0;
	double amount = -1.0;
	hs_hand_def def = hs_default_hand_def();
	for (int i = 0; i < argc; ++i) {
		const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
		if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
			fputs(hs_hand_usage, stdout);
			return 0;
		}
		if (!v) {
			fprintf(stderr, "handspring hand: %s needs a value\n%s", a, hs_hand_usage);
			return 2;
		}
		++i;
		if (strcmp(a, "--posture") == 0) {
			which = -1;
			for (int k = 0; k < 5; ++k)
				if (strcmp(v, postures[k]) == 0)
					which = k;
			if (which < 0) {
				fprintf(stderr, "handspring hand: --posture must be open, fist, pinch, point or grasp, got '%s'\n", v);
				return 2;
			}
		} else if (strcmp(a, "--amount") == 0) {
			char *end;
			amount = strtod(v, &end);
			if (*end || !(amount >= 0.0)) {
				fprintf(stderr, "handspring hand: --amount needs a number >= 0, got '%s'\n", v);
				return 2;
			}
		} else if (strcmp(a, "--side") == 0 && (strcmp(v, "left") == 0 || strcmp(v, "right") == 0)) {
			def.left = strcmp(v, "left") == 0;
		} else {
			fprintf(stderr, "handspring hand: unknown option '%s %s'\n%s", a, v, hs_hand_usage);
			return 2;
		}
	}
	if (amount < 0.0)
		amount = which == HS_POSTURE_GRASP ? 0.05 : 1.0;
	uint8_t sensors[HS_GLOVE_SENSORS];
	if (hs_hand_posture(&def, (hs_posture)which, amount, sensors) != HS_OK) {
		fprintf(stderr, "handspring hand: posture %s: amount %g is out of range (%s)\n", postures[which], amount,
		        which == HS_POSTURE_GRASP ? "width within [0.01, 0.12] m" : "within [0, 1]");
		return 2;
	}
	hs_vec3 p[HS_HAND_POINTS], lines[HS_HAND_LINES][2];
	hs_hand_kinematics(&def, hs_v3(0, 0, 0), hs_quat_identity(), sensors, p, lines);
	printf("# the default %s hand (hs_default_hand_def), posture %s %g, in the wrist frame (m)\n",
	       def.left ? "left" : "right", postures[which], amount);
	printf("# finger_radius %g m: the check lines run this far from each segment's axis\n", def.finger_radius);
	for (int f = 0; f < 5; ++f)
		printf("# %-6s base at (%g, %g, %g), segments %g, %g, %g m\n", finger[f], def.base[f].x,
		       def.left ? -def.base[f].y : def.base[f].y, def.base[f].z, def.segment_length[f][0],
		       def.segment_length[f][1], def.segment_length[f][2]);
	printf("point,name,x,y,z\n");
	for (int i = 0; i < HS_HAND_POINTS; ++i)
		printf("%d,%s_%s,%.9g,%.9g,%.9g\n", i, finger[i / 4], joint[i % 4], p[i].x, p[i].y, p[i].z);
	return 0;
}
