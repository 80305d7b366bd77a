#!/usr/bin/env bash
# Longer fuzzing runs (issue 14, item 3; docs/verification.md "Fuzzing"):
#   scripts/fuzz.sh [--merge] [--jobs J] [--timeout T] SECONDS [target...]
# builds the libFuzzer targets into build-fuzz/ (as scripts/test_fuzz.sh) and fuzzes each target
# (default: all) for SECONDS, J targets at once (default: the number of cores). Each target keeps
# its working corpus in build-fuzz/fuzz-runs/<target>/corpus (seeded from fuzz/corpus/<target>,
# grown across runs; the repository is not written) and its crash, leak, timeout and oom inputs in
# build-fuzz/fuzz-runs/<target>/artifacts/. Prints per target: executions, exec/s, new inputs,
# coverage (edges "cov", features "ft") and crashes. --merge: afterwards merge the inputs that add
# coverage back into fuzz/corpus/<target> (libFuzzer -merge=1). --timeout: libFuzzer's per-input
# limit in wall seconds (default 10); a niced campaign on a busy machine needs more, or a slow
# input (seconds unloaded) ends the run as a false "timeout". Exit status 1 when any target
# found a crash (minimise it: build-fuzz/fuzz/<target> -minimize_crash=1 -runs=10000 FILE).
set -euo pipefail
usage() {
  echo "usage: $0 [--merge] [--jobs J] [--timeout T] SECONDS [fuzz_scene|fuzz_sweep|fuzz_render|fuzz_params ...]" >&2
  exit 2
}
all_targets=(fuzz_scene fuzz_sweep fuzz_render fuzz_params)
merge=0
jobs=$(nproc)
timeout=10
while [[ $# -gt 0 && $1 == --* ]]; do
  case $1 in
    --merge) merge=1; shift ;;
    --jobs) [[ $# -ge 2 && $2 =~ ^[1-9][0-9]*$ ]] || usage; jobs=$2; shift 2 ;;
    --timeout) [[ $# -ge 2 && $2 =~ ^[1-9][0-9]*$ ]] || usage; timeout=$2; shift 2 ;;
    *) usage ;;
  esac
done
[[ $# -ge 1 && $1 =~ ^[1-9][0-9]*$ ]] || usage
seconds=$1
shift
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=("${all_targets[@]}")
for t in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $t "* ]] || usage
done
cd "$(dirname "$0")/.."
export CCACHE_BASEDIR="$PWD"
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DRPU_FUZZ=ON -DRPU_SIM=OFF -DRPU_BENCH=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]}"

dict_of() { case $1 in fuzz_sweep | fuzz_params) echo fuzz/$1.dict ;; *) echo fuzz/fuzz_scene.dict ;; esac; }
run_one() {
  local t=$1 dir=build-fuzz/fuzz-runs/$1
  mkdir -p "$dir/corpus" "$dir/artifacts"
  cp -n fuzz/corpus/"$t"/* "$dir/corpus/" 2>/dev/null || true
  build-fuzz/fuzz/"$t" -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 \
      -print_final_stats=1 -dict="$(dict_of "$t")" -artifact_prefix="$dir/artifacts/" \
      "$dir/corpus" >"$dir/run.log" 2>&1 || true
}
for t in "${targets[@]}"; do
  rm -f build-fuzz/fuzz-runs/"$t"/run.log
  while [[ $(jobs -rp | wc -l) -ge $jobs ]]; do wait -n || true; done
  run_one "$t" &
done
wait

status=0
printf '%-12s %12s %9s %9s %8s %8s %8s %5s\n' target executions exec/s new_units cov ft crashes slow
for t in "${targets[@]}"; do
  dir=build-fuzz/fuzz-runs/$t
  stat() { sed -n "s/^stat::$1: *//p" "$dir/run.log" | tail -1; }
  last=$(grep -E '^#[0-9]+' "$dir/run.log" | tail -1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  # Crash, leak, timeout and oom inputs fail the run; slow units (libFuzzer's -report_slow_units,
  # 10 s) are only counted: on a loaded machine they are the load, rerun them to judge.
  crashes=$(grep -cE 'Test unit written to .*/(crash|leak|timeout|oom)-' "$dir/run.log" || true)
  slow=$(grep -c 'Test unit written to .*/slow-unit-' "$dir/run.log" || true)
  printf '%-12s %12s %9s %9s %8s %8s %8s %5s\n' "$t" "$(stat number_of_executed_units)" \
         "$(stat average_exec_per_sec)" "$(stat new_units_added)" "${cov:-?}" "${ft:-?}" "$crashes" \
         "$slow"
  if [[ $crashes -ne 0 ]]; then
    status=1
    grep -E 'SUMMARY: |Test unit written to .*/(crash|leak|timeout|oom)-' "$dir/run.log" || true
  fi
  if [[ $merge -eq 1 ]]; then
    build-fuzz/fuzz/"$t" -merge=1 -timeout=10 fuzz/corpus/"$t" "$dir/corpus" >"$dir/merge.log" 2>&1
    echo "$t: merged into fuzz/corpus/$t: $(grep -o 'MERGE-OUTER: [0-9]* new files' "$dir/merge.log" || echo '? new files')"
  fi
done
exit "$status"
