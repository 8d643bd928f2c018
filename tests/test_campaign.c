// test_campaign.c — campaigns (docs/campaigns.md): the thrower's errors against the closed form of the
// throw they make, a trial's row independent of how the trials are split, the Wilson interval
// against published values and GSL's z, the summary's checks, and every bad campaign file's message.
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <gsl/gsl_cdf.h>
#include <stdlib.h>
#include <string.h>

#include "test_util.h"

#define THROW "scenarios/hand/throw_at_target.yaml"
#define SMALL "tests/campaigns/tiny.yaml"
#define BAD_DIR "tests/bad_campaign"

// v turned by `elevation` about -y (the line across a swing toward +x: up is positive), then by
// `azimuth` about z.
static hs_vec3 turn(hs_vec3 v, double azimuth, double elevation) {
	hs_vec3 up = hs_v3(cos(elevation) * v.x - sin(elevation) * v.z, v.y, sin(elevation) * v.x + cos(elevation) * v.z);
	return hs_v3(cos(azimuth) * up.x - sin(azimuth) * up.y, sin(azimuth) * up.x + cos(azimuth) * up.y, up.z);
}

// throw_at_target's swing, scaled by s = 1 + speed and turned about where the block is at t = 1.2
// (A): the block, last held at t = 1.3 at R' = A + s T (R - A), is let go in frame 79 with
// v' = s T v and flies P(78 + n) = R' + n dt v' + g dt^2 (n - 1) n / 2 (the scenario's closed
// form: it leaves frame 79 where the hand carried it, at v' + g dt / 2); it lands in the first
// frame whose centre is below z = 0.025, back along that frame's motion to where its base met the
// floor, and is rectified to z = 0.025.
static hs_vec3 closed_form_rest(double speed, double azimuth, double elevation) {
	const double dt = 1.0 / 60.0, g = 9.81, s = 1.0 + speed;
	hs_vec3 a = hs_v3(-0.1, 0, 0.25), r = hs_v3(0.147, 0, 0.55), v = hs_v3(2.47, 0, 3.0);
	hs_vec3 rr = hs_add(a, turn(hs_scale(hs_sub(r, a), s), azimuth, elevation));
	hs_vec3 vv = turn(hs_scale(v, s), azimuth, elevation);
	double z = rr.z, before = z;
	int n = 0;
	while (z >= 0.025) {
		++n;
		before = z;
		z = rr.z + n * dt * vv.z - 0.5 * g * dt * dt * (n - 1) * n;
	}
	double f = (z - 0.025) / (z - before); // the part of the frame's fall below the floor
	return hs_v3(rr.x + (n - f) * dt * vv.x, rr.y + (n - f) * dt * vv.y, 0.025);
}

static hs_vec3 rest_with_error(const hs_throw_error *e) {
	hs_error err;
	hs_scenario_options o = {.throw_error = e};
	hs_scenario *s = hs_scenario_load_with(THROW, &o, &err);
	if (!s)
		fail_msg("%s", err.message);
	while (hs_scenario_step(s)) {
	}
	hs_object_state st;
	assert_int_equal(hs_world_object_state(hs_scenario_world(s), hs_world_object_at(hs_scenario_world(s), 0), &st), HS_OK);
	hs_scenario_destroy(s);
	return st.position;
}

// No error: the scenario as written, 0.0432 m past the target's centre (its own clause, 1e-7).
static void test_no_error_is_the_script(void **state) {
	(void)state;
	hs_throw_error e = {.hand = 0, .from = 1.2, .release = 1.31};
	assert_vec3_near(rest_with_error(&e), hs_v3(2.0431934859544350, 0, 0.025), 1e-7);
}

// A faster swing turned 5 deg to the left lands where the closed form puts it.
static void test_speed_and_azimuth_closed_form(void **state) {
	(void)state;
	const double speeds[] = {-0.1, 0.08}, azimuths[] = {0.0872664625997165, -0.05};
	for (int i = 0; i < 2; ++i) {
		hs_throw_error e = {.hand = 0, .from = 1.2, .release = 1.31, .speed = speeds[i], .azimuth = azimuths[i]};
		assert_vec3_near(rest_with_error(&e), closed_form_rest(speeds[i], azimuths[i], 0.0), 1e-7);
	}
}

// Elevation turns the swing about the line across it (up positive): from 50.5 deg up, 6 deg more
// lands shorter and 6 deg less further (45 deg is the longest throw), both where the closed form says.
static void test_elevation_closed_form(void **state) {
	(void)state;
	for (int sign = -1; sign <= 1; sign += 2) {
		double el = sign * 6.0 * HS_PI / 180.0;
		hs_throw_error e = {.hand = 0, .from = 1.2, .release = 1.31, .elevation = el};
		hs_vec3 rest = rest_with_error(&e);
		assert_vec3_near(rest, closed_form_rest(0.0, 0.0, el), 1e-7);
		assert_true(sign > 0 ? rest.x < 2.0 : rest.x > 2.05);
	}
}

