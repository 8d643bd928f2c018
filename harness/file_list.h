// file_list.h — the files a scenario or a campaign read (its own file, then every file it names),
// so that a program writing outputs can refuse to overwrite one of them (hs_scenario_input_path).
#ifndef HS_HARNESS_FILE_LIST_H
#define HS_HARNESS_FILE_LIST_H

typedef struct hs_file_list {
	int count;
	char **paths;
} hs_file_list;

// Appends a copy of `path` (out of memory: not added; the list is advice to writers, not input).
void hs_file_list_add(hs_file_list *list, const char *path);
void hs_file_list_free(hs_file_list *list);

#endif
