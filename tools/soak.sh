#!/usr/bin/env bash
# Soak runs: every shipped scene (tests/soak/runs.txt), coarse, to 4x its end time (or the
# time.end a run of runs.txt sets: until all material has left the domain). Each run must
# finish (exit 0, summary.json "completed") or stop with a clear diagnostic (exit 3, a message
# on stderr, summary.json "failed" with its error, not an "internal error"); a signal, an abort,
# any other status or a hang (past --timeout) fails it. Docs: docs/reliability.md.
#
#   tools/soak.sh [--hvi PATH] [--out DIR] [--timeout S] [--list] [NAME...]
#
# NAMEs select runs (default: all). Writes DIR/<name>/ (the run's folder), DIR/<name>.log (its
# stdout and stderr) and appends one line per run to DIR/tally.tsv. Exit 0 when every selected run
# passed. Run it niced on a shared machine: OMP_NUM_THREADS=1 nice -n 10 tools/soak.sh
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
hvi="$root/build/bin/hvi"
out="$root/build/soak_out"
timeout_s=3600
list=0
names=()
while (($#)); do
  case "$1" in
    --hvi) hvi="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --timeout) timeout_s="$2"; shift 2 ;;
    --list) list=1; shift ;;
    -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
    -*) echo "soak.sh: unknown option $1" >&2; exit 2 ;;
    *) names+=("$1"); shift ;;
  esac
done
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"

trim() { local s="$1"; s="${s#"${s%%[![:space:]]*}"}"; printf '%s' "${s%"${s##*[![:space:]]}"}"; }

# NAME|SCENE|OVERRIDE... lines of runs.txt, comments and blank lines dropped.
runs() { grep -v '^[[:space:]]*#' "$root/tests/soak/runs.txt" | grep -v '^[[:space:]]*$'; }

if ((list)); then
  runs | while IFS='|' read -r name _; do trim "$name"; echo; done
  exit 0
fi
[[ -x "$hvi" ]] || { echo "soak.sh: no hvi binary at $hvi (build it, or pass --hvi)" >&2; exit 2; }
mkdir -p "$out"
[[ -f "$out/tally.tsv" ]] || printf 'name\tverdict\texit\tt_end_us\tt_reached_us\twall_s\tnote\n' >"$out/tally.tsv"

selected() {
  ((${#names[@]} == 0)) && return 0
  local n
  for n in "${names[@]}"; do [[ "$n" == "$1" ]] && return 0; done
  return 1
}

# A key of summary.json (python3 is there: tools/setup.sh installs it for the plots).
summary() {
  python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); v=d.get(sys.argv[2]); print("" if v is None else v)' \
    "$1" "$2" 2>/dev/null
}

pass=0 fail=0 ran=0
while IFS='|' read -r name scene rest; do
  name="$(trim "$name")"; scene="$(trim "$scene")"
  selected "$name" || continue
  args=()
  IFS='|' read -ra ovs <<<"$rest"
  for o in "${ovs[@]}"; do o="$(trim "$o")"; [[ -n "$o" ]] && args+=(--set "$o"); done
  # 4x the end time, from the resolved scene (internal units: us); a run that sets time.end
  # itself (runs until all material has left) keeps it.
  if ! resolved="$("$hvi" check "$root/$scene" "${args[@]}" 2>"$out/$name.log")"; then
    echo "FAIL $name: hvi check refused the run (see $out/$name.log)"
    printf '%s\tFAIL\t%s\t\t\t\tcheck refused\n' "$name" 2 >>"$out/tally.tsv"
    fail=$((fail + 1)); continue
  fi
  read -r t0 t1 < <(awk '/^\[time\]/{s=1;next} /^\[/{s=0} s&&$1=="start"{a=$3} s&&$1=="end"{b=$3} END{print a, b}' <<<"$resolved")
  endset=()
  if [[ "$rest" == *time.end=* ]]; then
    tend="$t1"
  else
    tend="$(python3 -c "print(repr($t0 + 4.0 * ($t1 - $t0)))")"
    endset=(--set "time.end=\"$tend us\"")
  fi
  dir="$out/$name"
  rm -rf "$dir"
  start=$(date +%s.%N)
  # -k: a run that ignores SIGTERM (a hang in a loop without the stop flag) is killed 30 s later.
  timeout -k 30 "$timeout_s" "$hvi" run "$root/$scene" --out "$dir" --quiet "${args[@]}" \
    "${endset[@]}" >"$out/$name.log" 2>&1
  rc=$?
  wall=$(python3 -c "print(round($(date +%s.%N) - $start, 1))")
  ran=$((ran + 1))
  status="" reached="" note=""
  if [[ -f "$dir/summary.json" ]]; then
    status="$(summary "$dir/summary.json" status)"
    reached="$(summary "$dir/summary.json" final_time_us)"
  fi
  verdict=FAIL
  case "$rc" in
    0) if [[ "$status" == completed ]]; then verdict=ok; note="completed"
       else note="exit 0 but summary.json status '$status'"; fi ;;
    3) err="$(summary "$dir/summary.json" error)"
       if [[ "$err" == *"internal error"* ]]; then
         # The driver turns a solver's stray exception into exit 3: a bug, not a diagnostic.
         note="exit 3 from an internal error (a bug): $(tr '\t\n' '  ' <<<"$err" | cut -c1-200)"
       elif [[ "$status" == failed && -n "$err" && -s "$out/$name.log" ]]; then
         verdict=ok; note="exit 3: $(tr '\t\n' '  ' <<<"$err" | cut -c1-200)"
       else note="exit 3 without a full diagnostic (summary status '$status', error '$err')"; fi ;;
    124|137) note="hang: still running after ${timeout_s} s (timeout killed it)" ;;
    *) if ((rc > 128)); then note="killed by signal $((rc - 128)) ($(kill -l $((rc - 128)) 2>/dev/null))"
       else note="unexpected exit status $rc"; fi
       note="$note: $(tail -n 3 "$out/$name.log" | tr '\t\n' '  ' | cut -c1-200)" ;;
  esac
  echo "$([[ $verdict == ok ]] && echo ok || echo FAIL) $name: exit $rc, t = ${reached:-?} of $tend us, ${wall} s: $note"
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$verdict" "$rc" "$tend" "$reached" "$wall" "$note" >>"$out/tally.tsv"
  if [[ $verdict == ok ]]; then pass=$((pass + 1)); else fail=$((fail + 1)); fi
done < <(runs)
echo "soak: $ran runs, $pass passed, $fail failed (tally: $out/tally.tsv)"
((ran + fail > 0)) || { echo "soak: no run matches: ${names[*]}" >&2; exit 2; }
((fail == 0))
