// campaign_summary.c — a campaign's trial rows, summed up per cell: trials, hits, the hit rate and
// its Wilson score interval (95 %), the mean distance to the target; with a thrower the misses
// split into grasps lost in the swing and the thrower's misses, and the rate per visitor (a
// visitor: visitor_throws consecutive trials of a cell, hit when any of them hits; beside it the
// binomial 1 - (1 - rate)^N). The rows are read back from the merged CSV, so the summary of a run
// spread over many machines is the summary of the same bytes as a run on one.
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "campaign_internal.h"
#include "error.h"
#include "file_read.h"

// z of a two-sided 95 % interval: gsl_cdf_ugaussian_Pinv(0.975) (test_campaign checks it against
// GSL), written out so the interval does not depend on a libm's log.
#define WILSON_Z 1.959963984540054

void hs_wilson_interval(long hits, long n, double *lo, double *hi) {
	if (n <= 0) {
		*lo = 0.0;
		*hi = 1.0;
		return;
	}
	double p = (double)hits / (double)n, z2 = WILSON_Z * WILSON_Z, nn = (double)n;
	double denom = 1.0 + z2 / nn;
	double centre = (p + z2 / (2.0 * nn)) / denom;
	double half = WILSON_Z * sqrt(p * (1.0 - p) / nn + z2 / (4.0 * nn * nn)) / denom;
	*lo = centre - half < 0.0 ? 0.0 : centre - half;
	*hi = centre + half > 1.0 ? 1.0 : centre + half;
}

typedef struct cell_sum {
	long trials, hits, faults;
	long lost;                  // misses (not faulted) whose grasp was lost in the swing
	long visitors, visitor_hits; // complete groups of visitor_throws trials; those with a hit
	bool group_hit;             // the current group has a hit so far
	double distance;            // summed in trial order
} cell_sum;

// The fields of one row, split in place at the commas; -1 when there are more than `most`.
static int split(char *line, char **field, int most) {
	int n = 0;
	for (char *s = line;; ++s) {
		if (n == most)
			return -1;
		field[n++] = s;
		s = strchr(s, ',');
		if (!s)
			return n;
		*s = '\0';
	}
}

// A whole decimal field: the trial index or 0/1.
static bool whole(const char *text, long *out) {
	char *end;
	long v = strtol(text, &end, 10);
	if (end == text || *end)
		return false;
	*out = v;
	return true;
}

// Trial k of a cell belongs to visitor k / visitor_throws; a last group cut short by the cell's
// end is no visitor.
static void count_visitor(const hs_campaign *c, long k, bool hit, cell_sum *s) {
	long n = c->visitor_throws;
	if (n < 1 || k >= c->per_cell / n * n)
		return;
	s->group_hit = (k % n != 0 && s->group_hit) || hit;
	if (k % n == n - 1) {
		s->visitors++;
		s->visitor_hits += s->group_hit;
	}
}

// Row `expect`: its trial is `expect`, its field count the header's, hit 0 or 1, a finite distance.
static bool read_row(const hs_campaign *c, char *line, long expect, int fields, cell_sum *sums, const char *path,
                     unsigned long at, hs_error *err) {
	char *f[HS_CAMPAIGN_MAX_AXES + 12];
	long trial, hit;
	if (split(line, f, HS_CAMPAIGN_MAX_AXES + 12) != fields)
		return hs_set_error(err, path, at, "a row of %d fields, like the header, expected", fields);
	if (!whole(f[0], &trial) || trial != expect)
		return hs_set_error(err, path, at, "trial %ld expected (rows sorted by trial, each once), got '%.20s'", expect, f[0]);
	if (!whole(f[fields - 2], &hit) || (hit != 0 && hit != 1))
		return hs_set_error(err, path, at, "'hit' must be 0 or 1, got '%.20s'", f[fields - 2]);
	int grasp = hs_campaign_watches_grasp(c) ? 1 : 0, distance = fields - 3 - grasp;
	long lost = 0;
	if (grasp && (!whole(f[fields - 3], &lost) || (lost != 0 && lost != 1)))
		return hs_set_error(err, path, at, "'grasp_lost' must be 0 or 1, got '%.20s'", f[fields - 3]);
	cell_sum *s = &sums[trial / c->per_cell];
	bool fault = strcmp(f[fields - 1], "fault") == 0;
	s->trials++;
	s->hits += hit;
	s->faults += fault;
	s->lost += lost && !hit && !fault;
	if (c->target.given) {
		char *end;
		double d = strtod(f[distance], &end);
		if (end == f[distance] || *end || !isfinite(d))
			return hs_set_error(err, path, at, "'distance' must be a finite number, got '%.20s'", f[distance]);
		s->distance += d;
	}
	count_visitor(c, trial % c->per_cell, hit != 0, s);
	return true;
}

