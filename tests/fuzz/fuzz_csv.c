// fuzz_csv.c — libFuzzer target for the CSV readers behind `handspring check` and `campaign
// --summarize`: hs_trajectory_compare and hs_campaign_summarize. The input's first byte picks the
// reader: 0 the input as the golden against a fixed trajectory (tests/fuzz/campaign/base.yaml's
// run), 1 the fixed trajectory as the golden against the input, 2 the input as the trial CSV of
// a fixed campaign (tests/fuzz/campaign/summary.yaml). A comparison must answer with a one-line
// reason or a match; a summary with 0, 1, or 2 and one "PATH:LINE: what" message. Never a crash, a
// leak, undefined behaviour or a hang. Run from the repository's top folder (make fuzz does).
#include <stdint.h>

#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv);

static char *trajectory;
static size_t trajectory_size;
static hs_campaign *campaign;

int LLVMFuzzerInitialize(int *argc, char ***argv) {
	(void)argc;
	(void)argv;
	fuzz_make_dir();
	fuzz_copy_in("tests/fuzz/campaign/base.yaml", "base.yaml");
	fuzz_copy_in("tests/fuzz/campaign/summary.yaml", "summary.yaml");
	char path[256];
	hs_error err;
	snprintf(path, sizeof path, "%s/base.yaml", fuzz_dir);
	hs_scenario *s = hs_scenario_load(path, &err);
	snprintf(path, sizeof path, "%s/summary.yaml", fuzz_dir);
	campaign = hs_campaign_load(path, &err);
	FILE *out = open_memstream(&trajectory, &trajectory_size);
	FUZZ_REQUIRE(s != NULL && campaign != NULL && out != NULL);
	hs_trajectory_write_header(out);
	hs_trajectory_write_frame(out, s);
	while (hs_scenario_step(s))
		hs_trajectory_write_frame(out, s);
	fclose(out);
	hs_scenario_destroy(s);
	return 0;
}

static void compare(const uint8_t *data, size_t size, bool input_is_golden) {
	FILE *input = size ? fmemopen((void *)data, size, "r") : tmpfile();
	FILE *fixed = fmemopen(trajectory, trajectory_size, "r");
	FUZZ_REQUIRE(input != NULL && fixed != NULL);
	char why[512];
	memset(why, 'x', sizeof why);
	bool same = input_is_golden ? hs_trajectory_compare(input, fixed, HS_GOLDEN_TOLERANCE, "fuzz", why, sizeof why)
	                            : hs_trajectory_compare(fixed, input, HS_GOLDEN_TOLERANCE, "fuzz", why, sizeof why);
	FUZZ_REQUIRE(same ? why[0] == '\0' : strncmp(why, "fuzz: ", 6) == 0 && strchr(why, '\n') == NULL);
	fclose(input);
	fclose(fixed);
}

static void summarize(const uint8_t *data, size_t size) {
	FILE *input = size ? fmemopen((void *)data, size, "r") : tmpfile();
	FILE *null = fopen("/dev/null", "w");
	FUZZ_REQUIRE(input != NULL && null != NULL);
	hs_error err;
	memset(&err, 'x', sizeof err);
	int status = hs_campaign_summarize(campaign, input, "trials.csv", null, null, &err);
	FUZZ_REQUIRE(status >= 0 && status <= 2);
	if (status != 0)
		fuzz_check_message(err.message);
	fclose(input);
	fclose(null);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
	if (size < 1)
		return 0;
	if (data[0] % 3 == 2)
		summarize(data + 1, size - 1);
	else
		compare(data + 1, size - 1, data[0] % 3 == 0);
	return 0;
}
