// number.c — strict numbers from text: what "1e3", "1/60" and "0x10" mean is decided here once.
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hs_harness.h"
#include "number.h"

static bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Decimal numbers only: [-+]?(d+(.d*)?|.d+)([eE][-+]?d+)? — no hex, no '_', no trailing junk.
static bool is_decimal(const char *s, size_t n) {
	size_t i = 0, digits = 0;
	if (i < n && (s[i] == '+' || s[i] == '-'))
		++i;
	for (; i < n && is_digit(s[i]); ++i)
		++digits;
	if (i < n && s[i] == '.')
		for (++i; i < n && is_digit(s[i]); ++i)
			++digits;
	if (digits == 0)
		return false;
	if (i < n && (s[i] == 'e' || s[i] == 'E')) {
		++i;
		if (i < n && (s[i] == '+' || s[i] == '-'))
			++i;
		size_t start = i;
		while (i < n && is_digit(s[i]))
			++i;
		if (i == start)
			return false;
	}
	return i == n;
}

static char lower(char c) { return (c >= 'A' && c <= 'Z') ? (char)(c - 'A' + 'a') : c; }

// YAML's .inf/.nan and strtod's inf/infinity/nan, in any case and with a sign
static bool is_non_finite_word(const char *s, size_t n) {
	size_t i = 0;
	if (i < n && (s[i] == '+' || s[i] == '-'))
		++i;
	if (i < n && s[i] == '.')
		++i;
	static const char *const words[] = {"inf", "infinity", "nan"};
	for (size_t w = 0; w < 3; ++w) {
		size_t len = strlen(words[w]);
		if (n - i != len)
			continue;
		size_t k = 0;
		while (k < len && lower(s[i + k]) == words[w][k])
			++k;
		if (k == len)
			return true;
	}
	return false;
}

hs_number_kind hs_parse_number(const char *s, size_t n, double *out) {
	if (is_non_finite_word(s, n))
		return HS_NUMBER_NOT_FINITE;
	if (!is_decimal(s, n) || n > 200)
		return HS_NUMBER_SYNTAX;
	char buf[208];
	memcpy(buf, s, n);
	buf[n] = '\0';
	double v = strtod(buf, NULL); // underflow to 0 or a subnormal is fine; ranges are checked later
	if (!isfinite(v))
		return HS_NUMBER_NOT_FINITE;
	*out = v;
	return HS_NUMBER_OK;
}

bool hs_comma_decimal(const char *s, size_t n, char *point, size_t size) {
	size_t i = n > 0 && (s[0] == '+' || s[0] == '-') ? 1 : 0, comma = 0;
	for (size_t k = i; k < n; ++k)
		if (s[k] == ',' && comma == 0 && k > i && k + 1 < n)
			comma = k;
		else if (!is_digit(s[k]))
			return false;
	if (comma == 0 || n >= size)
		return false;
	memcpy(point, s, n);
	point[comma] = '.';
	point[n] = '\0';
	return true;
}

hs_integer_kind hs_parse_integer(const char *s, size_t n, int64_t *out) {
	size_t i = n > 0 && (s[0] == '+' || s[0] == '-') ? 1 : 0;
	if (i == n)
		return HS_INTEGER_SYNTAX;
	for (size_t k = i; k < n; ++k)
		if (!is_digit(s[k]))
			return HS_INTEGER_SYNTAX;
	if (n > 40) // more digits than any int64_t: no buffer needed to know
		return HS_INTEGER_RANGE;
	char buf[48];
	memcpy(buf, s, n);
	buf[n] = '\0';
	errno = 0;
	long long v = strtoll(buf, NULL, 10); // long long: 64 bits on every target we build for
	if (errno == ERANGE)
		return HS_INTEGER_RANGE;
	*out = (int64_t)v;
	return HS_INTEGER_OK;
}

bool hs_unit_quat(const double q[4], double *norm, hs_quat *out) {
	*norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
	if (!(fabs(*norm - 1.0) <= HS_QUAT_NORM_TOLERANCE))
		return false;
	*out = hs_quat_normalize(hs_q(q[0], q[1], q[2], q[3]));
	return true;
}

// The tool's --dt: "a/b" or a number, like the YAML `dt:` (a fraction is exact where 0.0166… is not).
bool hs_scenario_parse_dt(const char *text, double *dt) {
	if (!text)
		return false;
	const char *slash = strchr(text, '/');
	double a, b = 1.0;
	size_t n = slash ? (size_t)(slash - text) : strlen(text);
	if (hs_parse_number(text, n, &a) != HS_NUMBER_OK)
		return false;
	if (slash && (hs_parse_number(slash + 1, strlen(slash + 1), &b) != HS_NUMBER_OK || b == 0.0))
		return false;
	double v = a / b;
	if (!(v >= HS_SCENARIO_MIN_DT && v <= HS_SCENARIO_MAX_DT))
		return false;
	*dt = v;
	return true;
}
