// glove.c — the glove's calibration: its 18 sensors read as joint angles and back (0.5° a unit,
// the 1999 paper §5.1; docs/model.md §1), the deadband that holds a reading against sensor noise,
// and the glove table of each sensor value's half turn that the kinematics (hand.c) look up.
#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "glove.h"
#include "lanes2.h"

hs_hand_joints hs_hand_joints_from_sensors(const hs_hand_def *def, const uint8_t sensors[HS_GLOVE_SENSORS]) {
	hs_hand_joints j = {0};
	if (def == NULL || sensors == NULL) // documented: zero angles
		return j;
	const uint8_t *v = sensors;
	j.thumb_roll = (double)v[HS_SENSOR_THUMB_ROLL] * HS_RAD_PER_UNIT;
	j.thumb_mcp = (double)v[HS_SENSOR_THUMB_MCP] * HS_RAD_PER_UNIT;
	j.thumb_ip = (double)v[HS_SENSOR_THUMB_IP] * HS_RAD_PER_UNIT;
	j.thumb_abduction = (double)v[HS_SENSOR_THUMB_ABDUCTION] * HS_RAD_PER_UNIT;
	for (int f = 0; f < 4; f++) {
		j.mcp[f] = (double)v[HS_SENSOR_INDEX_MCP + 2 * f] * HS_RAD_PER_UNIT;
		j.pip[f] = (double)v[HS_SENSOR_INDEX_PIP + 2 * f] * HS_RAD_PER_UNIT;
		j.dip[f] = def->dip_per_pip * j.pip[f];
	}
	for (int a = 0; a < 3; a++)
		j.abduction[a] = (double)v[HS_SENSOR_INDEX_MIDDLE_ABDUCTION + a] * HS_RAD_PER_UNIT;
	j.palm_arch = (double)v[HS_SENSOR_PALM_ARCH] * HS_RAD_PER_UNIT;
	j.wrist_pitch = ((double)v[HS_SENSOR_WRIST_PITCH] - HS_WRIST_ZERO) * HS_RAD_PER_UNIT;
	j.wrist_yaw = ((double)v[HS_SENSOR_WRIST_YAW] - HS_WRIST_ZERO) * HS_RAD_PER_UNIT;
	return j;
}

// nearest sensor unit of an angle (rad), plus `zero`, clamped to 0..255; NaN reads as `zero`
static uint8_t sensor_from_angle(double angle, int zero) {
	if (isnan(angle))
		return (uint8_t)zero;
	double u = round(angle * HS_UNITS_PER_RAD) + (double)zero;
	if (u < 0.0)
		u = 0.0;
	if (u > 255.0)
		u = 255.0;
	return (uint8_t)u;
}

void hs_hand_sensors_from_angles(const hs_hand_joints *joints, uint8_t sensors[HS_GLOVE_SENSORS]) {
	if (joints == NULL || sensors == NULL)
		return;
	const hs_hand_joints *j = joints;
	sensors[HS_SENSOR_THUMB_ROLL] = sensor_from_angle(j->thumb_roll, 0);
	sensors[HS_SENSOR_THUMB_MCP] = sensor_from_angle(j->thumb_mcp, 0);
	sensors[HS_SENSOR_THUMB_IP] = sensor_from_angle(j->thumb_ip, 0);
	sensors[HS_SENSOR_THUMB_ABDUCTION] = sensor_from_angle(j->thumb_abduction, 0);
	for (int f = 0; f < 4; f++) {
		sensors[HS_SENSOR_INDEX_MCP + 2 * f] = sensor_from_angle(j->mcp[f], 0);
		sensors[HS_SENSOR_INDEX_PIP + 2 * f] = sensor_from_angle(j->pip[f], 0);
	}
	for (int a = 0; a < 3; a++)
		sensors[HS_SENSOR_INDEX_MIDDLE_ABDUCTION + a] = sensor_from_angle(j->abduction[a], 0);
	sensors[HS_SENSOR_PALM_ARCH] = sensor_from_angle(j->palm_arch, 0);
	sensors[HS_SENSOR_WRIST_PITCH] = sensor_from_angle(j->wrist_pitch, HS_WRIST_ZERO);
	sensors[HS_SENSOR_WRIST_YAW] = sensor_from_angle(j->wrist_yaw, HS_WRIST_ZERO);
}

void hs_glove_deadband(const uint8_t held[HS_GLOVE_SENSORS], int band, const uint8_t raw[HS_GLOVE_SENSORS],
                       uint8_t used[HS_GLOVE_SENSORS]) {
	int i = 0;
#if defined(__SSE2__)
	// the clamp to [r - band, r + band] on unsigned bytes: a bound beyond 0..255 saturates there,
	// where it cannot move a byte either
	const __m128i b = _mm_set1_epi8((char)band);
	for (; i + 16 <= HS_GLOVE_SENSORS; i += 16) {
		__m128i r = _mm_loadu_si128((const __m128i *)(const void *)&raw[i]);
		__m128i v = _mm_loadu_si128((const __m128i *)(const void *)&held[i]);
		v = _mm_min_epu8(_mm_max_epu8(v, _mm_subs_epu8(r, b)), _mm_adds_epu8(r, b));
		_mm_storeu_si128((__m128i *)(void *)&used[i], v);
	}
#endif
	for (; i < HS_GLOVE_SENSORS; ++i) {
		int r = raw[i], v = held[i];
		v = v < r - band ? r - band : v > r + band ? r + band : v;
		used[i] = (uint8_t)v;
	}
}

void hs_glove_table_build(const hs_hand_def *def, hs_glove_table *table) {
	for (int v = 0; v < 256; ++v) { // each angle as hs_hand_joints_from_sensors and the poses form it
		double a = (double)v * HS_RAD_PER_UNIT;
		table->rows[HS_GLOVE_UNIT][v] = hs_half_turn_of(a);
		table->rows[HS_GLOVE_MINUS][v] = hs_half_turn_of(-a);
		table->rows[HS_GLOVE_HALF][v] = hs_half_turn_of(HS_ARCH_RING_SHARE * a);
		table->rows[HS_GLOVE_DIP][v] = hs_half_turn_of(def->dip_per_pip * a);
		table->rows[HS_GLOVE_WRIST][v] = hs_half_turn_of(((double)v - HS_WRIST_ZERO) * HS_RAD_PER_UNIT);
	}
}
