#!/usr/bin/env bash
# Line and toggle coverage of every RTL module (docs/verification.md, section 6):
#   scripts/coverage.sh [--smoke | --check]
# configures build-cov/ (Ninja, Release, RPU_SIM_COVERAGE=ON: every Verilated testbench and the
# rpu_top configurations of RPU_SIM_COVERAGE_CONFIGS Verilated with --coverage-line
# --coverage-toggle; RPU_BENCH off), builds the testbenches, tb_rpu_top and rpu, and runs the RTL
# tests under CTest with RPU_COVERAGE_DIR=build-cov/coverage/data: every Verilated model writes its
# counts there, after its first reset (*.base.dat) and at the end (*.dat; sim/harness/
# coverage_file.h). Then it merges them with verilator_coverage (merged.dat, merged_base.dat),
# judges them with scripts/coverage_report.py (judged.dat: toggles less the base; report.txt: the
# table and every gap), writes the annotated sources into build-cov/coverage/annotate (a '%' marks
# a point never reached) and the table into docs/verification.md, section 6.
#
# The tests: `ctest -L rtl` without those that Verilate nothing (lint, style, file list, bad
# input), that need a configuration a coverage build leaves out (n8_n1_1 and the fault, trace and
# SystemC builds), and the smoke tests that have their own build (mutation) or data (coverage).
# That is every unit testbench of the default suite and every co-simulation frame of the unrolled
# and iterative defaults: curves, textures and surfaces (docs/verification.md says which).
#   --smoke  the common/ testbenches and rpu_resolve only (no rpu_top: minutes); prints the table,
#            leaves the docs alone
#   --check  leaves the docs alone; exit 1 when their table is not the measured one
# Exit status 1 when a test fails (the data of the others is still merged and reported).
set -euo pipefail
usage() {
  echo "usage: $0 [--smoke | --check]" >&2
  exit 2
}
mode=full
case ${1-} in
  "") ;;
  --smoke) mode=smoke ;;
  --check) mode=check ;;
  *) usage ;;
esac
[[ $# -le 1 ]] || usage
cd "$(dirname "$0")/.."
# ccache: hash paths relative to the checkout, so every clone of the project shares one cache.
export CCACHE_BASEDIR="$PWD"
out=build-cov/coverage
t0=$(date +%s)
phases=""
phase_start=$t0
phase_end() {  # phase_end NAME: records the wall time since the last phase ended
  local now
  now=$(date +%s)
  phases+="$1 $((now - phase_start)) s; "
  phase_start=$now
}

cmake -S . -B build-cov -G Ninja -DCMAKE_BUILD_TYPE=Release -DRPU_SIM_COVERAGE=ON \
      -DRPU_BENCH=OFF >/dev/null
exclude='^(rtl_file_list|rtl_lint|rtl_style|rtl_style_catches|rtl_bad_.*|rtl_fault_.*'
exclude+='|rtl_trace_pixel.*|rtl_systemc_.*|rtl_render_.*_n8_n1_1|rtl_render_.*_n12_n1_3_iterative'
exclude+='|mutation_smoke|coverage_smoke)$'
select=(-L rtl -E "$exclude")
if [[ $mode == smoke ]]; then
  select=(-R '^tb_rpu_(fifo|mul|div|sqrt|cordic)_|^tb_rpu_resolve$')
fi
mapfile -t tests < <(ctest --test-dir build-cov -N "${select[@]}" | sed -n 's/^ *Test *#[0-9]*: //p')
[[ ${#tests[@]} -gt 0 ]] || { echo "coverage.sh: no tests selected" >&2; exit 1; }
# The targets: a unit testbench is its test's executable; tb_rpu_top's tests run tb_rpu_top, the
# others (rtl_compare_*, rtl_render_*, rtl_demo, rtl_frame_parallel) run rpu.
targets=()
for t in "${tests[@]}"; do
  case $t in
    tb_rpu_top*) [[ " ${targets[*]} " == *" tb_rpu_top "* ]] || targets+=(tb_rpu_top) ;;
    tb_*) targets+=("$t") ;;
    *) [[ " ${targets[*]} " == *" rpu "* ]] || targets+=(rpu) ;;
  esac
done
phase_end configure
cmake --build build-cov -j"$(nproc)" --target "${targets[@]}"
phase_end build

rm -rf "$out"
mkdir -p "$out/data"
status=0
RPU_COVERAGE_DIR="$PWD/$out/data" ctest --test-dir build-cov --output-on-failure -j"$(nproc)" \
    "${select[@]}" || status=1
phase_end ctest

finals=()
bases=()
for f in "$out"/data/*.dat; do
  [[ -e $f ]] || continue
  if [[ $f == *.base.dat ]]; then bases+=("$f"); else finals+=("$f"); fi
done
[[ ${#finals[@]} -gt 0 ]] || { echo "coverage.sh: no coverage data in $out/data" >&2; exit 1; }
# Every model writes its base before its end counts (coverage_file.h); a base without end counts
# is a model that did not finish (a crash): it is left out with them.
usable_bases=()
for b in "${bases[@]}"; do
  [[ -e ${b%.base.dat}.dat ]] && usable_bases+=("$b")
done
verilator_coverage --write "$out/merged.dat" "${finals[@]}"
if [[ ${#usable_bases[@]} -gt 0 ]]; then
  verilator_coverage --write "$out/merged_base.dat" "${usable_bases[@]}"
else
  echo "# SystemC::Coverage-3" >"$out/merged_base.dat"
fi
report=(python3 scripts/coverage_report.py "$out/merged.dat" --base "$out/merged_base.dat")
"${report[@]}" --print --gaps --write-dat "$out/judged.dat" >"$out/report.txt"
verilator_coverage --annotate "$out/annotate" --annotate-all --annotate-min 1 "$out/judged.dat" \
    >"$out/annotate.log"
case $mode in
  full) "${report[@]}" --update-docs ;;
  check) "${report[@]}" --check || status=1 ;;
esac
phase_end report
sed -n '/^| module/,/^| \*\*all/p' "$out/report.txt"
echo "coverage.sh: ${#tests[@]} tests, ${#finals[@]} coverage files; $out/report.txt (every gap)," \
     "$out/annotate/"
echo "coverage.sh: ${phases}total $(($(date +%s) - t0)) s"
exit "$status"
