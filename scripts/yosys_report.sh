#!/usr/bin/env bash
# Resource and logic-depth report of the RTL modules: Yosys `synth_xilinx` (7-series, flattened,
# no I/O or clock buffers) of each module at its default parameters (or the configuration named
# in the table below), the cell counts from `stat`, the longest combinational path from `ltp`
# on the mapped netlist and Yosys' static timing estimate from `sta`. Every run reads every file
# of the RTL file list rtl/rpu.f; `hierarchy -top` elaborates the module and what it instantiates.
# Needs only bash, coreutils, awk, sed, grep and Yosys (Debian's 0.23).
#
# Usage: scripts/yosys_report.sh [options] [module[:reduced] ...]
#   (no modules)        every module of the run order below, smallest first; a module no file
#                       of rtl/rpu.f defines is skipped
#   module:reduced      that module at its reduced configuration (rpu_ip, rpu_top)
#   -r, --reduced       rpu_ip and rpu_top at their reduced configurations instead of the defaults
#   -R                  both: the reduced configurations as extra rows, run before the full ones
#   -G mod:Param=Value  override one parameter of one module (repeatable)
#   -j N                parallel Yosys runs (default 1)
#   -t SECONDS          time limit per module (default 1200); over it the row says "timeout"
#   -m MB               memory limit per Yosys run (virtual, default 8000); over it: "out of memory"
#   -o FILE             also write the Markdown table to FILE
#   -c FILE             also write the table as CSV to FILE
#   -k DIR              keep the Yosys scripts, logs and reports in DIR (default: a temporary dir)
#   -n                  dry run: print each module's configuration and files, run nothing
#   -P DIR              no synthesis: tabulate again the files an earlier run kept in DIR (-k)
#   -H                  hierarchical, through the cached flow scripts/synth_hier.py: each
#                       distinct derived module synthesised once in its own Yosys process (-j
#                       at a time), the counts summed over the instance tree; cached in
#                       build/synth_cache (-C moves it), so a second run synthesises nothing
#                       and an edit of one unit re-runs that unit. No cross-module
#                       optimisation and no longest path; sta is the slowest module's own
#                       logic. The modules named run one after another, each with -j jobs
#   -C DIR              -H: the cache directory (default build/synth_cache)
#   -h                  this help
# The Markdown table goes to stdout, progress to stderr. Exit status 1 if a run failed (an
# error, not a timeout or a skipped module).
#
# Columns (all from `stat` after synth_xilinx -flatten):
#   LUT      LUT1..LUT6 (INV: own column)         FF      FDRE/FDSE/FDCE/FDPE (+ latches)
#   SRL      SRL16E/SRLC32E (one LUT each)        LUTRAM  distributed-RAM cells in LUTs
#   DSP      DSP48E1                              BRAM36  RAMB36E1 + RAMB18E1 / 2
#   CARRY4, MUXF7/8 as counted.
# Longest path: `ltp` (longest topological path) on the mapped netlist with every flip-flop,
# SRL, block RAM and DSP with an internal M or P register as a path break (a path starts at a
# register or an input port and ends at a register or an output port). Every LUT, CARRY4,
# MUXF7/F8, LUTRAM read and DSP48E1 on the path counts one level (unit delay). A DSP whose A or B
# operand is registered inside it (AREG/BREG, how synth_xilinx absorbs operand registers) ends
# the paths into that operand and starts the paths through its multiplier
# (scripts/yosys/ltp_cells.v). It is a logic-depth measure, not a timing analysis: a CARRY4 is
# 4 carry bits and much faster than a LUT level, a DSP much slower.
# sta ns: Yosys' static timing estimate, `sta` on the mapped netlist after reading the Xilinx
# cell library with its specify blocks (`read_verilog -lib -specify -overwrite
# +/xilinx/cells_sim.v`; without them CARRY4 has no timing arcs and the figure is far too low):
# the latest arrival time at a register input or output port, in ns, from the launching cell's
# clock-to-out (FF 0.30, SRL 1.47, DSP/BRAM more) through the cells' delays. Cell delays only:
# no routing, no setup time, no clock skew (placed and routed, the same path is slower).
# Input ports arrive at 0.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=scripts/rtl_files.sh
. "$root/scripts/rtl_files.sh"
rpu_rtl_read "$root" || exit 2
ltp_cells=$root/scripts/yosys/ltp_cells.v

