#!/usr/bin/env bash
# Formal checks of the stream and control properties written in the RTL under `ifdef FORMAL
# (docs/verification.md): Yosys (read_verilog -formal, write_smt2) + yosys-smtbmc, no SymbiYosys.
# For each target: bounded model check (BMC) to the target's depth, k-induction where it closes,
# and cover analysis (every cover statement must be reachable: the assumptions are not vacuous).
# The fifo_bug_* targets are mutated copies of rpu_fifo that must FAIL (a counterexample).
# A failing property makes the script exit 1 and print the trace (VCD) file.
#
# Usage: scripts/formal.sh [--smoke] [--out DIR] [--solver S] [target ...]
#   targets: fifo resolve admit admit_p5 admit_p7 top axi fifo_bug_full fifo_bug_stale top_bug_lost
#            axi_bug_payload axi_bug_early_b (default: all)
#   --smoke  the default-CI subset: rpu_top only to a short BMC depth (the full depth covers
#            the reduced pipeline's latency and takes several minutes)
#   --out    output directory (default build/formal): <target>/{model.ys,yosys.log,*.log,*.vcd}
# Solvers: z3 through smtbmc's --unroll for the unit targets (z3 4.8.12 stalls on the
# uninterpreted-state encoding; Debian's boolector 1.5 cannot read smtbmc's SMT-LIB2). rpu_top:
# z3 stalls at its first step, so its BMC and covers run cvc5, and its k-induction runs Yosys's
# own SAT-based `sat -tempinduct` on the same pruned netlist (cvc5 needs minutes per induction
# step, Yosys's SAT solver about a minute for the whole proof). --solver S: S for every target.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
# The design: every file of rtl/rpu.f (read deferred: `hierarchy -top` elaborates the target's
# module and what it instantiates, nothing else).
# shellcheck source=scripts/rtl_files.sh
. scripts/rtl_files.sh
rpu_rtl_read "$root" || exit 2

smoke=0
out=build/formal
solver=""
targets=()
while (($#)); do
  case "$1" in
    --smoke) smoke=1 ;;
    --out) out=$2; shift ;;
    --solver) solver=$2; shift ;;
    -h|--help) sed -n '2,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "$0"; exit 0 ;;
    -*) echo "formal.sh: $1: unknown option" >&2; exit 2 ;;
    *) targets+=("$1") ;;
  esac
  shift
