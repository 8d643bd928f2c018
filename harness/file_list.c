// file_list.c — a list of file paths (file_list.h).
#include <stdlib.h>
#include <string.h>

#include "file_list.h"

void hs_file_list_add(hs_file_list *list, const char *path) {
	if (!list || !path)
		return;
	for (int i = 0; i < list->count; ++i)
		if (strcmp(list->paths[i], path) == 0)
			return;
	char **grown = realloc(list->paths, (size_t)(list->count + 1) * sizeof *grown);
	char *copy = malloc(strlen(path) + 1);
	if (grown)
		list->paths = grown;
	if (!grown || !copy) {
		free(copy);
		return;
	}
	strcpy(copy, path);
	list->paths[list->count++] = copy;
}

void hs_file_list_free(hs_file_list *list) {
	for (int i = 0; list && i < list->count; ++i)
		free(list->paths[i]);
	if (list) {
		free(list->paths);
		list->paths = NULL;
		list->count = 0;
	}
}
