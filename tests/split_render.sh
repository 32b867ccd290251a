#!/usr/bin/env bash
# Command-line tests of split renders (render --spp-range / --part, merge), checkpoints and
# resuming, and the time budget.
# Usage: split_render.sh CASE OBJEKTIV SOURCE_DIR WORK_DIR IINFO
#   CASE: merge | merge-errors | kill-resume | budgets | bad-values | interrupt-lens-passes
set -uo pipefail
case_name=$1 obj=$2 src=$3 work=$4 iinfo=$5
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

fail() { echo "FAIL: $*"; exit 1; }
# expect CODE TEXT COMMAND...: runs COMMAND, checks its exit code and that its output holds TEXT.
expect() {
  local code=$1 text=$2
  shift 2
  "$@" > out.txt 2>&1
  local rc=$?
  [ "$rc" = "$code" ] || fail "exit $rc, expected $code: $* :: $(cat out.txt)"
  grep -qF -- "$text" out.txt || fail "no '$text' in the output of $* :: $(cat out.txt)"
  echo "ok ($rc): $*"
}
same() { "$obj" imgtool diff --exact "$1" "$2" || fail "$1 is not $2 bit for bit"; }

scene=$src/tests/data/split-render.xml
case $case_name in
merge)
  # Everything at once (AOVs, a real lens with ghosts, glare and diffraction), split by samples
  # and by regions, mixed: the first samples of the whole image, the rest in two regions of
  # three ranges and one.
  "$obj" render "$scene" -q -o whole.exr || fail "the whole render failed"
  "$obj" render "$scene" -q --spp-range 0:5 -o p0.exr || fail "part 0"
  "$obj" render "$scene" -q --spp-range 5:7 --crop 0,0,48,20 -o p1.exr || fail "part 1"
  "$obj" render "$scene" -q --spp-range 7:12 --crop 0,0,48,20 --threads 1 -o p2.exr || fail "part 2"
  "$obj" render "$scene" -q --spp-range 5:12 --crop 0,20,48,48 -o p3.exr || fail "part 3"
  [ ! -e p0.png ] || fail "a part wrote a PNG"
  "$obj" merge p3.exr p1.exr p0.exr p2.exr -o merged.exr || fail "merge"
  same merged.exr whole.exr
  [ -s merged.png ] || fail "no PNG beside the merged EXR"
  # Regions alone (--part), with the scene moved away and named with --scene.
  mkdir moved && cp "$scene" moved/scene.xml
  "$obj" render moved/scene.xml -q --part --crop 0,0,30,48 -o r0.exr || fail "region 0"
  "$obj" render moved/scene.xml -q --part --crop 30,0,48,48 -o r1.exr || fail "region 1"
  mv moved elsewhere
  expect 1 "give its path with --scene" "$obj" merge r0.exr r1.exr -o regions.exr
  "$obj" merge r0.exr r1.exr --scene elsewhere/scene.xml -o regions.exr -q || fail "merge of regions"
  same regions.exr whole.exr
  ;;
merge-errors)
  cornell=$src/scenes/cornell-box/cornell-box.xml
  d=(-D res=24 --spp 8)
  "$obj" render "$cornell" "${d[@]}" -q --spp-range 0:3 -o a.exr || fail "part a"
  "$obj" render "$cornell" "${d[@]}" -q --spp-range 3:8 -o b.exr || fail "part b"
  "$obj" render "$cornell" "${d[@]}" -q --spp-range 2:8 -o b2.exr || fail "part b2"
  "$obj" render "$cornell" "${d[@]}" -q --spp-range 4:8 -o b3.exr || fail "part b3"
  "$obj" render "$cornell" -D res=24 --spp 8 -D max_depth=3 -q --spp-range 3:8 -o other.exr || fail "part other"
  "$obj" render "$cornell" "${d[@]}" -q -o plain.exr || fail "plain render"
  expect 1 "samples 3:8 of pixel (0, 0) are in none of the parts (it has samples 0:3 from a.exr)" "$obj" merge a.exr -o m.exr
  expect 1 "both hold samples of pixel (0, 0)" "$obj" merge a.exr b.exr b2.exr -o m.exr
  expect 1 "samples 3:4 of pixel (0, 0) are in none of the parts" "$obj" merge a.exr b3.exr -o m.exr
  expect 1 "parts of different renders: -D values" "$obj" merge a.exr other.exr -o m.exr
  expect 1 "not a render part" "$obj" merge a.exr plain.exr -o m.exr
  expect 2 "would overwrite b.exr" "$obj" merge a.exr b.exr -o b.exr
  expect 2 "--spp-range" "$obj" render "$cornell" "${d[@]}" --spp-range 5:9 -o x.exr
  expect 2 "--spp-range" "$obj" render "$cornell" "${d[@]}" --spp-range 5 -o x.exr
  expect 2 "end whole renders" "$obj" render "$cornell" "${d[@]}" --spp-range 0:4 --time-limit 5 -o x.exr
  sed 's|<integer name="height" value="$res"/>|&<integer name="crop_offset_x" value="4"/><integer name="crop_width" value="8"/>|' \
    "$cornell" > cropped.xml
  grep -q crop_width cropped.xml || fail "no crop window in cropped.xml"
  cp "$src/scenes/cornell-box/cornell-box.obj" .
  expect 2 "inside the scene's crop window 4,0,12,24" "$obj" render cropped.xml "${d[@]}" --part --crop 0,0,8,8 -o x.exr
  # A scene file changed after the parts were rendered.
  cp "$cornell" .
  "$obj" render cornell-box.xml "${d[@]}" -q --spp-range 0:3 -o c0.exr || fail "part c0"
  "$obj" render cornell-box.xml "${d[@]}" -q --spp-range 3:8 -o c1.exr || fail "part c1"
  echo "# changed" >> cornell-box.obj
  expect 1 "not those the parts were rendered from" "$obj" merge c0.exr c1.exr -o m.exr
  # A checkpoint is not a part.
  "$obj" render "$cornell" -D res=64 --spp 100000 -q --checkpoint 0.2 -o long.exr > /dev/null 2>&1 &
  pid=$!
  for _ in $(seq 300); do [ -e long.checkpoint.exr ] && break; sleep 0.1; done
  kill -KILL $pid
  wait $pid 2> /dev/null
  [ -e long.checkpoint.exr ] || fail "no checkpoint written"
  expect 1 "is a checkpoint, not a finished part" "$obj" merge long.checkpoint.exr -o m.exr
  # And a checkpoint of another render is not resumed.
  expect 1 "a checkpoint of another render (samples per pixel 100 against 100000)" \
    "$obj" render "$cornell" -D res=64 --spp 100 --resume -o long.exr
  ;;
