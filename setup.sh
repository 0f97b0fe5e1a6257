#!/usr/bin/env bash
# tsis setup: installs the Debian 12 packages tsis needs (only those missing),
# unpacks the CGAL data meshes, builds, and then renders or tests.
#
#   ./setup.sh            install + build
#   ./setup.sh render     install + build + render the default scene to tsis.png
#   ./setup.sh test       install + build + run the test suite (CTest)
#   ./setup.sh fuzz [S] [ARGS…]  install clang + build and run the mesh-loader fuzzer for S seconds (default 60; ARGS to libFuzzer)
#   ./setup.sh sanitize   build with ASan+UBSan into build-sanitize/ and run the whole suite
#   ./setup.sh sanitize-quick   the same for the loaders, physics, CL host code and one render (CI)
#   ./setup.sh python     install + build the module alone + install `import tsis` for /usr/bin/python3
#   ./setup.sh clang      build everything with clang and -Werror into build-clang/ (CI)
#   ./setup.sh tidy       clang-tidy (.clang-tidy) on the C++ files changed since .ci/tidy-base (CI)
#   ./setup.sh bench-blender [ARGS…]  install Blender (only if missing) and time tsis against EEVEE's
#                         viewport side by side: bench/eevee_side_by_side.sh ARGS → bench/results/eevee.md
#
# Idempotent; run as root on a fresh machine (or with the packages present).
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(
  build-essential cmake pkg-config ca-certificates
  pocl-opencl-icd ocl-icd-opencl-dev opencl-c-headers opencl-clhpp-headers clinfo
  libosmesa6-dev libegl-dev libegl-mesa0 libglm-dev libopenimageio-dev openimageio-tools
  libcgal-dev libeigen3-dev libcgal-demo libtinygltf-dev
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev
  libglfw3-dev libimgui-dev xvfb xauth
  libembree-dev clang-format python3
  python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib python3-venv python3-pip
  clang clang-tidy
)
BUILD_DIR=${TSIS_BUILD_DIR:-build}
JOBS=${TSIS_JOBS:-$(nproc)}

log() { echo "setup: $*" >&2; }

install_packages() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    log "all packages present"
    return
  fi
  if [ "$(id -u)" -ne 0 ]; then
    log "missing packages: ${missing[*]} — run as root (or install them) and retry"
    exit 1
  fi
  log "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# Real test meshes from CGAL's demo data (cow, head, elephant, dragon, …).
unpack_meshes() {
  local tarball=/usr/share/doc/libcgal-dev/data.tar.gz dest=data/meshes
  [ -f "$tarball" ] || tarball=$(ls /usr/share/doc/libcgal-*/data.tar.gz 2>/dev/null | head -n1 || true)
  if [ -z "$tarball" ] || [ ! -f "$tarball" ]; then
    log "CGAL data meshes not found; real meshes unavailable"
    return
  fi
  [ -f "$dest/.unpacked" ] && return
  mkdir -p "$dest"
  local tmp
  tmp=$(mktemp -d)
  tar -xzf "$tarball" -C "$tmp"
  for name in $(cat data/meshes.txt); do
    local f
    f=$(find "$tmp" -name "$name" -print -quit)
    if [ -n "$f" ]; then cp "$f" "$dest/"; else log "mesh $name not in $tarball"; fi
  done
  rm -rf "$tmp"
  touch "$dest/.unpacked"
  log "unpacked $(ls "$dest" | wc -l) meshes into $dest"
}

# build [--target T]: everything, or the targets named.
build() {
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$BUILD_DIR" -j "$JOBS" "$@"
}

# Everything (tests, bench, the Python module) with clang and warnings as
# errors; its compile_commands.json is what `tidy` reads.
CLANG_DIR=${TSIS_CLANG_BUILD_DIR:-build-clang}
clang_build() {
  CC=clang CXX=clang++ cmake -S . -B "$CLANG_DIR" -DCMAKE_BUILD_TYPE=Release -DTSIS_WERROR=ON \
      -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
  cmake --build "$CLANG_DIR" -j "$JOBS"
}

