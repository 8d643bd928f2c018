// number.h — values read from text, parsed one way for YAML and CSV alike: strict decimal
// numbers, 64-bit integers, and the unit-quaternion check (one tolerance everywhere).
#ifndef HS_HARNESS_NUMBER_H
#define HS_HARNESS_NUMBER_H

#include <stddef.h>
#include <stdint.h>

#include "handspring.h"

// A strict decimal number (no hex, no words; inf and nan said as such).
typedef enum hs_number_kind { HS_NUMBER_OK, HS_NUMBER_SYNTAX, HS_NUMBER_NOT_FINITE } hs_number_kind;
hs_number_kind hs_parse_number(const char *s, size_t n, double *out);

// A decimal integer [-+]?[0-9]+ as 64 bits (long is 32 bits on i386): HS_INTEGER_RANGE when it
// does not fit int64_t.
typedef enum hs_integer_kind { HS_INTEGER_OK, HS_INTEGER_SYNTAX, HS_INTEGER_RANGE } hs_integer_kind;
hs_integer_kind hs_parse_integer(const char *s, size_t n, int64_t *out);

// True when s[0..n) is a number written with a decimal comma ("1,5", "-0,25"): `point` (of
// `size` bytes) receives it with a point instead, for a message that says so.
bool hs_comma_decimal(const char *s, size_t n, char *point, size_t size);

// Quaternions typed or recorded must have norm 1 within this; they are then renormalised exactly,
// so every build starts from the same bits.
#define HS_QUAT_NORM_TOLERANCE 1e-6
// True when q = [w, x, y, z] is a unit quaternion within the tolerance; *norm its norm, *out the
// exactly renormalised quaternion.
bool hs_unit_quat(const double q[4], double *norm, hs_quat *out);

#endif
