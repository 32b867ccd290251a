#!/usr/bin/env bash
# Command-line tests of output safety: unwritable outputs and outputs that would replace one of
# the scene's own files are refused before rendering (exit 2).
# Usage: output_safety.sh CASE OBJEKTIV SOURCE_DIR WORK_DIR
#   CASE: unwritable | inputs
set -uo pipefail
case_name=$1 obj=$2 src=$3 work=$4
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
*) fail "unknown case $case_name" ;;
esac
echo "passed: $case_name"
