#!/usr/bin/env bash
# Builds the five libFuzzer harnesses (tests/fuzz/fuzz_{core,shading,textured,shapes,samplers}.cpp)
# with clang++ under AddressSanitizer and UndefinedBehaviorSanitizer, and runs each for the given
# seconds on a scratch copy of its seed corpus (tests/fuzz/corpus/<area>/, where it has one);
# prints per harness the inputs it ran (libFuzzer's final "Done N runs" line) and fails on any
# crash, leak, timeout or out-of-memory. Nothing is written into the repository: builds, corpora,
# logs and crashing inputs go to a scratch folder (kept, and printed, on failure).
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
# $TMPDIR or /tmp, removed after a clean run), LTC_FUZZ_PARALLEL (harnesses built and run at
# once, each on its own core, 1; each keeps its seconds, so N of them take about 1/N of the
# time), LTC_FUZZ_STAGE (all; build: only build the harnesses into LTC_FUZZ_BIN, run: only fuzz
# the ones built there, so that a caller can compile them while the cores are otherwise idle).
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
parallel=${LTC_FUZZ_PARALLEL:-1}
if [[ ! "$parallel" =~ ^[1-9][0-9]*$ ]]; then
  echo "fuzz: LTC_FUZZ_PARALLEL='$parallel': give a number of harnesses at once (1, 2, ...)" >&2
  exit 2
fi
stage=${LTC_FUZZ_STAGE:-all}
case "$stage" in
  all) ;;
  build | run)
    if [[ -z "${LTC_FUZZ_BIN:-}" ]]; then
      echo "fuzz: LTC_FUZZ_STAGE=$stage needs LTC_FUZZ_BIN, the folder of the harness binaries" >&2
      exit 2
    fi
    mkdir -p "$LTC_FUZZ_BIN"
    bin=$(cd "$LTC_FUZZ_BIN" && pwd) ;;
  *) echo "fuzz: LTC_FUZZ_STAGE='$stage': give all, build or run" >&2; exit 2 ;;
esac
if [[ -n "${LTC_FUZZ_BUILD_JOBS:-}" ]]; then
  echo "fuzz: LTC_FUZZ_BUILD_JOBS is gone; LTC_FUZZ_PARALLEL=N builds and runs N harnesses at once" >&2
fi
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
if [[ "$stage" == all ]]; then bin=$work; fi
# -g1: line tables, all the sanitizers' stack traces use (file:line, inlined frames), at less
# compile time than -g.
flags=(-std=c++17 -g1 -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -I "$root/include")

for h in "${harnesses[@]}"; do
  [[ -f "$root/tests/fuzz/fuzz_$h.cpp" ]] || { echo "fuzz: no harness $root/tests/fuzz/fuzz_$h.cpp" >&2; exit 2; }
done

# One harness's build into $bin; writes status_<area> (build on failure).
build_one() {
  local h=$1
  if ! "$cxx" "${flags[@]}" "$root/tests/fuzz/fuzz_$h.cpp" -o "$bin/fuzz_$h" >"$work/build_$h.log" 2>&1; then
    echo "fuzz: build of $h failed:" >&2
    cat "$work/build_$h.log" >&2
    echo build >"$work/status_$h"
    return 1
  fi
}

