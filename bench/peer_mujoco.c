// peer_mujoco.c — the seed scene in MuJoCo (libmujoco-dev 2.2.2), for item 5 of `make bench`.
// Built only when <mujoco/mujoco.h> exists (bench/bench.mk).
//
// The model is an MJCF string loaded with mj_loadXML through a virtual file system (mjVFS, no
// temporary file): a floor plane, eight free 5 cm boxes (density 500, μ = 0.5) and the two cubes
// handspring grasps as mocap bodies whose mocap_pos follows the hand's loop; MuJoCo's defaults
// otherwise (Euler integrator, Newton solver, pyramidal cones). MuJoCo 2.2 has no sleeping.
#include <mujoco/mujoco.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

typedef struct mj_scene {
	mjModel *m;
	mjData *d;
	hs_vec3 start[10];
	int k;
	uint64_t checksum;
} mj_scene;

static mjModel *load_xml(const char *xml) {
	mjVFS *vfs = malloc(sizeof *vfs);
	if (!vfs) {
		fprintf(stderr, "bench: MuJoCo: out of memory\n");
		exit(2);
	}
	mj_defaultVFS(vfs);
	int len = (int)strlen(xml);
	if (mj_makeEmptyFileVFS(vfs, "scene.xml", len) != 0) {
		fprintf(stderr, "bench: MuJoCo: cannot make the VFS file\n");
		exit(2);
	}
	int i = mj_findFileVFS(vfs, "scene.xml");
	memcpy(vfs->filedata[i], xml, (size_t)len);
	char error[1000] = "";
	mjModel *m = mj_loadXML("scene.xml", vfs, error, (int)sizeof error);
	mj_deleteVFS(vfs);
	free(vfs);
	if (!m) {
		fprintf(stderr, "bench: MuJoCo: %s\n", error);
		exit(2);
	}
	return m;
}

