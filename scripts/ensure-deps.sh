#!/bin/sh
# Makes sure the libraries the lessons build against are installed:
# stb (PNG read/write), cmocka (tests) and pkg-config (to find both).
# Called by the Makefile before the first compile; a no-op when all are present.
set -eu

missing=""
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
    echo "ensure-deps: this system has no apt-get; install these yourself:" >&2
    echo "ensure-deps:   pkg-config, stb (stb_image.h, stb_image_write.h + pkg-config file 'stb'), cmocka" >&2
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
