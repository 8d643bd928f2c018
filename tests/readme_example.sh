#!/bin/sh
# readme_example.sh — `make check-readme`: the README's examples build and run as a user would
# build them, against an installed copy, through pkg-config.
#
#  1. `make install PREFIX=$BUILD/readme/prefix`; a second tree holds only the static archives
#     (what a user has who links statically: pkg-config --static then picks the .a files).
#  2. Every public header compiles on its own as C (gcc, clang: -std=c99 and -std=c11 with the
#     project's warnings) and as C++ (g++, clang++: -std=c++11 -Wall -Wextra -Wpedantic -Werror).
#  3. Every function the public headers declare is exported by the installed shared library.
#  4. Each example of README.md (the ```c block after `<!-- example: NAME -->`) is built with
#     gcc and clang as C, and with g++ as C++ (g++ -x c++), each shared (run path to the copy)
#     and static; every build must print exactly the ```text block after `<!-- output: NAME -->`.
#     Its command blocks run as written: the tour in a scratch folder, the link lines with the two
#     examples (their run path lets them start without LD_LIBRARY_PATH).
#  5. The man page renders and names every command; the installed catalog runs.
#  6. `make uninstall` leaves no file behind; an install with DESTDIR stages under it.
# Runs from the top folder; BUILD (default build) and MAKE (default make) as in the Makefile.
set -eu

