// letter.c — the papers' letter as a whole: one call sets every option that departs from a paper
// to what the paper says (docs/model.md §11 "The papers' letter" lists each departure, the
// paper's words and the option that restores it alone).
#include "world_internal.h"

// The 1999 paper's hand model as written ([H] §3-4), or (letter false) the defaults.
static void hand1999(hs_world_def *def, bool letter) {
	hs_world_def d = hs_default_world_def();
	def->paper_contacts = letter ? true : d.paper_contacts;           // §3.2: parts where they end the frame
	def->grasp_any_contacts = letter ? true : d.grasp_any_contacts;   // §3.2 (2): any two contacts
	def->grasp_opposed = letter ? false : d.grasp_opposed;            // the normals' angle alone
	def->grasp_close_mm = letter ? 0.0 : d.grasp_close_mm;            // no closing asked
	def->paper_grasp_end = letter ? true : d.paper_grasp_end;         // successive instances of grasping
	def->glove_deadband = letter ? 0 : d.glove_deadband;              // every raw reading
	def->release_fit = letter ? HS_RELEASE_FIT_OBJECT : d.release_fit; // eq. 3 from the object
	def->release_window_s = d.release_window_s;
	def->paper_landing = letter ? true : d.paper_landing;             // §4.2: lifted straight up
	def->paper_floor_push = letter ? true : d.paper_floor_push;       // eq. 1-2, then §4.2
	def->paper_push_end = letter ? true : d.paper_push_end;           // eq. 3 from the last two positions
	def->paper_tipping = letter ? true : d.paper_tipping;             // §4.2 rule (1): inertia lost
	def->paper_carry = letter ? true : d.paper_carry;                 // §4.3: translated along
	def->stacking = letter ? HS_STACKING_PAPER : d.stacking;
}

// The Responsive Workbench paper's spring model as written ([W] §4), or (letter false) the defaults.
static void workbench(hs_spring_def *def, bool letter) {
	def->pen_tip_spring = letter;   // §4.4: the spring from the pen tip
	def->paper_collisions = letter; // §4.5: contact as geometric intersection, impacts only
}

hs_status hs_world_def_letter(hs_world_def *def, hs_letter letter) {
	if (!def || (letter != HS_LETTER_NONE && letter != HS_LETTER_HAND1999 && letter != HS_LETTER_WORKBENCH))
		return HS_ERR_INVALID_ARGUMENT;
	hand1999(def, letter == HS_LETTER_HAND1999);
	workbench(&def->spring, letter == HS_LETTER_WORKBENCH);
	return HS_OK;
}
