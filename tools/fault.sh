#!/usr/bin/env bash
# Fault experiments on `hvi run` (docs/reliability.md): SIGKILL at random moments, disk full,
# read-only folder, two runs into one folder, hostile inputs. Each check prints "ok" or "FAIL"
# with what it saw; the last line is the tally. Exit 0 when every check passed.
#
#   tools/fault.sh [--hvi PATH] [--work DIR] [--kills N] [--seed S] [SECTION...]
#
# SECTIONs: kill diskfull readonly concurrent badinput (default: all). diskfull and readonly
# mount small tmpfs folders (root); where mount is refused they are skipped with a message.
# What the checks hold the program to (README, issue 11): a killed run leaves every snapshot
# readable and --restart reproduces the uninterrupted run bit for bit; a full disk is exit 4
# (the cause named, the printed --restart command continues the run once there is room), a
# read-only folder exit 2 (or 4 if found at a write), and neither loses anything written
# before; a second run into a folder in use is refused with exit 2 and the first finishes
# untouched; bad input is exit 2 with a message, never a signal or a hang.
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
hvi="$root/build/bin/hvi"
work="$root/build/fault_out"
kills=20
seed=$$
sections=()
while (($#)); do
  case "$1" in
    --hvi) hvi="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    --kills) kills="$2"; shift 2 ;;
    --seed) seed="$2"; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    -*) echo "fault.sh: unknown option $1" >&2; exit 2 ;;
    *) sections+=("$1"); shift ;;
  esac
