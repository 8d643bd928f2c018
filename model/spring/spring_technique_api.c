// spring_technique_api.c — the public API of the manipulation techniques (handspring.h,
// docs/techniques.md): their settings, checked, in the world's state.
#include <string.h>

#include "spring_system.h"
#include "spring_technique.h"
#include "world_internal.h"

hs_technique_def hs_default_technique_def(void) {
	hs_technique_def d;
	memset(&d, 0, sizeof d);
	d.technique = HS_TECHNIQUE_SPRING;
	d.release = HS_RELEASE_MODE_HAND;
	d.magnet = false;
	d.body = hs_v3(0.0, 0.0, 0.0);
	d.magnet_far = 0.6;    // m: an arm's reach, nearly straight
	d.magnet_near = 0.35;  // m: the elbow bent, the hand before the chest
	d.magnet_within = 0.6; // s: one deliberate pull
	return d;
}

static bool technique_valid(const hs_technique_def *d) {
	return d && (int)d->technique >= HS_TECHNIQUE_SPRING && d->technique <= HS_TECHNIQUE_CROSS_SURFACE &&
	       (int)d->release >= HS_RELEASE_MODE_HAND && d->release <= HS_RELEASE_MODE_RETURN &&
	       hs_vec3_is_finite(d->body) && hs_within(d->body, HS_MAX_COORDINATE) && isfinite(d->magnet_far) &&
	       isfinite(d->magnet_near) && d->magnet_near > 0.0 && d->magnet_near < d->magnet_far &&
	       d->magnet_far <= HS_MAX_COORDINATE && isfinite(d->magnet_within) && d->magnet_within > 0.0 &&
	       d->magnet_within <= 1e6;
}

hs_status hs_world_spring_set_technique(hs_world *world, const hs_technique_def *def) {
	if (!world || !world->state.spring || !world->state.spring->def.techniques || !technique_valid(def))
		return HS_ERR_INVALID_ARGUMENT;
	world->state.spring->tech.set = *def;
	world->state.spring->tech.set.magnet = def->magnet; // (a bool: 0 or 1 whatever the caller's byte)
	return HS_OK;
}

hs_status hs_world_spring_technique(const hs_world *world, hs_technique_def *out) {
	if (!world || !world->state.spring || !out)
		return HS_ERR_INVALID_ARGUMENT;
	*out = world->state.spring->tech.set;
	return HS_OK;
}