// A release 25 ms late at 60 frames/s: the block leaves 1.5 frames further along the swing.
static void test_late_release_goes_further(void **state) {
	(void)state;
	hs_throw_error late = {.hand = 0, .from = 1.2, .release = 1.31, .timing = 0.025};
	hs_throw_error early = late;
	early.timing = -0.025;
	double x_late = rest_with_error(&late).x, x_early = rest_with_error(&early).x;
	assert_true(x_late > 2.0431934859544350 + 0.03);
	assert_true(x_early < 2.0431934859544350 - 0.03);
}

// The script a whole frame late ends where it ends on time (the block waits on the floor): the
// frame clock's phase is all `delay` changes. Half a frame late the release falls elsewhere.
static void test_delay_is_the_frame_phase(void **state) {
	(void)state;
	hs_throw_error frame = {.hand = 0, .from = 1.2, .release = 1.31, .delay = 1.0 / 60.0};
	hs_throw_error half = frame;
	half.delay = 0.5 / 60.0;
	assert_vec3_near(rest_with_error(&frame), hs_v3(2.0431934859544350, 0, 0.025), 1e-12);
	assert_true(fabs(rest_with_error(&half).x - 2.0431934859544350) > 1e-3);
}

// Rows written by one process, by slices in another order, and twice, are the same bytes.
static char *rows_of(hs_campaign *c, long first, long last) {
	char *text = NULL;
	size_t size = 0;
	FILE *f = open_memstream(&text, &size);
	assert_non_null(f);
	hs_error err;
	for (long i = first; i < last; ++i)
		if (!hs_campaign_run_trial(c, i, f, &err))
			fail_msg("%s", err.message);
	fclose(f);
	return text;
}

// The i-th comma-separated field of a row (a static copy).
static const char *field(const char *row, int i) {
	static char buf[4][64];
	static int k;
	k = (k + 1) % 4;
	for (; i > 0 && row; --i)
		row = strchr(row, ',') ? strchr(row, ',') + 1 : NULL;
	assert_non_null(row);
	size_t n = strcspn(row, ",\n");
	snprintf(buf[k], sizeof buf[k], "%.*s", (int)n, row);
	return buf[k];
}

static void test_split_is_the_whole(void **state) {
	(void)state;
	hs_error err;
	hs_campaign *c = hs_campaign_load(SMALL, &err);
	if (!c)
		fail_msg("%s", err.message);
	long n = hs_campaign_trials(c);
	assert_int_equal(n, 2 * 2 * 2 * 5);
	char *whole = rows_of(c, 0, n);
	char *late = rows_of(c, n / 3, n), *early = rows_of(c, 0, n / 3);
	size_t joined = strlen(early) + strlen(late) + 1;
	char *both = malloc(joined);
	assert_non_null(both);
	snprintf(both, joined, "%s%s", early, late);
	assert_string_equal(both, whole);
	hs_campaign_destroy(c);
	c = hs_campaign_load(SMALL, &err); // a fresh load: nothing carried over
	char *again = rows_of(c, 0, n);
	assert_string_equal(again, whole);
	// common random numbers: trial k of every cell has the same seed (field 3) and thrower (7-10)
	char *one = rows_of(c, 2, 3), *other = rows_of(c, 2 + 5 * 7, 3 + 5 * 7);
	for (int f = 3; f <= 10; f += f == 3 ? 4 : 1)
		assert_string_equal(field(one, f), field(other, f));
	assert_string_not_equal(field(one, 4), field(other, 4)); // another dt
	hs_campaign_destroy(c);
	free(whole), free(late), free(early), free(both), free(again), free(one), free(other);
}

// Published Wilson intervals (Newcombe 1998, Table I: 81/263 -> 0.2553-0.3662; 15/148 ->
// 0.0624-0.1605) and the edges; z is GSL's 97.5 % point.
static void test_wilson_interval(void **state) {
	(void)state;
	double lo, hi;
	assert_near(1.959963984540054, gsl_cdf_ugaussian_Pinv(0.975), 1e-15);
	hs_wilson_interval(81, 263, &lo, &hi);
	assert_near(lo, 0.2553, 5e-5);
	assert_near(hi, 0.3662, 5e-5);
	hs_wilson_interval(15, 148, &lo, &hi);
	assert_near(lo, 0.0624, 5e-5);
	assert_near(hi, 0.1605, 5e-5);
	hs_wilson_interval(0, 10, &lo, &hi);
	assert_near(lo, 0.0, 0.0);
	assert_near(hi, 0.2775, 5e-5);
	hs_wilson_interval(10, 10, &lo, &hi);
	assert_near(lo, 0.7225, 5e-5);
	assert_near(hi, 1.0, 1e-15);
	hs_wilson_interval(0, 0, &lo, &hi);
	assert_true(lo == 0.0 && hi == 1.0);
}

