#!/bin/sh
# libccd_src.sh DIR — puts the source of libccd 2.1 in DIR (DIR/src/ccd.c ...), when it is not
# there yet.
#
# handspring compiles libccd itself, with its own floating-point flags (docs/building.md
# "libccd"): a distribution's libccd is built with that distribution's flags, which on i386 (x87
# registers) and arm64 (fused multiply-add) round differently from x86-64, and libccd's
# penetration depths feed object positions. Built here with -ffp-contract=off and SSE2 arithmetic,
# the same source gives the same bits on every architecture.
#
# The source is Debian's source package of libccd 2.1 (the upstream release tarball), fetched
# with apt-get from the machine's own Debian mirror into a private package list (no root
# needed), and checked against the SHA-256 below before it is unpacked.
# Exit status: 0 when DIR holds the source, 1 when it could not be fetched (the message says
# how to put it there by hand).
set -eu

dir=${1:?usage: libccd_src.sh DIR}
version=2.1
tarball=libccd_$version.orig.tar.gz
sha256=3543093486a8bdb7129e18d69d8f2b42e3056877521425210f9fe560789ebba5

[ -f "$dir/src/ccd.c" ] && [ -f "$dir/src/ccd/ccd.h" ] && exit 0

fail() {
	echo "libccd_src: $1" >&2
	echo "libccd_src: put libccd $version's source (Debian's $tarball, SHA-256 $sha256, or" \
		"upstream's v$version release) unpacked in $dir, or name its folder with make CCD_SRC=..." >&2
	exit 1
}

command -v apt-get >/dev/null 2>&1 || fail "apt-get is not here to fetch libccd $version's source"
parent=$(dirname "$dir")
mkdir -p "$parent"
parent=$(cd "$parent" && pwd)
work=$(mktemp -d "$parent/.libccd.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM

# the machine's Debian sources, read for source packages
mkdir -p "$work/lists/partial" "$work/cache/archives/partial" "$work/sources" "$work/get"
: >"$work/status"
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
	[ -f "$f" ] && sed -n 's/^[[:space:]]*deb[[:space:]]/deb-src /p' "$f" >>"$work/sources/machine.list"
done
for f in /etc/apt/sources.list.d/*.sources; do
	[ -f "$f" ] && sed 's/^Types:.*/Types: deb-src/' "$f" >"$work/sources/$(basename "$f")"
done
set -- -o Dir::State="$work" -o Dir::State::Lists="$work/lists" -o Dir::State::status="$work/status" \
	-o Dir::Cache="$work/cache" -o Dir::Etc::SourceList=/dev/null -o Dir::Etc::SourceParts="$work/sources" \
	-o Debug::NoLocking=1
[ "$(id -u)" = 0 ] && set -- "$@" -o APT::Sandbox::User=root
echo "libccd_src: fetching libccd $version's source into $dir" >&2
apt-get "$@" update -qq >"$work/update.log" 2>&1 || true
if ! (cd "$work/get" && apt-get "$@" source --download-only libccd) >"$work/get.log" 2>&1; then
	sed 's/^/  /' "$work/get.log" >&2
	fail "apt-get could not fetch Debian's source package of libccd $version"
fi
got=$(sha256sum "$work/get/$tarball" | cut -d' ' -f1)
[ "$got" = "$sha256" ] || fail "$tarball has SHA-256 $got, not $sha256"
mkdir "$work/src"
tar -xzf "$work/get/$tarball" -C "$work/src" --strip-components=1 --no-same-owner
[ -f "$work/src/src/ccd.c" ] || fail "$tarball holds no src/ccd.c"
rm -rf "$dir"
mv "$work/src" "$dir"
