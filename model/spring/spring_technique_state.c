// spring_technique_state.c — the techniques' state of a new spring system (spring_technique_state.h).
#include <string.h>

#include "spring_technique_state.h"

void hs_spring_technique_init(hs_spring_technique *t) {
	memset(t, 0, sizeof *t);
	t->set = hs_default_technique_def();
	t->hold = HS_TECHNIQUE_SPRING;
	t->grab_rot = t->grab_obj_rot = t->home_rot = hs_quat_identity();
	t->magnet_object = -1;
}
