// uv_ball.c — the 5 cm balls of the frame-rate and scaling scenes: convex UV polyhedra of any
// number of faces (bench/frame_rate.c builds its scenes with them, bench/hand_scaling.c times them).
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

hs_shape *bench_uv_ball(int slices, int stacks, double r, hs_status *status) {
	int nv = 2 + slices * (stacks - 1), nf = slices * stacks;
	hs_vec3 *v = malloc((size_t)nv * sizeof *v);
	int *fv = malloc((size_t)nf * 4 * sizeof *fv), *fs = malloc((size_t)nf * sizeof *fs);
	if (!v || !fv || !fs) {
		fprintf(stderr, "bench: ball: %s\n", hs_status_string(HS_ERR_NO_MEMORY));
		exit(2);
	}
	int n = 0, m = 0, f = 0;
	v[n++] = hs_v3(0.0, 0.0, r);
	for (int j = 1; j < stacks; ++j) {
		double th = HS_PI * j / stacks;
		for (int i = 0; i < slices; ++i) {
			double ph = 2.0 * HS_PI * i / slices;
			v[n++] = hs_v3(r * sin(th) * cos(ph), r * sin(th) * sin(ph), r * cos(th));
		}
	}
	v[n++] = hs_v3(0.0, 0.0, -r);
	for (int j = 0; j < stacks; ++j) // ring j (1-based) slice i is vertex 1 + (j − 1) · slices + i
		for (int i = 0; i < slices; ++i) {
			int i1 = (i + 1) % slices, top = 1 + (j - 1) * slices, low = top + slices, k = 0, face[4];
			if (j == 0) { // north fan
				face[k++] = 0, face[k++] = 1 + i, face[k++] = 1 + i1;
			} else if (j == stacks - 1) { // south fan
				face[k++] = n - 1, face[k++] = top + i1, face[k++] = top + i;
			} else { // planar trapezoids between rings j and j + 1
				face[k++] = top + i, face[k++] = low + i, face[k++] = low + i1, face[k++] = top + i1;
			}
			memcpy(fv + m, face, (size_t)k * sizeof *face);
			m += k;
			fs[f++] = k;
		}
	char why[128] = "";
	hs_shape *s = hs_shape_polyhedron(v, n, fv, fs, f, why, sizeof why, status);
	if (!s)
		fprintf(stderr, "bench: ball of %d faces: %s\n", f, why);
	free(v);
	free(fv);
	free(fs);
	return s;
}
