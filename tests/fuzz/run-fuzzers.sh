#!/usr/bin/env bash
# Builds the libFuzzer targets (the `fuzz` preset, clang 14) and runs each for SECONDS seconds
# on a copy of its seed corpus in a temporary folder, so the repository is never written.
# Prints each fuzzer's executions, executions a second, coverage and outcome, and exits non-zero
# when any fuzzer found a crash, a leak, a timeout (-timeout=10 s an input) or an input needing
# more than 2 GiB (-rss_limit_mb=2048); the reproducer is saved under build/fuzz/findings/ and
# the fuzzer's log beside it. Replay one with
#   LSAN_OPTIONS=suppressions=tests/fuzz/lsan.supp build/fuzz/tests/fuzz/ensil_fuzz_NAME FILE
# (ENSIL_FUZZ_VERBOSE=1 prints why each input was refused).
#
# Usage: tests/fuzz/run-fuzzers.sh SECONDS [NAME...]   (default: every fuzzer)
set -euo pipefail
cd "$(dirname "$0")/../.."

if [ $# -lt 1 ] || ! [[ $1 =~ ^[0-9]+$ ]] || [ "$1" -lt 1 ]; then
    echo "usage: $0 SECONDS [NAME...]" >&2
    exit 2
fi
seconds=$1
shift
fuzzers=("$@")
if [ ${#fuzzers[@]} -eq 0 ]; then
    fuzzers=(vtk_legacy_header ensemble_reader mesh_cache project_file setting_options)
fi

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz

# Leaks inside HDF5 itself are not ensil's (lsan.supp says why).
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"

findings=$PWD/build/fuzz/findings
mkdir -p "$findings"
work=$(mktemp -d "${TMPDIR:-/tmp}/ensil-fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT

# stat NAME LOG: the figure libFuzzer's -print_final_stats gives as stat::NAME.
stat() { sed -n "s/^stat::$1: *//p" "$2" | tail -n 1; }

summary=()
failed=0
for name in "${fuzzers[@]}"; do
    binary=build/fuzz/tests/fuzz/ensil_fuzz_$name
    if [ ! -x "$binary" ]; then
        echo "run-fuzzers: no fuzzer '$name' ($binary)" >&2
        exit 2
    fi
    mkdir -p "$work/$name/corpus" "$work/$name/tmp" "$findings/$name"
    cp -r "tests/fuzz/corpus/$name/." "$work/$name/corpus/"
    log=$work/$name/log
    echo "run-fuzzers: $name for $seconds s"
    status=0
    # TMPDIR: the targets' temporary files land in the work folder, removed afterwards.
    # ENSIL_FUZZ_RUNS=N: a fixed budget of N inputs from a fixed seed, so a CI run does not
    # fail or pass by luck of the clock (SECONDS still caps it); unset, the time decides and
    # each run explores anew. The inputs are not quite the same from run to run: the readers'
    # threads and the random names of the temporary files change the coverage libFuzzer sees
    # (two runs here differed already after the seeds), and so its mutations. CI once found in
    # its 1500 what a run here did not; longer runs by hand (CONTRIBUTING.md "Fuzzing") look further.
    budget=()
    if [ -n "${ENSIL_FUZZ_RUNS:-}" ]; then budget=(-seed=1 -runs="$ENSIL_FUZZ_RUNS"); fi
    TMPDIR=$work/$name/tmp "$binary" "${budget[@]}" -max_total_time="$seconds" \
        -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 -artifact_prefix="$findings/$name/" "$work/$name/corpus" \
        >"$log" 2>&1 || status=$?
    runs=$(stat number_of_executed_units "$log")
    speed=$(stat average_exec_per_sec "$log")
    coverage=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2)
    outcome="no finding"
    if [ "$status" -ne 0 ]; then
        failed=1
        kind=$(grep -o -m 1 -E 'ERROR: (libFuzzer|AddressSanitizer|LeakSanitizer): [a-z-]+|runtime error|ensil fuzz: [^:]*' "$log" || true)
        artifact=$(sed -n 's/.*Test unit written to //p' "$log" | tail -n 1)
        outcome="FINDING (exit $status: ${kind:-see log}) ${artifact:-no reproducer written}"
        cp "$log" "$findings/$name/$(date +%Y%m%d-%H%M%S).log"
        echo "---- last lines of $name's log:"
        tail -n 40 "$log"
        echo "----"
    fi
    rmdir "$findings/$name" 2>/dev/null || true  # left only when it holds a finding
    summary+=("$(printf '%-18s %12s %10s %8s  %s' "$name" "${runs:-?}" "${speed:-?}" \
        "${coverage:-?}" "$outcome")")
done

printf '\n%-18s %12s %10s %8s  %s\n' fuzzer executions exec/s cov result
printf '%s\n' "${summary[@]}"
if [ "$failed" -ne 0 ]; then
    echo "run-fuzzers: findings saved under $findings" >&2
    exit 1
fi
