// fuzz_common.h — shared by the libFuzzer targets: a private temp folder per process and the
// checks every outcome must pass (one "PATH:LINE: what" message, or finite state).
#ifndef HS_FUZZ_COMMON_H
#define HS_FUZZ_COMMON_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "error.h"
#include "hand_script.h"

// A crash the fuzzer reports with the input that caused it.
#define FUZZ_REQUIRE(cond)                                                                              \
	do {                                                                                                \
		if (!(cond)) {                                                                                  \
			fprintf(stderr, "fuzz: %s:%d: requirement failed: %s\n", __FILE__, __LINE__, #cond);       \
			abort();                                                                                    \
		}                                                                                               \
	} while (0)

static char fuzz_dir[64];

// A fresh folder under /tmp for this process (removed at exit).
static inline void fuzz_cleanup(void) {
	char cmd[128];
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", fuzz_dir);
	if (fuzz_dir[0] && system(cmd) != 0)
		fprintf(stderr, "fuzz: could not remove %s\n", fuzz_dir);
}

static inline void fuzz_make_dir(void) {
	if (fuzz_dir[0])
		return;
	snprintf(fuzz_dir, sizeof fuzz_dir, "/tmp/hs_fuzz_XXXXXX");
	if (!mkdtemp(fuzz_dir)) {
		perror("fuzz: mkdtemp");
		abort();
	}
	atexit(fuzz_cleanup);
}

static inline void fuzz_write(const char *path, const uint8_t *data, size_t size) {
	FILE *f = fopen(path, "wb");
	FUZZ_REQUIRE(f != NULL);
	FUZZ_REQUIRE(fwrite(data, 1, size, f) == size);
	FUZZ_REQUIRE(fclose(f) == 0);
}

// Copies the repository file `from` into this process's folder as `name` (fuzz_write).
static inline void fuzz_copy_in(const char *from, const char *name) {
	char *text = NULL, to[256];
	size_t size = 0;
	FILE *in = fopen(from, "rb");
	FILE *m = open_memstream(&text, &size);
	FUZZ_REQUIRE(in != NULL && m != NULL);
	int c;
	while ((c = fgetc(in)) != EOF)
		fputc(c, m);
	fclose(in);
	fclose(m);
	snprintf(to, sizeof to, "%s/%s", fuzz_dir, name);
	fuzz_write(to, (const uint8_t *)text, size);
	free(text);
}

// "PREFIX:LINE: something", one line: the only shape an error may take.
static inline void fuzz_check_message(const char *message) {
	size_t n = strlen(message);
	FUZZ_REQUIRE(n > 0 && n < sizeof(((hs_error *)0)->message));
	FUZZ_REQUIRE(strchr(message, '\n') == NULL);
	// the last ":LINE: " before the text: scan for ":<digits>: "
	const char *p = message;
	int found = 0;
	while ((p = strchr(p, ':')) != NULL) {
		const char *q = p + 1;
		if (*q >= '1' && *q <= '9') {
			while (*q >= '0' && *q <= '9')
				++q;
			if (q[0] == ':' && q[1] == ' ' && q[2] != '\0') {
				found = 1;
				break;
			}
		}
		++p;
	}
	FUZZ_REQUIRE(found);
}

#endif
