// contact_part.c — a many-faced part's queries through its normal-cone tree (face_tree.h), out of
// line: the face scan's answers (contact_part.h, the rule of the 1999 paper §3.2 (A)) for parts of
// HS_FACE_TREE_MIN_FACES faces or more.
#include "contact_part.h"

bool hs_contact_inside_many(const hs_world_model *model, const hs_shape *shape, const hs_part *part, hs_vec3 p,
                            double grow) {
	const hs_face_tree *tree = tree_of(model, shape);
	int root = hs_face_tree_root(tree, shape, part);
	return root >= 0 ? hs_face_tree_inside(tree, root, shape, p, grow) : scan_inside(shape, part, p, grow);
}

int hs_contact_nearest_many(const hs_world_model *model, const hs_shape *shape, const hs_part *part, hs_vec3 p) {
	const hs_face_tree *tree = tree_of(model, shape);
	int root = hs_face_tree_root(tree, shape, part);
	return root >= 0 ? hs_face_tree_nearest(tree, root, shape, part->first_face, p) : scan_nearest(shape, part, p);
}
