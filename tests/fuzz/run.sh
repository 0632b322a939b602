#!/usr/bin/env bash
# Builds the five libFuzzer harnesses (tests/fuzz/fuzz_{core,shading,textured,shapes,samplers}.cpp)
# with clang++ under AddressSanitizer and UndefinedBehaviorSanitizer, and runs each, one after
# another, for the given seconds on a scratch copy of its seed corpus (tests/fuzz/corpus/<area>/,
# where it has one); prints per harness the inputs it ran (libFuzzer's final "Done N runs" line)
# and fails on any crash, leak, timeout or out-of-memory. Nothing is written into the repository:
# builds, corpora, logs and crashing inputs go to a scratch folder (kept, and printed, on failure).
#
#   tests/fuzz/run.sh [seconds] [extra libFuzzer arguments...]
#
# seconds: one number for every harness, or area=N pairs (core=30,shading=60; the areas not named
# keep their default share). The default shares, 120 s in all, are sized to the harnesses'
# rates, so that each passes 100 thousand inputs on one core: core 18, shading 34, textured 36,
# shapes 14, samplers 18.
#
# Environment: CXX (clang++), LTC_FUZZ_HARNESSES (the areas to run, "core shading textured shapes
# samplers"), LTC_FUZZ_WORK (the scratch folder, kept; default a new one under /dev/shm, else
# $TMPDIR or /tmp, removed after a clean run), LTC_FUZZ_BUILD_JOBS (harnesses compiled at once, 1).
# See tests/fuzz/README.md.
set -euo pipefail

declare -A share=([core]=18 [shading]=34 [textured]=36 [shapes]=14 [samplers]=18)
spec=
if [[ $# -gt 0 && "$1" != -* ]]; then spec=$1; shift; fi
if [[ "$spec" =~ ^[0-9]+$ ]]; then
  for h in "${!share[@]}"; do share[$h]=$spec; done
elif [[ -n "$spec" ]]; then
  IFS=, read -ra pairs <<<"$spec"
  for p in "${pairs[@]}"; do
    if [[ ! "$p" =~ ^([a-z]+)=([0-9]+)$ || -z "${share[${BASH_REMATCH[1]}]:-}" ]]; then
      echo "fuzz: seconds '$spec': give a number or area=N pairs (areas: ${!share[*]})" >&2
      exit 2
    fi
    share[${BASH_REMATCH[1]}]=${BASH_REMATCH[2]}
  done
fi
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cxx=${CXX:-clang++}
harnesses=(${LTC_FUZZ_HARNESSES:-core shading textured shapes samplers})
jobs=${LTC_FUZZ_BUILD_JOBS:-1}
if [[ -n "${LTC_FUZZ_WORK:-}" ]]; then
  work=$LTC_FUZZ_WORK keep=1
  mkdir -p "$work"
else
  # In memory where there is a tmpfs: libFuzzer writes a file per new corpus unit, hundreds a
  # second at first, and on a disk file system that creation cost the harnesses a third of
  # their inputs.
  scratch=${TMPDIR:-/tmp}
  if [[ -d /dev/shm && -w /dev/shm ]]; then scratch=/dev/shm; fi
  work=$(mktemp -d "$scratch/ltc-fuzz.XXXXXX") keep=0
fi
work=$(cd "$work" && pwd)
flags=(-std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -I "$root/include")

echo "fuzz: building ${harnesses[*]} in $work"
pids=() names=()
build_failed=0
wait_builds() {
  for i in "${!pids[@]}"; do
    if ! wait "${pids[$i]}"; then
      echo "fuzz: build of ${names[$i]} failed:" >&2
      cat "$work/build_${names[$i]}.log" >&2
      build_failed=1
    fi
  done
  pids=() names=()
}
for h in "${harnesses[@]}"; do
  src="$root/tests/fuzz/fuzz_$h.cpp"
  [[ -f "$src" ]] || { echo "fuzz: no harness $src" >&2; exit 2; }
  "$cxx" "${flags[@]}" "$src" -o "$work/fuzz_$h" >"$work/build_$h.log" 2>&1 &
  pids+=($!) names+=("$h")
  if (( ${#pids[@]} >= jobs )); then wait_builds; fi
done
wait_builds
if (( build_failed )); then exit 2; fi

failed=()
total=0
summary=()
for h in "${harnesses[@]}"; do
  corpus="$work/corpus_$h" artifacts="$work/artifacts_$h"
  mkdir -p "$corpus" "$artifacts"
  if [[ -d "$root/tests/fuzz/corpus/$h" ]]; then
    find "$root/tests/fuzz/corpus/$h" -maxdepth 1 -type f -exec cp {} "$corpus/" \;
  fi
  log="$work/log_$h.txt"
  rc=0
  # From the scratch folder: with -jobs, libFuzzer writes its fuzz-<job>.log files to the
  # current directory.
  TIMEFORMAT='%U %S'
  seconds=${share[$h]:-24}
  { time (cd "$work" && "$work/fuzz_$h" -max_total_time="$seconds" -max_len=512 -print_final_stats=1 \
            -artifact_prefix="$artifacts/" "$@" "$corpus" >"$log" 2>&1); } 2>"$work/cpu_$h.txt" || rc=$?
  cpu=$(awk '{ printf "%.0f", $1 + $2 }' "$work/cpu_$h.txt" 2>/dev/null || echo 0)
  # The inputs run: the "Done N runs" line of the run, or of each job with -jobs.
  logs=("$log")
  for j in "$work"/fuzz-*.log; do if [[ -f "$j" ]]; then logs+=("$j"); fi; done
  runs=$(sed -n 's/^Done \([0-9]*\) runs in.*/\1/p' "${logs[@]}" | awk '{ s += $1 } END { print s + 0 }')
  took=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "${logs[@]}" | awk '{ s += $1 } END { print s + 0 }')
  if (( ${#logs[@]} > 1 )); then cat "${logs[@]:1}" >>"$log"; rm -f "${logs[@]:1}"; fi
  rate=$(( took > 0 ? runs / took : 0 ))
  total=$(( total + runs ))
  # Also per second of CPU time (user and system, of every process the run started), which a
  # machine shared with other work lowers less than the wall-clock rate.
  cpu_rate=$(( cpu > 0 ? runs / cpu : 0 ))
  line=$(printf '%-9s %12d inputs in %5d s (%d/s; %d/s of CPU), corpus %d files' "$h" "$runs" "$took" "$rate" \
         "$cpu_rate" "$(find "$corpus" -type f | wc -l)")
  if (( rc != 0 )) || ! grep -q '^Done [0-9]* runs' "$log"; then
    line+="  FAILED (exit $rc)"
    failed+=("$h")
    echo "fuzz: $h failed (exit $rc); the end of $log:" >&2
    tail -n 60 "$log" >&2
    ls "$artifacts" | sed "s|^|fuzz: crashing input $artifacts/|" >&2
  fi
  echo "fuzz: $line"
  summary+=("$line")
done

echo "fuzz: summary ($cxx, ASan and UBSan)"
printf '  %s\n' "${summary[@]}"
echo "  total     $(printf '%12d' "$total") inputs"
if (( ${#failed[@]} > 0 )); then
  echo "fuzz: FAILED: ${failed[*]} (logs, corpora and crashing inputs in $work)" >&2
  exit 1
fi
if (( ! keep )); then rm -rf "$work"; fi
exit 0
