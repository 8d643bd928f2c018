#!/bin/sh
# vendor.sh — the three.js files `handspring view --html` puts in its page, copied verbatim from the
# npm package that package.json pins (three 0.185.0, the last release with minified builds) into
# vendor/three/, with the package's MIT licence; the build embeds them in the tool (docs/viewer.md).
#   vendor.sh NODE_MODULES           copy them (after `npm ci` of this folder's package-lock.json)
#   vendor.sh NODE_MODULES --check   exit 1 unless the vendored copies are byte-identical to the package's
set -eu
nm=$1
here=$(dirname "$0")
dest=$here/vendor/three
files="build/three.core.min.js build/three.module.min.js examples/jsm/controls/OrbitControls.js LICENSE"
want=$(sed -n 's/.*"three": "\(.*\)".*/\1/p' "$here/package.json")
have=$(sed -n 's/^  "version": "\(.*\)".*/\1/p' "$nm/three/package.json")
[ "$want" = "$have" ] || { echo "vendor: node_modules has three $have, package.json pins $want" >&2; exit 1; }
mkdir -p "$dest"
for f in $files; do
	if [ "${2:-}" = --check ]; then
		cmp -s "$nm/three/$f" "$dest/$(basename "$f")" ||
			{ echo "vendor: $dest/$(basename "$f") differs from three $have's $f" >&2; exit 1; }
	else
		cp "$nm/three/$f" "$dest/"
	fi
done
[ "${2:-}" = --check ] && echo "vendor: tool/viewer/vendor/three is three $have's files, byte for byte"
exit 0
