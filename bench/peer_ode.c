// peer_ode.c — the seed scene in ODE (libode-dev, double precision), for item 5 of `make bench`.
// Built only when <ode/ode.h> exists (bench/bench.mk).
//
// Ten 5 cm boxes (density 500) on a z = 0 plane; the two handspring grasps are kinematic bodies
// moved along the hand's loop (position set each step, velocity the step's displacement / dt, so
// contacts see their motion); the other eight are dynamic. One hash space, up to 4 contacts per
// touching pair (μ = 0.5), dWorldQuickStep (20 iterations, ODE's default and fastest stepper) with
// and without auto-disable (ODE's default: every body stepped every frame) and with it — ODE's
// counterpart of handspring's sleeping.
#include <ode/ode.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define ODE_MAX_CONTACTS 4

typedef struct ode_scene {
	dWorldID world;
	dSpaceID space;
	dJointGroupID contacts;
	dBodyID bodies[10];
	dGeomID geoms[10];
	dGeomID floor;
	hs_vec3 start[10];
	bool kinematic[10];
	int k; // frame within the loop
	uint64_t checksum;
} ode_scene;

static void near_callback(void *data, dGeomID a, dGeomID b) {
	ode_scene *sc = data;
	dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
	// nothing to solve without a dynamic body, nor between sleeping bodies and the floor (a moving
	// kinematic body still touches a sleeping one, which the contact then wakes)
	bool ka = ba && dBodyIsKinematic(ba), kb = bb && dBodyIsKinematic(bb);
	bool da = ba && !ka, db = bb && !kb;
	if (!da && !db)
		return;
	bool still_a = !da || !dBodyIsEnabled(ba), still_b = !db || !dBodyIsEnabled(bb);
	if (still_a && still_b && !ka && !kb)
		return;
	dContact contact[ODE_MAX_CONTACTS];
	memset(contact, 0, sizeof contact);
	int n = dCollide(a, b, ODE_MAX_CONTACTS, &contact[0].geom, sizeof(dContact));
	for (int i = 0; i < n; ++i) {
		contact[i].surface.mode = dContactApprox1 | dContactSoftCFM;
		contact[i].surface.mu = 0.5;
		contact[i].surface.soft_cfm = 1e-5;
		dJointID j = dJointCreateContact(sc->world, sc->contacts, &contact[i]);
		dJointAttach(j, ba, bb);
	}
}

static ode_scene *ode_create(bool auto_disable) {
	ode_scene *sc = calloc(1, sizeof *sc);
	if (!sc) {
		fprintf(stderr, "bench: ODE: out of memory\n");
		exit(2);
	}
	sc->world = dWorldCreate();
	dWorldSetGravity(sc->world, 0.0, 0.0, -BENCH_G);
	dWorldSetQuickStepNumIterations(sc->world, 20);
	dWorldSetContactSurfaceLayer(sc->world, 0.001);
	dWorldSetAutoDisableFlag(sc->world, auto_disable ? 1 : 0);
	sc->space = dHashSpaceCreate(0);
	sc->contacts = dJointGroupCreate(0);
	sc->floor = dCreatePlane(sc->space, 0.0, 0.0, 1.0, 0.0);
	for (int i = 0; i < 10; ++i) { // the seed row; cubes 4 and 5 are the grasped pair
		sc->start[i] = bench_cell(i, 0);
		sc->kinematic[i] = i == 4 || i == 5;
		sc->bodies[i] = dBodyCreate(sc->world);
		dMass m;
		dMassSetBox(&m, 500.0, BENCH_CUBE, BENCH_CUBE, BENCH_CUBE);
		dBodySetMass(sc->bodies[i], &m);
		dBodySetPosition(sc->bodies[i], sc->start[i].x, sc->start[i].y, sc->start[i].z);
		if (sc->kinematic[i])
			dBodySetKinematic(sc->bodies[i]);
		sc->geoms[i] = dCreateBox(sc->space, BENCH_CUBE, BENCH_CUBE, BENCH_CUBE);
		dGeomSetBody(sc->geoms[i], sc->bodies[i]);
	}
	sc->checksum = 14695981039346656037ull;
	return sc;
}