# ASan+UBSan build of our code (PoCL, LLVM and Mesa stay as Debian ships them;
# what they leak is suppressed by library in tests/sanitize/). -O1 -g1: stacks
# with lines at a fraction of -O0's run time. Usage: sanitize [TARGET…]
SANITIZE_DIR=${TSIS_SANITIZE_BUILD_DIR:-build-sanitize}
sanitize_build() {
  cmake -S . -B "$SANITIZE_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
      -DTSIS_SANITIZE=ON -DTSIS_BUILD_BENCH=OFF >/dev/null
  local targets=()
  for t in "$@"; do targets+=(--target "$t"); done
  cmake --build "$SANITIZE_DIR" -j "$JOBS" "${targets[@]}"
}

# What the Python tests need beyond Debian's packages: Ray (tsis.distributed's
# cluster engine, an optional dependency of the module) from PyPI, in a venv
# that sees Debian's numpy and pytest ($BUILD_DIR/pyenv; CTest's python.tests
# runs in it when it is there).
PYENV_RAY=${TSIS_RAY_VERSION:-ray==2.60.0}
python_env() {
  local venv="$BUILD_DIR/pyenv"
  if [ -x "$venv/bin/python" ] && "$venv/bin/python" -c 'import ray' 2>/dev/null; then return; fi
  log "installing $PYENV_RAY for the Python tests into $venv"
  mkdir -p "$BUILD_DIR"
  /usr/bin/python3 -m venv --system-site-packages "$venv"
  "$venv/bin/python" -m pip install -q --disable-pip-version-check "$PYENV_RAY"
}

if [ "${1:-}" = fuzz ]; then
  PACKAGES+=(libclang-rt-14-dev)
fi
# Blender is large and only this benchmark needs it: never in the default list.
if [ "${1:-}" = bench-blender ]; then
  PACKAGES+=(blender)
fi
install_packages
unpack_meshes
case "${1:-}" in
  fuzz | sanitize | sanitize-quick | clang | tidy | bench-blender) ;;
  # The module alone: the library it links, not the CLI, tests or benches.
  python) build --target tsis_python ;;
  test)
    python_env
    build
    ;;
  *) build ;;
esac
case "${1:-}" in
  render)
    "$BUILD_DIR/tsis" render -o tsis.png
    log "wrote tsis.png"
    ;;
  test)
    cd "$BUILD_DIR"
    ctest --output-on-failure -j "$JOBS" --timeout 1200
    ;;
  fuzz)
    tests/fuzz/run.sh "${2:-60}" "${@:3}"
    ;;
  sanitize)
    sanitize_build
    cd "$SANITIZE_DIR"
    ctest --output-on-failure -j "$JOBS" --timeout 3600
    ;;
  sanitize-quick)
    # What CI can afford: the module tests of the loaders, physics and CL host
    # code, and the smoke renders (tests/CMakeLists.txt), by CTest label.
    sanitize_build tsis tsis_mesh_tests tsis_physics_tests tsis_cl_tests
    cd "$SANITIZE_DIR"
    ctest --output-on-failure -j "$JOBS" --timeout 1800 -L '^(mesh|physics|cl|smoke)$'
    ;;
  python)
    # Into the interpreter's own site directory (/usr/local/lib/python3.11/dist-packages).
    cmake --install "$BUILD_DIR" --component python --strip
    /usr/bin/python3 -c 'import tsis; print("setup: import tsis works:", tsis.__file__)'
    ;;
  clang)
    clang_build
    ;;
  tidy)
    [ -f "$CLANG_DIR/compile_commands.json" ] || clang_build
    .ci/tidy "$CLANG_DIR"
    ;;
  bench-blender)
    # Builds tsis and bench_frame in build-bench/ (TSIS_BENCH_BUILD) itself.
    bench/eevee_side_by_side.sh "${@:2}"
    ;;
  "") ;;
  *) log "unknown step '$1' (render, test, fuzz, sanitize, sanitize-quick, python, clang, tidy or bench-blender)"; exit 2 ;;
esac
