# Sourced by scripts/test_sanitize.sh, scripts/test_fuzz.sh and scripts/fuzz.sh: configures the
# one instrumented build, build-fuzz/ (clang, ASan + UBSan + libFuzzer's coverage
# instrumentation, RelWithDebInfo, no co-simulation, no benchmarks). The sanitizer run builds
# and tests rpu and the unit tests in it, the fuzz runs the fuzz targets: one compile of the
# code for both.
# ccache: hash paths relative to the checkout, so every clone of the project shares one cache.
export CCACHE_BASEDIR="$PWD"
configure_asan_build() {
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DRPU_FUZZ=ON -DRPU_SIM=OFF -DRPU_BENCH=OFF >/dev/null
}