static void ode_destroy(ode_scene *sc) {
	dJointGroupDestroy(sc->contacts);
	dSpaceDestroy(sc->space); // destroys its geoms
	dWorldDestroy(sc->world);
	free(sc);
}

static void ode_step(void *state, long frames) {
	ode_scene *sc = state;
	const double dt = BENCH_DT;
	for (long f = 0; f < frames; ++f) {
		int next = sc->k + 1 == BENCH_PATH_FRAMES ? 0 : sc->k + 1;
		hs_vec3 a = bench_path(sc->k), b = bench_path(next);
		for (int i = 4; i <= 5; ++i) {
			hs_vec3 p = hs_add(sc->start[i], a), v = hs_scale(hs_sub(b, a), 1.0 / dt);
			dBodySetPosition(sc->bodies[i], p.x, p.y, p.z);
			dBodySetLinearVel(sc->bodies[i], v.x, v.y, v.z);
		}
		dSpaceCollide(sc->space, sc, near_callback);
		dWorldQuickStep(sc->world, dt);
		dJointGroupEmpty(sc->contacts);
		sc->k = next;
		const dReal *p = dBodyGetPosition(sc->bodies[4]);
		sc->checksum = bench_mix(sc->checksum, p[2]);
	}
}

// The projectile of item 3 in ODE: one body, no geometry, the same stepper at BENCH_DT.
static double ode_projectile_error(void) {
	dWorldID w = dWorldCreate();
	dWorldSetGravity(w, 0.0, 0.0, -BENCH_G);
	dBodyID b = dBodyCreate(w);
	dMass m;
	dMassSetBox(&m, 500.0, BENCH_CUBE, BENCH_CUBE, BENCH_CUBE);
	dBodySetMass(b, &m);
	dBodySetPosition(b, 0.0, 0.0, BENCH_PROJ_Z0);
	dBodySetLinearVel(b, BENCH_PROJ_VX, 0.0, BENCH_PROJ_VZ);
	double xs[256], zs[256];
	int n = 0;
	xs[n] = 0.0;
	zs[n++] = BENCH_PROJ_Z0;
	while (n < 256 && zs[n - 1] >= BENCH_PROJ_PLANE) {
		dWorldQuickStep(w, BENCH_DT);
		const dReal *p = dBodyGetPosition(b);
		xs[n] = p[0];
		zs[n++] = p[2];
	}
	dWorldDestroy(w);
	return fabs(bench_crossing_x(xs, zs, n, BENCH_PROJ_PLANE) - bench_projectile_range());
}

int bench_peer_ode(const bench_opts *opts, bench_peer_result out[2]) {
	dInitODE2(0);
	double proj = ode_projectile_error();
	const char *config = dGetConfiguration();
	for (int v = 0; v < 2; ++v) {
		bench_peer_result *r = &out[v];
		memset(r, 0, sizeof *r);
		bool auto_disable = v == 1;
		ode_scene *sc = ode_create(auto_disable);
		r->step = bench_measure(ode_step, sc, opts);
		for (int i = 0; i < 10; ++i) {
			if (sc->kinematic[i])
				continue;
			const dReal *p = dBodyGetPosition(sc->bodies[i]);
			double d = hs_distance(hs_v3(p[0], p[1], p[2]), sc->start[i]);
			r->resting_drift = d > r->resting_drift ? d : r->resting_drift;
		}
		r->checksum = sc->checksum;
		ode_destroy(sc);
		r->projectile_error = proj;
		r->ran = true;
		snprintf(r->name, sizeof r->name, auto_disable ? "ODE+sleep" : "ODE");
		snprintf(r->version, sizeof r->version, "0.16 (%s)", strstr(config, "ODE_double_precision") ? "double" : "single");
		snprintf(r->setup, sizeof r->setup,
		         "dWorldQuickStep 20 it., hash space, 2 kinematic + 8 dynamic boxes, auto-disable %s; drift %.1e m",
		         auto_disable ? "on" : "off (default)", r->resting_drift);
		bench_progress("[peers] %s: %.3f us/step, projectile error %.2e m\n", r->name, 1e6 * r->step.median,
		               r->projectile_error);
	}
	dCloseODE();
	return 2;
}