kill-resume)
  # Killed for real (SIGKILL) at random moments, resumed each time: the image of a render never
  # stopped, bit for bit.
  cornell=$src/scenes/cornell-box/cornell-box.xml
  d=(-D res=96 --spp 512 --threads 2)
  "$obj" render "$cornell" "${d[@]}" -q -o reference.exr || fail "the reference render"
  # A temporary of a killed process (its pid no longer runs) and one of a live process.
  host=$(hostname | tr -- '-/' '__')
  sleep 0 & dead=$!
  wait $dead
  touch ".out.checkpoint.exr.$host-$dead-0.tmp" ".out.checkpoint.exr.$host-$$-0.tmp"
  kills=0
  for round in 1 2 3 4 5 6; do
    "$obj" render "$cornell" "${d[@]}" --checkpoint 0.1 --resume -o out.exr > "log$round.txt" 2>&1 &
    pid=$!
    for _ in $(seq 600); do grep -q rendering "log$round.txt" && break; sleep 0.05; done
    sleep "0.$((RANDOM % 6 + 2))"
    if kill -KILL $pid 2> /dev/null; then kills=$((kills + 1)); fi
    wait $pid 2> /dev/null
    grep -h "resuming\|no checkpoint" "log$round.txt"
    [ -e out.exr ] && break
  done
  (( kills >= 2 )) || fail "killed only $kills times: the render is too fast for this test"
  grep -q resuming log*.txt || fail "no run resumed from a checkpoint"
  if [ ! -e out.exr ]; then
    "$obj" render "$cornell" "${d[@]}" --checkpoint 0.1 --resume -o out.exr > last.txt 2>&1 || fail "the last run"
    grep -q resuming last.txt || fail "the last run did not resume: $(cat last.txt)"
  fi
  [ ! -e out.checkpoint.exr ] || fail "the checkpoint was left behind"
  # Temporaries of checkpoints killed while being written are removed by the next run; a live
  # process's are not.
  [ -e ".out.checkpoint.exr.$host-$$-0.tmp" ] || fail "a live process's temporary was removed"
  rm ".out.checkpoint.exr.$host-$$-0.tmp"
  ! ls -A | grep -q '\.tmp$' || fail "temporary files left: $(ls -A)"
  echo "killed $kills times"
  same out.exr reference.exr
  ;;
budgets)
  cornell=$src/scenes/cornell-box/cornell-box.xml
  "$obj" render "$cornell" -D res=64 --spp 1000000 --time-limit 1 -o limited.exr > log.txt 2>&1 || fail "time-limited render"
  grep -q "stopped at the time limit" log.txt || fail "no word of the time limit: $(cat log.txt)"
  "$iinfo" -v limited.exr > header.txt || fail "iinfo"
  grep -q 'objektiv:render_end: "time limit"' header.txt || fail "header: $(cat header.txt)"
  grep -q 'objektiv:time_limit: 1' header.txt || fail "no time limit in the header: $(cat header.txt)"
  grep -q 'objektiv:partial: 0' header.txt || fail "a time-limited image is whole: $(cat header.txt)"
  "$obj" render "$cornell" -D res=64 --spp 4096 --noise-target 0.3 -o noisy.exr > log.txt 2>&1 || fail "noise target"
  grep -q "stopped at the noise target" log.txt || fail "no word of the noise target: $(cat log.txt)"
  "$iinfo" -v noisy.exr > header.txt || fail "iinfo"
  grep -q 'objektiv:render_end: "noise target"' header.txt || fail "header: $(cat header.txt)"
  # A limit shorter than the first pass: every pixel still gets a sample.
  "$obj" render "$cornell" -D res=64 --spp 64 --time-limit 0.001 -o short.exr > log.txt 2>&1 || fail "short limit"
  "$iinfo" -v short.exr > header.txt || fail "iinfo"
  grep -q 'objektiv:samples_per_pixel: 1$' header.txt || fail "not one sample per pixel: $(cat header.txt)"
  # Light paths' noise is not in the camera samples the noise target reads: refused.
  cat > light.xml <<'XML'
