#!/usr/bin/env bash
# Command-line tests of output safety: unwritable outputs and outputs that would replace one of
# the scene's own files are refused before rendering (exit 2); Ctrl-C stops a render and writes
# a whole, partial image (exit 130); a second Ctrl-C aborts at once; Ctrl-C in the glare
# pass stops it after the chunk in progress, with the paths traced standing for all.
# Usage: output_safety.sh CASE OBJEKTIV SOURCE_DIR WORK_DIR IINFO
#   CASE: unwritable | inputs | interrupt | interrupt-twice | interrupt-glare
set -uo pipefail
case_name=$1 obj=$2 src=$3 work=$4 iinfo=$5
cornell=$src/scenes/cornell-box/cornell-box.xml
rm -rf "$work" && mkdir -p "$work" || exit 1

fail() { echo "FAIL: $*"; exit 1; }
# expect CODE TEXT COMMAND...: runs COMMAND, checks its exit code and that its output holds TEXT.
expect() {
  local code=$1 text=$2
  shift 2
  "$@" > "$work/out.txt" 2>&1
  local rc=$?
  [ "$rc" = "$code" ] || fail "exit $rc, expected $code: $* :: $(cat "$work/out.txt")"
  grep -qF -- "$text" "$work/out.txt" || fail "no '$text' in the output of $* :: $(cat "$work/out.txt")"
  echo "ok ($rc): $*"
}
# No temporary files (".NAME.PID-N.tmp") left in a directory.
no_temporaries() { ! ls -A "$1" | grep -q '\.tmp$' || fail "temporary files left in $1: $(ls -A "$1")"; }
# Starts a render in the background (pid in $pid, output in out.txt and err.txt), with job
# control (set -m) so that it does not start with SIGINT ignored, and waits until it renders.
start_render() {
  set -m
  "$obj" render "$cornell" "$@" > "$work/out.txt" 2> "$work/err.txt" &
  pid=$!
  wait_for rendering 1200 || fail "the render did not start: $(cat "$work/err.txt")"
}
# wait_for TEXT TENTHS: until err.txt holds TEXT, at most TENTHS tenths of a second.
wait_for() {
  for _ in $(seq "$2"); do grep -q "$1" "$work/err.txt" && return 0; kill -0 $pid 2> /dev/null || break; sleep 0.1; done
  grep -q "$1" "$work/err.txt"
}
# wait_exit TENTHS: until the render has ended (else it is killed and the test fails); status in $rc.
wait_exit() {
  for _ in $(seq "$1"); do kill -0 $pid 2> /dev/null || break; sleep 0.1; done
  kill -0 $pid 2> /dev/null && { kill -KILL $pid; fail "still running $(($1 / 10)) s after the signal"; }
  wait $pid
  rc=$?
}

small=(-D res=16 --spp 2)
case $case_name in
unwritable)
  expect 2 "does not exist" "$obj" render "$cornell" "${small[@]}" -o "$work/missing/deeper/out.exr"
  [ ! -e "$work/missing" ] || fail "the missing directory was created"
  expect 2 "is not a directory" "$obj" render "$cornell" "${small[@]}" -o "$cornell/out.exr"
  expect 2 "--stats-json cannot be written" "$obj" render "$cornell" "${small[@]}" -o "$work/ok.exr" \
    --stats-json "$work/missing/stats.json"
  mkdir "$work/adir"
  expect 2 "is a directory" "$obj" render "$cornell" "${small[@]}" -o "$work/ok.exr" --stats-json "$work/adir"
  expect 2 "is also the EXR" "$obj" render "$cornell" "${small[@]}" -o "$work/ok.exr" --stats-json "$work/ok.exr"
  [ ! -e "$work/ok.exr" ] || fail "an image was written"
  # A read-only directory: root may write anywhere, so run as nobody where we are root.
  mkdir -m 755 "$work/ro" && chmod 555 "$work/ro"
  as_user=()
  if [ "$(id -u)" = 0 ]; then
    chmod 755 "$work"
    as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups)
    "${as_user[@]}" true 2>/dev/null || { echo "skip: read-only directory (cannot drop root)"; exit 0; }
  fi
  expect 2 "cannot create a file" "${as_user[@]}" "$obj" render "$cornell" "${small[@]}" -o "$work/ro/out.exr"
  ;;
