#!/usr/bin/env bash
# Runs every file of the bad-input corpus (this folder) and the readers' fuzzing seeds
# (tests/fuzz/corpus/ensemble_reader: real files, damaged files and earlier findings) through
# `ensil info` and `ensil preprocess` as a user would, and counts the outcomes: read (exit 0),
# refused with a message naming the file or the field (exit 1 or 2), refused naming neither,
# crashed (killed by a signal), or hung (past 60 s). The figures for a closing note; the table-driven
# test (tests/app/bad_input_test.cpp) checks each message.
#
# Usage: tests/data/bad/summarise-corpus.sh [ENSIL]   (default: build/ci/app/ensil)
set -uo pipefail
cd "$(dirname "$0")/../../.."
ensil=${1:-build/ci/app/ensil}
[ -x "$ensil" ] || { echo "no ensil at $ensil: build it first" >&2; exit 2; }

declare -A count=()
cases=0
for file in tests/data/bad/*.nc tests/data/bad/*.vtk tests/fuzz/corpus/ensemble_reader/*; do
    [ -f "$file" ] || continue
    for command in info preprocess; do
        args=("$command" "$file")
        [ "$command" = preprocess ] && args+=(--iso 1 --no-cache)
        err=$(timeout 60 "$ensil" "${args[@]}" 2>&1 >/dev/null)
        rc=$?
        cases=$((cases + 1))
        if [ $rc -eq 0 ]; then
            outcome=read
        elif [ $rc -eq 124 ]; then
            outcome=hung
        elif [ $rc -ge 128 ]; then
            outcome=crashed
        elif grep -qF "$(basename "$file")" <<<"$err" || grep -q "'[^']*'" <<<"$err"; then
            outcome="refused, naming file or field"
        else
            outcome="refused, naming neither"
        fi
        count[$outcome]=$(( ${count[$outcome]:-0} + 1 ))
        if [ "$outcome" = crashed ] || [ "$outcome" = hung ] ||
           [ "$outcome" = "refused, naming neither" ]; then
            echo "$outcome: ensil ${args[*]}: ${err:0:200}"
        fi
    done
done
echo "$cases runs:"
for outcome in read "refused, naming file or field" "refused, naming neither" crashed hung; do
    printf '  %-30s %d\n' "$outcome" "${count[$outcome]:-0}"
done
[ "${count[crashed]:-0}" -eq 0 ] && [ "${count[hung]:-0}" -eq 0 ]
