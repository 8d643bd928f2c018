// suggest.c — the nearest valid word to a misspelt one, by optimal string alignment distance
// (Levenshtein plus swapped neighbours: 'duraton', 'positon' and 'contact_sequense' are one edit
// from what was meant, and so is a swap such as 'dutation').
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "suggest.h"

enum { WORD_MAX = 64 }; // longer words are never near: the table stays on the stack

int hs_edit_distance(const char *a, size_t na, const char *b, size_t nb) {
	if (na > WORD_MAX || nb > WORD_MAX)
		return WORD_MAX + 1;
	int d[WORD_MAX + 1][WORD_MAX + 1];
	for (size_t i = 0; i <= na; ++i)
		d[i][0] = (int)i;
	for (size_t j = 0; j <= nb; ++j)
		d[0][j] = (int)j;
	for (size_t i = 1; i <= na; ++i)
		for (size_t j = 1; j <= nb; ++j) {
			int cost = a[i - 1] != b[j - 1];
			int best = d[i - 1][j - 1] + cost;
			if (d[i - 1][j] + 1 < best)
				best = d[i - 1][j] + 1;
			if (d[i][j - 1] + 1 < best)
				best = d[i][j - 1] + 1;
			if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] && d[i - 2][j - 2] + 1 < best)
				best = d[i - 2][j - 2] + 1;
			d[i][j] = best;
		}
	return d[na][nb];
}

int hs_suggest(const char *typed, size_t n, const char *const *names, int count) {
	int best = -1, best_d = WORD_MAX + 1;
	for (int i = 0; i < count; ++i) {
		size_t m = strlen(names[i]);
		int d = hs_edit_distance(typed, n, names[i], m);
		// near: 2 edits or a third of the word; never a word that shares nothing with it
		bool near = (d <= 2 || (size_t)d * 3 <= n) && (size_t)d < n && (size_t)d < m;
		if (near && d > 0 && d < best_d) {
			best = i;
			best_d = d;
		}
	}
	return best;
}

void hs_suggest_append(char *buf, size_t size, const char *typed, size_t n, const char *const *names, int count,
                       int list) {
	size_t w = strlen(buf);
	int near = hs_suggest(typed, n, names, count);
	if (near >= 0 && w < size)
		w += (size_t)snprintf(buf + w, size - w, ": did you mean '%s'?", names[near]);
	if (!list || count > HS_SUGGEST_LIST_MAX)
		return;
	for (int i = 0; i < count && w < size; ++i)
		w += (size_t)snprintf(buf + w, size - w, "%s%s", i == 0 ? " (expected " : i == count - 1 ? " or " : ", ",
		                      names[i]);
	if (w < size)
		snprintf(buf + w, size - w, ")");
}
