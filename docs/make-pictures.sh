#!/bin/sh
# docs/make-pictures.sh ENSIL FOLDER: draws the documentation's pictures with ENSIL's own
# `ensil render`, into FOLDER. By hand, after a change to what a picture shows:
#   docs/make-pictures.sh build/ci/app/ensil docs/images
# CTest's app.docs_pictures runs it into the build folder, so a command here that stops working
# fails the tests. Needs a display, or EGL (ensil render draws without one).
set -eu
if [ $# -ne 2 ]; then
    echo "usage: docs/make-pictures.sh path/to/ensil FOLDER" >&2
    exit 2
fi
ensil=$1
out=$2
mkdir -p "$out"
# README's picture: the demo ensemble at the workbench's defaults.
"$ensil" render --demo --out "$out/demo.png" --size 1200x750 --quiet
