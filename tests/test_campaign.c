// test_campaign.c — campaigns (docs/campaigns.md): the thrower's errors against the closed form of the
// throw they make, a trial's row independent of how the trials are split, the Wilson interval
// against published values and GSL's z, the summary's checks, grasps lost apart from the thrower's
// misses, the rate per visitor, and every bad campaign file's message.
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <gsl/gsl_cdf.h>
#include <stdlib.h>
#include <string.h>

#include "campaign_internal.h"
#include "test_util.h"

#define THROW "scenarios/hand/throw_at_target.yaml"
#define SMALL "tests/campaigns/tiny.yaml"
#define BAD_DIR "tests/bad_campaign"
#define VISITORS "tests/campaigns/visitors.yaml"
#define GRASP_LOST "tests/campaigns/grasp_lost.yaml"

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
	assert_non_null(strstr(summary, "lo95,hi95,faults,mean_distance,grasp_lost,misses,visitor_throws,visitors,"
	                                "visitor_hits,visitor_rate,visitor_lo95,visitor_hi95,visitor_binomial\n0,"));
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

// The line of the first clause of `path` whose text holds `needle` (the scenario's own lines, so
// the test follows edits of the file).
static unsigned long clause_line(const char *path, const char *needle) {
	FILE *f = fopen(path, "r");
	assert_non_null(f);
	char line[1024];
	unsigned long n = 0, found = 0;
	while (!found && fgets(line, sizeof line, f))
		found = ++n, found = strstr(line, needle) && strstr(line, "- {") ? n : 0;
	fclose(f);
	assert_true(found > 0);
	return found;
}

// A cell's summary row (a static copy of the line, one of two) from a summary CSV text.
static const char *summary_row(const char *summary, long cell) {
	static char rows[2][1024];
	static int k;
	char *row = rows[k = !k], start[24];
	snprintf(start, sizeof start, "\n%ld,", cell);
	const char *at = strstr(summary, start);
	assert_non_null(at);
	snprintf(row, sizeof rows[0], "%.*s", (int)strcspn(at + 1, "\n"), at + 1);
	return row;
}

// The summary CSV of a header and rows.
static void summarize_rows(const hs_campaign *c, const char *rows, char *summary, size_t size) {
	char header[HS_CAMPAIGN_HEADER];
	hs_campaign_header(c, header, sizeof header);
	size_t n = strlen(header) + strlen(rows) + 2;
	char *all = malloc(n);
	assert_non_null(all);
	snprintf(all, n, "%s\n%s", header, rows);
	FILE *in = fmemopen(all, strlen(all), "r"), *out = fmemopen(summary, size, "w");
	hs_error err;
	int status = hs_campaign_summarize(c, in, "rows.csv", out, NULL, &err);
	fclose(in);
	fclose(out);
	if (status != 0)
		fail_msg("%s", err.message);
	free(all);
}

// When the script opens the hand: throw_underarm from its key at the release (2.0 s),
// throw_at_target from its key 10 ms before the campaign's release (1.3 s, opened by 1.31 s).
static void test_glove_opens(void **state) {
	(void)state;
	hs_error err;
	hs_campaign *c = hs_campaign_load(GRASP_LOST, &err), *d = hs_campaign_load(SMALL, &err);
	assert_non_null(c);
	assert_non_null(d);
	assert_near(c->thrower.opens[0], 2.0, 1e-12);
	assert_near(d->thrower.opens[0], 1.3, 1e-12);
	hs_campaign_destroy(c);
	hs_campaign_destroy(d);
}

