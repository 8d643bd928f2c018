// fuzz_campaign.c — libFuzzer target for the campaign reader (hs_campaign_load): the input is a
// campaign file in a private folder beside a short scenario it may name (base.yaml, copied from
// tests/fuzz/campaign/). Every input must end in exactly one "PATH:LINE: what" message, or in a
// campaign whose trial count is positive, whose header and first trial's row are written, and
// whose rows read back by hs_campaign_summarize when every trial is run (small campaigns only).
// Never a crash, a leak, undefined behaviour or a hang. Run from the repository's top folder.
#include <stdint.h>

#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv);

enum { MAX_TRIALS_RUN = 8 };

static char campaign_path[256];

int LLVMFuzzerInitialize(int *argc, char ***argv) {
	(void)argc;
	(void)argv;
	fuzz_make_dir();
	fuzz_copy_in("tests/fuzz/campaign/base.yaml", "base.yaml");
	snprintf(campaign_path, sizeof campaign_path, "%s/campaign.yaml", fuzz_dir);
	return 0;
}

// Every trial of a small campaign, then its summary read back: status 0 or 1 (faulted runs).
static void run_all(hs_campaign *c) {
	char *rows = NULL;
	size_t size = 0;
	FILE *out = open_memstream(&rows, &size);
	FUZZ_REQUIRE(out != NULL);
	hs_campaign_write_header(c, out);
	hs_error err;
	for (long t = 0; t < hs_campaign_trials(c); ++t)
		if (!hs_campaign_run_trial(c, t, out, &err)) {
			fuzz_check_message(err.message);
			fclose(out);
			free(rows);
			return;
		}
	fclose(out);
	FILE *in = fmemopen(rows, size, "r");
	FUZZ_REQUIRE(in != NULL);
	int status = hs_campaign_summarize(c, in, "trials.csv", NULL, NULL, &err);
	FUZZ_REQUIRE(status == 0 || status == 1);
	fclose(in);
	free(rows);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
	fuzz_write(campaign_path, data, size);
	hs_error err;
	memset(&err, 'x', sizeof err);
	hs_campaign *c = hs_campaign_load(campaign_path, &err);
	if (!c) {
		fuzz_check_message(err.message);
		return 0;
	}
	long trials = hs_campaign_trials(c);
	FUZZ_REQUIRE(trials > 0);
	FUZZ_REQUIRE(hs_campaign_trial_frames(c, 0) >= 0.0);
	if (trials <= MAX_TRIALS_RUN)
		run_all(c);
	hs_campaign_destroy(c);
	return 0;
}
