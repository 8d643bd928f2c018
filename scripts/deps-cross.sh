#!/bin/sh
# deps-cross.sh — what the determinism matrix's foreign builds need (scripts/determinism.sh --full),
# installed when it is missing; safe to run again (it only does what is not done yet).
#
#   deps-cross.sh [--check]      BUILD (default: build) names the build folder
#
# 1. Debian packages (as root, through apt-get; otherwise it prints the exact command to run):
#    gcc-i686-linux-gnu + libc6-dev-i386-cross    the i386 build (-m32 -msse2 -mfpmath=sse)
#    gcc-aarch64-linux-gnu + libc6-dev-arm64-cross  the aarch64 build
#    libc6-i386                                  runs the i386 tool (/lib/ld-linux.so.2, /lib32)
#    qemu-user                                   runs the aarch64 tool (qemu-aarch64), and the i386
#                                                one where the kernel cannot (qemu-i386)
#    Debian's cross compilers, not gcc-multilib: gcc-12-multilib and gcc-12-aarch64-linux-gnu
#    conflict in bookworm, and the cross compilers carry their own C library.
# 2. The libraries the tool links (libyaml, GSL; libccd it compiles itself) for i386 and arm64, in a private sysroot
#    per architecture, $BUILD/det/sysroot-{i386,arm64} (no root needed): the Debian packages are
#    fetched by apt-get with a private package list for that architecture and unpacked with
#    dpkg-deb. Not `dpkg --add-architecture` + `apt-get install libgsl-dev:arm64`: libgsl-dev is
#    not Multi-Arch: same, so its i386, arm64 and amd64 versions conflict (the native build needs
#    the amd64 one), and a foreign architecture in the system's apt makes every `apt-get update`
#    on the machine fail whenever one mirror index of it is out of sync.
#    Each sysroot gets bin/pkg-config, a wrapper that answers for the sysroot (put it first in
#    PATH: the Makefile calls `pkg-config` by name).
# --check: install nothing; exit 1 (saying what is missing) unless everything is there.
# Exit status: 0 when everything is in place, 1 otherwise (the matrix then skips those builds).
set -eu

BUILD=${BUILD:-build}
check_only=no
[ "${1:-}" = --check ] && check_only=yes

has_cmd() { command -v "$1" >/dev/null 2>&1; }

# ---------------------------------------------------------------------------------------------
# 1. system packages
need=""
has_cmd i686-linux-gnu-gcc || need="$need gcc-i686-linux-gnu"
[ -e /usr/i686-linux-gnu/lib/libc.so ] || need="$need libc6-dev-i386-cross"
[ -e /lib/ld-linux.so.2 ] || need="$need libc6-i386" # runs the i386 tool (its C library, in /lib32)
has_cmd aarch64-linux-gnu-gcc || need="$need gcc-aarch64-linux-gnu"
[ -e /usr/aarch64-linux-gnu/lib/libc.so ] || need="$need libc6-dev-arm64-cross"
has_cmd qemu-aarch64 || need="$need qemu-user"
has_cmd dpkg-deb || need="$need dpkg"

if [ -n "$need" ]; then
	if [ "$check_only" = yes ]; then
		echo "deps-cross: missing Debian packages:$need" >&2
		exit 1
	fi
	if [ "$(id -u)" = 0 ] && has_cmd apt-get; then
		echo "deps-cross: installing$need" >&2
		export DEBIAN_FRONTEND=noninteractive
		apt-get -o DPkg::Lock::Timeout=600 update -qq >&2 || echo "deps-cross: apt-get update reported errors; trying the install anyway" >&2
		# shellcheck disable=SC2086
		apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends $need >&2
	else
		sudo=""
		has_cmd sudo && sudo="sudo "
		echo "deps-cross: missing Debian packages:$need" >&2
		echo "deps-cross: install them with: ${sudo}apt-get install -y --no-install-recommends$need" >&2
		exit 1
	fi
fi

# ---------------------------------------------------------------------------------------------
# 2. the foreign libraries, one private sysroot per architecture

# runtime and development packages: the tool is linked against the shared libraries and finds them
# at run time through an rpath into the sysroot
PACKAGES="libyaml-dev libyaml-0-2 libgsl-dev libgsl27 libgslcblas0"

sysroot() { # ARCH TRIPLET
	arch=$1 triplet=$2
	det=$(mkdir -p "$BUILD/det" && cd "$BUILD/det" && pwd)
	root="$det/sysroot-$arch"
	stamp="$root/.packages"
	if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$PACKAGES" ] && [ -x "$root/bin/pkg-config" ]; then
		return 0
	fi
	if [ "$check_only" = yes ]; then
		echo "deps-cross: the $arch sysroot $root is not made yet" >&2
		return 1
	fi
	echo "deps-cross: fetching the $arch packages ($PACKAGES) into $root" >&2
	apt="$det/apt-$arch"
	rm -rf "$apt" "$root"
	mkdir -p "$apt/lists/partial" "$apt/cache/archives/partial" "$apt/sources" "$apt/debs" "$root/bin"
	: >"$apt/status"
	# the machine's own Debian sources (the mirror it is allowed to use), read for this architecture
	for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources; do
		[ -f "$f" ] && cp "$f" "$apt/sources/"
	done
	[ -f "$apt/sources/sources.list" ] && mv "$apt/sources/sources.list" "$apt/sources/main.list"
	set -- -o Dir::State="$apt" -o Dir::State::Lists="$apt/lists" -o Dir::State::status="$apt/status" \
		-o Dir::Cache="$apt/cache" -o Dir::Etc::SourceList=/dev/null -o Dir::Etc::SourceParts="$apt/sources" \
		-o APT::Architecture="$arch" -o APT::Architectures::="$arch" -o Debug::NoLocking=1
	[ "$(id -u)" = 0 ] && set -- "$@" -o APT::Sandbox::User=root
	# an index of another suite that is out of sync must not stop us: the download below says
	# whether what we need is there
	apt-get "$@" update -qq >"$apt/update.log" 2>&1 || echo "deps-cross: apt-get update ($arch) reported errors (see $apt/update.log)" >&2
	# shellcheck disable=SC2086
	if ! (cd "$apt/debs" && apt-get "$@" download $PACKAGES) >"$apt/download.log" 2>&1; then
		cat "$apt/download.log" >&2
		echo "deps-cross: could not download the $arch packages" >&2
		return 1
	fi
	for deb in "$apt/debs"/*.deb; do dpkg-deb -x "$deb" "$root"; done
	cat >"$root/bin/pkg-config" <<EOF
#!/bin/sh
# pkg-config for the $arch sysroot (made by scripts/deps-cross.sh)
PKG_CONFIG_LIBDIR='$root/usr/lib/$triplet/pkgconfig:$root/usr/share/pkgconfig'
PKG_CONFIG_SYSROOT_DIR='$root'
PKG_CONFIG_PATH=
export PKG_CONFIG_LIBDIR PKG_CONFIG_SYSROOT_DIR PKG_CONFIG_PATH
exec /usr/bin/pkg-config "\$@"
EOF
	chmod +x "$root/bin/pkg-config"
	ls "$root/usr/lib/$triplet/libgsl.so" "$root/usr/lib/$triplet/libyaml.so" >/dev/null
	echo "$PACKAGES" >"$stamp"
}

status=0
sysroot i386 i386-linux-gnu || status=1
sysroot arm64 aarch64-linux-gnu || status=1
exit $status
