#!/usr/bin/env bash
# Builds ensil's Linux packages (.deb, .rpm and .tar.gz) with CPack.
#   packaging/build-package.sh              configure and build the release preset, then package
#   packaging/build-package.sh BUILD_DIR    package an existing build (e.g. build/ci), after
#                                           bringing its `ensil` target up to date
# The packages land in BUILD_DIR/packages/. Standard output is the .deb's path and nothing else
# (the build's and CPack's messages go to standard error), so scripts can take it with $(...).
set -euo pipefail
cd "$(dirname "$0")/.."
exec 3>&1 1>&2

if [ $# -gt 1 ]; then
    echo "usage: packaging/build-package.sh [BUILD_DIR]" >&2
    exit 2
fi
if [ $# -eq 1 ]; then
    build_dir=$1
    if [ ! -f "$build_dir/CPackConfig.cmake" ]; then
        echo "build-package: $build_dir has no CPackConfig.cmake; configure it first" \
             "(cmake --preset ci) or run without arguments to build the release preset" >&2
        exit 2
    fi
    targets=(ensil)
    # The Python module, where the build has it (python/CMakeLists.txt): the package holds it.
    if cmake --build "$build_dir" --target help | grep -qw ensil_python; then
        targets+=(ensil_python)
    fi
    cmake --build "$build_dir" --target "${targets[@]}"
else
    build_dir=build/release
    cmake --preset release
    cmake --build --preset release
fi

out_dir=$build_dir/packages
rm -f "$out_dir"/ensil_*.deb "$out_dir"/ensil-*.tar.gz "$out_dir"/ensil-*.rpm
cpack --config "$build_dir/CPackConfig.cmake" -B "$out_dir"

deb=$(ls "$out_dir"/ensil_*.deb)
ls -l "$out_dir"/ensil_*.deb "$out_dir"/ensil-*.tar.gz "$out_dir"/ensil-*.rpm
echo "$deb" >&3
