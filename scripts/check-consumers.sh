#!/usr/bin/env bash
# Installs sss twice (static, from build/release; shared, into build/shared) and builds and runs
# integration/consumer against each install: through find_package(sss CONFIG), and the C program
# through pkg-config alone, checking that both give the same compile flags. Called by
# scripts/run-tests.sh after the release build.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

check_prefix() {  # name, prefix
  local name=$1 prefix=$2
  echo "== consumer ($name): CMake package"
  cmake -S integration/consumer -B "build/consumer-$name" -G Ninja -DCMAKE_PREFIX_PATH="$PWD/$prefix" \
    -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
  cmake --build "build/consumer-$name" --parallel "$jobs"
  LD_LIBRARY_PATH="$PWD/$prefix/lib" "build/consumer-$name/minimal_integration"
  LD_LIBRARY_PATH="$PWD/$prefix/lib" "build/consumer-$name/minimal_integration_cpp"

  echo "== consumer ($name): pkg-config"
  export PKG_CONFIG_PATH="$PWD/$prefix/lib/pkgconfig"
  local static_flag=()
  [[ $name == static ]] && static_flag=(--static)
  # shellcheck disable=SC2046
  cc -std=c99 -Wall -Werror integration/consumer/minimal_integration.c -o "build/consumer-$name/pc_minimal" \
    $(pkg-config --cflags sss egl) $(pkg-config --libs "${static_flag[@]}" sss egl) -lm
  LD_LIBRARY_PATH="$PWD/$prefix/lib" "build/consumer-$name/pc_minimal"
  # The tools through sss-tools.pc (C++: the kernel API and a fitted kernel).
  # shellcheck disable=SC2046
  c++ -std=c++17 -Wall -Werror integration/consumer/minimal_integration.cpp -o "build/consumer-$name/pc_tools" \
    $(pkg-config --cflags sss-tools) $(pkg-config --libs "${static_flag[@]}" sss-tools)
  LD_LIBRARY_PATH="$PWD/$prefix/lib" "build/consumer-$name/pc_tools"
  # The runtime library needs no NLopt: neither sss.pc nor, shared, libsss.so names it.
  if pkg-config --libs --static sss | grep nlopt >/dev/null; then
    echo "check-consumers: sss.pc (the runtime) asks for NLopt" >&2
    exit 1
  fi

  # The defines the CMake target gives its users must be the ones sss.pc gives.
  local cmake_defs pc_defs
  cmake_defs=$(grep 'minimal_integration\.c' "build/consumer-$name/compile_commands.json" | grep -o -- '-DSSS_[A-Z_]*' |
    sort -u | tr '\n' ' ' || true)
  pc_defs=$(pkg-config --cflags sss | grep -o -- '-DSSS_[A-Z_]*' | sort -u | tr '\n' ' ' || true)
  if [[ "$cmake_defs" != "$pc_defs" ]]; then
    echo "check-consumers: CMake gives '$cmake_defs' but sss.pc gives '$pc_defs'" >&2
    exit 1
  fi
  echo "== consumer ($name): CMake and pkg-config both define '${pc_defs}'"
}

cmake --install build/release --prefix build/prefix-static
check_prefix static build/prefix-static

cmake -S . -B build/shared -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBUILD_SHARED_LIBS=ON \
  -DSSS_BUILD_TESTS=OFF -DSSS_BUILD_DEMO=OFF -DSSS_BUILD_INTEGRATION=OFF
cmake --build build/shared --parallel "$jobs"
cmake --install build/shared --prefix build/prefix-shared
# The state guard's test hook is only in the tests' variant of the library (ctest
# library.has_no_test_hook checks the static libsss): not in the shared one's symbols either.
if nm -C build/prefix-shared/lib/libsss.so | grep restore_skip_mask; then
  echo "check-consumers: the shared libsss contains the state guard's test hook" >&2
  exit 1
fi
# The shared runtime needs no NLopt; the shared tools library does.
if readelf -d build/prefix-shared/lib/libsss.so | grep nlopt >/dev/null; then
  echo "check-consumers: the shared libsss (the runtime) needs NLopt" >&2
  exit 1
fi
readelf -d build/prefix-shared/lib/libsss_tools.so | grep nlopt >/dev/null  # the check sees NEEDED entries
check_prefix shared build/prefix-shared
echo "== consumer (subdirectory): add_subdirectory of this checkout"
cmake -S integration/consumer -B build/consumer-subdirectory -G Ninja -DSSS_SOURCE_DIR="$PWD"
cmake --build build/consumer-subdirectory --parallel "$jobs"
build/consumer-subdirectory/minimal_integration
build/consumer-subdirectory/minimal_integration_cpp
if [[ -e build/consumer-subdirectory/sss/tests || -e build/consumer-subdirectory/sss/demo ]]; then
  echo "check-consumers: as a subdirectory sss built its tests or demo" >&2
  exit 1
fi
echo "== consumer (FetchContent): FetchContent_MakeAvailable, its source pointed at this checkout"
cmake -S integration/consumer -B build/consumer-fetch -G Ninja -DSSS_FETCH=ON -DFETCHCONTENT_SOURCE_DIR_SSS="$PWD"
cmake --build build/consumer-fetch --parallel "$jobs"
build/consumer-fetch/minimal_integration
build/consumer-fetch/minimal_integration_cpp
if [[ -e build/consumer-fetch/_deps/sss-build/tests || -e build/consumer-fetch/_deps/sss-build/demo ]]; then
  echo "check-consumers: through FetchContent sss built its tests or demo" >&2
  exit 1
fi
echo "check-consumers: static and shared installs, a subdirectory and a FetchContent build run, for CMake and pkg-config consumers"
