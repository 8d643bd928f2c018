#!/bin/sh
# tutorial.sh TOOL [FILE.md...] — `make check-tutorial`: every scenario written out in the docs runs
# as written and passes its own expect clauses.
#
# In each page (default: docs/first-scenarios.md and scenarios/README.md) a ```yaml block right
# after `<!-- scenario: NAME -->` is a whole scenario: it is written to NAME.yaml in a fresh
# folder and run with `TOOL run`, which must exit 0 (every expectation passes). A ```text block
# after `<!-- output: NAME -->` is what that run prints: it must match line for line, except the
# value of `final hash:` (the line must be there; the hash is the goldens' business).
# Runs from the top folder.
set -eu

tool=${1:?usage: tutorial.sh TOOL [FILE.md...]}
shift
[ $# -gt 0 ] || set -- docs/first-scenarios.md scenarios/README.md
work=$(mktemp -d "${TMPDIR:-/tmp}/hs-tutorial.XXXXXX")
trap 'rm -rf "$work"' EXIT
fails=0
runs=0

fail() {
	echo "check-tutorial: $*" >&2
	fails=$((fails + 1))
}

extract() { # extract FILE KIND NAME: the ``` block right after the line `<!-- KIND: NAME -->`
	awk -v marker="<!-- $2: $3 -->" '
		$0 == marker { found = 1; next }
		found == 1 && /^```/ { found = 2; next }
		found == 1 && NF { exit }
		found == 2 && /^```/ { exit }
		found == 2 { print }' "$1"
}

for page in "$@"; do
	names=$(sed -n 's/^<!-- scenario: \([A-Za-z0-9_-]*\) -->$/\1/p' "$page")
	[ -n "$names" ] || fail "$page has no scenario (<!-- scenario: NAME --> then a \`\`\`yaml block)"
	for name in $names; do
		yaml="$work/$name.yaml"
		extract "$page" scenario "$name" >"$yaml"
		if [ ! -s "$yaml" ]; then
			fail "$page: the scenario '$name' has no \`\`\`yaml block right after its marker"
			continue
		fi
		runs=$((runs + 1))
		status=0
		"$tool" run "$yaml" >"$work/$name.out" 2>"$work/$name.err" || status=$?
		if [ "$status" -ne 0 ]; then
			cat "$work/$name.out" "$work/$name.err" >&2
			fail "$page: the scenario '$name' exits with status $status (0: every expectation passes)"
			continue
		fi
		extract "$page" output "$name" >"$work/$name.expected"
		if [ -s "$work/$name.expected" ]; then
			grep -q '^final hash: [0-9a-f]\{16\}$' "$work/$name.out" || fail "$page: '$name' prints no final hash"
			sed 's/^final hash: .*/final hash: (any)/' "$work/$name.expected" >"$work/$name.want"
			sed 's/^final hash: .*/final hash: (any)/' "$work/$name.out" >"$work/$name.got"
			if ! cmp -s "$work/$name.want" "$work/$name.got"; then
				diff "$work/$name.want" "$work/$name.got" >&2 || :
				fail "$page: the scenario '$name' prints something else than the page shows"
				continue
			fi
		fi
		echo "check-tutorial: $page: $name: $(grep '^expectations:' "$work/$name.out")"
	done
done

if [ "$fails" -ne 0 ]; then
	echo "check-tutorial: $fails failure(s)" >&2
	exit 1
fi
echo "check-tutorial: $runs scenarios of the docs run as written and pass"
