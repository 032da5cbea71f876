#!/bin/sh
# Makes sure the libraries the lessons build against are installed:
# stb (PNG read/write), cmocka (tests) and pkg-config (to find both).
# Called by the Makefile before the first compile; a no-op when all are present.
#
#   sh tools/ensure-deps.sh [PROGRAM[:PACKAGE]]...
#
# Each PROGRAM named is a tool a make target needs on demand (make
# compile_commands.json asks for bear): it is installed too, with the Debian
# package PACKAGE (the program's own name if none is given), when it is not
# on the PATH.
#
# --gpu adds what the GPU reference (tests/gpu/gpu_reference.c, make test) needs:
# the EGL and OpenGL headers and libraries (pkg-config egl and opengl, and
# GL/glcorearb.h), and Mesa itself, whose EGL and llvmpipe driver it runs on.
set -eu

missing=""
gpu=false
for need in "$@"; do
    if [ "$need" = --gpu ]; then
        gpu=true
        continue
    fi
    program=${need%%:*}
    package=${need#*:}
    command -v "$program" >/dev/null 2>&1 || missing="$missing $package"
done
command -v pkg-config >/dev/null 2>&1 || missing="$missing pkg-config"
if command -v pkg-config >/dev/null 2>&1; then
    pkg-config --exists stb    || missing="$missing libstb-dev"
    pkg-config --exists zlib   || missing="$missing zlib1g-dev"
    pkg-config --exists cmocka || missing="$missing libcmocka-dev"
else
    missing="$missing libstb-dev zlib1g-dev libcmocka-dev"
fi
# Mesa's EGL (its glvnd vendor file) and its software driver (swrast_dri.so
# holds llvmpipe) are found by file: they have no pkg-config file.
if $gpu; then
    if command -v pkg-config >/dev/null 2>&1; then
        pkg-config --exists egl    || missing="$missing libegl-dev"
        pkg-config --exists opengl || missing="$missing libopengl-dev"
    else
        missing="$missing libegl-dev libopengl-dev"
    fi
    [ -f /usr/include/GL/glcorearb.h ] || missing="$missing libgl-dev"
    ls /usr/share/glvnd/egl_vendor.d/*mesa*.json >/dev/null 2>&1 || missing="$missing libegl-mesa0"
    swrast=false
    for f in /usr/lib/*/dri/swrast_dri.so /usr/lib/dri/swrast_dri.so; do
        [ -f "$f" ] && swrast=true
    done
    $swrast || missing="$missing libgl1-mesa-dri"
fi
[ -z "$missing" ] && exit 0

if ! command -v apt-get >/dev/null 2>&1; then
    echo "ensure-deps: missing:$missing" >&2
    echo "ensure-deps: this system has no apt-get; install these yourself" >&2
    echo "ensure-deps: (libstb-dev: stb_image.h and the pkg-config file 'stb'; zlib1g-dev: zlib.h)" >&2
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
