#!/bin/sh
# Installs what handspring needs, when it is missing: Debian packages through apt-get as root,
# otherwise it prints the exact command to run as root (with `sudo` in front only where sudo
# exists) and exits 1. Needs nothing beyond a POSIX shell and coreutils, so it runs on a fresh
# Debian with only a compiler and make. clang is a base package: `make check` builds the tool with
# gcc and clang and compares them (the determinism pair); g++ (and clang's clang++) compile the
# README's examples and the public headers as C++, and pkg-config links them against an installed
# copy (make check-readme). GNU parallel and OpenSSH (server and client) run campaigns over cores
# and machines, and make check-campaign drives them through a private sshd on 127.0.0.1 (issue 14,
# docs/campaigns.md). `deps.sh bench` adds the benchmark peers
# (ODE, MuJoCo); `deps.sh fuzz` adds the compiler-rt runtime that holds libFuzzer; `deps.sh
# valgrind` adds valgrind (make valgrind, make determinism); `deps.sh python` adds what the
# Python bindings' test needs (make check-python, python/README.md); `deps.sh browser` adds
# Chromium, Node.js and npm (make check-browser).
set -eu

need=""
has_file() { [ -e "$1" ]; }
has_cmd() { command -v "$1" >/dev/null 2>&1; }

has_cmd pkg-config || need="$need pkg-config"
has_file /usr/include/cmocka.h || need="$need libcmocka-dev"
has_file /usr/include/ccd/ccd.h || need="$need libccd-dev"
has_file /usr/include/gsl/gsl_odeiv2.h || need="$need libgsl-dev"
has_file /usr/include/yaml.h || need="$need libyaml-dev"
has_file /usr/include/png.h || need="$need libpng-dev"
has_cmd gnuplot || need="$need gnuplot-nox"
has_cmd clang || need="$need clang"
# the importers of real hand recordings (scripts/importers, checked by make check) are Python 3
has_cmd python3 || need="$need python3"
has_cmd g++ || need="$need g++"
# GNU's, not moreutils' program of the same name
{ has_cmd parallel && parallel --version 2>/dev/null | grep -q 'GNU parallel'; } || need="$need parallel"
has_file /usr/sbin/sshd || need="$need openssh-server"
{ has_cmd ssh && has_cmd ssh-keygen; } || need="$need openssh-client"

for extra in "$@"; do
	case "$extra" in
	bench)
		has_file /usr/include/ode/ode.h || need="$need libode-dev"
		has_file /usr/include/mujoco/mujoco.h || need="$need libmujoco-dev"
		;;
	fuzz)
		# libFuzzer ships in compiler-rt, packaged per LLVM version: libclang-rt-14-dev on
		# Debian 12 (clang 14). Ask for the one matching the installed clang; 14 before clang is in.
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
	esac
done

[ -z "$need" ] && exit 0

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
