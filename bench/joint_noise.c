// joint_noise.c — `hs_bench --noisy-joints IN OUT`: a joint recording as a hand tracker gives it.
//
// `handspring joints` writes a scenario's hand as exact landmarks; a tracker's landmarks jitter.
// This copies IN to OUT with seeded uniform noise of ±BENCH_JOINT_NOISE_MM on every joint
// coordinate (the columns x*, y*, z*, px*, py*, pz*; not t, the orientations, tracked nor
// confidence), so the joint-driven frame of `make bench-instr` fits new glove readings every
// frame. The same IN gives the same OUT on every machine (a fixed LCG, no libc random).
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define JN_LINE 8192
#define JN_COLUMNS 256

static uint64_t jn_seed = 0x2545F4914F6CDD1Dull;

// Uniform within [−1, 1].
static double jn_uniform(void) {
	jn_seed = jn_seed * 6364136223846793005ull + 1442695040888963407ull;
	return (double)(jn_seed >> 11) / (double)(1ull << 52) - 1.0;
}

// Whether header column `name` is a joint coordinate.
static bool jn_coordinate(const char *name) {
	if (name[0] == 'p')
		name++;
	return (name[0] == 'x' || name[0] == 'y' || name[0] == 'z') && name[1] >= '0' && name[1] <= '9';
}

// One sample line: the coordinates moved, the rest copied.
static void jn_sample(char *line, const bool *noisy, int columns, double amount, FILE *out) {
	int c = 0;
	for (char *cell = line, *next; cell; cell = next, ++c) {
		next = strchr(cell, ',');
		if (next)
			*next++ = '\0';
		char *end;
		double v = strtod(cell, &end);
		if (c > 0)
			fputc(',', out);
		if (c < columns && noisy[c] && end != cell && *end == '\0' && v == v)
			fprintf(out, "%.9g", v + amount * jn_uniform());
		else
			fputs(cell, out);
	}
	fputc('\n', out);
}

int bench_noisy_joints(const char *in_path, const char *out_path) {
	FILE *in = fopen(in_path, "r"), *out = in ? fopen(out_path, "w") : NULL;
	if (!in || !out) {
		fprintf(stderr, "hs_bench: cannot open %s\n", in ? out_path : in_path);
		if (in)
			fclose(in);
		return 2;
	}
	bool noisy[JN_COLUMNS] = {false}, header = false;
	int columns = 0;
	double amount = BENCH_JOINT_NOISE_MM * 1e-3; // in the file's units, m unless it says
	char line[JN_LINE];
	while (fgets(line, sizeof line, in)) {
		line[strcspn(line, "\r\n")] = '\0';
		if (!header && strncmp(line, "@units", 6) == 0)
			amount = BENCH_JOINT_NOISE_MM * (strstr(line, "mm") ? 1.0 : strstr(line, "cm") ? 0.1 : 1e-3);
		if (line[0] == '\0' || line[0] == '#' || line[0] == '@' || header == false) {
			if (line[0] == 't' && !header) { // the header: which columns are coordinates
				header = true;
				char copy[JN_LINE];
				memcpy(copy, line, sizeof copy);
				for (char *name = strtok(copy, ","); name && columns < JN_COLUMNS; name = strtok(NULL, ","))
					noisy[columns++] = jn_coordinate(name);
			}
			fprintf(out, "%s\n", line);
			continue;
		}
		jn_sample(line, noisy, columns, amount, out);
	}
	bool ok = !ferror(in) && header;
	fclose(in);
	ok = fclose(out) == 0 && ok;
	if (!ok)
		fprintf(stderr, "hs_bench: %s: no header line, or a read or write error\n", in_path);
	return ok ? 0 : 2;
}
