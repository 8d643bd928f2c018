#!/bin/sh
# figures.sh — `make figures`: the papers' pictures drawn from catalog scenarios (docs/plots.md):
# each a filmstrip (`handspring view --strip`) of the frames nearest the times given.
#   figures.sh TOOL OUTDIR
set -eu
tool=$1
out=$2
mkdir -p "$out"
n=0
fig() { # name, scenario, times, what it shows
	"$tool" view "scenarios/$2.yaml" --strip "$out/$1.png" --at "$3" --size 360x300 2>/dev/null ||
		{ echo "figures: $1 ($2) failed" >&2; exit 1; }
	n=$((n + 1))
	printf 'figures: %-34s %s\n' "$1.png" "$4"
}
# the 1999 virtual-hand paper ("A Model for Manipulation of Objects with Virtual Hand in 3D Virtual Space")
fig 1999_fig7b_scene         hand/seed_scene_hand          0,1,2,3.5     "Fig. 7b: the scene, ten cubes, a hand grasps two"
fig 1999_fig8_polyhedra      polyhedra_drop                0,0.4,0.8,3   "Fig. 8: arbitrary polyhedra fall, tip and rest"
fig 1999_fig9_flick          hand/flick_pyramid            0,0.9,1.2,2.6 "Fig. 9: a flick tips the pyramid over"
fig 1999_fig10_throw         hand/throw_at_target          0.5,1,1.3,3   "Fig. 10: a throw at the target"
fig 1999_fig11_paper         hand/push_l_block_into_cube_paper   0.5,1.0,1.2,2.4   "Fig. 11: an L-block pushed into a cube, which piles onto it (paper stacking)"
fig 1999_fig11_support       hand/push_l_block_into_cube_support 0.5,1.0,1.2,2.4   "Fig. 11: the same push, support stacking: the cube pushed along"
# the Responsive Workbench paper (Koutek & Post, "Dynamics in Interaction on the Responsive Workbench")
fig workbench_fig1_springs   spring/lift_heavy_and_light   0,2,4,8       "Fig. 1: springs of a heavy and a light object"
fig workbench_fig3_pull_push spring/pull_push_floor        0,2,4,8       "Fig. 3: pull and push on the floor"
fig workbench_fig4_wall      spring/pull_into_wall         0,1,2,4       "Fig. 4: the wall stops the object, the spring stretches"
fig workbench_fig5_world     spring/select_among_three     0,1,2,4       "Fig. 5: a small world, selecting one of three"
fig workbench_fig7_8_lift    spring/lift_swing_drop        0.5,2,3.5,6.5 "Figs. 7-8: lift, move, drop"
# the default hand's check points in the wrist frame (handspring hand): top and side views, for
# scenarios/README.md (writing a hand scenario needs no hidden geometry)
"$tool" hand --posture open > "$out/hand_open.csv"
"$tool" hand --posture grasp --amount 0.05 > "$out/hand_grasp.csv"
gnuplot -e "out='$out'" scripts/hand_frame.gp
n=$((n + 1))
printf 'figures: %-34s %s\n' "hand_wrist_frame.png" "the default hand's check points in the wrist frame"
echo "figures: $n figures in $out"
