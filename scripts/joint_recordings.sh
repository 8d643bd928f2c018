#!/bin/sh
# joint_recordings.sh — writes the catalog's joint recordings from the glove
# model's own motion: hand/free_manipulation's hand as MediaPipe landmarks and as OpenXR joints.
#   joint_recordings.sh TOOL
set -eu
tool=${1:-build/handspring}
for f in mediapipe openxr; do
	# 120 samples/s: every frame time of the robustness sweep but 1/17 s falls on a sample (the grasp
	# closes within 5 ms, which a 60 Hz recording would spread over a whole frame)
	"$tool" joints scenarios/hand/free_manipulation.yaml --format "$f" --rate 120 --out "scenarios/hand/joints_$f.csv"
	echo "joint_recordings: scenarios/hand/joints_$f.csv"
done
