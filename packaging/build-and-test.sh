#!/usr/bin/env bash
# README command 2 (and CI): install dependencies, build with warnings as errors, run every
# test (OpenGL and GUI tests on a virtual X display, Mesa llvmpipe), then rebuild everything
# with Address and UndefinedBehavior sanitizers and run every test again (every layer, the
# OpenGL and GUI tests on the same virtual display), and run each fuzzer briefly
# (tests/fuzz/run-fuzzers.sh; ENSIL_SKIP_FUZZ=1 skips it); last, package the ci build (.deb
# and .tar.gz), check the tarball, install the .deb into this system, run the installed ensil
# and remove it.
set -euo pipefail
cd "$(dirname "$0")/.."

# Each stage's wall-clock time, and the whole run's, printed as it ends (CI must stay within
# 45 minutes from a fresh clone; these say where the time goes).
run_start=$SECONDS
stage() {
    local name=$1 start=$SECONDS
    shift
    echo "==> stage: $name" >&2
    "$@"
    echo "==> stage: $name took $((SECONDS - start)) s (run so far: $((SECONDS - run_start)) s)" >&2
}

stage "install dependencies" packaging/install-deps.sh

stage "check formatting" packaging/check-format.sh
# Every #include between rooms points down the layer graph (ARCHITECTURE.md); the links are
# checked when CMake configures (cmake/forbid_link.cmake).
stage "check layers" packaging/check-layers.py
# Calls that exist on one operating system only stay in data/platform.* (one branch per system).
stage "check platform calls" packaging/check-platform-calls.py
stage "configure (ci)" cmake --preset ci
stage "build (ci)" cmake --build --preset ci
# clang-tidy (.clang-tidy's checks, every layer) on each C++ file changed since its last clean
# check (packaging/tidy-checked.txt holds their hashes; the whole tree would take ~20 minutes).
stage "check tidy" packaging/check-tidy.py build/ci
# On a virtual display (Mesa llvmpipe); each OpenGL, widget and workbench test process gets a
# display of its own besides (tests/support/with-private-display.sh says why). No test is ever
# run twice to make it pass: a test that fails now and then is a bug, in the code or the test.
stage "test (ci)" tests/support/with-private-display.sh ctest --preset ci

# Every test again, built with Address and UndefinedBehavior sanitizers (a Debug build): the
# GPU-free layers and the OpenGL, widget and workbench tests alike, on a virtual display as
# above. Leaks inside Mesa and libdbus are not ensil's (tests/support/lsan.supp says why).
stage "configure (asan)" cmake --preset asan
stage "build (asan)" cmake --build --preset asan
# LeakSanitizer's exit-time scan once crashed now and then ("Tracer caught signal 11") in GUI
# tests: GCC 12's sanitizer runtime takes a dynamic TLS block (Mesa's, loaded with dlopen) whose
# address ends in 0x010 for a pre-2.25 glibc header, reads two heap words before it as a range
# and scans it. The asan test preset turns that interception off (intercept_tls_get_addr=0).
# The monkey test (tests/app/monkey_test.cpp) takes ENSIL_MONKEY_ACTIONS random actions; longer
# runs are by hand (CONTRIBUTING.md, "The monkey test").
ENSIL_MONKEY_ACTIONS=2000 stage "test (asan)" tests/support/with-private-display.sh \
    ctest --preset asan

# Each libFuzzer target (the readers, the mesh cache, projects, command-line values) on its
# seed corpus and then 1500 inputs from a fixed seed (a fixed budget, not the clock's; the
# inputs still vary a little from run to run, run-fuzzers.sh says why; the longer runs are by
# hand, CONTRIBUTING.md "Fuzzing"); a crash, leak or hang fails the run. ENSIL_SKIP_FUZZ=1 skips it.
if [ "${ENSIL_SKIP_FUZZ:-0}" != 1 ]; then
    ENSIL_FUZZ_RUNS=1500 stage "fuzz" tests/fuzz/run-fuzzers.sh 120
fi

# Packaging the ci build (stripped) rather than building a release saves CI a full rebuild.
deb=$(stage "package" packaging/build-package.sh build/ci)
stage "check the tarball" packaging/test-tarball.sh "$(dirname "$deb")"/ensil-*-Linux.tar.gz "$deb"
stage "check the package" packaging/test-package.sh "$deb"
stage "check the RPM" packaging/test-rpm.sh "$(dirname "$deb")"/ensil-*.rpm
echo "==> all stages took $((SECONDS - run_start)) s" >&2