# The report's columns (tabulate writes the values in this order).
header=(Module Configuration LUT INV FF SRL LUTRAM DSP48E1 BRAM36 CARRY4 MUXF7/8 "Est. LCs"
        "Longest path (levels)" "sta ns" "Yosys s" "Yosys MB")

# ---- the module table ----
# Parameters set for the report (empty: the module's defaults).
declare -A PARAMS=(
  [rpu_sqrt]="RadW=58"                       # the guide's radicand (= the default)
  [rpu_div]="NumW=51 DenW=28 QuotW=27"       # rpu_ray_gen's reciprocal 2^(2FV+2)/|v|, FV = 24
  [rpu_fifo]="Width=256 Log2Depth=10"        # about rpu_top's result FIFOs
  [rpu_skid]="W=76"                          # rpu_top's work-item input register
  [rpu_mul]="AW=51 BW=23 Signed=0"           # the guide pair's L²·w, its widest product
)
# Modules priced without a submodule (read as a black box): the AXI shell alone, its rpu_top
# priced by its own rows.
declare -A BLACKBOX=(
  [rpu_axi]="rpu_top"
)
# Reduced configurations (-r or module:reduced): the iterative IP, one rpu_ip_step unit reused
# K = N/N1 = 8 times instead of 8 unrolled step units (about 1/8 of the one-item-per-cycle rate).
declare -A REDUCED=(
  [rpu_ip]="Unrolled=0"
  [rpu_top]="Unrolled=0"
)
# Default module list and run order: roughly by size, the biggest last.
ALL=(rpu_resolve rpu_fifo rpu_mul rpu_sqrt rpu_chord rpu_div rpu_capture rpu_curve_point rpu_guide_pair rpu_ray_plane
     rpu_ray_gen rpu_texture rpu_sphere rpu_frame rpu_candidate rpu_test_point rpu_ip_step rpu_ip
     rpu_axi rpu_top)

usage() { sed -n '2,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "$0"; }

jobs_max=1 tlimit=1200 mlimit=8000 md_out="" csv_out="" keep="" reduced_mode="" dry=0 reparse="" hier=0
hier_cache=""
declare -A OVERRIDE=()
specs=()
while (($#)); do
  case $1 in
    -j) jobs_max=$2; shift 2 ;;
    -j*) jobs_max=${1#-j}; shift ;;
    -t) tlimit=$2; shift 2 ;;
    -o) md_out=$2; shift 2 ;;
    -c) csv_out=$2; shift 2 ;;
    -k) keep=$2; shift 2 ;;
    -m) mlimit=$2; shift 2 ;;
    -n) dry=1; shift ;;
    -P) reparse=$2; shift 2 ;;
    -H) hier=1; shift ;;
    -C) hier_cache=$2; shift 2 ;;
    -r|--reduced) reduced_mode=only; shift ;;
    -R) reduced_mode=both; shift ;;
    -G) m=${2%%:*}; OVERRIDE[$m]="${OVERRIDE[$m]:-} ${2#*:}"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "yosys_report: unknown option $1" >&2; usage >&2; exit 2 ;;
    *) specs+=("$1"); shift ;;
  esac
