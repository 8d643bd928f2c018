#!/bin/sh
# determinism.sh — the determinism matrix (DESIGN.md "Determinism"): the tool built by different
# compilers at different optimisation levels runs the whole catalog, and every trajectory's
# per-frame state hashes (the `hash` column of each CSV) must be identical across the builds.
#
#   determinism.sh --pair   gcc -O0, gcc -O2, clang -O2                      (make check)
#   determinism.sh --full   gcc and clang at -O0, -O2, -O3, and both ASan+UBSan builds
#                           (make determinism)
#
# Each build goes to its own folder, $BUILD/det/NAME (make BUILD=... CC=... OPT=... all), and
# writes its trajectories to $BUILD/det/NAME/traj. Prints the matrix: one row per scenario, one
# column per build, "ref" for the first build, "=" where every frame's hash agrees with it, or
# "F<frame>" at the first frame that differs. Exit status 1 when any build disagrees or fails.
set -eu

BUILD=${BUILD:-build}
JOBS=${JOBS:-2}
CATALOG=${CATALOG:-scenarios}
mode=${1:---pair}

case "$mode" in
--pair) builds="gcc-O0:gcc:-O0:0 gcc-O2:gcc:-O2:0 clang-O2:clang:-O2:0" ;;
--full)
	builds="gcc-O0:gcc:-O0:0 gcc-O2:gcc:-O2:0 gcc-O3:gcc:-O3:0 clang-O0:clang:-O0:0 clang-O2:clang:-O2:0"
	builds="$builds clang-O3:clang:-O3:0 gcc-asan:gcc:-O1:1 clang-asan:clang:-O1:1"
	;;
*)
	echo "usage: determinism.sh [--pair|--full]" >&2
	exit 2
	;;
esac

for tool in gcc clang; do
	if ! command -v "$tool" >/dev/null 2>&1; then
		echo "determinism: $tool is missing (scripts/deps.sh installs it)" >&2
		exit 1
	fi
done

det="$BUILD/det"
mkdir -p "$det"
names=""
# every build must see the same sources: an edit during the run would look like a divergence
sources() { cat model/*.c model/*.h tool/*.c Makefile | cksum; }
before=$(sources)
for spec in $builds; do
	IFS=: read -r name cc opt san <<EOF
$spec
EOF
	dir="$det/$name"
	# a make of its own (no jobserver of the caller's), quiet unless it fails
	if ! MAKEFLAGS='' make --no-print-directory -j"$JOBS" BUILD="$dir" CC="$cc" OPT="$opt" SANITIZE="$san" all \
		>"$det/$name.build.log" 2>&1; then
		cat "$det/$name.build.log" >&2
		echo "determinism: the $name build failed" >&2
		exit 1
	fi
	rm -rf "$dir/traj"
	status=0
	"$dir/handspring" all --dir "$CATALOG" --out-dir "$dir/traj" >"$dir/catalog.txt" 2>"$dir/catalog.err" || status=$?
	if [ "$status" -gt 1 ] || [ -s "$dir/catalog.err" ]; then
		cat "$dir/catalog.err" >&2
		echo "determinism: the $name build could not run the catalog (status $status)" >&2
		exit 1
	fi
	[ "$status" -eq 1 ] && echo "determinism: note: $name: an expectation failed (see $dir/catalog.txt)" >&2
	names="$names $name"
done

if [ "$(sources)" != "$before" ]; then
	echo "determinism: the sources changed while the builds were made: run it again" >&2
	exit 1
fi

# shellcheck disable=SC2086 # the names are words without blanks
set -- $names
ref=$1
files=$(cd "$det/$ref/traj" && find . -name '*.csv' | sed 's|^\./||' | sort)
if [ -z "$files" ]; then
	echo "determinism: no trajectories in $det/$ref/traj" >&2
	exit 1
fi

# frame,hash of every row (the hash column found by its header name)
hashes() {
	awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "hash") h = i; if (!h) exit 1; next }
		/^#/ { next } { print $1 "," $h }' "$1"
}

bad=0
width=0
for f in $files; do
	n=$(printf '%s' "${f%.csv}" | wc -c)
	[ "$n" -gt "$width" ] && width=$n
done
printf "determinism matrix (%s): per-frame state hashes of %s/*.yaml\n" "$mode" "$CATALOG"
printf "%-${width}s" "scenario"
for name in "$@"; do printf "  %-10s" "$name"; done
printf "  %s\n" "frames"
tmp="$det/.cmp"
for f in $files; do
	printf "%-${width}s" "${f%.csv}"
	hashes "$det/$ref/traj/$f" >"$tmp.ref"
	for name in "$@"; do
		if [ "$name" = "$ref" ]; then
			cell=ref
		elif [ ! -f "$det/$name/traj/$f" ]; then
			cell=missing
			bad=1
		else
			hashes "$det/$name/traj/$f" >"$tmp.other"
			if cmp -s "$tmp.ref" "$tmp.other"; then
				cell="="
			else
				# the first row that differs names its frame
				frame=$(paste -d' ' "$tmp.ref" "$tmp.other" | awk '$1 != $2 { split($1 != "" ? $1 : $2, x, ","); print x[1]; exit }')
				cell="F${frame:-end}"
				bad=1
			fi
		fi
		printf "  %-10s" "$cell"
	done
	printf "  %s\n" "$(tail -n 1 "$tmp.ref" | cut -d, -f1)"
done
rm -f "$tmp.ref" "$tmp.other"

# the other way round: a build must not write trajectories the reference did not
for name in "$@"; do
	extra=$(find "$det/$name/traj" -name '*.csv' | sed "s|^$det/$name/traj/||" | sort | while read -r g; do
		[ -f "$det/$ref/traj/$g" ] || printf ' %s' "$g"
	done)
	if [ -n "$extra" ]; then
		echo "determinism: $name wrote trajectories $ref did not:$extra" >&2
		bad=1
	fi
done

if [ "$bad" -ne 0 ]; then
	echo "determinism: FAILED: the builds disagree (cells F<n>: first frame whose hash differs from $ref)"
	exit 1
fi
same=yes
for name in "$@"; do
	[ "$name" = "$ref" ] && continue
	diff -rq "$det/$ref/traj" "$det/$name/traj" >/dev/null 2>&1 || same=no
done
echo "determinism: $# builds agree on every frame of $(echo "$files" | wc -l) scenarios (whole trajectory files identical: $same)"