// A row of the trial CSV: the header's fields of at most HS_CAMPAIGN_MAX_WORD bytes or numbers of
// 17 digits fit many times over; a longer line (a file of no line breaks, /dev/zero) is refused at
// once. Rows are counted against the campaign's trials, so the file's size is bounded too.
#define SUMMARY_MAX_LINE ((size_t)64 << 10)

// The next line; false at the end, or with err set when the file cannot be read on.
static bool next_row(hs_line_reader *r, char **line, const char *path, bool *ok, hs_error *err) {
	size_t n;
	hs_line_status status = hs_line_next(r, line, &n);
	if (status == HS_LINE_OK || status == HS_LINE_END)
		return status == HS_LINE_OK;
	char why[96];
	*ok = hs_set_error(err, path, (unsigned long)r->number + 1, "%s", hs_line_status_text(r, status, why, sizeof why));
	return false;
}

// Reads the header and every row into the cells' sums.
static bool read_rows(const hs_campaign *c, FILE *in, const char *path, cell_sum *sums, hs_error *err) {
	char header[HS_CAMPAIGN_HEADER];
	hs_campaign_header(c, header, sizeof header);
	int fields = 1;
	for (const char *s = header; *s; ++s)
		fields += *s == ',';
	hs_line_reader r;
	hs_line_reader_open(&r, in);
	size_t rows = (size_t)c->trials + 1; // the total: every row at its longest (SIZE_MAX where that overflows)
	hs_line_reader_limit(&r, SUMMARY_MAX_LINE, rows > SIZE_MAX / SUMMARY_MAX_LINE ? SIZE_MAX : rows * SUMMARY_MAX_LINE);
	char *line = NULL;
	long trial = 0;
	unsigned long at = 0;
	bool ok = true;
	while (ok && next_row(&r, &line, path, &ok, err)) {
		++at;
		if (at == 1)
			ok = strcmp(line, header) == 0 ||
			     hs_set_error(err, path, 1, "not this campaign's trials: the header must be '%.300s'", header);
		else if (trial == c->trials)
			ok = hs_set_error(err, path, at, "more rows than the campaign's %ld trials", c->trials);
		else
			ok = read_row(c, line, trial++, fields, sums, path, at, err);
	}
	r.file = NULL; // the caller's
	hs_line_reader_close(&r);
	if (ok && trial < c->trials)
		ok = hs_set_error(err, path, at + 1, "%ld of the campaign's %ld trials missing, the first trial %ld", c->trials - trial,
		                  c->trials, trial);
	return ok;
}

// A column's width in the table: its name's, its longest value's, at least 9.
static int column_width(const hs_axis *a) {
	size_t w = strlen(a->name) > 9 ? strlen(a->name) : 9;
	for (int v = 0; (a->kind == HS_AXIS_MODEL || a->kind == HS_AXIS_SCENARIO) && v < a->count; ++v)
		w = strlen(a->text[v]) > w ? strlen(a->text[v]) : w;
	return (int)w;
}

// A cell's axis values as the trial rows show them (width 0), or as table columns.
static void write_values(const hs_campaign *c, long cell, FILE *out, const char *sep, bool table) {
	hs_trial t;
	hs_trial_prepare(c, cell * c->per_cell, &t);
	for (int a = 0; a < c->axis_count; ++a) {
		const hs_axis *axis = &c->axes[a];
		int width = table ? column_width(axis) : 0;
		if (axis->kind == HS_AXIS_MODEL || axis->kind == HS_AXIS_SCENARIO)
			fprintf(out, "%s%*s", sep, width, axis->text[t.value[a]]);
		else if (table)
			fprintf(out, "%s%*.6g", sep, width, axis->value[t.value[a]]);
		else
			fprintf(out, "%s%.17g", sep, axis->value[t.value[a]]);
	}
}

// The thrower's columns: grasps lost, the other misses (faults apart), the visitors.
static void write_thrower_columns(const hs_campaign *c, const cell_sum *s, FILE *out) {
	if (hs_campaign_watches_grasp(c))
		fprintf(out, ",%ld,%ld", s->lost, s->trials - s->hits - s->lost - s->faults);
	if (!c->thrower.given)
		return;
	double lo, hi, p = (double)s->hits / (double)s->trials;
	hs_wilson_interval(s->visitor_hits, s->visitors, &lo, &hi);
	fprintf(out, ",%ld,%ld,%ld,%.6f,%.6f,%.6f,%.6f", c->visitor_throws, s->visitors, s->visitor_hits,
	        s->visitors > 0 ? (double)s->visitor_hits / (double)s->visitors : 0.0, lo, hi,
	        1.0 - pow(1.0 - p, (double)c->visitor_throws));
}

