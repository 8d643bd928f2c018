// output.c — the tool's one writer (output.h): a temporary beside the target made by mkstemp,
// every write, flush, fsync and close checked, renamed over the target only when all succeeded;
// outputs that are the command's inputs (device and inode) refused.
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "output.h"

#if defined(__GNUC__)
#define OUTPUT_PRINTF __attribute__((format(printf, 2, 3)))
#else
#define OUTPUT_PRINTF
#endif

// The command's inputs (device and inode, and the path for the message) and its outputs so far
// (the canonical path of each target): kept for the process, which runs one command.
typedef struct known_file {
	dev_t dev;
	ino_t ino;
	char *path;
} known_file;
static known_file *inputs;
static int input_count;
static int output_count; // outputs: below

static void forget_files(void);

// The registries live until the process exits; freed then, so a leak check sees nothing left.
static void remember_at_exit(void) {
	static bool registered;
	if (!registered)
		registered = atexit(forget_files) == 0;
}

static char *copy_of(const char *s) {
	char *r = malloc(strlen(s) + 1);
	if (r)
		strcpy(r, s);
	return r;
}

void output_input(const char *path) {
	struct stat st;
	if (!path || strcmp(path, "-") == 0 || stat(path, &st) != 0)
		return;
	remember_at_exit();
	known_file *grown = realloc(inputs, (size_t)(input_count + 1) * sizeof *grown);
	if (!grown)
		return;
	inputs = grown;
	inputs[input_count] = (known_file){st.st_dev, st.st_ino, copy_of(path)};
	if (inputs[input_count].path)
		input_count++;
}

static const char *input_named(const struct stat *st) {
	for (int i = 0; i < input_count; ++i)
		if (inputs[i].dev == st->st_dev && inputs[i].ino == st->st_ino)
			return inputs[i].path;
	return NULL;
}

OUTPUT_PRINTF static bool fail(output *o, const char *fmt, ...) {
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(o->error, sizeof o->error, fmt, ap);
	va_end(ap);
	return false;
}

// Like mkdir -p for the folder that will hold `file`.
bool make_parent_dirs(const char *file) {
	char *path = copy_of(file);
	if (!path)
		return false;
	bool ok = true;
	for (char *p = path + 1; ok && *p; ++p) {
		if (*p != '/')
			continue;
		*p = '\0';
		struct stat st;
		if (mkdir(path, 0777) != 0 && !(errno == EEXIST && stat(path, &st) == 0 && S_ISDIR(st.st_mode)))
			ok = false;
		*p = '/';
	}
	free(path);
	return ok;
}

// What a chain of symbolic links at `path` ends at (at most 40 links, as the kernel follows);
// NULL when out of memory or too deep. Relative links are taken from their link's folder.
static char *resolve_link(const char *path) {
	char *at = copy_of(path);
	for (int depth = 0; at && depth < 40; ++depth) {
		struct stat st;
		if (lstat(at, &st) != 0 || !S_ISLNK(st.st_mode))
			return at;
		char buf[4096];
		ssize_t n = readlink(at, buf, sizeof buf - 1);
		if (n < 0) {
			free(at);
			return NULL;
		}
		buf[n] = '\0';
		const char *slash = strrchr(at, '/');
		size_t dir = buf[0] != '/' && slash ? (size_t)(slash - at) + 1 : 0;
		char *next = malloc(dir + (size_t)n + 1);
		if (next)
			sprintf(next, "%.*s%s", (int)dir, at, buf);
		free(at);
		at = next;
	}
	free(at);
	return NULL;
}

// An output's identity: its folder's device and inode, and its name in it. Two outputs of the
// command are the same file when these are equal (whatever links or ".." their paths take).
typedef struct place {
	dev_t dev;
	ino_t ino;
	char *name;
} place;
static place *outputs;

static bool place_of(const char *target, place *p) {
	const char *slash = strrchr(target, '/');
	char *dir = slash ? copy_of(target) : copy_of(".");
	struct stat st;
	if (dir && slash)
		dir[slash == target ? 1 : slash - target] = '\0';
	bool ok = dir && stat(dir, &st) == 0 && (p->name = copy_of(slash ? slash + 1 : target)) != NULL;
	free(dir);
	if (ok) {
		p->dev = st.st_dev;
		p->ino = st.st_ino;
	}
	return ok;
}

// False when another output of the command is the same file; else records this one.
static bool claim(const char *target) {
	place p;
	if (!place_of(target, &p))
		return true; // the folder was just made: it cannot be resolved only when out of memory
	for (int i = 0; i < output_count; ++i)
		if (outputs[i].dev == p.dev && outputs[i].ino == p.ino && strcmp(outputs[i].name, p.name) == 0) {
			free(p.name);
			return false;
		}
	remember_at_exit();
	place *grown = realloc(outputs, (size_t)(output_count + 1) * sizeof *grown);
	if (!grown) {
		free(p.name);
		return true;
	}
	outputs = grown;
	outputs[output_count++] = p;
	return true;
}

