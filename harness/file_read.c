// file_read.c — input files read with limits (HS_MAX_INPUT_BYTES, HS_MAX_LINE_BYTES) checked as
// the bytes arrive: a scenario or recorded path that names /dev/zero, a FIFO or a huge file fails
// at once with the limit in the message instead of filling memory.
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "file_read.h"

FILE *hs_open_input(const char *path) {
	// O_NONBLOCK: opening a FIFO without a writer would otherwise wait for one forever
	int fd = open(path, O_RDONLY | O_NONBLOCK);
	if (fd < 0)
		return NULL;
	struct stat st;
	int flags = fcntl(fd, F_GETFL);
	if (fstat(fd, &st) != 0 || flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0) {
		int saved = errno;
		close(fd);
		errno = saved;
		return NULL;
	}
	if (S_ISDIR(st.st_mode)) { // fopen would accept a folder and fail later
		close(fd);
		errno = EISDIR;
		return NULL;
	}
	FILE *f = fdopen(fd, "rb");
	if (!f) {
		int saved = errno;
		close(fd);
		errno = saved;
	}
	return f;
}

bool hs_read_file(const char *path, char **text, size_t *size, hs_error *err) {
	FILE *f = hs_open_input(path);
	if (!f)
		return hs_set_error(err, path, 1, "cannot read: %s", strerror(errno));
	size_t cap = 4096, n = 0;
	char *buf = malloc(cap);
	bool ok = buf != NULL;
	while (ok) {
		if (n == cap) {
			if (cap >= HS_MAX_INPUT_BYTES) {
				ok = hs_set_error(err, path, 1, "cannot read: larger than %zu MiB", HS_MAX_INPUT_BYTES >> 20);
				break;
			}
			char *bigger = realloc(buf, cap * 2);
			if (!bigger) {
				ok = false;
				break;
			}
			buf = bigger;
			cap *= 2;
		}
		size_t got = fread(buf + n, 1, cap - n, f);
		bool nul = memchr(buf + n, '\0', got) != NULL; // the caller reports it: stop reading here
		n += got;
		if (got == 0 || nul) {
			if (got == 0 && ferror(f))
				ok = hs_set_error(err, path, 1, "cannot read: %s", strerror(errno ? errno : EIO));
			break;
		}
	}
	if (!buf || (!ok && err->message[0] == '\0'))
		hs_set_error(err, path, 1, "cannot read: out of memory");
	fclose(f);
	if (!ok || !buf) {
		free(buf);
		return false;
	}
	*text = buf;
	*size = n;
	return true;
}

void hs_line_reader_open(hs_line_reader *r, FILE *file) {
	memset(r, 0, sizeof *r);
	r->file = file;
	r->cap = 4096;
	r->buf = malloc(r->cap);
}

void hs_line_reader_limit(hs_line_reader *r, size_t line_cap, size_t total_cap) {
	r->max_line = line_cap < HS_MAX_LINE_BYTES ? line_cap : HS_MAX_LINE_BYTES;
	r->max_total = total_cap; // a reader that counts its rows may take more than HS_MAX_INPUT_BYTES
}

static size_t max_line(const hs_line_reader *r) { return r->max_line ? r->max_line : HS_MAX_LINE_BYTES; }
static size_t max_total(const hs_line_reader *r) { return r->max_total ? r->max_total : HS_MAX_INPUT_BYTES; }

const char *hs_line_status_text(const hs_line_reader *r, hs_line_status status, char *buf, size_t size) {
	switch (status) {
	case HS_LINE_TOO_LONG:
		snprintf(buf, size, "a line longer than %zu bytes", max_line(r));
		break;
	case HS_LINE_TOO_BIG:
		snprintf(buf, size, "larger than %zu bytes", max_total(r));
		break;
	case HS_LINE_NO_MEMORY:
		snprintf(buf, size, "out of memory");
		break;
	default:
		snprintf(buf, size, "cannot read: %s", strerror(errno ? errno : EIO));
		break;
	}
	return buf;
}

// Moves the unread bytes to the front, grows the buffer when they fill it, and reads more.
static hs_line_status fill(hs_line_reader *r) {
	memmove(r->buf, r->buf + r->start, r->len - r->start);
	r->len -= r->start;
	r->start = 0;
	if (r->len + 1 >= r->cap) { // at most max_line bytes are unread: the buffer never outgrows that
		size_t cap = r->cap * 2 < max_line(r) + 2 ? r->cap * 2 : max_line(r) + 2;
		char *bigger = realloc(r->buf, cap);
		if (!bigger)
			return HS_LINE_NO_MEMORY;
		r->buf = bigger;
		r->cap = cap;
	}
	size_t room = r->cap - 1 - r->len; // > 0; one byte stays for the '\0' of a last line without '\n'
	size_t got = fread(r->buf + r->len, 1, room, r->file);
	if (got > max_total(r) - r->total)
		return HS_LINE_TOO_BIG;
	r->total += got;
	r->len += got;
	if (got == 0) {
		if (ferror(r->file))
			return HS_LINE_READ_ERROR;
		r->eof = true;
	}
	return HS_LINE_OK;
}

hs_line_status hs_line_next(hs_line_reader *r, char **line, size_t *length) {
	if (!r->buf)
		return HS_LINE_NO_MEMORY;
	for (;;) {
		char *start = r->buf + r->start;
		char *newline = memchr(start, '\n', r->len - r->start);
		if (newline || (r->eof && r->len > r->start)) { // the last line may lack its '\n'
			size_t n = newline ? (size_t)(newline - start) : r->len - r->start;
			start[n] = '\0';
			r->start += n + (newline != NULL);
			r->number++;
			*line = start;
			*length = n;
			return HS_LINE_OK;
		}
		if (r->eof)
			return HS_LINE_END;
		if (r->len - r->start > max_line(r))
			return HS_LINE_TOO_LONG;
		hs_line_status status = fill(r);
		if (status != HS_LINE_OK)
			return status;
	}
}

void hs_line_reader_close(hs_line_reader *r) {
	if (r->file)
		fclose(r->file);
	free(r->buf);
	memset(r, 0, sizeof *r);
}

char *hs_sibling_path(const char *scenario_path, const char *file) {
	size_t dir = 0;
	const char *slash = strrchr(scenario_path, '/');
	if (slash && file[0] != '/')
		dir = (size_t)(slash - scenario_path) + 1;
	char *out = malloc(dir + strlen(file) + 1);
	if (out) {
		memcpy(out, scenario_path, dir);
		strcpy(out + dir, file);
	}
	return out;
}
