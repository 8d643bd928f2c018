#!/bin/sh
# check.sh — `make check-browser`: the replay page of `handspring view --html` in a real browser.
# Installs Chromium and Node.js when missing (scripts/deps.sh browser), puppeteer-core and three from
# tool/viewer/package-lock.json into BUILD/viewer-node (npm ci, again only when the lock changed),
# checks that tool/viewer/vendor/three is the pinned package's files byte for byte, writes the pages
# of one hand and one spring scenario of the catalog and drives each in headless Chromium
# (view_test.mjs says what is asserted).
#   check.sh TOOL BUILD
set -eu
tool=$1
build=$2
sh scripts/deps.sh browser
node_dir=$build/viewer-node
mkdir -p "$node_dir"
if ! cmp -s tool/viewer/package-lock.json "$node_dir/package-lock.json" || ! cmp -s tool/viewer/package.json "$node_dir/package.json" ||
	[ ! -d "$node_dir/node_modules/puppeteer-core" ]; then
	cp tool/viewer/package.json tool/viewer/package-lock.json "$node_dir/"
	(cd "$node_dir" && npm ci --ignore-scripts --no-audit --no-fund --loglevel=error >&2)
fi
sh tool/viewer/vendor.sh "$node_dir/node_modules" --check
out=$build/browser
mkdir -p "$out"
"$tool" view scenarios/hand/push_press_down.yaml --html "$out/hand.html" 2>/dev/null
"$tool" view scenarios/spring/pull_into_wall.yaml --html "$out/spring.html" --html-at 1 2>/dev/null
node tests/browser/view_test.mjs "$node_dir/node_modules" "$out" "$out/hand.html" "$out/spring.html"
