// output.c — the tool's output files: written whole under a temporary name, then renamed.
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "output.h"

// Like mkdir -p for the folder that will hold `file`.
bool make_parent_dirs(const char *file) {
	char *path = malloc(strlen(file) + 1);
	if (!path)
		return false;
	strcpy(path, file);
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

bool output_open(output *o, const char *path) {
	memset(o, 0, sizeof *o);
	o->path = malloc(strlen(path) + 1);
	if (!o->path)
		return false;
	strcpy(o->path, path);
	struct stat st;
	if (lstat(path, &st) == 0 && !S_ISREG(st.st_mode)) { // a symbolic link too: a rename would replace it
		o->file = fopen(path, "w");
		return o->file != NULL;
	}
	size_t n = strlen(path) + 5;
	o->temp = malloc(n);
	if (!o->temp)
		return false;
	snprintf(o->temp, n, "%s.tmp", path);
	if (!make_parent_dirs(path))
		return false;
	o->file = fopen(o->temp, "w");
	return o->file != NULL;
}

bool output_close(output *o, bool keep) {
	bool ok = true;
	if (o->file) {
		ok = !ferror(o->file);
		ok = fclose(o->file) == 0 && ok;
		o->file = NULL;
		if (ok && keep && o->temp)
			ok = rename(o->temp, o->path) == 0;
		if ((!ok || !keep) && o->temp)
			remove(o->temp);
	}
	return ok;
}

void output_free(output *o) {
	free(o->path);
	free(o->temp);
	memset(o, 0, sizeof *o);
}