static void write_summary(const hs_campaign *c, const cell_sum *sums, FILE *out) {
	fputs("cell", out);
	for (int a = 0; a < c->axis_count; ++a)
		fprintf(out, ",%s", c->axes[a].name);
	fprintf(out, ",trials,hits,rate,lo95,hi95,faults%s%s%s\n", c->target.given ? ",mean_distance" : "",
	        hs_campaign_watches_grasp(c) ? ",grasp_lost,misses" : "",
	        c->thrower.given ? ",visitor_throws,visitors,visitor_hits,visitor_rate,visitor_lo95,visitor_hi95,"
	                           "visitor_binomial"
	                         : "");
	for (long k = 0; k < c->cells; ++k) {
		double lo, hi;
		hs_wilson_interval(sums[k].hits, sums[k].trials, &lo, &hi);
		fprintf(out, "%ld", k);
		write_values(c, k, out, ",", false);
		fprintf(out, ",%ld,%ld,%.6f,%.6f,%.6f,%ld", sums[k].trials, sums[k].hits,
		        (double)sums[k].hits / (double)sums[k].trials, lo, hi, sums[k].faults);
		if (c->target.given)
			fprintf(out, ",%.6f", sums[k].distance / (double)sums[k].trials);
		write_thrower_columns(c, &sums[k], out);
		fputs("\n", out);
	}
}

// A cell's grasps lost, the thrower's misses and the rate per visitor, as table columns.
static void write_thrower_table(const hs_campaign *c, const cell_sum *s, FILE *out) {
	if (hs_campaign_watches_grasp(c))
		fprintf(out, "  %10ld %7ld", s->lost, s->trials - s->hits - s->lost - s->faults);
	if (!c->thrower.given)
		return;
	double lo, hi, p = (double)s->hits / (double)s->trials;
	hs_wilson_interval(s->visitor_hits, s->visitors, &lo, &hi);
	fprintf(out, "  %5ld %6.3f [%.3f, %.3f] %9.3f", s->visitors,
	        s->visitors > 0 ? (double)s->visitor_hits / (double)s->visitors : 0.0, lo, hi,
	        1.0 - pow(1.0 - p, (double)c->visitor_throws));
}

static void write_table(const hs_campaign *c, const cell_sum *sums, FILE *out) {
	fprintf(out, "campaign %s: %ld cells x %ld trials", c->path, c->cells, c->per_cell);
	if (c->thrower.given)
		fprintf(out, "; a visitor: %ld throws, hit when any hits (binomial: 1 - (1 - rate)^%ld)", c->visitor_throws,
		        c->visitor_throws);
	fprintf(out, "\n%6s", "cell");
	for (int a = 0; a < c->axis_count; ++a)
		fprintf(out, " %*s", column_width(&c->axes[a]), c->axes[a].name);
	fprintf(out, " %8s %8s  %-17s%s%s%s\n", "hits", "rate", "95 % (Wilson)", c->target.given ? " mean distance" : "",
	        hs_campaign_watches_grasp(c) ? "  grasp lost  misses" : "",
	        c->thrower.given ? "  visitors  rate  95 % (Wilson)  binomial" : "");
	for (long k = 0; k < c->cells; ++k) {
		double lo, hi;
		hs_wilson_interval(sums[k].hits, sums[k].trials, &lo, &hi);
		fprintf(out, "%6ld", k);
		write_values(c, k, out, " ", true);
		fprintf(out, " %8ld %8.3f  [%.3f, %.3f]", sums[k].hits, (double)sums[k].hits / (double)sums[k].trials, lo, hi);
		if (c->target.given)
			fprintf(out, "    %.3f m", sums[k].distance / (double)sums[k].trials);
		write_thrower_table(c, &sums[k], out);
		if (sums[k].faults > 0)
			fprintf(out, "    %ld FAULTED", sums[k].faults);
		fputs("\n", out);
	}
}

int hs_campaign_summarize(const hs_campaign *c, FILE *in, const char *in_path, FILE *summary, FILE *table,
                          hs_error *err) {
	cell_sum *sums = calloc((size_t)c->cells, sizeof *sums);
	if (!sums)
		return hs_set_error(err, in_path, 1, "out of memory"), 2;
	bool ok = read_rows(c, in, in_path, sums, err);
	if (ok && summary)
		write_summary(c, sums, summary);
	if (ok && table)
		write_table(c, sums, table);
	long faults = 0;
	for (long k = 0; ok && k < c->cells; ++k)
		faults += sums[k].faults;
	if (faults > 0) // the numbers of those runs went bad: the summary is written, the status says so
		hs_set_error(err, in_path, 1, "%ld of %ld trials faulted (a step failed or a value went non-finite): "
		             "their clauses column says fault", faults, c->trials);
	free(sums);
	return !ok ? 2 : faults > 0 ? 1 : 0;
}