// Without input noise the grasp holds through every swing; with three times the paper's noise it
// is lost in every throw of this file: those rows say grasp_lost 1, they miss, and the scenario's
// own grasp clauses (its contact sequence or its grasp from 0.8 s to 1.95 s) fail first, which no
// row of a held grasp does. The summary counts them apart from the thrower's misses.
static void test_grasp_lost_apart(void **state) {
	(void)state;
	hs_error err;
	hs_campaign *c = hs_campaign_load(GRASP_LOST, &err);
	if (!c)
		fail_msg("%s", err.message);
	char header[HS_CAMPAIGN_HEADER];
	hs_campaign_header(c, header, sizeof header);
	assert_non_null(strstr(header, ",distance,grasp_lost,hit,clauses"));
	char seq[16], held[16];
	snprintf(seq, sizeof seq, "L%lu", clause_line("scenarios/hand/throw_underarm.yaml", "contact_sequence"));
	snprintf(held, sizeof held, "L%lu", clause_line("scenarios/hand/throw_underarm.yaml", "grasped: true"));
	char *rows = rows_of(c, 0, hs_campaign_trials(c));
	long lost[2] = {0, 0};
	for (const char *row = rows; *row; row = strchr(row, '\n') + 1) {
		long cell = atol(field(row, 1));
		// trial,cell,k,seed,dt,noise,throw_scale,5 draws,distance,grasp_lost,hit,clauses
		bool was_lost = strcmp(field(row, 13), "1") == 0, grasp_clause = strcmp(field(row, 15), seq) == 0 ||
		                                                                  strcmp(field(row, 15), held) == 0;
		assert_int_equal(was_lost, grasp_clause);
		if (was_lost)
			assert_string_equal(field(row, 14), "0"); // no hit
		lost[cell] += was_lost;
	}
	assert_int_equal(lost[0], 0);
	assert_int_equal(lost[1], 12);
	char summary[4096];
	summarize_rows(c, rows, summary, sizeof summary);
	assert_non_null(strstr(summary, ",faults,mean_distance,grasp_lost,misses,visitor_throws,"));
	// cell,dt,noise,throw_scale,trials,hits,rate,lo95,hi95,faults,mean_distance,grasp_lost,misses
	const char *noisy = summary_row(summary, 1);
	assert_string_equal(field(noisy, 5), "0");
	assert_string_equal(field(noisy, 11), "12");
	assert_string_equal(field(noisy, 12), "0");
	hs_campaign_destroy(c);
	free(rows);
}

// Sets the hit (and grasp_lost) field of trial i's row in place: both are one digit.
static void set_outcome(char *rows, long i, char lost, char hit) {
	char *row = rows;
	for (long k = 0; k < i; ++k)
		row = strchr(row, '\n') + 1;
	char *last = row + strcspn(row, "\n");
	while (*--last != ',') { // the clauses field
	}
	last[-1] = hit;
	last[-3] = lost;
}

// Visitors of 3 throws, four a cell of 13 (the 13th throw is no visitor's). Cell 0 hits with
// throws 1, 7 and 8: visitors 0 and 2 hit, 2 of 4, while a throw hits 3 times in 13, so the
// binomial is 1 - (10/13)^3. Cell 1 hits with its 13th throw only: no visitor hits. A grasp lost
// in a throw that hits anyway is a hit, not a grasp lost.
static void test_visitors(void **state) {
	(void)state;
	hs_error err;
	hs_campaign *c = hs_campaign_load(VISITORS, &err);
	if (!c)
		fail_msg("%s", err.message);
	assert_int_equal(c->visitor_throws, 3);
	char *rows = rows_of(c, 0, hs_campaign_trials(c));
	for (long i = 0; i < 26; ++i)
		set_outcome(rows, i, '0', i == 1 || i == 7 || i == 8 || i == 25 ? '1' : '0');
	set_outcome(rows, 7, '1', '1');
	set_outcome(rows, 9, '1', '0');
	char summary[4096];
	summarize_rows(c, rows, summary, sizeof summary);
	// cell,dt,trials,hits,rate,lo95,hi95,faults,mean_distance,grasp_lost,misses,
	// visitor_throws,visitors,visitor_hits,visitor_rate,visitor_lo95,visitor_hi95,visitor_binomial
	const char *first = summary_row(summary, 0), *second = summary_row(summary, 1);
	assert_string_equal(field(first, 3), "3");
	assert_string_equal(field(first, 9), "1");  // trial 9 lost its grasp and missed; trial 7 hit
	assert_string_equal(field(first, 10), "9"); // the thrower's misses: 13 - 3 - 1
	assert_string_equal(field(first, 11), "3");
	assert_string_equal(field(first, 12), "4");
	assert_string_equal(field(first, 13), "2");
	assert_near(atof(field(first, 14)), 0.5, 1e-12);
	assert_near(atof(field(first, 17)), 1.0 - pow(10.0 / 13.0, 3.0), 1e-6);
	double lo, hi;
	hs_wilson_interval(2, 4, &lo, &hi);
	assert_near(atof(field(first, 15)), lo, 1e-6);
	assert_near(atof(field(first, 16)), hi, 1e-6);
	assert_string_equal(field(second, 3), "1");
	assert_string_equal(field(second, 13), "0");
	assert_near(atof(field(second, 14)), 0.0, 0.0);
	assert_near(atof(field(second, 17)), 1.0 - pow(12.0 / 13.0, 3.0), 1e-6);
	hs_campaign_destroy(c);
	free(rows);
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
	    cmocka_unit_test(test_glove_opens),
	    cmocka_unit_test(test_grasp_lost_apart),
	    cmocka_unit_test(test_visitors),
	    cmocka_unit_test(test_bad_campaigns),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