done
((${#sections[@]})) || sections=(kill diskfull readonly concurrent badinput)
[[ -x "$hvi" ]] || { echo "fault.sh: no hvi binary at $hvi (build it, or pass --hvi)" >&2; exit 2; }
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"
RANDOM=$seed
mkdir -p "$work"
work="$(cd "$work" && pwd)"
mounts=()
cleanup() { local m; for m in "${mounts[@]}"; do umount "$m" 2>/dev/null; done; }
trap cleanup EXIT

npass=0 nfail=0 nskip=0
declare -A tally
ok() { echo "ok   $*"; npass=$((npass + 1)); }
bad() { echo "FAIL $*"; nfail=$((nfail + 1)); }
skip() { echo "skip $*"; nskip=$((nskip + 1)); }
count() { tally[$1]=$((${tally[$1]:-0} + 1)); }
check() { local what="$1"; shift; if "$@"; then ok "$what"; else bad "$what"; fi; }

# The test run: Sod's tube with TVD to 0.8 us, a snapshot every 0.05 us (16 snapshots and
# checkpoints, a few seconds on one core). B: another solver, for mixed-folder checks.
scene="$root/cases/scenes/sod_x.toml"
A=(--set solver=tvd --set 'time.end="0.8 us"'
   --set 'output.times=["0.05 us","0.1 us","0.15 us","0.2 us","0.25 us","0.3 us","0.35 us","0.4 us","0.45 us","0.5 us","0.55 us","0.6 us","0.65 us","0.7 us","0.75 us","0.8 us"]')
B=(--set solver=sph)  # the scene's own 0.2 us (to 0.8 us SPH's Sod can stop with exit 3)

js() {  # js FILE KEY: a top-level key of a JSON file
  python3 -c 'import json,sys; v=json.load(open(sys.argv[1])).get(sys.argv[2]); print("" if v is None else v)' "$1" "$2" 2>/dev/null
}
# Readable by the project's own reader: hvi compare of a snapshot with itself.
readable() { "$hvi" compare "$1" "$1" --quiet --out "$work/.cmp" >/dev/null 2>&1; }
all_readable() {  # all_readable DIR: every snap_*.h5 (and failed_*.h5) reads
  local f n=0
  for f in "$1"/snap_*.h5 "$1"/failed_*.h5; do
    [[ -e "$f" ]] || continue
    n=$((n + 1))
    readable "$f" || { echo "     unreadable: $f"; return 1; }
  done
  return 0
}
# The last snapshot of DIR equals that of the reference run bit for bit in density (the
# restart promise): compare with a zero density threshold, same final time and step count.
same_as_ref() {
  local d="$1" ref="$work/ref"
  [[ "$(js "$d/summary.json" steps)" == "$(js "$ref/summary.json" steps)" ]] || { echo "     steps $(js "$d/summary.json" steps) vs $(js "$ref/summary.json" steps)"; return 1; }
  "$hvi" compare "$d" "$ref" --quiet --out "$work/.cmp" --max-density-l1 0 >/dev/null 2>&1
}
files_of() { (cd "$1" && find . -type f ! -name '.*' | sort); }
sums_of() { (cd "$1" && find . -type f ! -name '.*' -print0 | sort -z | xargs -0 md5sum); }
kept() {  # kept LISTING DIR: every file of an earlier files_of listing is still in DIR
  [[ -z "$1" ]] || ! comm -23 <(printf '%s\n' "$1") <(files_of "$2") | grep -q .
}
no_temp_files() { ! find "$1" -name '.*.tmp*' | grep -q .; }
is_signal() { (($1 > 128 && $1 != 130)); }
has_overwrite() { "$hvi" run --help 2>&1 | grep -q -- --overwrite; }

ensure_ref() {
  [[ -f "$work/ref/summary.json" && -f "$work/refB/summary.json" ]] && return 0
  rm -rf "$work/ref" "$work/refB"
  "$hvi" run "$scene" --out "$work/ref" --quiet "${A[@]}" >/dev/null 2>&1 &&
    "$hvi" run "$scene" --out "$work/refB" --quiet "${B[@]}" >/dev/null 2>&1 ||
    { echo "fault.sh: the reference runs failed" >&2; exit 1; }
  count runs; count runs
}

try_mount() {  # try_mount DIR SIZE [ro]: a fresh tmpfs; false if mount is refused
  mkdir -p "$1"
  umount "$1" 2>/dev/null
  mount -t tmpfs -o "size=$2${3:+,$3}" tmpfs "$1" 2>/dev/null || return 1
  mounts+=("$1")
}

section_kill() {
  ensure_ref
  local t0 t1 wall k ms d rc before
  t0=$(date +%s%N); "$hvi" run "$scene" --out "$work/timing" --quiet "${A[@]}" >/dev/null 2>&1
  t1=$(date +%s%N); wall=$(((t1 - t0) / 1000000)); count runs
  echo "--- kill: $kills SIGKILLs at random moments of a ${wall} ms run"
  for ((k = 1; k <= kills; k++)); do
    ms=$((RANDOM * RANDOM % (wall + 1)))
    # The machine's load changes: where the run had ended before the kill, try again at half
    # the moment (up to 4 times), so that each of the N is a real kill.
    local try
    for ((try = 0; try < 4; try++)); do
      d="$work/kill_$k"; rm -rf "$d"
      "$hvi" run "$scene" --out "$d" --quiet "${A[@]}" >/dev/null 2>&1 &
      local pid=$!
      sleep "$(printf '%d.%03d' $((ms / 1000)) $((ms % 1000)))"
      before="$( [[ -d "$d" ]] && files_of "$d")"
      kill -9 "$pid" 2>/dev/null; wait "$pid" 2>/dev/null; rc=$?
      count runs
      ((rc == 137)) && break
      ms=$((ms / 2))
    done
    if ((rc != 137)); then skip "kill $k: the run had ended each time (exit $rc)"; continue; fi
    count kills
    check "kill $k at ${ms} ms: every snapshot readable" all_readable "$d"
    if [[ -f "$d/checkpoint.bin" ]]; then
      "$hvi" run "$scene" --out "$d" --quiet --restart "${A[@]}" >"$d.restart.log" 2>&1; rc=$?
      count runs
      check "kill $k: --restart exits 0 (got $rc)" test "$rc" -eq 0
      check "kill $k: restarted run equals the uninterrupted one bit for bit" same_as_ref "$d"
      check "kill $k: nothing written before the kill is lost" kept "$before" "$d"
      check "kill $k: every snapshot readable after the restart" all_readable "$d"
      check "kill $k: no temporary file left after the restart" no_temp_files "$d"
    else
      # Killed before the first checkpoint: --restart must refuse clearly, a new run must work.
      "$hvi" run "$scene" --out "$d" --quiet --restart "${A[@]}" >"$d.restart.log" 2>&1; rc=$?
      count runs
      check "kill $k (before any checkpoint): --restart refused with exit 2 (got $rc)" test "$rc" -eq 2
      local again=()
      has_overwrite && again=(--overwrite)
      "$hvi" run "$scene" --out "$d" --quiet "${again[@]}" "${A[@]}" >"$d.rerun.log" 2>&1; rc=$?
      count runs
      check "kill $k: a new run into the folder exits 0 (got $rc)" test "$rc" -eq 0
      check "kill $k: the new run equals the reference" same_as_ref "$d"
    fi
  done
}

section_diskfull() {
  ensure_ref
  local d="$work/full" size rc log
  size=$(du -sk "$work/ref" | cut -f1)
  echo "--- diskfull: the run needs ${size} KiB"
  if ! try_mount "$d" "$((size * 2 / 5))k"; then skip "diskfull: mount -t tmpfs refused"; return; fi
  "$hvi" run "$scene" --out "$d/run" --quiet "${A[@]}" >"$work/full.log" 2>&1; rc=$?
  count runs; count diskfull
  check "diskfull mid-run: exit 4, output could not be written (got $rc)" test "$rc" -eq 4
  check "diskfull mid-run: the message names the cause" grep -qi "no space left" "$work/full.log"
  check "diskfull mid-run: every snapshot written is readable" all_readable "$d/run"
  if [[ -f "$d/run/checkpoint.bin" ]]; then
    mount -o remount,size=$((size * 4))k "$d"
    # The command the run printed to continue (README: exit 4), else the one we know.
    local hint
    hint="$(grep -o 'continue with `[^`]*`' "$work/full.log" | tail -n1 | sed 's/^continue with `//; s/`$//')"
    check "diskfull: the run printed the command that continues it" test -n "$hint"
    if [[ -n "$hint" ]]; then
      eval "$hint --quiet" >"$work/full.restart.log" 2>&1; rc=$?
    else
      "$hvi" run "$scene" --out "$d/run" --quiet --restart "${A[@]}" >"$work/full.restart.log" 2>&1; rc=$?
    fi
    count runs
    check "diskfull: after freeing space the printed --restart command exits 0 (got $rc)" test "$rc" -eq 0
    check "diskfull: the restarted run equals the reference" same_as_ref "$d/run"
  else
    bad "diskfull: no checkpoint survived (the run had $((size * 2 / 5)) KiB of ${size})"
  fi
  # Full from the first byte.
  umount "$d"; try_mount "$d" 8k || return
  "$hvi" run "$scene" --out "$d/run" --quiet "${A[@]}" >"$work/full0.log" 2>&1; rc=$?
  count runs; count diskfull
  check "diskfull at start: exit 4, or 2 if the folder check refuses it (got $rc)" test "$rc" -eq 4 -o "$rc" -eq 2
  check "diskfull at start: the message names the cause" grep -qi "no space left" "$work/full0.log"
}

section_readonly() {
  ensure_ref
  local d="$work/ro" rc sums
  echo "--- readonly"
  if ! try_mount "$d" 64m; then skip "readonly: mount -t tmpfs refused"; return; fi
  # A run stopped half-way (a checkpoint to restart from), then the folder turns read-only.
  "$hvi" run "$scene" --out "$d/run" --quiet --stop-after 60 "${A[@]}" >/dev/null 2>&1; rc=$?
  count runs
  check "readonly: --stop-after 60 stops with exit 130 and a checkpoint (got $rc)" test "$rc" -eq 130 -a -f "$d/run/checkpoint.bin"
  sums="$(sums_of "$d/run")"
  mount -o remount,ro "$d"
  "$hvi" run "$scene" --out "$d/run" --quiet --restart "${A[@]}" >"$work/ro.restart.log" 2>&1; rc=$?
  count runs; count readonly
  check "readonly: --restart into a read-only folder is exit 2 (folder check) or 4 (write failed) (got $rc)" test "$rc" -eq 2 -o "$rc" -eq 4
  check "readonly: the message names the cause" grep -qi "read-only" "$work/ro.restart.log"
  "$hvi" run "$scene" --out "$d/new" --quiet "${A[@]}" >"$work/ro.new.log" 2>&1; rc=$?
  count runs; count readonly
  check "readonly: a new folder on a read-only mount is exit 2 (got $rc)" test "$rc" -eq 2
  check "readonly: nothing in the folder changed" test "$sums" == "$(sums_of "$d/run")"
  mount -o remount,rw "$d"
  "$hvi" run "$scene" --out "$d/run" --quiet --restart "${A[@]}" >/dev/null 2>&1; rc=$?
  count runs
  check "readonly: writable again, --restart exits 0 (got $rc)" test "$rc" -eq 0
  check "readonly: the restarted run equals the reference" same_as_ref "$d/run"
}

section_concurrent() {
  ensure_ref
  local d="$work/conc" rcA rcB pid i
  echo "--- concurrent: a second run into a folder in use, and into a finished run's folder"
  for second in plain overwrite; do
    local extra=()
    if [[ $second == overwrite ]]; then
      has_overwrite || { skip "concurrent: hvi run has no --overwrite"; continue; }
      extra=(--overwrite)
    fi
    rm -rf "$d"
    "$hvi" run "$scene" --out "$d" --quiet "${A[@]}" >"$work/conc.A.log" 2>&1 &
    pid=$!
    for ((i = 0; i < 500; i++)); do [[ -e "$d/scene.toml" ]] && break; sleep 0.01; done
    "$hvi" run "$scene" --out "$d" --quiet "${extra[@]}" "${B[@]}" >"$work/conc.B.log" 2>&1; rcB=$?
    local aliveB=0; kill -0 "$pid" 2>/dev/null && aliveB=1
    wait "$pid"; rcA=$?
    count runs; count runs; count concurrent
    check "concurrent ($second): the first run was still running when the second ended" test "$aliveB" -eq 1
    check "concurrent ($second): the second run is refused with exit 2 (got $rcB)" test "$rcB" -eq 2
    check "concurrent ($second): the first run exits 0 (got $rcA)" test "$rcA" -eq 0
    check "concurrent ($second): the folder holds the first run's files, no other" test "$(files_of "$d")" == "$(files_of "$work/ref")"
    check "concurrent ($second): summary.json is the first run's (tvd)" test "$(js "$d/summary.json" solver)" == tvd
    check "concurrent ($second): the first run equals the reference" same_as_ref "$d"
    check "concurrent ($second): every snapshot readable" all_readable "$d"
  done
  # Stale results: a finished run's folder is refused without --overwrite, cleared with it.
  local sums; sums="$(sums_of "$d")"
  "$hvi" run "$scene" --out "$d" --quiet "${B[@]}" >"$work/stale.log" 2>&1; rcB=$?
  count runs; count concurrent
  check "stale: a run into another run's folder is refused with exit 2 (got $rcB)" test "$rcB" -eq 2
  check "stale: the refused run changed nothing" test "$sums" == "$(sums_of "$d")"
  if has_overwrite; then
    "$hvi" run "$scene" --out "$d" --quiet --overwrite "${B[@]}" >"$work/stale.ow.log" 2>&1; rcB=$?
    count runs
    check "stale: --overwrite runs (exit $rcB)" test "$rcB" -eq 0
    check "stale: after --overwrite only the new run's files are there" test "$(files_of "$d")" == "$(files_of "$work/refB")"
  else
    skip "stale: hvi run has no --overwrite"
  fi
}

section_badinput() {
  local d="$work/bad" rc f n=0
  echo "--- badinput: hostile --out paths and scene files, tests/scenes/bad/*.toml"
  rm -rf "$d"; mkdir -p "$d"
  : >"$d/a_file"
  mkfifo "$d/fifo"
  : >"$d/empty.toml"
  expect2() {  # expect2 WHAT CMD...: exit 2 with a message, within 20 s
    local what="$1" out; shift
    out="$(timeout -k 5 20 "$@" 2>&1 >/dev/null)"; rc=$?
    count badinputs
    if ((rc == 124)); then bad "$what: hangs (killed after 20 s)"
    elif is_signal "$rc"; then bad "$what: signal, exit $rc: $(tail -n1 <<<"$out")"
    elif ((rc != 2)); then bad "$what: exit $rc, expected 2: $(tail -n1 <<<"$out")"
    elif [[ -z "$out" ]]; then bad "$what: exit 2 without a message"
    else ok "$what: exit 2"; fi
  }
  for out in "$d/a_file" "$d/a_file/below" /proc/hvi_x /dev/null ""; do
    expect2 "--out '$out'" "$hvi" run "$scene" --out "$out" --quiet "${A[@]}"
  done
  for s in /dev/zero /dev/urandom /dev/null "$d/fifo" "$d" "$d/missing.toml" "$d/empty.toml"; do
    expect2 "check '$s'" "$hvi" check "$s"
  done
  for f in "$root"/tests/scenes/bad/*.toml; do
    # "# set: key=value" headers: the override that breaks the scene (tests/unit/cases).
    local sets=() l
    while IFS= read -r l; do sets+=(--set "${l#\# set: }"); done < <(grep '^# set: ' "$f")
    expect2 "check bad/$(basename "$f")" "$hvi" check "$f" "${sets[@]}"
  done
  expect2 "check with --set time.start=\"1e20 us\"" "$hvi" check "$scene" --set 'time.start="1e20 us"' --set 'time.end="100000000000000000001 us"'
  expect2 "run --stop-after -1" "$hvi" run "$scene" --out "$d/stop" --stop-after -1 "${A[@]}"
  expect2 "run --restart --out MISSING" "$hvi" run "$scene" --out "$d/missing_run" --restart "${A[@]}"
  check "run --restart --out MISSING did not create the folder" test ! -e "$d/missing_run"
  expect2 "hvi frobnicate" "$hvi" frobnicate
}

for s in "${sections[@]}"; do
  case "$s" in
    kill|diskfull|readonly|concurrent|badinput) "section_$s" ;;
    *) echo "fault.sh: unknown section $s" >&2; exit 2 ;;
  esac
done
echo "fault: ${tally[runs]:-0} runs, ${tally[kills]:-0} kills, ${tally[diskfull]:-0} disk-full runs," \
  "${tally[readonly]:-0} read-only runs, ${tally[concurrent]:-0} concurrent/stale runs," \
  "${tally[badinputs]:-0} bad inputs; checks: $npass ok, $nfail failed, $nskip skipped"
((nfail == 0))
