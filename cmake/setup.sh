#!/usr/bin/env bash
# DevSurf setup: installs the Debian packages it needs (only the missing ones), configures and
# builds, then either starts DevSurf on a built-in example (`run`) or runs every test headless
# (`test`). Idempotent: a second run with everything in place only rebuilds what changed.
set -euo pipefail

mode="${1:-run}"
case "$mode" in
  run|test|build) ;;
  *) echo "usage: bash cmake/setup.sh [run|test|build]" >&2; exit 1 ;;
esac

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
build_asan="$root/build-asan"
build_tsan="$root/build-tsan"
jobs="$(nproc 2>/dev/null || echo 2)"

packages=(
  cmake g++ ninja-build ccache pkg-config
  qt6-base-dev libqt6opengl6-dev qt6-svg-dev qt6-tools-dev qt6-l10n-tools
  libvtk9-dev libeigen3-dev libsuitesparse-dev libopenmesh-dev libboost-serialization-dev
  libopenblas0-serial libdxflib-dev libnanoflann-dev
  libocct-data-exchange-dev libocct-modeling-algorithms-dev libocct-modeling-data-dev
  libocct-foundation-dev libocct-ocaf-dev
  qt6-translations-l10n fonts-noto-cjk
  xvfb xauth
)
if [ "$mode" = test ]; then
  # Test-time only: an independent DXF reader, PDF tools (page size, rasterising), Ceres
  # Solver as the benchmark's peer, and FreeCAD's interpreter reading STEP and IGES back.
  packages+=(python3-ezdxf poppler-utils libceres-dev freecad-python3)
fi

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "== Installing ${#missing[@]} Debian packages: ${missing[*]}"
  as_root apt-get update -qq
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
fi

# CHOLMOD calls the generic libblas.so.3 (and liblapack.so.3, which loads libopenblas.so.0):
# make all three the single-threaded OpenBLAS, not the reference BLAS, ATLAS or a threaded
# OpenBLAS (libopenblas0-pthread, which other packages may pull in, takes all three over in
# auto mode).
multiarch=$(gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)
for lib in libblas.so.3 liblapack.so.3 libopenblas.so.0; do
  alt=$lib-$multiarch
  serial=$(update-alternatives --list "$alt" 2>/dev/null | grep openblas-serial || true)
  if [ -n "$serial" ] && [ "$(readlink -f /etc/alternatives/"$alt")" != "$(readlink -f "$serial")" ]; then
    as_root update-alternatives --set "$alt" "$serial"
  fi
done

# The sanitizer builds keep line tables only (-g1): their reports still name file and line, and
# compiling and linking with less debug information saves CI time (about a tenth of the compile
# time of the solver's sources). They optimise at -O1, the level the sanitizers' own
# documentation names: instrumented code compiles about a third faster than at -O2 (68 → 49 s
# for the slowest file), and the sanitizer build is the longest step of the test command.
sanitizer_flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
  "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG")

configure_and_build() { # dir, targets ("" for all), extra cmake args...
  local dir="$1" targets="$2"; shift 2
  # Configure every time (a few seconds): packages installed since the last run, such as the
  # benchmark's Ceres peer for `test` after `run`, are then found.
  cmake -S "$root" -B "$dir" -G Ninja "$@" >/dev/null
  # shellcheck disable=SC2086 # targets is a list
  cmake --build "$dir" -j "$jobs" ${targets:+--target $targets}
}

# `run` builds the application and the command-line tool only. `test` runs the unit tests once,
# in the AddressSanitizer build below, so its Release build leaves them out and builds the
# desktop, views, OpenCASCADE and benchmark tests (DEVSURF_SKIP_SANITIZED_TESTS); `build`
# builds every test in Release.
case "$mode" in
  run) release_targets="devsurf devsurf-cli"; release_flags=() ;;
  test) release_targets=""; release_flags=(-DDEVSURF_SKIP_SANITIZED_TESTS=ON) ;;
  build) release_targets=""; release_flags=(-DDEVSURF_SKIP_SANITIZED_TESTS=OFF) ;;
esac
echo "== Building (Release) in $build"
configure_and_build "$build" "$release_targets" -DCMAKE_BUILD_TYPE=Release "${release_flags[@]}"

case "$mode" in
  build)
    ;;
  run)
    example="$build/examples/annulus.devsurf"
    mkdir -p "$build/examples"
    "$build/bin/devsurf-cli" example annulus -o "$example" >/dev/null
    echo "== DevSurf on the built-in example 'annulus' ($example)"
    if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
      echo "No display: DevSurf is a desktop application. Start it from a desktop session," >&2
      echo "or run it headless with: xvfb-run -a $build/bin/devsurf $example" >&2
      "$build/bin/devsurf-cli" info "$example"
      exit 1
    fi
    exec "$build/bin/devsurf" "$example"
    ;;
  test)
    echo "== Running the desktop, views, OpenCASCADE and benchmark tests (headless)"
    (cd "$build" && xvfb-run -a -s "-screen 0 1920x1080x24" ctest --output-on-failure -j "$jobs")
    echo "== Building and running the unit tests under AddressSanitizer + UBSan in $build_asan"
    configure_and_build "$build_asan" "" "${sanitizer_flags[@]}" -DDEVSURF_SANITIZE=ON \
      -DDEVSURF_UNIT_TESTS_ONLY=ON
    (cd "$build_asan" && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
      UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      xvfb-run -a ctest --output-on-failure -j "$jobs")
    # ThreadSanitizer only where our code starts threads without a GUI: the solver worker and
    # the distance report's parallel measurement (tst_model_threads).
    echo "== Building and running the threaded tests under ThreadSanitizer in $build_tsan"
    cmake -S "$root" -B "$build_tsan" -G Ninja "${sanitizer_flags[@]}" -DDEVSURF_TSAN=ON \
      -DDEVSURF_UNIT_TESTS_ONLY=ON >/dev/null
    cmake --build "$build_tsan" -j "$jobs" --target tst_worker tst_model_threads
    # One BLAS/OpenMP thread: the threads under test are ours, not the uninstrumented libgomp's.
    (cd "$build_tsan" && OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 \
      TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$root/tests/tsan.supp" \
      xvfb-run -a ctest --output-on-failure -j "$jobs" -R '^(tst_worker|tst_model_threads)$')
    ;;
esac
