// callgrind.c — the calls and totals of a callgrind output file (valgrind's "Callgrind Format
// Specification"): function names may be compressed (`fn=(12) name`, then `fn=(12)`), a `calls=`
// line is followed by one cost line, the inclusive cost of those calls; every other cost line is
// the current function's own. Costs are the first event after the position columns.
#include "callgrind.h"

#include <inttypes.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct cg_edge {
	int caller, callee;
	uint64_t cost;
} cg_edge;

struct hs_cg_profile {
	char **names; // by id
	int name_count, name_cap;
	cg_edge *edges;
	int edge_count, edge_cap;
	uint64_t totals, self_sum;
	int positions; // columns before the events on a cost line
};

static bool grow(void **items, int *cap, int need, size_t size) {
	if (need <= *cap)
		return true;
	int cap2 = *cap ? 2 * *cap : 64;
	while (cap2 < need)
		cap2 *= 2;
	void *p = realloc(*items, (size_t)cap2 * size);
	if (!p)
		return false;
	memset((char *)p + (size_t)*cap * size, 0, (size_t)(cap2 - *cap) * size);
	*items = p;
	*cap = cap2;
	return true;
}

// The id of `text` ("(12) name", "(12)" or "name"), registering a name it brings; −1 on error.
static int name_id(hs_cg_profile *p, const char *text) {
	int id = -1;
	const char *name = text;
	if (text[0] == '(') {
		id = atoi(text + 1);
		const char *close = strchr(text, ')');
		name = close ? close + 1 : "";
		while (*name == ' ')
			name++;
	} else {
		for (int i = 0; i < p->name_count; ++i)
			if (p->names[i] && strcmp(p->names[i], text) == 0)
				return i;
		id = p->name_count;
	}
	if (id < 0 || !grow((void **)&p->names, &p->name_cap, id + 1, sizeof *p->names))
		return -1;
	if (id >= p->name_count)
		p->name_count = id + 1;
	if (*name && !p->names[id])
		p->names[id] = strdup(name);
	return id;
}

static int find_name(const hs_cg_profile *p, const char *name) {
	for (int i = 0; i < p->name_count; ++i)
		if (p->names[i] && strcmp(p->names[i], name) == 0)
			return i;
	return -1;
}

// The first event of a cost line (after the position columns); 0 when it has none.
static uint64_t line_cost(const hs_cg_profile *p, const char *line) {
	const char *s = line;
	for (int k = 0; k < p->positions; ++k) {
		s += strspn(s, " \t");
		s += strcspn(s, " \t");
	}
	return strtoull(s, NULL, 10);
}

static bool add_edge(hs_cg_profile *p, int caller, int callee, uint64_t cost) {
	for (int i = 0; i < p->edge_count; ++i)
		if (p->edges[i].caller == caller && p->edges[i].callee == callee) {
			p->edges[i].cost += cost;
			return true;
		}
	if (!grow((void **)&p->edges, &p->edge_cap, p->edge_count + 1, sizeof *p->edges))
		return false;
	p->edges[p->edge_count++] = (cg_edge){caller, callee, cost};
	return true;
}

static bool is_cost_line(const char *line) {
	return (line[0] >= '0' && line[0] <= '9') || line[0] == '+' || line[0] == '-' || line[0] == '*';
}

// One line of the file; `fn`, `cfn` and `in_call` carry the parser's state between lines.
static bool parse_line(hs_cg_profile *p, const char *line, int *fn, int *cfn, bool *in_call) {
	if (strncmp(line, "positions:", 10) == 0) {
		p->positions = 0;
		for (const char *s = line + 10; *s;) {
			s += strspn(s, " \t");
			if (*s)
				p->positions++;
			s += strcspn(s, " \t");
		}
	} else if (strncmp(line, "totals:", 7) == 0 || strncmp(line, "summary:", 8) == 0) {
		p->totals = strtoull(strchr(line, ':') + 1, NULL, 10);
	} else if (strncmp(line, "fn=", 3) == 0) {
		*fn = name_id(p, line + 3);
		*in_call = false;
		return *fn >= 0;
	} else if (strncmp(line, "cfn=", 4) == 0) {
		*cfn = name_id(p, line + 4);
		return *cfn >= 0;
	} else if (strncmp(line, "calls=", 6) == 0) {
		*in_call = true;
	} else if (is_cost_line(line)) {
		uint64_t cost = line_cost(p, line);
		if (*in_call) {
			*in_call = false;
			return *fn < 0 || *cfn < 0 || add_edge(p, *fn, *cfn, cost);
		}
		p->self_sum += cost;
	}
	return true;
}

hs_cg_profile *hs_cg_load(const char *path, char *why, size_t why_size) {
	FILE *f = fopen(path, "r");
	if (!f) {
		snprintf(why, why_size, "cannot open %s", path);
		return NULL;
	}
	hs_cg_profile *p = calloc(1, sizeof *p);
	char line[4096];
	int fn = -1, cfn = -1;
	bool in_call = false, ok = p != NULL;
	if (p)
		p->positions = 1; // "positions: line", the default
	while (ok && fgets(line, sizeof line, f)) {
		line[strcspn(line, "\r\n")] = '\0';
		ok = parse_line(p, line, &fn, &cfn, &in_call);
	}
	ok = ok && !ferror(f);
	fclose(f);
	if (!ok) {
		snprintf(why, why_size, "%s: cannot read it as a callgrind profile", path);
		hs_cg_free(p);
		return NULL;
	}
	return p;
}

void hs_cg_free(hs_cg_profile *p) {
	if (!p)
		return;
	for (int i = 0; i < p->name_count; ++i)
		free(p->names[i]);
	free(p->names);
	free(p->edges);
	free(p);
}

uint64_t hs_cg_total(const hs_cg_profile *p) { return p->totals ? p->totals : p->self_sum; }

uint64_t hs_cg_call(const hs_cg_profile *p, const char *caller, const char *callee) {
	int a = find_name(p, caller), b = find_name(p, callee);
	uint64_t sum = 0;
	for (int i = 0; a >= 0 && b >= 0 && i < p->edge_count; ++i)
		if (p->edges[i].caller == a && p->edges[i].callee == b)
			sum += p->edges[i].cost;
	return sum;
}

uint64_t hs_cg_inclusive(const hs_cg_profile *p, const char *fn) {
	int b = find_name(p, fn);
	uint64_t sum = 0;
	for (int i = 0; b >= 0 && i < p->edge_count; ++i)
		if (p->edges[i].callee == b && p->edges[i].caller != b)
			sum += p->edges[i].cost;
	return sum;
}