done
defaulted=0
((${#specs[@]})) || { specs=("${ALL[@]}"); defaulted=1; }
[[ $jobs_max =~ ^[1-9][0-9]*$ ]] || { echo "yosys_report: -j needs a positive number" >&2; exit 2; }
[[ $tlimit =~ ^[1-9][0-9]*$ ]] || { echo "yosys_report: -t needs a positive number" >&2; exit 2; }
[[ $mlimit =~ ^[1-9][0-9]*$ ]] || { echo "yosys_report: -m needs a positive number" >&2; exit 2; }
# -r: reducible modules at their reduced configuration; -R: those rows first, then the full ones.
if [[ -n $reduced_mode ]]; then
  plain=() reduced=() full=()
  for spec in "${specs[@]}"; do
    if [[ $spec == *:* || -z ${REDUCED[$spec]:-} ]]; then plain+=("$spec")
    else reduced+=("$spec:reduced"); full+=("$spec"); fi
  done
  specs=("${plain[@]}" "${reduced[@]}")
  if [[ $reduced_mode == both ]]; then specs+=("${full[@]}"); fi
fi
command -v yosys >/dev/null || { echo "yosys_report: yosys not found" >&2; exit 2; }

if [[ -n $reparse ]]; then
  [[ -d $reparse ]] || { echo "yosys_report: no directory $reparse" >&2; exit 2; }
  work=$(cd "$reparse" && pwd)
elif [[ -n $keep ]]; then
  mkdir -p "$keep"
  work=$(cd "$keep" && pwd)
  rm -f "$work"/[0-9][0-9]_*  # an earlier run's files
else
  work=$(mktemp -d "${TMPDIR:-/tmp}/yosys_report.XXXXXX")
  trap 'rm -rf "$work"' EXIT
fi
# Interrupted: end the Yosys runs this report started (each a process group led by `timeout`).
stop_runs() {
  local f
  # shellcheck disable=SC2046  # the job pids, one word each
  kill $(jobs -p) 2>/dev/null
  for f in "$work"/*.pid; do
    [[ -e $f ]] && kill -TERM -- "-$(cat "$f")" 2>/dev/null
  done
  for f in "$work"/*.flowpid; do
    [[ -e $f ]] && kill -TERM "$(cat "$f")" 2>/dev/null
  done
  echo "yosys_report: interrupted" >&2
  exit 130
}
trap stop_runs INT TERM
yosys_version=$(yosys -V 2>/dev/null | head -1)

# Every module the files of rtl/rpu.f define (a line `module name`), one per line.
defined_modules() {
  sed -n 's/^[[:space:]]*module[[:space:]]\{1,\}\([A-Za-z_][A-Za-z0-9_$]*\).*/\1/p' "${rtl_sources[@]}" |
    sort -u
}
modules=$(defined_modules)
# Every Yosys run reads the whole list (-I for its include directories, then every source file)
# with -defer: `hierarchy -top` elaborates the module and its submodules only, exactly as when
# only their files are read (elaborating every module at read time changes the names Yosys
# gives to cells, and with them, slightly, what ABC maps).
rtl_read=""
for d in "${rtl_incdirs[@]}"; do rtl_read+="-I$d "; done
rtl_read+="${rtl_sources[*]}"

# The row of a finished run: resources from stat, the path and its make-up from ltp and the
# cell lists, peak memory from the log. Fields: module, configuration, "ok", the values of
# header[2..] in order, other cell types (if any).
tabulate() {
  local tag=$1 mod=$2 config=$3 secs=$4
  awk -v mod="$mod" -v config="$config" -v secs="$secs" -v work="$work" -v tag="$tag" '
    function load(cls,   f, line) {
      f = work "/" tag ".cells." cls
      while ((getline line < f) > 0) {
        sub(/^[ \t]+/, "", line); sub(/[ \t\r]+$/, "", line)
        if (index(line, mod "/") == 1) line = substr(line, length(mod) + 2)
        if (line != "") kind[line] = cls
      }
      close(f)
    }
    BEGIN {
      load("L"); load("C"); load("M"); load("D"); load("R")
      # LUTs used by each distributed-RAM primitive
      lr["RAM32X1S"] = 1; lr["RAM64X1S"] = 1; lr["RAM128X1S"] = 2; lr["RAM256X1S"] = 4
      lr["RAM32X1D"] = 2; lr["RAM64X1D"] = 2; lr["RAM128X1D"] = 4; lr["RAM32M"] = 4
      lr["RAM64M"] = 4; lr["RAM32M16"] = 8; lr["RAM64M8"] = 8; lr["RAM512X1S"] = 8
      f = work "/" tag ".stat"
      while ((getline line < f) > 0) {
        if (line ~ /Estimated number of LCs:/) { n = split(line, a, " "); lcs = a[n]; continue }
        n = split(line, a, " ")
        if (n != 2 || a[2] !~ /^[0-9]+$/) continue
        t = a[1]; c = a[2] + 0
        if (t ~ /^LUT[1-6]$/) lut += c
        else if (t == "INV") inv += c
        else if (t ~ /^FD[RSCP]E$/ || t ~ /^LD[CP]E$/) ff += c
        else if (t ~ /^SRL/) srl += c
        else if (t in lr) lutram += c * lr[t]
        else if (t == "DSP48E1") dsp += c
        else if (t == "RAMB36E1") b36 += c
        else if (t == "RAMB18E1") b18 += c
        else if (t == "CARRY4") carry += c
        else if (t ~ /^MUXF[78]$/) muxf += c
        else if (t != "GND" && t != "VCC" && t != "BUFG" && t != "IBUF" && t != "OBUF")
          other = other (other == "" ? "" : ", ") t " " c
      }
      close(f)
      f = work "/" tag ".ltp"
      len = "?"
      while ((getline line < f) > 0) {
        if (match(line, /\(length=-?[0-9]+\)/)) { len = substr(line, RSTART + 8, RLENGTH - 9); continue }
        if (line !~ /\(via .*\)[ \t\r]*$/) continue
        sub(/[ \t\r]+$/, "", line)
        p = index(line, "(via ")
        cell = substr(line, p + 5, length(line) - p - 5)
        k = (cell in kind) ? kind[cell] : "O"
        cnt[k]++
      }
      close(f)
      # sta: the latest arrival time in ps (clock-to-out of the launching cell plus the cell
      # delays of the Xilinx specify library, no routing, no setup time).
      f = work "/" tag ".sta"
      sta = "?"
      while ((getline line < f) > 0)
        if (match(line, /Latest arrival time in .* is -?[0-9]+/)) {
          n = split(substr(line, RSTART, RLENGTH), a, " ")
          sta = sprintf("%.2f", a[n] / 1000)
        }
      close(f)
      f = work "/" tag ".log"
      mem = "-"
      while ((getline line < f) > 0)
        if (match(line, /MEM: [0-9.]+ MB peak/)) mem = sprintf("%d", substr(line, RSTART + 5, RLENGTH - 13) + 0.5)
      close(f)
      names["L"] = "LUT"; names["C"] = "CARRY4"; names["M"] = "MUXF"; names["D"] = "DSP"
      names["R"] = "LUTRAM"; names["O"] = "other"
      mix = ""
      split("L C M D R O", order, " ")
      for (i = 1; i <= 6; i++)
        if (cnt[order[i]] > 0) mix = mix (mix == "" ? "" : " + ") cnt[order[i]] " " names[order[i]]
      path = len (mix == "" ? "" : " (" mix ")")
      bram = b36 + b18 / 2
      if (lcs == "") lcs = "-"
      printf "%s\t%s\tok\t%d\t%d\t%d\t%d\t%d\t%d\t%s\t%d\t%d\t%s\t%s\t%s\t%s\t%s", mod, config, lut, inv,
             ff, srl, lutram, dsp, bram, carry, muxf, lcs, path, sta, secs, mem
      printf "%s\n", other == "" ? "" : "\t" other
    }' </dev/null >"$work/$tag.row"
}

# -H: one module through the cached hierarchical flow (scripts/synth_hier.py); its JSON report
# becomes the row (LUT, INV, FF, SRL, LUTRAM, DSP48E1, BRAM36, CARRY4, MUXF7/8, Est. LCs summed
# over the instance tree; sta: the slowest module's own logic; Yosys s: the flow's wall time).
run_hier() {
  local tag=$1 mod=$2 config=$3 params=$4 p rc args=()
  for p in $params; do args+=(-G "$p"); done
  if [[ -n $hier_cache ]]; then args+=(--cache "$hier_cache"); fi
  if ((dry)); then
    echo "$mod: $config: scripts/synth_hier.py ${args[*]} $mod"
    return 0
  fi
  echo "[$(date +%T)] $mod: started ($config)" >&2
  set +e
  python3 "$root/scripts/synth_hier.py" -j "$jobs_max" -t "$tlimit" -m "$mlimit" "${args[@]}" \
    --json "$work/$tag.json" --md "$work/$tag.md" "$mod" >"$work/$tag.out" 2>"$work/$tag.log" &
  echo $! >"$work/$tag.flowpid"  # stop_runs ends it (it ends its own Yosys runs)
  wait $!
  rc=$?
  rm -f "$work/$tag.flowpid"
  set -e
  python3 - "$work/$tag.json" "$mod" "$config" "$rc" "$work/$tag.log" >"$work/$tag.row" <<'PY'
import json, sys
path, mod, config, rc, log = sys.argv[1:]
try:
    r = json.load(open(path))
except (OSError, ValueError):
    last = [l for l in open(log, errors="replace").read().splitlines() if l.strip()][-1:]
    print(f"{mod}\t{config}\terror: {(last or ['exit ' + rc])[0][:120]}")
    sys.exit()
if r["status"] != "ok":
    first = r["failures"][0]
    kind = "timeout" if ": timeout" in first else \
        "out of memory" if "out of memory" in first else "error"
    print(f"{mod}\t{config}\t{kind}: {first[:120]}")
    sys.exit()
t = r["totals"]
sta = f"{r['sta_ns']:.2f}" if r["sta_ns"] is not None else "-"
bram = t["bram36"] if t["bram36"] != int(t["bram36"]) else int(t["bram36"])
print("\t".join(str(v) for v in [
    mod, config, "ok", t["lut"], t["inv"], t["ff"], t["srl"], t["lutram"], t["dsp"], bram,
    t["carry4"], t["muxf"], t["est_lcs"], "- (per module)", sta, round(r["wall_seconds"]), "-"]))
PY
  echo "[$(date +%T)] $mod: $(cut -f3 "$work/$tag.row" | cut -c1-80)" >&2
}

# One module: synthesise, write $work/$tag.row (tab-separated fields of the table).
run_one() {
  local idx=$1 spec=$2 mod red=0 tag params p files t0 t1 rc
  mod=${spec%%:*}
  if [[ $spec == *:reduced ]]; then red=1; fi
  tag=$(printf '%02d_%s' "$idx" "${spec/:/_}")
  params="${PARAMS[$mod]:-}"
  if ((red)); then
    [[ -n ${REDUCED[$mod]:-} ]] || { echo "yosys_report: $mod has no reduced configuration" >&2; return 1; }
    params="$params ${REDUCED[$mod]}"
  fi
  # Later settings of a parameter replace earlier ones (table, reduced, -G).
  local merged=() q i
  for p in $params ${OVERRIDE[$mod]:-}; do
    for i in "${!merged[@]}"; do
      q=${merged[$i]}
      if [[ ${q%%=*} == "${p%%=*}" ]]; then unset 'merged[i]'; fi
    done
    merged+=("$p")
  done
  params="${merged[*]}"
  local config=${params:-defaults}
  if ((red)); then config="$config (reduced)"; fi
  local read="read_verilog -defer $rtl_read" bb
  if [[ -n ${BLACKBOX[$mod]:-} ]]; then
    local keep_src=() lib_src=() f
    for f in "${rtl_sources[@]}"; do
      bb=0
      for m in ${BLACKBOX[$mod]}; do grep -qE "^[[:space:]]*module[[:space:]]+$m\b" "$f" && bb=1; done
      if ((bb)); then lib_src+=("$f"); else keep_src+=("$f"); fi
    done
    read="read_verilog -defer"
    for d in "${rtl_incdirs[@]}"; do read+=" -I$d"; done
    read+=" ${keep_src[*]}"$'\n'"read_verilog -lib"
    for d in "${rtl_incdirs[@]}"; do read+=" -I$d"; done
    read+=" ${lib_src[*]}"
    config="$config (${BLACKBOX[$mod]} a black box)"
  fi
  if ((hier)); then config="$config (hierarchical)"; fi

  if ! grep -qxF -- "$mod" <<<"$modules"; then
    printf '%s\t%s\tskipped (no file of rtl/rpu.f defines it)\n' "$mod" "$config" >"$work/$tag.row"
    echo "[$(date +%T)] $spec: skipped, no file of rtl/rpu.f defines $mod" >&2
    return 0
  fi
  local chparam=""
  for p in $params; do chparam+=" -chparam ${p%%=*} ${p#*=}"; done
  local sel="$mod/t:FD* $mod/t:LD* %u $mod/t:SRL* %u $mod/t:RAMB* %u"
  sel="$sel $mod/t:DSP48E1 r:MREG>0 %i %u $mod/t:DSP48E1 r:PREG>0 %i %u"
  local comb="r:MREG<1 %i r:PREG<1 %i"
  if ((hier)); then
    run_hier "$tag" "$mod" "$config" "$params"
    return 0
  fi
  cat >"$work/$tag.ys" <<EOF
$read
hierarchy -check -top $mod$chparam
synth_xilinx -flatten -noiopad -noclkbuf -top $mod
tee -q -o $work/$tag.stat stat -tech xilinx
tee -q -o $work/$tag.cells.L select -list $mod/t:LUT* $mod/t:INV %u
tee -q -o $work/$tag.cells.C select -list $mod/t:CARRY4
tee -q -o $work/$tag.cells.M select -list $mod/t:MUXF*
tee -q -o $work/$tag.cells.D select -list $mod/t:DSP48E1
tee -q -o $work/$tag.cells.R select -list $mod/t:RAM* $mod/t:RAMB* %d
read_verilog -lib -specify -overwrite +/xilinx/cells_sim.v
tee -q -o $work/$tag.sta sta
read_verilog -lib $ltp_cells
chtype -set RPU_LTP_DSP48E1_AB $mod/t:DSP48E1 r:AREG>0 %i r:BREG>0 %i $comb
chtype -set RPU_LTP_DSP48E1_A $mod/t:DSP48E1 r:AREG>0 %i $comb
chtype -set RPU_LTP_DSP48E1_B $mod/t:DSP48E1 r:BREG>0 %i $comb
select -set breaks $sel
tee -q -o $work/$tag.ltp ltp -noff $mod/* @breaks %d
EOF
  if ((dry)); then
    echo "$spec: $config: rtl/rpu.f, top $mod"
    return 0
  fi
  echo "[$(date +%T)] $spec: started ($config)" >&2
  t0=$(date +%s)
  # `timeout` runs in a process group of its own (Yosys and its ABC children); its pid is
  # recorded so that an interrupted report can end that group (see the trap below).
  (
    ulimit -v $((mlimit * 1024))
    exec timeout -k 30 "$tlimit" yosys -q -l "$work/$tag.log" "$work/$tag.ys"
  ) >"$work/$tag.out" 2>&1 &
  echo $! >"$work/$tag.pid"
  set +e
  wait $!
  rc=$?
  set -e
  rm -f "$work/$tag.pid"
  t1=$(date +%s)
  if ((rc == 124 || rc == 137)); then
    printf '%s\t%s\ttimeout (> %s s)\n' "$mod" "$config" "$tlimit" >"$work/$tag.row"
    echo "[$(date +%T)] $spec: timeout after $((t1 - t0)) s" >&2
    return 0
  elif ((rc != 0)) && grep -qsE 'bad_alloc|[Oo]ut of memory|Cannot allocate' "$work/$tag.out" "$work/$tag.log"; then
    printf '%s\t%s\tout of memory (> %s MB)\n' "$mod" "$config" "$mlimit" >"$work/$tag.row"
    echo "[$(date +%T)] $spec: out of memory after $((t1 - t0)) s" >&2
    return 0
  elif ((rc != 0)); then
    local why
    why=$(grep -m1 -E 'ERROR|error' "$work/$tag.log" "$work/$tag.out" 2>/dev/null | cut -c1-120 | tr '\t|' '  ')
    printf '%s\t%s\terror: %s\n' "$mod" "$config" "${why:-exit $rc}" >"$work/$tag.row"
    echo "[$(date +%T)] $spec: FAILED ($why), see $work/$tag.log" >&2
    return 0
  fi
  echo $((t1 - t0)) >"$work/$tag.secs"
  tabulate "$tag" "$mod" "$config" $((t1 - t0))
  echo "[$(date +%T)] $spec: done in $((t1 - t0)) s" >&2
}

# ---- run, at most jobs_max at a time (or -P: tabulate the kept files again) ----
start=$(date +%s)
if [[ -n $reparse ]]; then
  for f in "$work"/*.row; do
    [[ -e $f ]] || continue
    IFS=$'\t' read -r -a fields <"$f"
    tag=$(basename "$f" .row)
    if [[ ${fields[2]} == ok && -e $work/$tag.secs ]]; then
      tabulate "$tag" "${fields[0]}" "${fields[1]}" "$(cat "$work/$tag.secs")"
    fi
  done
  specs=()
fi
[[ -n $reparse ]] || echo "yosys_report: ${#specs[@]} module(s), -j $jobs_max, limit $tlimit s per module, $yosys_version, work dir $work" >&2
for spec in "${specs[@]}"; do
  m=${spec%%:*}
  if ((!defaulted)) && ! grep -qxF -- "$m" <<<"$modules"; then
    echo "yosys_report: unknown module $m (no file of rtl/rpu.f defines it)" >&2
    exit 2
  fi
  if [[ $spec == *:* && ( $spec != *:reduced || -z ${REDUCED[$m]:-} ) ]]; then
    echo "yosys_report: $spec: only ${!REDUCED[*]} have a :reduced configuration" >&2
    exit 2
  fi
done
idx=0
for spec in "${specs[@]}"; do
  idx=$((idx + 1))
  # -H: one module at a time (each runs -j Yosys processes of its own).
  while (($(jobs -rp | wc -l) >= (hier ? 1 : jobs_max))); do wait -n || true; done
  if ((dry)); then run_one "$idx" "$spec"; continue; fi
  run_one "$idx" "$spec" &
done
wait
if ((dry)); then exit 0; fi
elapsed=$(($(date +%s) - start))

# ---- the table ----
md() {
  local h f fields k
  for h in "${header[@]}"; do printf '| %s ' "$h"; done; echo '|'
  for h in "${header[@]}"; do printf -- '|---'; done; echo '|'
  for f in "$work"/*.row; do
    [[ -e $f ]] || continue
    IFS=$'\t' read -r -a fields <"$f"
    printf '| %s | %s ' "${fields[0]}" "${fields[1]}"
    if [[ ${fields[2]} == ok ]]; then
      for ((k = 3; k < ${#header[@]} + 1; k++)); do printf '| %s ' "${fields[k]}"; done
      if [[ -n ${fields[${#header[@]}+1]:-} ]]; then
        echo "yosys_report: ${fields[0]}: other cells: ${fields[${#header[@]}+1]}" >&2
      fi
    else
      printf '| %s ' "${fields[2]}"
      for ((k = 3; k < ${#header[@]}; k++)); do printf '| '; done
    fi
    echo '|'
  done
}
csv() {
  local f fields k n=$((${#header[@]} + 1)) line
  line=$(printf '"%s",' "${header[@]}")
  echo "${line%,}"
  for f in "$work"/*.row; do
    [[ -e $f ]] || continue
    IFS=$'\t' read -r -a fields <"$f"
    if [[ ${fields[2]} != ok ]]; then fields=("${fields[0]}" "${fields[1]}" "" "${fields[2]}"); fi
    line=""
    for ((k = 0; k < n; k++)); do
      ((k == 2)) && continue
      line+="\"${fields[k]:-}\","
    done
    echo "${line%,}"
  done
}
table=$(md)
echo "$table"
if [[ -n $md_out ]]; then echo "$table" >"$md_out"; fi
if [[ -n $csv_out ]]; then csv >"$csv_out"; fi
echo "yosys_report: finished in $elapsed s" >&2
! grep -qs $'\terror:' "$work"/*.row