static void append(char *buf, size_t size, size_t *len, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
static void append(char *buf, size_t size, size_t *len, const char *fmt, ...) {
	va_list ap;
	va_start(ap, fmt);
	int n = vsnprintf(buf + *len, size - *len, fmt, ap);
	va_end(ap);
	if (n > 0)
		*len += (size_t)n < size - *len ? (size_t)n : size - *len - 1;
}

static mj_scene *mj_create(void) {
	mj_scene *sc = calloc(1, sizeof *sc);
	char xml[8192];
	size_t len = 0;
	double h = 0.5 * BENCH_CUBE;
	append(xml, sizeof xml, &len,
	       "<mujoco model=\"seed\">\n"
	       "  <option timestep=\"%.17g\" gravity=\"0 0 %.17g\"/>\n"
	       "  <default><geom friction=\"0.5 0.005 0.0001\"/></default>\n"
	       "  <worldbody>\n"
	       "    <geom name=\"floor\" type=\"plane\" size=\"5 5 0.1\"/>\n",
	       BENCH_DT, -BENCH_G);
	for (int i = 0; i < 10; ++i) {
		sc->start[i] = bench_cell(i, 0);
		hs_vec3 p = sc->start[i];
		if (i == 4 || i == 5) // the grasped pair: mocap bodies, moved by the path
			append(xml, sizeof xml, &len,
			       "    <body name=\"held%d\" mocap=\"true\" pos=\"%.17g %.17g %.17g\">"
			       "<geom type=\"box\" size=\"%g %g %g\" density=\"500\"/></body>\n",
			       i, p.x, p.y, p.z, h, h, h);
		else
			append(xml, sizeof xml, &len,
			       "    <body name=\"cube%d\" pos=\"%.17g %.17g %.17g\"><freejoint/>"
			       "<geom type=\"box\" size=\"%g %g %g\" density=\"500\"/></body>\n",
			       i, p.x, p.y, p.z, h, h, h);
	}
	append(xml, sizeof xml, &len, "  </worldbody>\n</mujoco>\n");
	sc->m = load_xml(xml);
	sc->d = mj_makeData(sc->m);
	mj_forward(sc->m, sc->d);
	sc->checksum = 14695981039346656037ull;
	return sc;
}

static void mj_scene_step(void *state, long frames) {
	mj_scene *sc = state;
	for (long f = 0; f < frames; ++f) {
		sc->k = sc->k + 1 == BENCH_PATH_FRAMES ? 0 : sc->k + 1;
		hs_vec3 off = bench_path(sc->k);
		for (int j = 0; j < 2; ++j) { // mocap bodies in model order: cube 4, then cube 5
			hs_vec3 p = hs_add(sc->start[4 + j], off);
			sc->d->mocap_pos[3 * j + 0] = p.x;
			sc->d->mocap_pos[3 * j + 1] = p.y;
			sc->d->mocap_pos[3 * j + 2] = p.z;
		}
		mj_step(sc->m, sc->d);
		sc->checksum = bench_mix(sc->checksum, sc->d->qpos[2]);
	}
}

// The projectile of item 3: one free box, no floor, MuJoCo's integrator at BENCH_DT.
static double mj_projectile_error(void) {
	char xml[1024];
	snprintf(xml, sizeof xml,
	         "<mujoco model=\"projectile\"><option timestep=\"%.17g\" gravity=\"0 0 %.17g\"/><worldbody>"
	         "<body name=\"block\" pos=\"0 0 %.17g\"><freejoint/><geom type=\"box\" size=\"%g %g %g\" density=\"500\" "
	         "contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>",
	         BENCH_DT, -BENCH_G, BENCH_PROJ_Z0, 0.5 * BENCH_CUBE, 0.5 * BENCH_CUBE, 0.5 * BENCH_CUBE);
	mjModel *m = load_xml(xml);
	mjData *d = mj_makeData(m);
	d->qvel[0] = BENCH_PROJ_VX;
	d->qvel[2] = BENCH_PROJ_VZ;
	double xs[256], zs[256];
	int n = 0;
	xs[n] = d->qpos[0];
	zs[n++] = d->qpos[2];
	while (n < 256 && zs[n - 1] >= BENCH_PROJ_PLANE) {
		mj_step(m, d);
		xs[n] = d->qpos[0];
		zs[n++] = d->qpos[2];
	}
	mj_deleteData(d);
	mj_deleteModel(m);
	return fabs(bench_crossing_x(xs, zs, n, BENCH_PROJ_PLANE) - bench_projectile_range());
}

bench_peer_result bench_peer_mujoco(const bench_opts *opts) {
	bench_peer_result r;
	memset(&r, 0, sizeof r);
	mj_scene *sc = mj_create();
	r.step = bench_measure(mj_scene_step, sc, opts);
	for (int i = 0, q = 0; i < 10; ++i) { // free joints in model order: 7 qpos each
		if (i == 4 || i == 5)
			continue;
		hs_vec3 p = hs_v3(sc->d->qpos[q], sc->d->qpos[q + 1], sc->d->qpos[q + 2]);
		double dist = hs_distance(p, sc->start[i]);
		r.resting_drift = dist > r.resting_drift ? dist : r.resting_drift;
		q += 7;
	}
	r.checksum = sc->checksum;
	mj_deleteData(sc->d);
	mj_deleteModel(sc->m);
	free(sc);
	r.projectile_error = mj_projectile_error();
	r.ran = true;
	snprintf(r.name, sizeof r.name, "MuJoCo");
	snprintf(r.version, sizeof r.version, "%s", mj_versionString());
	snprintf(r.setup, sizeof r.setup, "mj_step, Euler, defaults, 2 mocap + 8 free boxes, no sleeping; drift %.1e m",
	         r.resting_drift);
	bench_progress("[peers] MuJoCo: %.3f us/step, projectile error %.2e m\n", 1e6 * r.step.median, r.projectile_error);
	return r;
}
