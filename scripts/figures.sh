#!/bin/sh
# figures.sh — `make figures`: the papers' pictures drawn from catalog scenarios (docs/plots.md):
# each a filmstrip (`handspring view --strip`) of the frames nearest the times given.
# Figs. 3-6 of the 1999 paper are drawn by gnuplot from plots/paper_push.c, plots/paper_normals.c and
# plots/paper_hull.c (run from BINDIR, the plots' generators), which check the model's numbers.
#   figures.sh TOOL OUTDIR [BINDIR]
set -eu
tool=$1
out=$2
bin=${3:-build/plots/bin}
mkdir -p "$out"
n=0
fig() { # name, scenario, times, what it shows
	"$tool" view "scenarios/$2.yaml" --strip "$out/$1.png" --at "$3" --size 360x300 2>/dev/null ||
		{ echo "figures: $1 ($2) failed" >&2; exit 1; }
	n=$((n + 1))
	printf 'figures: %-34s %s\n' "$1.png" "$4"
}
# the 1999 virtual-hand paper ("A Model for Manipulation of Objects with Virtual Hand in 3D Virtual Space")
# Fig. 1 (the hand's check points) is hand_wrist_frame.png, below; Figs. 5-6 (the floor's rules)
# are drawn from the model's state by paper_hull (below); beside them, filmstrips of scenarios it
# draws: on two floor vertices a box short of its balance point settles back, one past it tips
# over, a pyramid set on its apex (one vertex) tips onto a face, and an L-block stood on the end of
# its upright (four vertices, G' outside) falls over onto the ends of both arms
fig 1999_fig5_6_settles      box_tip_short                 0,0.2,0.35,1  "Figs. 5-6 (2), filmstrip: on an edge, G' short of it: turns back onto its base"
fig 1999_fig5_6_tips         box_tip_past                  0,0.3,0.5,1   "Figs. 5-6 (2), filmstrip: on an edge, G' past it: tips over onto its side"
fig 1999_fig6_apex           pyramid_apex                  0,0.15,0.2,1  "Fig. 6 (1), filmstrip: on one vertex: turns about it (rule (1)) down onto a face"
fig 1999_fig6_3_l_block      l_block_on_end                0,0.15,0.25,1 "Fig. 6 (3), filmstrip: on four vertices, G' outside: falls about the nearest hull edge"
fig 1999_fig7b_scene         hand/seed_scene_hand          0,1,2,3.5     "Fig. 7b: the scene, ten cubes, a hand grasps two"
fig 1999_fig8_manipulation   hand/grasp_polyhedron         0.4,0.8,1.6,2.6 "Fig. 8: the hand picks up, carries and turns a hexagonal prism"
fig 1999_fig8_polyhedra      polyhedra_drop                0,0.4,0.8,3   "Fig. 8 (objects): arbitrary polyhedra fall, tip and rest"
fig 1999_fig9_flick          hand/flick_pyramid            0,0.9,1.2,2.6 "Fig. 9: a flick tips the pyramid over"
fig 1999_fig10_throw         hand/throw_at_target          0.5,1,1.3,3   "Fig. 10: a throw at the target"
fig 1999_fig11_paper         hand/push_l_block_into_cube_paper   0.5,1.0,1.2,2.4   "Fig. 11: an L-block pushed into a cube, which piles onto it (paper stacking)"
fig 1999_fig11_support       hand/push_l_block_into_cube_support 0.5,1.0,1.2,2.4   "Fig. 11: the same push, support stacking: the cube pushed along"
# the Responsive Workbench paper (Koutek & Post, "Dynamics in Interaction on the Responsive Workbench")
fig workbench_fig1_springs   spring/lift_heavy_and_light   0,2,4,8       "Fig. 1: springs of a heavy and a light object"
fig workbench_fig3_pull_push spring/pull_push_floor        0,2,4,8       "Fig. 3: pull and push on the floor"
fig workbench_fig4_wall      spring/pull_into_wall         0,1,2,4       "Fig. 4: the wall stops the object, the spring stretches"
fig workbench_fig5_world     spring/mini_world             0,1,3,6.5     "Fig. 5: the mini-world, walls, boxes and balls; a crate lifted, dropped"
fig workbench_select         spring/select_among_three     0,1,2,4       "§3: selecting the one of three the hand moves toward"
fig workbench_fig7_8_lift    spring/lift_swing_drop        0.5,2,3.5,6.5 "Figs. 7-8: lift, move, drop"
fig 1999_fig12_approach      hand/push_then_grasp          0.3,0.8,1.3,2.2 "Fig. 12's approach: one fingertip (1), two (3), the thumb closes (2)"
# Fig. 12: the contact states of that approach against time (plots/hand_timeline.gp)
mkdir -p "$out/traj/hand"
"$tool" run scenarios/hand/push_then_grasp.yaml --out "$out/traj/hand/push_then_grasp.csv" > /dev/null
gnuplot -e "traj='$out/traj'; out='$out'; scn='hand/push_then_grasp'" plots/hand_timeline.gp
rm -f "$out/hand_timeline_push_then_grasp.svg"
mv "$out/hand_timeline_push_then_grasp.png" "$out/1999_fig12_states.png"
n=$((n + 1))
printf 'figures: %-34s %s\n' "1999_fig12_states.png" "Fig. 12: contact states 0, 1, 3, 2, 0 of hand/push_then_grasp"
# Figs. 3-6: the push split into T and R at a real contact; the normals and an edge's pseudo-normal;
# the floor vertices' hull and G', each of §4.2's cases with the model's next frame checked
for g in paper_push paper_normals paper_hull; do
	"$bin/$g" "$out" > /dev/null || { echo "figures: $g failed" >&2; exit 1; }
	gnuplot -e "out='$out'" "plots/$g.gp"
