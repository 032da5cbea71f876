#!/bin/sh
# setup.sh: what Gradescope runs once, to build the autograder's image.
set -e
apt-get update
apt-get install -y build-essential libstb-dev zlib1g-dev libcmocka-dev pkg-config