done
((${#targets[@]})) || targets=(fifo resolve admit admit_p5 admit_p7 top axi fifo_bug_full fifo_bug_stale top_bug_lost
                              axi_bug_payload axi_bug_early_b)
for t in yosys yosys-smtbmc ${solver:-z3 cvc5}; do
  command -v "$t" >/dev/null || { echo "formal.sh: $t: not found (scripts/setup.sh)" >&2; exit 2; }
done
mkdir -p "$out"
out=$(cd "$out" && pwd)

# The reduced rpu_top: smallest widths, SqrtW 16 and the squared metric (shorter roots),
# N = N1 = 1 (one IP step), 4 credits, 2-bit ids (ids stay distinct among <= 4 outstanding),
# the narrowest surface search (LW 16, AW 12, 2 turn lanes, one indicator, a one-bit step 1).
top_params="CoordW=12 DirFrac=8 TFrac=8 UnitFrac=8 EdgeFrac=8 InvW=8 SqrtW=16 N=1 N1=1
  Metric=1 Unrolled=1 SegAddrW=1 IdxW=1 IdW=2 PrimW=1 FifoLog2=2 SurfW=16 AngleW=12 Turns=2
  N1First=1 Indicators=1 SurfAddrW=1"
# Datapath outputs: removed from the ports so that their logic leaves the model.
top_cut="res_pred1_o res_hit_o res_depth_o res_tau_o res_t_o res_x_o res_ovf_o res_prim_o
  res_pieces_o pix_hit_o pix_depth_o pix_prim_o"

# The AXI shell rpu_axi (RPU_FORMAL_AXI: rpu_top abstracted to free streams that keep the
# valid/ready rule, rtl/axi/rpu_axi_formal_top.vh) at the reduced widths, on 32-bit streams (the
# result record takes several beats).
axi_params="$(echo $top_params) AxisW=32"

# target -> "module|defines|params|bmc depth|induction depth (0: none)|cover depth|expect"
# Depths: the proof's pipelines are in-order queues of free delay (RPU_FORMAL_TOP), so every kind
# of result is reachable within ten steps; k-induction up to 12 (it closes at 2: with its base
# case that is the proof), the BMC to 12 (sat's base case grows to minutes per step there), the
# covers to 24. --smoke: BMC 6, the induction, covers to 12 (docs/verification.md).
top_bmc=12; top_ind=12; top_cover=24
((smoke)) && { top_bmc=6; top_cover=12; }
declare -A spec=(
  [fifo]="rpu_fifo|RPU_FORMAL_FIFO|Width=2 Log2Depth=2|24|8|12|pass"
  [resolve]="rpu_resolve|RPU_FORMAL_RESOLVE|PixW=2 DepthW=3 PrimW=2|24|8|12|pass"
  [admit]="rpu_surface_admit|RPU_FORMAL_ADMIT|Period=3 Returns=2|24|8|16|pass"
  [admit_p5]="rpu_surface_admit|RPU_FORMAL_ADMIT|Period=5 Returns=6|24|8|40|pass"
  [admit_p7]="rpu_surface_admit|RPU_FORMAL_ADMIT|Period=7 Returns=4|24|8|40|pass"
  [top]="rpu_top|RPU_FORMAL_TOP|$(echo $top_params)|$top_bmc|$top_ind|$top_cover|pass"
  [fifo_bug_full]="rpu_fifo|RPU_FORMAL_FIFO|Width=2 Log2Depth=2|24|0|0|fail"
  [fifo_bug_stale]="rpu_fifo|RPU_FORMAL_FIFO|Width=2 Log2Depth=2|24|0|0|fail"
  [top_bug_lost]="rpu_top|RPU_FORMAL_TOP|$(echo $top_params)|12|0|0|fail"
  [axi]="rpu_axi|RPU_FORMAL_AXI|$axi_params|16|8|16|pass"
  [axi_bug_payload]="rpu_axi|RPU_FORMAL_AXI|$axi_params|12|0|0|fail"
  [axi_bug_early_b]="rpu_axi|RPU_FORMAL_AXI|$axi_params|12|0|0|fail"
)

# Deliberate faults (sed expressions on a copy of rtl/common/rpu_fifo.v):
#   fifo_bug_full:  wr_ready_o always 1: a write while full overwrites the oldest entry.
#   fifo_bug_stale: the output register loads only when taken, not when empty: an entry
#                   arriving at an empty FIFO is announced with the previous entry's data.
#   top_bug_lost:   rpu_top's curve FIFO is also read when a texture result leaves: a curve
#                   result is lost, the next one takes its place (order, exactly once).
#   axi_bug_payload: rpu_axis_scatter (rpu_axi's pixel and result ports) loads a new record
#                   whenever one is offered, also while its beat is held: TDATA changes while
#                   TVALID is held (the AXI4-Stream rule).
#   axi_bug_early_b: rpu_axil_port writes (and answers on B) as soon as AW is taken, without
#                   waiting for W: a response for a request not yet made (AXI4-Lite).
declare -A mutation=(
  [top_bug_lost]="s/rd_ready_i(pop \&\& !head_surf \&\& !head_tex)/rd_ready_i(pop \&\& !head_surf)/"
  [fifo_bug_full]="s/assign wr_ready_o = fill != Depth\[Log2Depth:0\];/assign wr_ready_o = 1'b1;/"
  [fifo_bug_stale]="s/    if (load)  out_q <= mem_q/    if (take)  out_q <= mem_q/"
  [axi_bug_payload]="s/    if (valid_i \&\& ready_o) begin/    if (valid_i) begin/"
  [axi_bug_early_b]="s/  assign wr_o      = aw_full_q \&\& w_full_q \&\& !b_valid_q \&\& !wr_hold_i;/  assign wr_o      = aw_full_q \&\& !b_valid_q \&\& !wr_hold_i;/"
)
# The file each mutation applies to.
declare -A mutated=([top_bug_lost]=rpu_top.v [fifo_bug_full]=rpu_fifo.v [fifo_bug_stale]=rpu_fifo.v
                    [axi_bug_payload]=rpu_axis_scatter.v [axi_bug_early_b]=rpu_axil_port.v)

status=0
summary=()
now() { date +%s.%N; }
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }

# run_smtbmc DIR NAME ARGS...: 0 passed, 1 failed (assert / unreachable cover), 2 error.
run_smtbmc() {
  local dir=$1 name=$2; shift 2
  local rc=0
  yosys-smtbmc -s "$tsolver" --unroll "$@" --dump-vcd "$dir/$name.vcd" "$dir/model.smt2" \
    > "$dir/$name.log" 2>&1 || rc=$?
  if grep -q "Status: PASSED" "$dir/$name.log"; then return 0; fi
  if grep -q "Status: FAILED" "$dir/$name.log"; then return 1; fi
  return 2
}

for t in "${targets[@]}"; do
  [ -n "${spec[$t]+x}" ] || { echo "formal.sh: $t: unknown target" >&2; exit 2; }
  IFS='|' read -r mod defs params bmc ind cov expect <<< "${spec[$t]}"
  tsolver=${solver:-z3}
  [ "$mod" = rpu_top ] && tsolver=${solver:-cvc5}
  dir=$out/$t
  rm -rf "$dir"; mkdir -p "$dir"
  srcs=()
  for f in "${rtl_sources[@]}"; do
    mfile=${mutated[$t]:-}
    if [ -n "${mutation[$t]+x}" ] && [ "$(basename "$f")" = "$mfile" ]; then
      sed "${mutation[$t]}" "$f" > "$dir/$mfile"
      cmp -s "$f" "$dir/$mfile" && { echo "formal.sh: $t: mutation did not apply" >&2; exit 2; }
      srcs+=("$dir/$mfile")
    else
      srcs+=("$f")
    fi
  done
  incs=""
  for d in "${rtl_incdirs[@]}"; do incs+=" -I $d"; done
  defines="-D FORMAL"
  for d in $defs; do defines+=" -D $d"; done
  chparam=""
  for p in $params; do chparam+=" -chparam ${p%%=*} ${p#*=}"; done
  {
    echo "read_verilog -defer -formal -sv $defines$incs ${srcs[*]}"
    echo "hierarchy -check -top $mod$chparam"
    echo "proc"
    echo "flatten"
    if [ "$mod" = rpu_top ]; then
      # Prune the datapath: drop its outputs from the ports, map the FIFO memories to
      # flip-flops and bit-blast the registers and muxes, so that unobserved bits (and with
      # them every multiplier, divider and root) have no reader left.
      cut=""; for o in $top_cut; do cut+=" o:$o"; done
      echo "delete -output$cut"
    fi
    echo "memory_map"
    echo "opt_clean"
    echo "async2sync"
    echo "dffunmap"
    if [ "$mod" = rpu_top ]; then
      echo 'simplemap t:$dff t:$mux t:$pmux t:$and t:$or t:$xor t:$xnor t:$not t:$logic_* t:$reduce_* t:$pos t:$eq t:$ne'
      echo "opt_clean"
      echo "opt -fast -keepdc"
      echo "dffunmap"
      echo "opt_clean"
    fi
    echo "tee -o $dir/stat.txt stat"
    [ "$mod" = rpu_top ] && echo "write_rtlil $dir/model.il"
    echo "write_smt2 -wires $dir/model.smt2"
  } > "$dir/model.ys"
  t0=$(now)
  if ! yosys -q -l "$dir/yosys.log" "$dir/model.ys" > /dev/null 2>&1; then
    echo "FAIL $t: yosys (see $dir/yosys.log)"; grep -i error "$dir/yosys.log" | head -5
    status=1; summary+=("$t: yosys error"); continue
  fi
  t1=$(now)
  cells=$(awk '/Number of cells:/ { n = $4 } END { print n }' "$dir/stat.txt")
  ffs=$(awk '/\$_DFF_|\$dff / { n += $2 } END { print n + 0 }' "$dir/stat.txt")
  result=""
  ok=1
  # BMC (rpu_top: Yosys's sat, the base case of a temporal induction, to depth bmc).
  rc=0
  if [ "$mod" = rpu_top ]; then
    { echo "read_rtlil $dir/model.il"
      echo "chformal -remove -cover"
      echo "setundef -anyseq"
      echo "sat -tempinduct -tempinduct-baseonly -prove-asserts -set-assumes -maxsteps $bmc -dump_vcd $dir/bmc.vcd"
    } > "$dir/bmc.ys"
    yosys -l "$dir/bmc.log" "$dir/bmc.ys" > /dev/null 2>&1 || true
    if grep -q "Base case for induction length $bmc proven" "$dir/bmc.log"; then rc=0
    elif grep -q "model found for base case: FAIL" "$dir/bmc.log"; then
      # sat names no property: the failing step, and the trace.
      k=$(grep -o 'Trying induction with length [0-9]*' "$dir/bmc.log" | tail -1 | grep -o '[0-9]*$')
      echo "Assert failed in rpu_top (Yosys sat names no property) at step $k" >> "$dir/bmc.log"
      rc=1
    else rc=2; fi
  else
    run_smtbmc "$dir" bmc -t "$bmc" || rc=$?
  fi
  t2=$(now)
  if [ "$expect" = fail ]; then
    if ((rc == 1)) && grep -q "Assert failed" "$dir/bmc.log"; then
      result="counterexample as expected ($(grep -m1 'Assert failed' "$dir/bmc.log" | sed 's/.*Assert failed in //'); trace $dir/bmc.vcd)"
    else
      ok=0; result="NO counterexample for an injected fault (bmc rc $rc): $dir/bmc.log"
    fi
  else
    case $rc in
      0) result="BMC $bmc steps passed ($(secs "$t1" "$t2") s)" ;;
      1) ok=0; result="BMC FAILED: $(grep -m1 'Assert failed' "$dir/bmc.log" | sed 's/.*Assert failed in //'); trace $dir/bmc.vcd" ;;
      *) ok=0; result="BMC error: $dir/bmc.log" ;;
    esac
    # k-induction (rpu_top: Yosys's sat -tempinduct, base case and induction step, k up to ind).
    if ((ok && ind > 0)) && [ "$mod" = rpu_top ]; then
      t3=$(now)
      { echo "read_rtlil $dir/model.il"
        echo "chformal -remove -cover"
        echo "setundef -anyseq"
        echo "sat -tempinduct -prove-asserts -set-assumes -maxsteps $ind -dump_vcd $dir/induction.vcd"
      } > "$dir/induction.ys"
      yosys -l "$dir/induction.log" "$dir/induction.ys" > /dev/null 2>&1 || true
      t4=$(now)
      if grep -q "Induction step proven: SUCCESS" "$dir/induction.log"; then
        k=$(grep -o "Trying induction with length [0-9]*" "$dir/induction.log" | tail -1 | grep -o "[0-9]*$")
        result+="; k-induction (Yosys sat) closed at k = $k ($(secs "$t3" "$t4") s)"
      else
        ok=0; result+="; k-induction FAILED within $ind (a base-case failure is a real trace, an induction-step failure a missing invariant): $dir/induction.log, $dir/induction.vcd"
      fi
    elif ((ok && ind > 0)); then
      t3=$(now); rc=0; run_smtbmc "$dir" induction -i -t "$ind" || rc=$?; t4=$(now)
      if ((rc == 0)); then
        # The smallest k that closes, for the report.
        k=1
        while ((k < ind)); do
          yosys-smtbmc -s "$tsolver" --unroll -i -t "$k" "$dir/model.smt2" 2>&1 |
            grep -q "Status: PASSED" && break
          k=$((k + 1))
        done
        result+="; induction closed at k = $k ($(secs "$t3" "$t4") s)"
      else
        ok=0; result+="; induction FAILED within $ind: $(grep -m1 'Assert failed' "$dir/induction.log" | sed 's/.*Assert failed in //'); trace $dir/induction.vcd"
      fi
    fi
    # Covers: every cover statement reachable.
    if ((ok && cov > 0)); then
      t5=$(now); rc=0; run_smtbmc "$dir" cover -c -t "$cov" || rc=$?; t6=$(now)
      steps=$(grep -o "Reached cover statement.* in step [0-9]*" "$dir/cover.log" |
              sed 's/.*in step //' | sort -n | tr '\n' ' ')
      if ((rc == 0)); then
        result+="; all covers reached (steps ${steps% }; $(secs "$t5" "$t6") s)"
      else
        ok=0; result+="; COVER FAILED (unreached or assert): $dir/cover.log"
      fi
    fi
  fi
  total=$(secs "$t0" "$(now)")
  if ((ok)); then
    echo "ok   $t [$mod, $cells cells, $ffs FF cells]: $result; total $total s"
  else
    echo "FAIL $t [$mod]: $result"
    status=1
  fi
done
exit $status