done
mv "$out/paper_push.png" "$out/1999_fig3_push.png"
mv "$out/paper_normals.png" "$out/1999_fig4_normals.png"
mv "$out/paper_hull.png" "$out/1999_fig5_6_hull.png"
n=$((n + 3))
printf 'figures: %-34s %s\n' "1999_fig3_push.png" "Fig. 3: a push at one point, CB = T + R (eq. 1-2), checked against the model"
printf 'figures: %-34s %s\n' "1999_fig4_normals.png" "Fig. 4: contact normals and an edge's pseudo-normal; a grasp"
printf 'figures: %-34s %s\n' "1999_fig5_6_hull.png" "Figs. 5-6: floor vertices, hull, G'; stable, rules (1), (2)-a, (2)-b, (3), checked against the model"
# Workbench Figs. 2 and 6: the damping cases against their closed forms; the tracker's samples and
# speed during a recorded lift and throw (the plots of `make plots`, drawn here from the same generators)
mkdir -p "$out/traj/spring"
"$tool" run scenarios/spring/recorded_throw.yaml --out "$out/traj/spring/recorded_throw.csv" > /dev/null ||
	{ echo "figures: spring/recorded_throw failed" >&2; exit 1; }
for g in spring_damping spring_tracker; do
	"$bin/$g" "$out" > /dev/null || { echo "figures: $g failed" >&2; exit 1; }
	gnuplot -e "traj='$out/traj'; out='$out'" "plots/$g.gp"
done
rm -rf "$out/traj"
mv "$out/spring_damping.png" "$out/workbench_fig2_damping.png"
mv "$out/spring_tracker.png" "$out/workbench_fig6_tracker.png"
n=$((n + 2))
printf 'figures: %-34s %s\n' "workbench_fig2_damping.png" "WB Fig. 2: under-, critically and over-damped springs, simulated against closed forms"
printf 'figures: %-34s %s\n' "workbench_fig6_tracker.png" "WB Fig. 6: the 50 Hz tracker's samples and speed estimate in a recorded lift and throw"
# the default hand's check points in the wrist frame (handspring hand): top and side views, for
# scenarios/README.md (writing a hand scenario needs no hidden geometry)
"$tool" hand --posture open > "$out/hand_open.csv"
"$tool" hand --posture grasp --amount 0.05 > "$out/hand_grasp.csv"
gnuplot -e "out='$out'" scripts/hand_frame.gp
n=$((n + 1))
printf 'figures: %-34s %s\n' "hand_wrist_frame.png" "Fig. 1: the default hand's 20 check points in the wrist frame"
echo "figures: $n figures in $out"
