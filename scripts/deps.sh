#!/bin/sh
# Installs what handspring needs, when it is missing: Debian packages through apt-get as root,
# otherwise it prints the exact command to run as root (with `sudo` in front only where sudo
# exists) and exits 1. Needs nothing beyond a POSIX shell and coreutils, so it runs on a fresh
# Debian with only a compiler and make.
#
#   sh scripts/deps.sh [GROUP...]
#
# Each target asks only for the groups it uses:
#   build     the libraries and the tool (plain `make`): pkg-config, libyaml, GSL (libccd's source
#             comes through scripts/libccd_src.sh: the Makefile compiles it)
#   test      the unit tests and the README's examples: cmocka; libpng (test_view reads the
#             pictures `handspring view` draws, with gnuplot); clang (the determinism pair: the
#             catalog built with gcc and clang must agree); g++ and clang++ (the public headers
#             and the README's examples as C++); Python 3 (the importers of real hand recordings)
#   plots     gnuplot (make plots, make figures, make bench, handspring view)
#   campaign  GNU parallel and the ssh client (make campaign; docs/campaigns.md)
#   sshd      the ssh server (make check-campaign drives campaigns through a private sshd)
#   python    Debian's Python with numpy and pytest, pip, setuptools, venv (make check-python)
#   browser   Chromium, Node.js and npm (make check-browser)
#   bench     the benchmark peers ODE and MuJoCo (make bench), valgrind (make bench-instr)
#   fuzz      the compiler-rt runtime that holds libFuzzer (make fuzz)
#   valgrind  valgrind (make valgrind, make determinism)
#   check     what `make check` needs before its own targets ask for more: build, test, plots,
#             campaign and sshd (check-python and check-browser ask for python and browser)
# Without a group: check.
set -eu

need=""
has_file() { [ -e "$1" ]; }
has_cmd() { command -v "$1" >/dev/null 2>&1; }

[ $# -gt 0 ] || set -- check

for group in "$@"; do
	case "$group" in
	check) set -- "$@" build test plots campaign sshd ;;
	esac
done

for group in "$@"; do
	case "$group" in
	check) ;;
	build)
		has_cmd pkg-config || need="$need pkg-config"
		has_file /usr/include/gsl/gsl_odeiv2.h || need="$need libgsl-dev"
		has_file /usr/include/yaml.h || need="$need libyaml-dev"
		;;
	test)
		has_file /usr/include/cmocka.h || need="$need libcmocka-dev"
		has_file /usr/include/png.h || need="$need libpng-dev"
		has_cmd gnuplot || need="$need gnuplot-nox"
		has_cmd clang || need="$need clang"
		has_cmd g++ || need="$need g++"
		has_cmd python3 || need="$need python3"
		;;
	plots)
		has_cmd gnuplot || need="$need gnuplot-nox"
		;;
	campaign)
		# GNU's, not moreutils' program of the same name
		{ has_cmd parallel && parallel --version 2>/dev/null | grep -q 'GNU parallel'; } || need="$need parallel"
		{ has_cmd ssh && has_cmd ssh-keygen; } || need="$need openssh-client"
		;;
	sshd)
		has_file /usr/sbin/sshd || need="$need openssh-server"
		;;
	bench)
		has_file /usr/include/ode/ode.h || need="$need libode-dev"
		has_file /usr/include/mujoco/mujoco.h || need="$need libmujoco-dev"
		# make bench-instr and handspring bench --instr count instructions with callgrind
		has_cmd valgrind || need="$need valgrind"
		;;
	fuzz)
		# libFuzzer ships in compiler-rt, packaged per LLVM version: libclang-rt-14-dev on
		# Debian 12 (clang 14). Ask for the one matching the installed clang; 14 before clang is in.
		has_cmd clang || need="$need clang"
		major=14
		if has_cmd clang; then
			major=$(clang -dumpversion 2>/dev/null | cut -d. -f1)
			case "$major" in '' | *[!0-9]*) major=14 ;; esac
		fi
		ls /usr/lib/llvm-"$major"/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1 ||
			need="$need libclang-rt-$major-dev"
		;;
	valgrind)
		has_cmd valgrind || need="$need valgrind"
		;;
	python)
		# Debian's interpreter with numpy and pytest, pip, setuptools and venv: make check-python
		# builds a venv (--system-site-packages) and pip-installs python/ into it offline
		py=/usr/bin/python3
		[ -x "$py" ] || need="$need python3"
		"$py" -c 'import numpy' 2>/dev/null || need="$need python3-numpy"
		"$py" -c 'import pytest' 2>/dev/null || need="$need python3-pytest"
		"$py" -m pip --version >/dev/null 2>&1 || need="$need python3-pip"
		"$py" -c 'import setuptools' 2>/dev/null || need="$need python3-setuptools"
		"$py" -c 'import ensurepip, venv' 2>/dev/null || need="$need python3-venv"
		;;
	browser)
		# make check-browser: the replay page (view --html) in headless Chromium, driven by
		# puppeteer-core from npm under Node.js
		has_cmd chromium || need="$need chromium"
		has_cmd node || need="$need nodejs"
		has_cmd npm || need="$need npm"
		;;
	*)
		echo "deps: unknown group '$group' (build, test, plots, campaign, sshd, python, browser, bench, fuzz, valgrind, check)" >&2
		exit 2
		;;
	esac
done

# a package asked for by two groups once
need=$(printf '%s\n' $need | awk 'NF && !seen[$0]++' | tr '\n' ' ' | sed 's/ $//')
[ -z "$need" ] && exit 0
need=" $need"

if [ "$(id -u)" = 0 ] && has_cmd apt-get; then
	echo "deps: installing$need" >&2
	export DEBIAN_FRONTEND=noninteractive
	apt-get update -qq >&2
	# shellcheck disable=SC2086
	apt-get install -y -qq --no-install-recommends $need >&2
	exit 0
fi

sudo=""
if [ "$(id -u)" != 0 ] && has_cmd sudo; then sudo="sudo "; fi
echo "deps: missing Debian packages:$need" >&2
echo "deps: install them as root with: ${sudo}apt-get install -y$need" >&2
exit 1