inputs)
  # Copies of scenes with a texture, an environment map, a mesh, and of the data folder (lens
  # files, glass catalogs): a failing run must not damage the project's own files.
  cp -r "$src/scenes/lens" "$src/scenes/still-life" "$src/scenes/cornell-box" "$src/data" "$work/"
  (cd "$work" && find . -type f -exec md5sum {} + | sort -k2) > "$work.sums"
  export OBJEKTIV_DATA_DIR=$work/data
  expect 2 "would overwrite $work/lens/grid-tile.png" "$obj" render "$work/lens/distortion-chart.xml" \
    "${small[@]}" -o "$work/lens/grid-tile.exr"
  expect 2 "would overwrite $work/still-life/sky.exr" "$obj" render "$work/still-life/still-life.xml" \
    "${small[@]}" -o "$work/still-life/sky.exr"
  expect 2 "a file the scene reads" "$obj" render "$work/cornell-box/cornell-box.xml" "${small[@]}" \
    -o "$work/out.exr" --stats-json "$work/cornell-box/cornell-box.xml"
  expect 2 "a file the scene reads" "$obj" render "$work/cornell-box/cornell-box.xml" "${small[@]}" \
    -o "$work/out.exr" --stats-json "$work/cornell-box/../cornell-box/cornell-box.obj"
  ln -s "$work/lens/grid-tile.png" "$work/link.png"
  expect 2 "grid-tile.png, a file the scene reads" "$obj" render "$work/lens/distortion-chart.xml" "${small[@]}" \
    -o "$work/link.exr"
  expect 2 "a file the scene reads" "$obj" render "$work/lens/chromatic-closeup.xml" "${small[@]}" \
    -o "$work/out.exr" --stats-json "$work/data/lenses/tessar.brendel.100mm.lens"
  expect 2 "a file the scene reads" "$obj" render "$work/lens/chromatic-closeup.xml" "${small[@]}" \
    -o "$work/out.exr" --stats-json "$work/data/glass/HIKARI.AGF"
  rm "$work/out.txt"
  (cd "$work" && find . -type f -exec md5sum {} + | sort -k2) | diff "$work.sums" - || fail "files were changed or added"
  no_temporaries "$work/lens"
  ;;
interrupt)
  # A render far too long to finish (1024x1024 at 4096 spp), a few ms per pixel.
  start_render -D res=1024 --spp 4096 -o "$work/int.exr" --stats-json "$work/int.json"
  sleep 1
  kill -INT $pid
  start=$(date +%s%N)
  wait_exit 300
  echo "stopped $(( ($(date +%s%N) - start) / 1000000 )) ms after SIGINT (including writing the images), exit $rc"
  cat "$work/out.txt" "$work/err.txt"
  if [ $rc = 0 ]; then echo "the render finished before the signal: nothing to check"; exit 0; fi
  [ $rc = 130 ] || fail "exit $rc, expected 130"
  grep -q "(partial)" "$work/out.txt" || fail "the summary does not say partial"
  grep -q '"partial": true' "$work/int.json" || fail "--stats-json lacks \"partial\": true"
  "$iinfo" -v "$work/int.exr" > "$work/header.txt" || fail "iinfo cannot read the EXR"
  grep -q 'objektiv:partial: 1' "$work/header.txt" || fail "no objektiv:partial = 1 in the header: $(cat "$work/header.txt")"
  grep -q 'objektiv:pixels: 1048576' "$work/header.txt" || fail "no objektiv:pixels in the header"
  done_pixels=$(sed -n 's/.*objektiv:pixels_completed: \([0-9]*\).*/\1/p' "$work/header.txt")
  [ -n "$done_pixels" ] && [ "$done_pixels" -lt 1048576 ] || fail "pixels_completed '$done_pixels'"
  # The whole file reads (every pixel decodes), and the PNG is there.
  "$obj" imgtool diff "$work/int.exr" "$work/int.exr" --threshold 0 > /dev/null || fail "the EXR does not read whole"
  [ -s "$work/int.png" ] || fail "no PNG"
  no_temporaries "$work"
  ;;
interrupt-twice)
  # The first Ctrl-C lets each thread finish its pixel; at 16M samples per pixel that takes
  # seconds, and the second Ctrl-C must end the process at once, writing nothing.
  start_render -D res=4 --spp 16777216 -o "$work/int.exr"
  sleep 1  # well inside the first pixel
  kill -INT $pid
  wait_for interrupted 300 || fail "no message after the first SIGINT"
  kill -INT $pid
  wait_exit 50
  [ $rc = 130 ] || fail "exit $rc, expected 130"
  [ ! -e "$work/int.exr" ] || fail "an image was written after the second SIGINT"
  no_temporaries "$work"
  ;;
interrupt-glare)
  # The image is done in a moment; the glare pass (a lamp's ghosts by light tracing, 65536
  # paths per pixel: 268 million) would take about a minute.
  set -m
  "$obj" render "$src/tests/data/glare-interrupt.xml" -v -o "$work/glare.exr" --stats-json "$work/glare.json" \
    > "$work/out.txt" 2> "$work/err.txt" &
  pid=$!
  wait_for "light tracing: 268435456 paths" 1200 || fail "the glare pass did not start: $(cat "$work/err.txt")"
  sleep 1
  kill -INT $pid
  wait_exit 300
  cat "$work/out.txt" "$work/err.txt"
  [ $rc = 130 ] || fail "exit $rc, expected 130"
  grep -q "interrupted: ghosts and glare by light tracing from" "$work/err.txt" || fail "no warning on the glare pass"
  asked=$(sed -n 's/.*"glare_paths_asked": \([0-9]*\).*/\1/p' "$work/glare.json")
  traced=$(sed -n 's/.*"glare_paths": \([0-9]*\).*/\1/p' "$work/glare.json")
  [ "$asked" = 268435456 ] || fail "glare_paths_asked '$asked'"
  [ -n "$traced" ] && [ "$traced" -gt 0 ] && [ "$traced" -lt "$asked" ] || fail "glare_paths '$traced' of $asked"
  "$obj" imgtool diff "$work/glare.exr" "$work/glare.exr" --threshold 0 > /dev/null || fail "the EXR does not read whole"
  no_temporaries "$work"
  ;;
*) fail "unknown case $case_name" ;;
esac
echo "passed: $case_name"
