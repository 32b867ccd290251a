#!/usr/bin/env bash
# Fuzzes Objektiv's readers of user files with the libFuzzer harnesses in fuzz/ (clang,
# AddressSanitizer + UndefinedBehaviorSanitizer), for as long as asked.
#
#   scripts/fuzz.sh [--time SECONDS] [--jobs N] [--corpus DIR] [--build DIR] [HARNESS...]
#
#   --time    seconds per harness (default 3600)
#   --jobs    harnesses fuzzed at once, one process each (default 1)
#   --corpus  where the corpus grows, kept between runs (default $OBJEKTIV_FUZZ_DIR or
#             ~/.cache/objektiv-fuzz): DIR/HARNESS/ the corpus, DIR/logs/, DIR/artifacts/
#   --build   the fuzz build folder (default build-fuzz; configured and built if needed)
#   HARNESS   names from fuzz/CMakeLists.txt (default: all)
#
# Each harness starts from its corpus plus seeds gathered from the project's own files
# (scenes, lenses, cut-down glass catalogs, meshes, small images) and fuzz/seeds/HARNESS,
# with the dictionary fuzz/dict/HARNESS.dict. An input that crashes, trips a sanitizer, runs
# over 60 s (wall clock: a realistic camera with blades and a mask sets up in about 6 s of CPU
# under the sanitizers, and a niced fuzzer on a busy machine gets a fraction of a core) or
# allocates over 2 GiB is a finding: it is minimised, copied into
# fuzz/regressions/HARNESS/ (one per distinct report; the test suite replays that folder), and
# the harness goes on fuzzing for the rest of its time. Ends with a table of each harness's
# executions, per second and per CPU second; exits 1 if anything was found.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

time_per=3600
jobs=1
corpus_root=${OBJEKTIV_FUZZ_DIR:-$HOME/.cache/objektiv-fuzz}
build=build-fuzz
harnesses=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --time) time_per=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --corpus) corpus_root=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    -h|--help) sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "fuzz: unknown option $1" >&2; exit 2 ;;
    *) harnesses+=("$1"); shift ;;
  esac