<scene version="3.0.0">
  <integrator type="ptracer"/>
  <sensor type="perspective"><film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film></sensor>
  <shape type="sphere"><point name="center" x="0" y="0" z="3"/></shape>
  <emitter type="point"><point name="position" x="0" y="2" z="0"/></emitter>
</scene>
XML
  expect 1 "--noise-target measures the noise of camera samples" "$obj" render light.xml --noise-target 0.1 -o light.exr
  "$obj" render light.xml --time-limit 5 -q -o light.exr || fail "a light-traced render with a time limit"
  ;;
bad-values)
  cornell=$src/scenes/cornell-box/cornell-box.xml
  d=(-D res=8 --spp 4 -q)
  for v in nan inf -1 0 1e400 abc; do
    expect 2 "--time-limit" "$obj" render "$cornell" "${d[@]}" --time-limit "$v" -o x.exr
    expect 2 "--checkpoint" "$obj" render "$cornell" "${d[@]}" --checkpoint "$v" -o x.exr
    expect 2 "--noise-target" "$obj" render "$cornell" "${d[@]}" --noise-target "$v" -o x.exr
  done
  expect 2 "--noise-target" "$obj" render "$cornell" "${d[@]}" --noise-target 1.5 -o x.exr
  for v in "" " 0:4" "0:+4" "0:4 " "0:4:8" "1:1" "3:2" "0:5" "-1:3"; do
    expect 2 "--spp-range" "$obj" render "$cornell" "${d[@]}" --spp-range "$v" -o x.exr
  done
  for v in "" "0,0,4,4,junk" "0,0,4" " 0,0,4,4" "-1,0,4,4" "0,0,9,4"; do
    expect 2 "--crop" "$obj" render "$cornell" "${d[@]}" --crop "$v" -o x.exr
  done
  for v in -1 18446744073709551616 1.5 ""; do
    expect 2 "--seed" "$obj" render "$cornell" "${d[@]}" --seed "$v" -o x.exr
  done
  [ ! -e x.exr ] || fail "a bad value rendered"
  # The largest seed is kept whole.
  "$obj" render "$cornell" "${d[@]}" --seed 18446744073709551615 --spp-range 0:4 -o big-seed.exr || fail "largest seed"
  "$iinfo" -v big-seed.exr | grep -q 'objektiv:seed: "18446744073709551615"' || fail "seed: $("$iinfo" -v big-seed.exr)"
  expect 2 "--scene" "$obj" merge big-seed.exr --scene nowhere.xml -o m.exr
  ;;
interrupt-lens-passes)
  # Ctrl-C in the lens's passes, after every sample: the checkpoint (written before them) stays,
  # the image is marked partial, and --resume finishes without sampling again.
  scene=$src/tests/data/glare-interrupt.xml
  set -m
  "$obj" render "$scene" -v --checkpoint 100 -o lens.exr > out.txt 2> err.txt &
  pid=$!
  for _ in $(seq 1200); do grep -q "ghosts and glare by light tracing" err.txt && break; sleep 0.1; done
  grep -q "ghosts and glare by light tracing" err.txt || fail "the glare pass did not start: $(cat err.txt)"
  kill -INT $pid
  wait $pid
  rc=$?
  [ "$rc" = 130 ] || fail "exit $rc, expected 130: $(cat err.txt)"
  [ -e lens.checkpoint.exr ] || fail "no checkpoint kept: $(ls; cat err.txt)"
  grep -q "interrupted in the lens's passes" err.txt || fail "no word of it: $(cat err.txt)"
  "$iinfo" -v lens.exr > header.txt || fail "iinfo"
  grep -q 'objektiv:partial: 1' header.txt || fail "not marked partial: $(cat header.txt)"
  grep -q 'objektiv:render_end: "interrupted"' header.txt || fail "render_end: $(cat header.txt)"
  "$obj" render "$scene" -D glare=1 --resume -o lens.exr > out.txt 2> err.txt && fail "resumed with other values"
  grep -q "a checkpoint of another render" err.txt || fail "$(cat err.txt)"
  ;;
*) fail "no case $case_name" ;;
esac
echo PASS
