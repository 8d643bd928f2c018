// part_box.c — recognising a part that is a box with axis-aligned faces (part_box.h).
#include <math.h>

#include "part_box.h"

// Which of +x, -x, +y, -y, +z, -z the unit normal n is exactly, or -1.
static int axis_of(hs_vec3 n) {
	const double c[3] = {n.x, n.y, n.z};
	for (int k = 0; k < 3; ++k) {
		int a = (k + 1) % 3, b = (k + 2) % 3;
		if (c[a] == 0.0 && c[b] == 0.0 && (c[k] == 1.0 || c[k] == -1.0))
			return 2 * k + (c[k] < 0.0);
	}
	return -1;
}

void hs_part_box_find(const hs_shape *shape, const hs_part *part, hs_part_cache *pc) {
	for (int k = 0; k < 6; ++k) {
		pc->box_face[k] = -1;
		pc->box_offset[k] = 0.0;
		pc->box_axis[k] = -1;
	}
	if (part->face_count != 6 || part->first_face < 0 || part->first_face + 6 > shape->face_count)
		return;
	int face[6] = {-1, -1, -1, -1, -1, -1};
	for (int f = part->first_face; f < part->first_face + 6; ++f) {
		int k = axis_of(shape->faces[f].normal);
		if (k < 0 || face[k] >= 0 || !isfinite(shape->faces[f].offset))
			return;
		face[k] = f;
	}
	for (int k = 0; k < 6; ++k) {
		pc->box_face[k] = face[k];
		pc->box_offset[k] = shape->faces[face[k]].offset;
		pc->box_axis[face[k] - part->first_face] = k;
	}
}
