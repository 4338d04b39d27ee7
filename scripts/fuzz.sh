#!/usr/bin/env bash
# libFuzzer targets (fuzz/*_fuzzer.cpp) with ASan + UBSan, built with clang in build-asan.
#   bash scripts/fuzz.sh                      # every target, 1 000 000 executions each
#   bash scripts/fuzz.sh csv_reader 200000    # one target, N executions
#   TLAB_FUZZ_LIGHT=1 bash scripts/fuzz.sh serve_view 2000000
#       light: only the target and the sources its "// fuzz-sources:" line names are built with
#       clang, libFuzzer, ASan and UBSan (in build-fuzz-light); the rest of tlab is linked from the
#       Release build in build/ (built first), uninstrumented — minutes instead of a whole
#       sanitizer build of every library on a 2-core machine.
# New inputs go to build-asan/fuzz-corpus/<target> (the seed corpus fuzz/corpus/<target> is only
# read); a crash leaves build-asan/fuzz-artifacts/<target>/crash-*: fix it and add the input to a
# regression test in tests/.
set -euo pipefail
cd "$(dirname "$0")/.."
# Seeds beyond fuzz/corpus/<target>: the examples a user starts from (read only, like the corpus).
example_seeds() {
  case $1 in
    style_file) echo examples/styles ;;
    stimulus_set) echo examples/stimulus-sets ;;
  esac
}
targets=(experiment_file gltf_loader csv_reader statcheck answer_parser serve_reply serve_request serve_view style_file render_options stimulus_set)
[ $# -ge 1 ] && targets=("$1")
runs=${2:-1000000}
if [ "${TLAB_FUZZ_LIGHT:-0}" = 1 ]; then
  [ -x build/bin/serve_tests ] || { echo "fuzz: light mode links build/'s libraries: build tlab's tests first (scripts/build.sh)" >&2; exit 1; }
  libs=$(sed 's/.*-o \.\.\/\.\.\/bin\/serve_tests//; s#\.\./\.\./#build/#g; s#[^ ]*libgtest[a-z_]*\.a##g' build/tests/study/CMakeFiles/serve_tests.dir/link.txt)
  mkdir -p build-fuzz-light
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  for t in "${targets[@]}"; do
    sources=$(sed -n 's#^// fuzz-sources: ##p' "fuzz/${t}_fuzzer.cpp")
    [ -n "$sources" ] || { echo "fuzz: fuzz/${t}_fuzzer.cpp names no // fuzz-sources: for the light mode" >&2; exit 1; }
    # shellcheck disable=SC2086
    clang++ -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -DBOOST_ALL_NO_LIB -DTOML_HEADER_ONLY=0 -DTOML_SHARED_LIB=1 -I. \
      -isystem build/glad/include -isystem /usr/include/eigen3 -isystem /usr/include/libpng16 -w "fuzz/${t}_fuzzer.cpp" $sources \
      -o "build-fuzz-light/${t}_fuzzer" -pthread $libs
    mkdir -p "build-fuzz-light/fuzz-corpus/$t" "build-fuzz-light/fuzz-artifacts/$t"
    echo "fuzz (light): $t ($runs executions; instrumented: $sources)"
    "build-fuzz-light/${t}_fuzzer" -runs="$runs" -max_total_time=7200 -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
      -artifact_prefix="build-fuzz-light/fuzz-artifacts/$t/" -print_final_stats=1 "build-fuzz-light/fuzz-corpus/$t" "fuzz/corpus/$t" \
      $(example_seeds "$t")
  done
  exit 0
fi
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DTLAB_SANITIZE=ON -DTLAB_BUILD_FUZZERS=ON -DTLAB_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
cmake --build build-asan -j2 --target "${targets[@]/%/_fuzzer}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
for t in "${targets[@]}"; do
  mkdir -p "build-asan/fuzz-corpus/$t" "build-asan/fuzz-artifacts/$t"
  echo "fuzz: $t ($runs executions)"
  "build-asan/bin/${t}_fuzzer" -runs="$runs" -max_total_time=7200 -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
    -artifact_prefix="build-asan/fuzz-artifacts/$t/" -print_final_stats=1 \
    "build-asan/fuzz-corpus/$t" "fuzz/corpus/$t" $(example_seeds "$t")
done
