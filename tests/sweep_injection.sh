#!/bin/sh
# rpu sweep against hostile paths (issue 11, item 1). The sweep file, a scene and the output
# directories live under a directory named  x'$(touch PWNED)' sp<newline>nl<byte 0xff>  and the
# scene file is named  sc'$(touch PWNED)' e<newline>.json:
#   1. a sweep runs (exit 0) and its results.csv quotes the scene's columns;
#   2. --emit-jobs: every line of jobs.txt run by `sh -c` exits 0 and stores its result, and
#      merge.sh collects both rows;
#   3. with Yosys: rpu is killed by SIGTERM, then SIGINT, while Yosys runs; rpu dies of that
#      signal, and none of its children (scripts/synth_hier.py, its Yosys runs) outlives it;
#   and no PWNED file appears anywhere.
# Usage: sweep_injection.sh RPU SCENE.json WORK_DIR
set -u
rpu=$1 scene=$2 base=$3

fail() {
  echo "FAILED: $*" >&2
  exit 1
}

rm -rf "$base"
mkdir -p "$base/cwd" || fail "cannot create $base"
cd "$base/cwd" || fail "cannot enter $base/cwd"
weird=$(printf "x'\$(touch PWNED)' sp\nnl\377")
dir=$base/$weird
mkdir -p "$dir" || fail "cannot create the hostile directory"
cp "$scene" "$dir/$(printf "sc'\$(touch PWNED)' e\n.json")" || fail "cannot copy the scene"
# The scene path is relative to the sweep file's directory, so it holds every hostile byte.
# shellcheck disable=SC2016  # $(…) is data here
printf '%s\n' '{"scenes": ["sc'"'"'$(touch PWNED)'"'"' e\n.json", "builtin:curve12"],' \
  '"resolution": [8, 8], "grid": {"n": [8, 16]}, "rtl": false,' \
  '"yosys": {"enabled": true, "module": "rpu_ip_step", "timeout": 600}}' >"$dir/sweep.json"

no_pwned() {
  found=$(find "$base" -name PWNED | head -1)
  [ -z "$found" ] || fail "a command was injected ($1): $found"
  [ ! -e PWNED ] || fail "a command was injected ($1) into the working directory"
}

# 1. A whole sweep.
"$rpu" sweep "$dir/sweep.json" --out "$dir/out" --no-yosys || fail "the sweep exited $?"
no_pwned "sweep"
header=$(head -c 2000 "$dir/out/results.csv")
case $header in
  *",\"sc'\$(touch PWNED)' e
_ref_vs_float_ip\",\"sc'\$(touch PWNED)' e
_ref_vs_float\",curve12_ref_vs_float_ip,"*) ;;
  *) fail "results.csv does not quote the scene's columns: $header" ;;
esac

# 2. The emitted jobs, one line each through sh, and merge.sh.
"$rpu" sweep "$dir/sweep.json" --out "$dir/jobs" --no-yosys --emit-jobs || fail "--emit-jobs exited $?"
lines=0
while IFS= read -r line; do
  lines=$((lines + 1))
  sh -c "$line" || fail "jobs.txt line $lines exited $?: $line"
done <"$dir/jobs/jobs.txt"
[ "$lines" -eq 2 ] || fail "jobs.txt has $lines lines, expected 2"
# (one character per file: the paths hold newlines)
[ "$(find "$dir/jobs/configs" -name '*.json' -exec printf x \; | wc -c)" -eq 2 ] ||
  fail "the jobs did not store 2 results"
sh "$dir/jobs/merge.sh" || fail "merge.sh exited $?"
[ "$(grep -c '^[0-9a-f]*,ok,' "$dir/jobs/results.csv")" -eq 2 ] || fail "merge.sh did not collect 2 ok rows"
no_pwned "jobs"

# 3. Killing rpu while Yosys runs (rpu_ip_step takes minutes; it is killed at once).
# From /proc only (procps may be missing); a stat line is "pid (comm) state ppid ...".
descendants() {  # every process below pid $1
  cat /proc/[0-9]*/stat 2>/dev/null | awk -v root="$1" '
    { pid = $1; rest = $0; sub(/.*\) /, "", rest); split(rest, f, " "); parent[pid] = f[2] }
    END { for (p in parent) { q = p; while ((q in parent) && q != root && q > 1) q = parent[q];
                              if (q == root && p != root) print p } }'
}
alive() {  # running (not a zombie)
  [ -r "/proc/$1/stat" ] && ! sed 's/.*) //' "/proc/$1/stat" 2>/dev/null | grep -q '^Z'
}
for sig in TERM INT; do
  # A background job of sh starts with SIGINT ignored; env restores the default.
  env --default-signal=INT,TERM "$rpu" sweep "$dir/sweep.json" --out "$dir/kill_$sig" -j 1 \
    2>"$base/kill_$sig.log" &
  pid=$!
  kids="" t=0
  while [ $t -lt 600 ]; do  # up to 60 s for Yosys to start
    kids=$(descendants $pid)
    for k in $kids; do
      [ "$(cat "/proc/$k/comm" 2>/dev/null)" = yosys ] && break 2
    done
    kill -0 $pid 2>/dev/null || break
    sleep 0.1
    t=$((t + 1))
  done
  echo "SIG$sig: rpu $pid, children:" $kids >&2
  [ -n "$kids" ] || fail "SIG$sig: no Yosys child started (see $base/kill_$sig.log)"
  ls "$dir/kill_$sig/yosys_cache/runs/"*.log >/dev/null 2>&1 ||
    fail "SIG$sig: the Yosys report did not get its hostile output path"
  kill -s "$sig" $pid
  wait $pid
  rc=$?
  case $sig in TERM) want=143 ;; INT) want=130 ;; esac
  [ $rc -eq $want ] || fail "SIG$sig: rpu exited $rc, expected $want (ended by the signal)"
  t=0
  while [ $t -lt 150 ]; do  # up to 15 s for the children to end
    left=""
    for k in $kids; do alive "$k" && left="$left $k"; done
    [ -z "$left" ] && break
    sleep 0.1
    t=$((t + 1))
  done
  [ -z "$left" ] || {
    for k in $left; do echo "left: $k $(tr '\0' ' ' <"/proc/$k/cmdline")" >&2; done
    kill -s KILL $left 2>/dev/null
    fail "SIG$sig: children outlived rpu:$left"
  }
done
no_pwned "yosys"
echo "sweep_injection: ok"