# One harness: build (unless built by LTC_FUZZ_STAGE=build), then run for its seconds; writes
# status_<area> (build, fail or ok) and line_<area> (its summary line).
fuzz_one() {
  local h=$1 corpus="$work/corpus_$h" artifacts="$work/artifacts_$h" rundir="$work/run_$h"
  local log="$work/log_$h.txt" rc=0
  if [[ "$stage" == run ]]; then
    if [[ ! -x "$bin/fuzz_$h" ]]; then
      echo "fuzz: no $bin/fuzz_$h (build it with LTC_FUZZ_STAGE=build)" >&2
      echo build >"$work/status_$h"
      return
    fi
  elif ! build_one "$h"; then
    return
  fi
  mkdir -p "$corpus" "$artifacts" "$rundir"
  if [[ -d "$root/tests/fuzz/corpus/$h" ]]; then
    find "$root/tests/fuzz/corpus/$h" -maxdepth 1 -type f -exec cp {} "$corpus/" \;
  fi
  # From a folder of its own: with -jobs, libFuzzer writes its fuzz-<job>.log files to the
  # current directory.
  TIMEFORMAT='%U %S'
  local seconds=${share[$h]:-24}
  { time (cd "$rundir" && "$bin/fuzz_$h" -max_total_time="$seconds" -max_len=512 -print_final_stats=1 \
            -artifact_prefix="$artifacts/" "${fuzz_args[@]}" "$corpus" >"$log" 2>&1); } 2>"$work/cpu_$h.txt" || rc=$?
  local cpu
  cpu=$(awk '{ printf "%.0f", $1 + $2 }' "$work/cpu_$h.txt" 2>/dev/null || echo 0)
  # The inputs run: the "Done N runs" line of the run, or of each job with -jobs.
  local logs=("$log") j
  for j in "$rundir"/fuzz-*.log; do if [[ -f "$j" ]]; then logs+=("$j"); fi; done
  local runs took
  runs=$(sed -n 's/^Done \([0-9]*\) runs in.*/\1/p' "${logs[@]}" | awk '{ s += $1 } END { print s + 0 }')
  took=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "${logs[@]}" | awk '{ s += $1 } END { print s + 0 }')
  if (( ${#logs[@]} > 1 )); then cat "${logs[@]:1}" >>"$log"; rm -f "${logs[@]:1}"; fi
  local rate=$(( took > 0 ? runs / took : 0 ))
  # Also per second of CPU time (user and system, of every process the run started), which a
  # machine shared with other work lowers less than the wall-clock rate.
  local cpu_rate=$(( cpu > 0 ? runs / cpu : 0 ))
  local line
  line=$(printf '%-9s %12d inputs in %5d s (%d/s; %d/s of CPU), corpus %d files' "$h" "$runs" "$took" "$rate" \
         "$cpu_rate" "$(find "$corpus" -type f | wc -l)")
  local status=ok
  if (( rc != 0 )) || ! grep -q '^Done [0-9]* runs' "$log"; then
    line+="  FAILED (exit $rc)"
    status=fail
    { echo "fuzz: $h failed (exit $rc); the end of $log:"
      tail -n 60 "$log"
      ls "$artifacts" | sed "s|^|fuzz: crashing input $artifacts/|"; } >&2
  fi
  echo "$runs" >"$work/runs_$h"
  printf '%s\n' "$line" >"$work/line_$h"
  echo "fuzz: $line"
  echo "$status" >"$work/status_$h"
}
fuzz_args=("$@")

# Longest first (compile seconds, measured with -g1, plus the run's share), so that with
# LTC_FUZZ_PARALLEL=2 fuzz_shading's long compile starts at once and the short ones fill the
# other core.
declare -A build_cost=([core]=10 [shading]=52 [textured]=12 [shapes]=11 [samplers]=6)
# Built already (LTC_FUZZ_STAGE=run): by the share alone.
if [[ "$stage" == run ]]; then for h in "${!build_cost[@]}"; do build_cost[$h]=0; done; fi
order=($(for h in "${harnesses[@]}"; do echo "$(( ${build_cost[$h]:-20} + ${share[$h]:-24} )) $h"; done |
         sort -rn -k1,1 | awk '{ print $2 }'))

if [[ "$stage" == build ]]; then
  echo "fuzz: building ${order[*]}, $parallel at once, into $bin"
  running=0 build_failed=0
  for h in "${order[@]}"; do
    if (( running >= parallel )); then wait -n || build_failed=1; running=$(( running - 1 )); fi
    build_one "$h" &
    running=$(( running + 1 ))
  done
  while (( running > 0 )); do wait -n || build_failed=1; running=$(( running - 1 )); done
  if (( build_failed )); then echo "fuzz: a build failed (logs in $work)" >&2; exit 2; fi
  echo "fuzz: built ${order[*]} into $bin"
  if (( ! keep )); then rm -rf "$work"; fi
  exit 0
fi

echo "fuzz: $([[ "$stage" == run ]] && echo "running the harnesses of $bin:" || echo "building and running") ${order[*]}, $parallel at once, in $work"
running=0
for h in "${order[@]}"; do
  if (( running >= parallel )); then wait -n || true; running=$(( running - 1 )); fi
  fuzz_one "$h" &
  running=$(( running + 1 ))
done
wait || true

failed=() build_failed=0 total=0 summary=()
for h in "${harnesses[@]}"; do
  status=$(cat "$work/status_$h" 2>/dev/null || echo none)
  if [[ "$status" == build ]]; then build_failed=1; continue; fi
  if [[ "$status" == none ]]; then
    echo "fuzz: $h stopped before its summary (see $work)" >&2
    failed+=("$h"); summary+=("$(printf '%-9s FAILED (no summary)' "$h")"); continue
  fi
  if [[ "$status" != ok ]]; then failed+=("$h"); fi
  summary+=("$(cat "$work/line_$h")")
  total=$(( total + $(cat "$work/runs_$h") ))
done
if (( build_failed )); then echo "fuzz: a build failed (logs in $work)" >&2; exit 2; fi

echo "fuzz: summary ($cxx, ASan and UBSan, $parallel at once)"
printf '  %s\n' "${summary[@]}"
echo "  total     $(printf '%12d' "$total") inputs"
if (( ${#failed[@]} > 0 )); then
  echo "fuzz: FAILED: ${failed[*]} (logs, corpora and crashing inputs in $work)" >&2
  exit 1
fi
if (( ! keep )); then rm -rf "$work"; fi
exit 0
