#!/usr/bin/env bash
# libFuzzer targets (fuzz/*_fuzzer.cpp) with ASan + UBSan, built with clang in build-asan.
#   bash scripts/fuzz.sh                      # every target, 1 000 000 executions each
#   bash scripts/fuzz.sh csv_reader 200000    # one target, N executions
# New inputs go to build-asan/fuzz-corpus/<target> (the seed corpus fuzz/corpus/<target> is only
# read); a crash leaves build-asan/fuzz-artifacts/<target>/crash-*: fix it and add the input to a
# regression test in tests/.
set -euo pipefail
cd "$(dirname "$0")/.."
targets=(experiment_file gltf_loader csv_reader statcheck answer_parser serve_reply serve_request serve_view)
[ $# -ge 1 ] && targets=("$1")
runs=${2:-1000000}
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
    "build-asan/fuzz-corpus/$t" "fuzz/corpus/$t"
done