// The summary refuses another campaign's rows, a missing trial, a trial out of order, a bad hit.
static int summarize_text(const hs_campaign *c, const char *text, hs_error *err) {
	FILE *in = fmemopen((void *)text, strlen(text), "r");
	assert_non_null(in);
	int status = hs_campaign_summarize(c, in, "rows.csv", NULL, NULL, err);
	fclose(in);
	return status;
}

static void test_summary_checks_the_rows(void **state) {
	(void)state;
	hs_error err;
	hs_campaign *c = hs_campaign_load(SMALL, &err);
	assert_non_null(c);
	char header[1024];
	FILE *h = fmemopen(header, sizeof header, "w");
	hs_campaign_write_header(c, h);
	fclose(h);
	char *rows = rows_of(c, 0, hs_campaign_trials(c));
	size_t n = strlen(header) + strlen(rows) + 1;
	char *all = malloc(n);
	assert_non_null(all);
	snprintf(all, n, "%s%s", header, rows);
	assert_int_equal(summarize_text(c, all, &err), 0);
	// a faulted trial: summarised (a miss, counted in `faults`), status 1
	char *row0 = strchr(all, '\n') + 1, *end0 = strchr(row0, '\n');
	char *comma = end0;
	while (*--comma != ',') {
	}
	size_t m = strlen(all) + 8;
	char *faulted = malloc(m);
	assert_non_null(faulted);
	snprintf(faulted, m, "%.*s,fault%s", (int)(comma - all), all, end0);
	char summary[8192];
	FILE *in = fmemopen(faulted, strlen(faulted), "r"), *sum = fmemopen(summary, sizeof summary, "w");
	assert_int_equal(hs_campaign_summarize(c, in, "rows.csv", sum, NULL, &err), 1);
	fclose(in);
	fclose(sum);
	assert_string_equal(err.message, "rows.csv:1: 1 of 40 trials faulted (a step failed or a value went non-finite): "
	                                 "their clauses column says fault");
	assert_non_null(strstr(summary, "lo95,hi95,faults,mean_distance\n0,"));
	const char *cell0 = strstr(summary, "\n0,") + 1; // cell,dt,noise,threshold,trials,hits,rate,lo,hi,faults
	assert_string_equal(field(cell0, 9), "1");
	assert_string_equal(field(strstr(cell0, "\n1,") + 1, 9), "0");
	free(faulted);
	assert_int_equal(summarize_text(c, "trial,hit\n", &err), 2);
	assert_non_null(strstr(err.message, "rows.csv:1: not this campaign's trials"));
	all[strlen(all) - 1] = '\0'; // drop the last row
	*(strrchr(all, '\n') + 1) = '\0';
	assert_int_equal(summarize_text(c, all, &err), 2);
	assert_string_equal(err.message, "rows.csv:41: 1 of the campaign's 40 trials missing, the first trial 39");
	char *second = strchr(strchr(all, '\n') + 1, '\n') + 1; // row of trial 1 -> claim trial 7
	second[0] = '7';
	assert_int_equal(summarize_text(c, all, &err), 2);
	assert_string_equal(err.message, "rows.csv:3: trial 1 expected (rows sorted by trial, each once), got '7'");
	hs_campaign_destroy(c);
	free(rows), free(all);
}

// Every tests/bad_campaign file: its first line "# expect: MESSAGE" is what the load says.
static void test_bad_campaigns(void **state) {
	(void)state;
	DIR *d = opendir(BAD_DIR);
	assert_non_null(d);
	int files = 0;
	for (struct dirent *e; (e = readdir(d));) {
		if (!strstr(e->d_name, ".yaml"))
			continue;
		char path[512], line[1024] = "";
		snprintf(path, sizeof path, "%s/%s", BAD_DIR, e->d_name);
		FILE *f = fopen(path, "r");
		assert_non_null(f);
		assert_non_null(fgets(line, sizeof line, f));
		fclose(f);
		line[strcspn(line, "\n")] = '\0';
		hs_error err;
		hs_campaign *c = hs_campaign_load(path, &err);
		if (c)
			fail_msg("%s loaded", path);
		if (strcmp(err.message, line + strlen("# expect: ")) != 0)
			fail_msg("%s:\n got      %s\n expected %s", path, err.message, line + strlen("# expect: "));
		++files;
	}
	closedir(d);
	assert_true(files >= 20);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_no_error_is_the_script),
	    cmocka_unit_test(test_speed_and_azimuth_closed_form),
	    cmocka_unit_test(test_elevation_closed_form),
	    cmocka_unit_test(test_late_release_goes_further),
	    cmocka_unit_test(test_delay_is_the_frame_phase),
	    cmocka_unit_test(test_split_is_the_whole),
	    cmocka_unit_test(test_wilson_interval),
	    cmocka_unit_test(test_summary_checks_the_rows),
	    cmocka_unit_test(test_bad_campaigns),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
