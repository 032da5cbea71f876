#!/bin/sh
# Makes sure the libraries the lessons build against are installed:
# stb (PNG read/write), cmocka (tests) and pkg-config (to find both).
# Called by the Makefile before the first compile; a no-op when all are present.
#
#   sh scripts/ensure-deps.sh [PROGRAM[:PACKAGE]]...
#
# Each PROGRAM named is a tool a make target needs on demand (make
# compile_commands.json asks for bear): it is installed too, with the Debian
# package PACKAGE (the program's own name if none is given), when it is not
# on the PATH.
set -eu

missing=""
for need in "$@"; do
    program=${need%%:*}
    package=${need#*:}
    command -v "$program" >/dev/null 2>&1 || missing="$missing $package"
done
command -v pkg-config >/dev/null 2>&1 || missing="$missing pkg-config"
if command -v pkg-config >/dev/null 2>&1; then
    pkg-config --exists stb    || missing="$missing libstb-dev"
    pkg-config --exists cmocka || missing="$missing libcmocka-dev"
else
    missing="$missing libstb-dev libcmocka-dev"
fi
[ -z "$missing" ] && exit 0

if ! command -v apt-get >/dev/null 2>&1; then
    echo "ensure-deps: missing:$missing" >&2
    echo "ensure-deps: this system has no apt-get; install these yourself" >&2
    echo "ensure-deps: (libstb-dev: stb_image.h, stb_image_write.h and the pkg-config file 'stb')" >&2
    exit 1
fi

if [ "$(id -u)" -eq 0 ]; then
    sudo=""
elif command -v sudo >/dev/null 2>&1; then
    sudo="sudo"
else
    echo "ensure-deps: missing:$missing, and not root with no sudo to install them." >&2
    echo "ensure-deps: run as root: apt-get install$missing" >&2
    exit 1
fi

echo "ensure-deps: installing:$missing"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
# shellcheck disable=SC2086
$sudo apt-get install -y -qq $missing
echo "ensure-deps: installed:$missing"
