// spring_magnet.c — the magnet gesture ("Dynamics in Interaction on the Responsive Workbench" §3:
// "a fully extended hand bends in the elbow and moves into his working sphere. This method works
// like a magnet on objects"); docs/techniques.md.
//
// Reading fixed here:
//  - From the tracked stylus alone (the workbench tracks the pen and the head, not the arm): with
//    nothing on the spring, the arm counts as extended while the stylus is at least magnet_far
//    from the shoulder point `body`, and the selection candidate then (the pointing ray or the
//    hand's path, spring_grab.c) is remembered with the time; when the stylus comes within
//    magnet_near of `body` no more than magnet_within after it was last extended, that object is
//    brought to the pen (G at the stylus, at rest) and held as the slave. A slow return or a
//    reach that stops short of the sphere grabs nothing; the button is not used (it releases).
#include "spring_grab.h"
#include "spring_technique.h"
#include "world_internal.h"

void hs_spring_magnet(hs_world *world, hs_spring_system *sys, double t1) {
	hs_spring_technique *t = &sys->tech;
	if (!sys->def.techniques || !t->set.magnet || sys->attached >= 0)
		return;
	double reach = hs_distance(sys->stylus, t->set.body);
	if (reach >= t->set.magnet_far) {
		if (sys->candidate >= 0) {
			t->magnet_object = sys->candidate;
			t->magnet_seen = t1;
		}
		return;
	}
	if (t->magnet_object < 0 || reach > t->set.magnet_near)
		return;
	int i = t->magnet_object;
	t->magnet_object = -1;
	if (t1 - t->magnet_seen > t->set.magnet_within)
		return; // too slow: no gesture
	hs_body *body = &world->state.bodies[i];
	t->home_pos = body->pos;
	t->home_rot = body->rot;
	body->pos = sys->stylus; // brought to the pen, at rest
	body->vel = hs_v3(0.0, 0.0, 0.0);
	hs_spring_attach(world, sys, i, HS_ATTACH_MAGNET);
}