static void forget_files(void) {
	for (int i = 0; i < input_count; ++i)
		free(inputs[i].path);
	for (int i = 0; i < output_count; ++i)
		free(outputs[i].name);
	free(inputs);
	free(outputs);
	inputs = NULL;
	outputs = NULL;
	input_count = output_count = 0;
}

// The temporary beside `target`: ".NAME.XXXXXX" in its folder, made by mkstemp (O_EXCL: never
// through a link at that name), with the mode the target has or a new file would get.
static bool make_temp(output *o, const struct stat *existing) {
	const char *slash = strrchr(o->target, '/');
	size_t dir = slash ? (size_t)(slash - o->target) + 1 : 0;
	o->temp = malloc(strlen(o->target) + 10);
	if (!o->temp)
		return fail(o, "cannot write %s: out of memory", o->path);
	sprintf(o->temp, "%.*s.%s.XXXXXX", (int)dir, o->target, o->target + dir);
	int fd = mkstemp(o->temp);
	if (fd < 0) {
		int e = errno;
		free(o->temp);
		o->temp = NULL;
		return fail(o, "cannot write %s: cannot make a temporary file beside it: %s", o->path, strerror(e));
	}
	mode_t mask = umask(0);
	umask(mask);
	if (fchmod(fd, existing ? existing->st_mode & 07777 : 0666 & ~mask) != 0 || !(o->file = fdopen(fd, "w"))) {
		int e = errno;
		close(fd);
		unlink(o->temp);
		return fail(o, "cannot write %s: %s", o->path, strerror(e));
	}
	return true;
}

// A path that names a device, a pipe or a link to one: written in place.
static bool open_in_place(output *o) {
	o->in_place = true;
	o->file = fopen(o->path, "w");
	return o->file || fail(o, "cannot write %s: %s", o->path, strerror(errno));
}

// What the path names now: refused when it is a link to nothing, an input or a folder.
static bool precheck(output *o, const char *path, struct stat *st, bool *exists, bool *link) {
	struct stat lst;
	*exists = stat(path, st) == 0;
	*link = lstat(path, &lst) == 0 && S_ISLNK(lst.st_mode);
	const char *input = *exists ? input_named(st) : NULL;
	if (*link && !*exists)
		return fail(o, "cannot write %s: a symbolic link to a missing file (not followed)", path);
	if (input)
		return fail(o, "cannot write %s: it is the input %s (an output never overwrites an input)", path, input);
	if (*exists && S_ISDIR(st->st_mode))
		return fail(o, "cannot write %s: it is a folder", path);
	return true;
}

bool output_check(const char *path, char *error, size_t size) {
	output o;
	memset(&o, 0, sizeof o);
	struct stat st;
	bool exists, link;
	if (strcmp(path, "-") == 0 || precheck(&o, path, &st, &exists, &link))
		return true;
	snprintf(error, size, "%s", o.error);
	return false;
}

bool output_open(output *o, const char *path) {
	memset(o, 0, sizeof *o);
	if (!(o->path = copy_of(path)))
		return fail(o, "cannot write %s: out of memory", path);
	if (strcmp(path, "-") == 0) {
		o->in_place = o->is_stdout = true;
		o->file = stdout;
		return true;
	}
	struct stat st;
	bool exists, link;
	if (!precheck(o, path, &st, &exists, &link))
		return false;
	if (exists && !S_ISREG(st.st_mode))
		return open_in_place(o);
	o->target = link ? resolve_link(path) : copy_of(path);
	if (!o->target)
		return fail(o, "cannot write %s: cannot follow its symbolic link", path);
	if (!make_parent_dirs(o->target))
		return fail(o, "cannot write %s: cannot make its folder: %s", path, strerror(errno));
	if (!claim(o->target))
		return fail(o, "cannot write %s: another output of this command is the same file", path);
	return make_temp(o, exists ? &st : NULL);
}

bool output_close(output *o, bool keep) {
	if (!o->file)
		return true;
	// a write that failed earlier left the stream's error flag and, most likely, its errno
	int e = 0, earlier = ferror(o->file) ? errno : 0;
	errno = 0;
	if (fflush(o->file) != 0)
		e = errno ? errno : EIO;
	else if (ferror(o->file))
		e = earlier ? earlier : EIO;
	if (!e && o->temp && fsync(fileno(o->file)) != 0)
		e = errno;
	if (!o->is_stdout && fclose(o->file) != 0 && !e)
		e = errno ? errno : EIO;
	o->file = NULL;
	if (!e && keep && o->temp && rename(o->temp, o->target) != 0)
		e = errno;
	if (o->temp && (e || !keep))
		unlink(o->temp);
	return !e || fail(o, "cannot write %s: %s", o->path, strerror(e));
}

void output_free(output *o) {
	free(o->path);
	free(o->target);
	free(o->temp);
	o->path = o->target = o->temp = NULL;
	o->file = NULL;
}

bool output_stdout_ok(void) {
	errno = 0;
	if (fflush(stdout) == 0 && !ferror(stdout))
		return true;
	fprintf(stderr, "handspring: cannot write standard output: %s\n", strerror(errno ? errno : EIO));
	return false;
}