BUILD=${BUILD:-build}
MAKE=${MAKE:-make}
top=$(pwd)
case "$BUILD" in
/*) work="$BUILD/readme" ;;
*) work="$top/$BUILD/readme" ;;
esac
prefix="$work/prefix"
static="$work/static"
fails=0

fail() {
	echo "check-readme: $*" >&2
	fails=$((fails + 1))
}

rm -rf "$work"
mkdir -p "$work/bin"

# 1. install, and a static-only tree beside it (.pc files relocated with --define-variable)
if ! $MAKE --no-print-directory BUILD="$BUILD" install PREFIX="$prefix" >"$work/install.log" 2>&1; then
	cat "$work/install.log" >&2
	echo "check-readme: make install PREFIX=$prefix failed" >&2
	exit 1
fi
mkdir -p "$static/lib"
cp "$prefix"/lib/*.a "$static/lib/"
cp -R "$prefix/lib/pkgconfig" "$static/lib/"
ln -s "$prefix/include" "$static/include"

pc_shared() { PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config "$@"; }
pc_static() { PKG_CONFIG_PATH="$static/lib/pkgconfig" pkg-config --define-variable=prefix="$static" --static "$@"; }

# 2. the headers alone, as C and as C++
C_WARN="-std=c11 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wvla -Werror"
CXX_WARN="-std=c++11 -Wall -Wextra -Wpedantic -Werror"
cflags=$(pc_shared --cflags handspring-harness)
headers=0
for h in hs_math.h handspring.h hs_harness.h; do
	printf '#include <handspring/%s>\n#include <handspring/%s>\nint hs_header_test(void);\nint hs_header_test(void) { return 0; }\n' \
		"$h" "$h" >"$work/header.c"
	for cc in gcc clang; do
		for std in c99 c11; do
			# shellcheck disable=SC2086
			$cc $C_WARN -std=$std $cflags -fsyntax-only "$work/header.c" || fail "$h does not compile as $std with $cc"
			headers=$((headers + 1))
		done
	done
	for cxx in g++ clang++; do
		command -v $cxx >/dev/null 2>&1 || continue
		# shellcheck disable=SC2086
		$cxx -x c++ $CXX_WARN $cflags -fsyntax-only "$work/header.c" || fail "$h does not compile as C++ with $cxx"
		headers=$((headers + 1))
	done
done
echo "check-readme: the 3 public headers compile alone as C99, C11 and C++11 ($headers compilations)"

# 3. the exported functions
declared() { sed -n -e '/static inline/d' -e 's/^[A-Za-z_][A-Za-z0-9_ *]*[ *]\(hs_[A-Za-z0-9_]*\)(.*/\1/p' "$@"; }
for lib in handspring:"handspring.h hs_math.h" handspring-harness:"hs_harness.h"; do
	name=${lib%%:*}
	exported=$(nm -D --defined-only "$prefix/lib/lib$name.so" | awk '{ print $3 }')
	n=0
	for f in $(cd "$prefix/include/handspring" && declared ${lib#*:}); do
		n=$((n + 1))
		echo "$exported" | grep -qx "$f" || fail "lib$name.so does not export $f (declared in a public header)"
	done
	# the other way round, independent of how a declaration is laid out: every function of the
	# static library whose name a public header writes as a call, name(, must be exported
	for f in $(nm -g --defined-only "$prefix/lib/lib$name.a" | awk '$2 == "T" { print $3 }'); do
		(cd "$prefix/include/handspring" && grep -Eq "(^|[^A-Za-z0-9_])$f\(" ${lib#*:}) || continue
		echo "$exported" | grep -qx "$f" || fail "lib$name.so does not export $f (named in a public header)"
	done
	echo "check-readme: lib$name.so: $n functions declared in its public headers, $(echo "$exported" | wc -l) exported"
done

# 4. the README's examples
extract() { # extract KIND NAME: the first ``` block after the marker `<!-- KIND: NAME -->`
	awk -v marker="<!-- $1: $2 -->" '
		$0 == marker { found = 1; next }
		found == 1 && /^```/ { found = 2; next }
		found == 2 && /^```/ { exit }
		found == 2 { print }' README.md
}

for example in library harness; do
	src="$work/$example.c"
	extract example "$example" >"$src"
	extract output "$example" >"$work/$example.expected"
	if [ ! -s "$src" ] || [ ! -s "$work/$example.expected" ]; then
		fail "README.md has no example '$example' (<!-- example: $example --> then a \`\`\`c block, <!-- output: $example --> then a \`\`\`text block)"
		continue
	fi
	grep -q 'int main' "$src" || fail "the README's $example example has no main()"
	pkg=handspring
	[ "$example" = harness ] && pkg=handspring-harness
	for compiler in gcc clang g++; do
		case "$compiler" in
		g++) lang="-x c++ $CXX_WARN" ;;
		*) lang="$C_WARN" ;;
		esac
		for link in shared static; do
			exe="$work/bin/$example-$compiler-$link"
			if [ "$link" = shared ]; then
				flags="$(pc_shared --cflags $pkg) $src $(pc_shared --libs $pkg) -Wl,-rpath,$prefix/lib"
			else
				flags="$(pc_static --cflags $pkg) $src $(pc_static --libs $pkg)"
			fi
			echo "$compiler $lang $flags" >"$exe.cmd"
			# shellcheck disable=SC2086
			if ! $compiler $lang -o "$exe" $flags 2>"$exe.log"; then
				cat "$exe.cmd" "$exe.log" >&2
				fail "the $example example does not build ($compiler, $link)"
				continue
			fi
			needs=$(readelf -d "$exe" | grep -c "NEEDED.*lib$pkg\.so\." || :)
			if [ "$link" = shared ] && [ "$needs" -eq 0 ]; then fail "$exe does not load lib$pkg.so"; fi
			if [ "$link" = static ] && [ "$needs" -ne 0 ]; then fail "$exe loads lib$pkg.so"; fi
			# without LD_LIBRARY_PATH: the shared builds find the copy through their run path
			if ! env -u LD_LIBRARY_PATH "$exe" >"$exe.out" 2>"$exe.err"; then
				cat "$exe.err" >&2
				fail "the $example example exits with an error ($compiler, $link)"
			elif ! cmp -s "$exe.out" "$work/$example.expected"; then
				diff "$work/$example.expected" "$exe.out" >&2 || :
				fail "the $example example prints something else than the README shows ($compiler, $link)"
			else
				echo "check-readme: $example example, $compiler $link: $(cat "$exe.out")"
			fi
		done
	done
done

# 4b. the README's command blocks, as written, in scratch folders: the tour (`<!-- commands: tour -->`,
#     beside links to the build folder and the catalog) and the link lines (`<!-- commands: link -->`,
#     with the two examples as drop.c and run.c, HOME in the scratch folder, `make` run in the top
#     folder): every command must succeed, and ./drop and ./run print what the README shows
case "$BUILD" in /*) build_abs=$BUILD ;; *) build_abs=$top/$BUILD ;; esac
tour="$work/tour"
mkdir -p "$tour"
ln -s "$build_abs" "$tour/build"
ln -s "$top/scenarios" "$tour/scenarios"
extract commands tour >"$tour/tour.sh"
if [ ! -s "$tour/tour.sh" ]; then
	fail "README.md has no tour (<!-- commands: tour --> then a \`\`\`sh block)"
elif ! (cd "$tour" && sh -eu tour.sh >tour.out 2>&1); then
	tail -n 5 "$tour/tour.out" >&2
	fail "the README's tour fails (commands in $tour/tour.sh)"
else
	[ "$(head -n 1 "$tour/drop.csv")" = "frame,t,object,x,y,z,qw,qx,qy,qz,contact,floor,resting,hash" ] ||
		fail "the tour's drop.csv does not start with its header"
	grep -q '^sweep: 80 of 80 cells pass$' "$tour/tour.out" || fail "the tour's sweep does not say 'sweep: 80 of 80 cells pass'"
	[ -s "$tour/grasp.html" ] || fail "the tour wrote no grasp.html"
	[ -s "$tour/mine/golden/drop_cube.csv" ] && [ -s "$tour/mine/golden/free_manipulation.csv" ] ||
		fail "the tour's golden mine wrote no goldens in mine/golden"
	grep -q '2 match, 0 differ' "$tour/tour.out" || fail "the tour's check mine does not match its goldens"
	echo "check-readme: the tour runs as written (list, run, sweep, view --html, golden, check)"
fi
user="$work/user"
mkdir -p "$user/home"
ln -s "$top/scenarios" "$user/scenarios"
extract example library >"$user/drop.c"
extract example harness >"$user/run.c"
{
	echo "make() { command $MAKE --no-print-directory -C '$top' BUILD='$BUILD' \"\$@\" LDCONFIG=: >/dev/null; }"
	extract commands link
} >"$user/link.sh"
if ! grep -q 'rpath' "$user/link.sh"; then
	fail "the README's link lines (<!-- commands: link -->) give no run path (-Wl,-rpath)"
elif ! (cd "$user" && env -u LD_LIBRARY_PATH HOME="$user/home" sh -eu link.sh >link.out 2>&1); then
	tail -n 5 "$user/link.out" >&2
	fail "the README's link lines fail (commands in $user/link.sh)"
else
	{ extract output library; extract output harness; } >"$user/expected"
	cmp -s "$user/expected" "$user/link.out" || { diff "$user/expected" "$user/link.out" >&2 || :; fail "./drop and ./run print something else than the README shows"; }
	left=$(find "$user/home" ! -type d)
	[ -z "$left" ] || fail "the README's make uninstall left:" $left
	echo "check-readme: the README's link lines build drop and run, which start without LD_LIBRARY_PATH"
fi

# 5. the man page and the catalog: the page renders without a warning and names every command the
#    tool's --help lists; the installed catalog (with the recordings it reads) runs from there
page="$prefix/share/man/man1/handspring.1"
if [ ! -f "$page" ]; then
	fail "make install did not install the man page share/man/man1/handspring.1"
else
	warnings=$(groff -man -ww -z "$page" 2>&1) || fail "groff could not read the man page"
	[ -z "$warnings" ] || fail "the man page has warnings: $warnings"
	MANWIDTH=100 man -l "$page" >"$work/man.txt" 2>/dev/null || fail "man -l $page failed"
	for cmd in $("$prefix/bin/handspring" --help 2>&1 | sed -n 's/^  \([a-z][a-z]*\) .*/\1/p'); do
		grep -q "^       $cmd\\b" "$work/man.txt" || fail "the man page does not describe the command '$cmd'"
	done
	grep -q "$prefix/share/handspring/scenarios" "$work/man.txt" || fail "the man page does not name the installed catalog"
fi
catalog="$prefix/share/handspring/scenarios"
n=$("$prefix/bin/handspring" list --dir "$catalog" 2>/dev/null | wc -l)
[ "$n" -eq "$(find scenarios -name '*.yaml' | wc -l)" ] || fail "the installed catalog lists $n scenarios, not those of scenarios/"
for s in drop_cube hand/real_grab; do
	"$prefix/bin/handspring" run "$catalog/$s.yaml" >"$work/catalog.out" 2>&1 ||
		fail "the installed catalog's $s does not run: $(tail -n 2 "$work/catalog.out")"
done
echo "check-readme: the man page names every command; the installed catalog lists $n scenarios and runs"

# 6. uninstall removes every file; DESTDIR stages an install under it
$MAKE --no-print-directory -s BUILD="$BUILD" uninstall PREFIX="$prefix" >"$work/uninstall.log" 2>&1 ||
	fail "make uninstall PREFIX=$prefix failed: $(cat "$work/uninstall.log")"
left=$(find "$prefix" ! -type d | sed "s|^$prefix/||")
[ -z "$left" ] || fail "make uninstall left:" $left
[ ! -e "$prefix/include/handspring" ] || fail "make uninstall left the folder include/handspring"
stage="$work/stage"
$MAKE --no-print-directory -s BUILD="$BUILD" install DESTDIR="$stage" PREFIX=/usr/local >"$work/destdir.log" 2>&1 ||
	fail "make install DESTDIR=$stage failed: $(cat "$work/destdir.log")"
grep -qx 'prefix=/usr/local' "$stage/usr/local/lib/pkgconfig/handspring.pc" ||
	fail "with DESTDIR, handspring.pc does not say prefix=/usr/local"
[ -L "$stage/usr/local/lib/libhandspring.so.0" ] || fail "with DESTDIR, libhandspring.so.0 is not installed"
$MAKE --no-print-directory -s BUILD="$BUILD" uninstall DESTDIR="$stage" PREFIX=/usr/local >>"$work/destdir.log" 2>&1 ||
	fail "make uninstall DESTDIR=$stage failed"
left=$(find "$stage" ! -type d)
[ -z "$left" ] || fail "make uninstall with DESTDIR left:" $left

if [ "$fails" -ne 0 ]; then
	echo "check-readme: $fails failure(s); files in $work" >&2
	exit 1
fi
echo "check-readme: the README's examples build and run (gcc, clang, g++ as C++; shared and static); install/uninstall clean"
