#!/usr/bin/env bash
# Area and timing regression check of the RTL: synthesises every module of the budget file (or
# the modules named) with scripts/yosys_report.sh and fails when one exceeds its budget: LUT
# sites (logic LUT + INV + SRL + LUTRAM) or FF by more than 2 %, any DSP48E1 more, or Yosys'
# static timing estimate by more than 0.25 ns. Prints one line per module (ok / FAIL and the
# numbers) and, for a module clearly below its budget, a reminder to lower the budget.
#
# Usage: scripts/synth_budget.sh [-H] [-b BUDGET.csv] [-j N] [-t SECONDS] [module[:reduced] ...]
#   -H  the whole-design budgets (tests/synth_budget_top.csv: rpu_top unrolled and iterative),
#       priced by the cached hierarchical flow (yosys_report.sh -H, scripts/synth_hier.py); sta
#       is the slowest derived module's own logic
# Slow (about 30 minutes for every module on 2 cores; the whole tops cold about 16 minutes each, warm
# seconds): the CTests synth_budget and synth_budget_top are opt-in (cmake -DRPU_SYNTH_TESTS=ON;
# ctest -L synth).
set -euo pipefail
cd "$(dirname "$0")/.."
budget=""
jobs=1
timeout=2400
hier=()
while getopts "Hb:j:t:h" opt; do
  case "$opt" in
    H) hier=(-H) ;;
    b) budget=$OPTARG ;;
    j) jobs=$OPTARG ;;
    t) timeout=$OPTARG ;;
    *) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 2 ;;
  esac
done
if [ -z "$budget" ]; then
  if ((${#hier[@]})); then budget=tests/synth_budget_top.csv; else budget=tests/synth_budget.csv; fi
fi
shift $((OPTIND - 1))
[ -r "$budget" ] || { echo "synth_budget: $budget: cannot read the budget file" >&2; exit 2; }

mapfile -t known < <(grep -v '^#' "$budget" | tail -n +2 | cut -d, -f1)
if (($#)); then
  modules=("$@")
  for m in "${modules[@]}"; do
    # (a word match, not `printf | grep -q`: under pipefail grep -q's early exit can fail the
    # pipe with SIGPIPE and call a listed module unknown)
    [[ " ${known[*]} " == *" $m "* ]] ||
      { echo "synth_budget: $m: no budget in $budget" >&2; exit 2; }
  done
else
  modules=("${known[@]}")
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
scripts/yosys_report.sh "${hier[@]}" -j "$jobs" -t "$timeout" -c "$work/report.csv" "${modules[@]}" \
  > "$work/report.md" 2> "$work/report.err" || status=$?
if [ ! -s "$work/report.csv" ]; then
  echo "synth_budget: yosys_report.sh produced no results (exit $status):" >&2
  cat "$work/report.err" >&2
  exit 1
fi

# report.csv: "Module","Configuration","LUT","INV","FF","SRL","LUTRAM","DSP48E1",...,"sta ns",...
awk -F, -v budget_file="$budget" -v wanted="${modules[*]}" '
  function unq(s) { gsub(/"/, "", s); return s }
  BEGIN {
    while ((getline line < budget_file) > 0) {
      if (line ~ /^#/ || line ~ /^module,/ || line == "") continue
      split(line, b, ",")
      lut[b[1]] = b[2]; ff[b[1]] = b[3]; dsp[b[1]] = b[4]; sta[b[1]] = b[5]
    }
    fails = 0
    n = split(wanted, w, " ")
    for (i = 1; i <= n; i++) want[w[i]] = 1
  }
  NR == 1 {
    for (i = 1; i <= NF; i++) col[unq($i)] = i
    next
  }
  {
    m = unq($col["Module"])
    if (unq($col["Configuration"]) ~ /reduced/) m = m ":reduced"
    if (!(m in lut)) next
    seen[m] = 1
    sites = unq($col["LUT"]) + unq($col["INV"]) + unq($col["SRL"]) + unq($col["LUTRAM"])
    f = unq($col["FF"]) + 0; d = unq($col["DSP48E1"]) + 0; t = unq($col["sta ns"])
    if (t !~ /^[0-9.]+$/) {
      printf "FAIL %-16s no result (%s)\n", m, t; fails++; next
    }
    t += 0
    bad = ""
    if (sites > lut[m] * 1.02) bad = bad sprintf(" LUT sites %d > %d+2%%", sites, lut[m])
    if (f > ff[m] * 1.02) bad = bad sprintf(" FF %d > %d+2%%", f, ff[m])
    if (d > dsp[m]) bad = bad sprintf(" DSP %d > %d", d, dsp[m])
    if (t > sta[m] + 0.25) bad = bad sprintf(" sta %.2f ns > %.2f+0.25", t, sta[m])
    line = sprintf("%-16s LUT sites %6d (budget %6d)  FF %6d (%6d)  DSP %4d (%4d)  sta %6.2f ns (%.2f)",
                   m, sites, lut[m], f, ff[m], d, dsp[m], t, sta[m])
    if (bad != "") { print "FAIL " line ":" bad; fails++ }
    else {
      print "ok   " line
      if (sites < lut[m] * 0.95 || t < sta[m] - 0.5)
        print "     (well under budget: lower its row in " budget_file ")"
    }
  }
  END {
    for (m in lut) if (want[m] && !(m in seen)) { print "FAIL " m ": not in the report"; fails++ }
    exit fails > 0 ? 1 : 0
  }
' "$work/report.csv" || exit 1
echo "synth_budget: every module within its budget"
