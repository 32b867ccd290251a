#!/usr/bin/env bash
# README command 2: install, build (Release, build/), and run the whole test suite with CTest.
# With CI=true, or OBJEKTIV_SANITIZERS=1, also the slow stages: the same suite built by clang
# with AddressSanitizer and UndefinedBehaviorSanitizer (build-fuzz/, which also holds the
# libFuzzer harnesses), then a short fuzz of every harness (OBJEKTIV_FUZZ_SECONDS each,
# default 60). Each stage prints its time.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
stage() {  # stage NAME COMMAND...: runs it and prints its wall-clock and CPU time
  echo "test: $1"
  local TIMEFORMAT="test: $1: %0R s (CPU %0U s user, %0S s system)"
  shift
  time "$@"
}

stage "Release build" scripts/build.sh
[[ $(id -u) == 0 ]] && scripts/setup.sh --cluster  # for the test on a one-node Slurm cluster (root only)
stage "tests" ctest --test-dir build --output-on-failure -j "$jobs"

if [[ ${CI:-} != true && ${OBJEKTIV_SANITIZERS:-0} != 1 ]]; then
  echo "test: sanitizer build, tests under ASan+UBSan and fuzzing skipped (CI=true bash scripts/test.sh runs them too:" \
       "about 20 more minutes of CPU)"
  exit 0
fi

sanitizer_build() {
  scripts/setup.sh --sanitizers
  # Unity sources (16 files a unit) for the libraries and the harnesses: the instrumented build
  # spent most of its time compiling the same headers' templates once per file (objektiv_io and
  # what it needs: 488 s of CPU one by one, 298 s as unity sources). The tests stay one by one.
  cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ -DOBJEKTIV_FUZZ=ON \
    -DOBJEKTIV_BUILD_BENCH=OFF -DOBJEKTIV_ARCH="${OBJEKTIV_ARCH:-x86-64-v3}" \
    -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 >/dev/null
  cmake --build build-fuzz -j "$jobs"
}
sanitizer_tests() {
  # Stop at the first report; leaks too (fuzz/lsan.supp names the third-party ones).
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  LSAN_OPTIONS=suppressions=$PWD/fuzz/lsan.supp:print_suppressions=0 \
    ctest --test-dir build-fuzz --output-on-failure -j "$jobs" --timeout 900
}
stage "sanitizer build (clang, ASan+UBSan)" sanitizer_build
stage "tests under ASan+UBSan" sanitizer_tests
stage "fuzzing" scripts/fuzz.sh --time "${OBJEKTIV_FUZZ_SECONDS:-60}" --jobs "$jobs" --build build-fuzz \
  --corpus build-fuzz/corpus
