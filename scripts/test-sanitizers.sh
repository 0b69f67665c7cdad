#!/usr/bin/env bash
# The sanitizer suite (run by .ci/run, not by scripts/test.sh):
#   build-asan/  AddressSanitizer + UndefinedBehaviorSanitizer: every ctest
#                test (core, plugin, CLI, C API, QGIS: the QGIS tests run this
#                build's CLI), then the fuzz test (label "fuzz").
#   build-tsan/  ThreadSanitizer, OpenMP compiled out (libgomp is not
#                instrumented: its barriers are invisible to TSan): the core
#                and plugin/CLI tests, whose threads are std::threads.
# A report fails the test that met it (UBSan halts, every report exits 86).
# Usage: scripts/test-sanitizers.sh [asan|tsan]... (default: both)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
jobs="$(nproc)"
suites=("$@")
[ ${#suites[@]} -eq 0 ] && suites=(asan tsan)

export ASAN_OPTIONS="detect_leaks=1:exitcode=86:strict_string_checks=1:detect_stack_use_after_return=1"
export LSAN_OPTIONS="suppressions=$root/scripts/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:exitcode=86"
# atexit_sleep_ms: TSan otherwise sleeps 1 s in exit (for other threads'
# reports), which the cancel tests' one-second bound would count.
export TSAN_OPTIONS="halt_on_error=1:exitcode=86:second_deadlock_stack=1:atexit_sleep_ms=50:suppressions=$root/scripts/sanitizers/tsan.supp"

configure_and_build() {  # dir, sanitizers, extra cmake arguments...
  local dir=$1 sanitize=$2
  shift 2
  cmake -S "$root" -B "$root/$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMCMD_SANITIZE="$sanitize" "$@" >/dev/null
  cmake --build "$root/$dir" -j"$jobs"
}

for suite in "${suites[@]}"; do
  start=$SECONDS
  case "$suite" in
    asan)
      configure_and_build build-asan address,undefined
      ctest --test-dir "$root/build-asan" --output-on-failure -j"$jobs" -LE fuzz
      ctest --test-dir "$root/build-asan" --output-on-failure -L fuzz
      ;;
    tsan)
      configure_and_build build-tsan thread -DMCMD_OPENMP=OFF
      # The threaded paths: the core (worker pools, the whole raster's
      # domains) and the CLI (the background copy, the cancel watchdog).
      # Not the Python tests: TSan cannot be loaded into a Python built
      # without it (the module's threads are the core's, checked here).
      ctest --test-dir "$root/build-tsan" --output-on-failure -j"$jobs" -LE "fuzz|qgis|python" -E "c_api_installed_package|c_api_readme_example"
      ;;
    *) echo "test-sanitizers: unknown suite '$suite' (asan, tsan)" >&2; exit 2 ;;
  esac
  echo "test-sanitizers: $suite passed in $((SECONDS - start)) s"
done
