// harness_internal.h — private declarations shared by the harness's .c files (not installed).
#ifndef HS_HARNESS_INTERNAL_H
#define HS_HARNESS_INTERNAL_H

#include "hs_harness.h"

#if defined(__GNUC__)
#define HS_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define HS_PRINTF(f, a)
#endif

// A path as error messages show it: at most HS_SHOWN_PATH bytes, longer ones as "..." and their
// end, so the line and the reason always fit in an hs_error. Returns path or buf.
#define HS_SHOWN_PATH 200
const char *hs_shown_path(const char *path, char buf[HS_SHOWN_PATH + 4]);

// scenario.c — a strict decimal number (no hex, no words; inf and nan said as such)
typedef enum hs_number_kind { HS_NUMBER_OK, HS_NUMBER_SYNTAX, HS_NUMBER_NOT_FINITE } hs_number_kind;
hs_number_kind hs_parse_number(const char *s, size_t n, double *out);

// input.c — recorded tracker files: a header, then rows of `columns` numbers with t strictly
// increasing (column 1), x y z within ±1000 m (2-4) and qw qx qy qz a unit quaternion within 1e-3
// (5-8: a tracker writes few digits); blank and '#' lines are skipped. The caller checks the rest.
typedef struct hs_record_rows {
	long count;
	double *values; // count × columns
	long *lines;    // each row's line in the file
} hs_record_rows;
// `shown` is how messages write the header.
bool hs_record_read(const char *path, const char *what, const char *header, const char *shown, int columns,
                    long max_rows, hs_record_rows *rows, hs_error *err);
void hs_record_rows_free(hs_record_rows *rows);

// input.c — hand input scripts: keyframes or a recorded glove+tracker file, sampled per frame

typedef struct hs_hand_key {
	double t;      // s
	hs_vec3 wrist; // m
	hs_quat rot;
	double sensors[HS_GLOVE_SENSORS]; // sensor units, interpolated linearly, rounded when applied
} hs_hand_key;

typedef struct hs_hand_script {
	int key_count;
	hs_hand_key *keys; // strictly increasing t
} hs_hand_script;

// The hand at time t: positions and sensors linear between keys, orientation by slerp; before
// the first key and after the last the nearest key holds.
void hs_hand_script_sample(const hs_hand_script *script, double t, hs_vec3 *wrist, hs_quat *rot,
                           uint8_t sensors[HS_GLOVE_SENSORS]);
// Reads a recorded glove+tracker CSV (header t,x,y,z,qw,qx,qy,qz,s0..s17; any rate) into keys.
// Errors are "PATH:LINE: what is wrong".
bool hs_record_load(const char *path, hs_hand_script *script, hs_error *err);

#endif