done
all=$(sed -n 's/^set(OBJEKTIV_FUZZERS \(.*\))$/\1/p' fuzz/CMakeLists.txt)
[[ ${#harnesses[@]} -eq 0 ]] && read -ra harnesses <<< "$all"
for h in "${harnesses[@]}"; do
  [[ " $all " == *" $h "* ]] || { echo "fuzz: no harness '$h' (harnesses: $all)" >&2; exit 2; }
done
mkdir -p "$corpus_root"
corpus_root=$(cd "$corpus_root" && pwd)

# --- build ------------------------------------------------------------------------------
scripts/setup.sh --sanitizers
if [[ ! -f $build/CMakeCache.txt ]]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ -DOBJEKTIV_FUZZ=ON \
    -DOBJEKTIV_BUILD_BENCH=OFF -DOBJEKTIV_ARCH="${OBJEKTIV_ARCH:-x86-64-v3}" >/dev/null
fi
cmake --build "$build" -j "$(nproc 2>/dev/null || echo 2)" --target "${harnesses[@]/#/fuzz_}"

# --- seeds: the project's own files, small ones or cut down --------------------------------
seeds=$build/fuzz-seeds
rm -rf "$seeds"
seed() {  # seed HARNESS FILE...: copies the files (at most 64 KiB each) into the harness's seeds
  local h=$1; shift
  mkdir -p "$seeds/$h"
  for f in "$@"; do
    [[ -f $f && $(stat -c %s "$f") -le 65536 ]] && cp "$f" "$seeds/$h/$(echo "${f#./}" | tr / _)"
  done
  return 0
}
shopt -s nullglob
seed scene scenes/*/*.xml fuzz/seeds/scene/*
seed lens_native data/lenses/*.lens fuzz/seeds/lens_native/*
seed lens_pbrt data/lenses/*.dat fuzz/seeds/lens_pbrt/*
seed lens_zemax fuzz/seeds/lens_zemax/*
seed agf fuzz/seeds/agf/*
for f in data/glass/*.AGF; do  # each catalog's first three glasses
  awk '$1 == "NM" && ++n > 3 { exit } { print }' "$f" > "$seeds/agf/$(basename "$f").head"
done
seed mesh_obj scenes/*/*.obj fuzz/seeds/mesh_obj/*
seed mesh_ply scenes/*/*.ply fuzz/seeds/mesh_ply/* fuzz/scene_assets/*.ply
seed image scenes/*/*.png scenes/*/*.exr fuzz/seeds/image/* fuzz/scene_assets/*.png
seed render_part fuzz/seeds/render_part/*
shopt -u nullglob

# --- fuzzing ----------------------------------------------------------------------------
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:symbolize=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/fuzz/lsan.supp:print_suppressions=0}

# One line naming a finding, to tell findings apart: the report's kind, and where: for an abort
# the exception that escaped or the message printed just before (an assertion, a harness
# check), else the first frame in Objektiv's own code, else the first library in the stack.
finding_key() {
  local log=$1 summary kind where
  summary=$(grep -m1 '^SUMMARY: ' "$log" || true)
  case $summary in
    *leaked*) kind="LeakSanitizer: leak" ;;
    "") kind=$(grep -m1 -oE 'ERROR: libFuzzer: [a-z -]+' "$log" || echo "no report") ;;
    *) kind=$(sed -E "s|^SUMMARY: ||; s| in .*||; s|\(.*||; s|0x[0-9a-f]+||g; s|$root/||g" <<< "$summary") ;;
  esac
  if [[ $kind == *"deadly signal"* ]]; then
    where=$(grep -m1 -oE "terminate called after throwing an instance of '[^']+'" "$log" || true)
    [[ -z $where ]] && where=$(grep -B1 -m1 'ERROR: libFuzzer: deadly signal' "$log" | head -1 | tr -d '0-9')
  else
    where=$(grep -m1 -oE "$root/(src|fuzz)/[^ :]+\.cpp:[0-9]+" "$log" | sed "s|$root/||" || true)
    [[ -z $where ]] && where=$(grep -m1 -oE '/[^ ()]*/lib[^ ()/]*\.so[.0-9]*' "$log" || true)
  fi
  echo "$kind @ ${where:-?}"
}

# fuzz_one HARNESS: fuzzes for time_per seconds, restarting after each finding; writes
# "HARNESS SECONDS EXECS FINDINGS CPU_SECONDS" to DIR/logs/HARNESS.stats.
fuzz_one() {
  local h=$1 bin=$root/$build/fuzz/fuzz_$1
  local corpus=$corpus_root/$h art=$corpus_root/artifacts/$h logs=$corpus_root/logs
  local keys=$corpus_root/logs/$h.findings regressions=$root/fuzz/regressions/$h
  mkdir -p "$corpus" "$art" "$logs"
  touch "$keys"
  local dict=() && [[ -f fuzz/dict/$h.dict ]] && dict=(-dict="$root/fuzz/dict/$h.dict")
  local start=$SECONDS end=$((SECONDS + time_per)) execs=0 run=0
  local -A found=()  # the distinct findings of this run
  while (( SECONDS < end )); do
    local log=$logs/$h.$run.log rc=0
    "$bin" "$corpus" "$seeds/$h" "${dict[@]}" -max_total_time=$((end - SECONDS)) -timeout=60 \
      -rss_limit_mb=4096 -malloc_limit_mb=2048 -artifact_prefix="$art/" -print_final_stats=1 >"$log" 2>&1 || rc=$?
    execs=$((execs + $(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1 | grep . || echo 0)))
    run=$((run + 1))
    (( rc == 0 )) && break
    local input
    input=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -1)
    if [[ -z $input || ! -f $input ]]; then
      echo "fuzz: $h stopped (exit $rc) without a test unit; see $log" >&2
      found[stopped]=1
      break
    fi
    local key
    key=$(finding_key "$log")
    found["$key"]=1
    if grep -qxF "$key" "$keys"; then
      rm -f "$log" "$input"  # found before
    else
      echo "$key" >> "$keys"
      local kind name
      kind=$(basename "$input" | cut -d- -f1)
      name=$kind-$(sha1sum "$input" | cut -c1-12)
      mkdir -p "$regressions"
      if [[ $kind == crash ]] && timeout 120 "$bin" -minimize_crash=1 -max_total_time=60 -timeout=60 \
          -exact_artifact_path="$art/$name.min" "$input" >"$logs/$h.minimize.log" 2>&1 && [[ -s $art/$name.min ]]; then
        cp "$art/$name.min" "$regressions/$name"
      else
        cp "$input" "$regressions/$name"
      fi
      echo "fuzz: $h: new finding: $key -> fuzz/regressions/$h/$name" >&2
      echo "      reproduce: $build/fuzz/fuzz_$h fuzz/regressions/$h/$name  (log: $log)" >&2
    fi
  done
  # The fuzzers' CPU time (user + system, from the shell's `times`): on a busy machine, or
  # niced, executions per CPU second say what a machine of one's own would reach.
  # `times` itself, not in a pipe or $(...): a forked shell starts with no children's time.
  times > "$logs/$h.times"
  local cpu
  cpu=$(awk 'NR == 2 { t = 0; for (i = 1; i <= 2; ++i) { split($i, p, /[ms]/); t += 60 * p[1] + p[2] } printf "%d", t }' "$logs/$h.times")
  echo "$h $((SECONDS - start)) $execs ${#found[@]} $cpu" > "$logs/$h.stats"
  for key in "${!found[@]}"; do echo "$key"; done > "$logs/$h.found"
}

echo "fuzz: ${#harnesses[@]} harnesses, ${time_per} s each, $jobs at a time; corpus in $corpus_root"
running=0
for h in "${harnesses[@]}"; do
  fuzz_one "$h" &
  running=$((running + 1))
  if (( running >= jobs )); then
    wait -n || true
    running=$((running - 1))
  fi
done
wait

status=0
printf '%-12s %8s %8s %12s %8s %12s %9s\n' harness seconds "CPU s" execs exec/s "exec/CPU s" findings
for h in "${harnesses[@]}"; do
  read -r _ secs execs found cpu < "$corpus_root/logs/$h.stats"
  printf '%-12s %8d %8d %12d %8d %12d %9d\n' "$h" "$secs" "$cpu" "$execs" $((execs / (secs > 0 ? secs : 1))) \
    $((execs / (cpu > 0 ? cpu : 1))) "$found"
  (( found == 0 )) || { status=1; sed 's/^/    /' "$corpus_root/logs/$h.found"; }
done
exit $status
