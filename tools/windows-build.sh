#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The Windows build made on Linux (docs/windows.md): builds the third-party
# libraries vendored under third_party/ for x86_64-w64-mingw32 as static
# libraries into a cache prefix that later runs reuse, then configures and
# builds Tactus with the `windows` preset (cmake/toolchain-mingw64.cmake).
# A library is built again only when its install stamp (its version and a hash
# of its sources and build file) differs from the one recorded.
# Needs g++-mingw-w64-x86-64 (the -posix compilers), libz-mingw-w64-dev, cmake,
# ninja and the header-only libraries (nlohmann-json3-dev, libcli11-dev,
# libeigen3-dev) and liblouis-data (the tables).
# Usage: tools/windows-build.sh [package] [TARGET...]   (default target: tactus-cli)
#   package: then the NSIS installer (CPack, packaging/windows; needs nsis):
#   build/windows/package/tactus-<version>-win64.exe
# Usage: tools/windows-build.sh tests [TARGET...]
#   GoogleTest (Debian's googletest sources) into the prefix too, and the test
#   executables in build/windows/tests (default: translate, layout, plan,
#   edit, encode, estimate, motion and workers tests);
#   tools/windows-core-tests.sh runs them under Wine.
# Environment: TACTUS_WINDOWS_DEPS (default build/windows-deps), JOBS (default 2).
set -eu
package=0
tests=0
if [ "${1:-}" = tests ]; then
    tests=1
    shift
    [ -d /usr/src/googletest ] || { echo "windows-build: no /usr/src/googletest (apt-get install googletest)" >&2; exit 2; }
elif [ "${1:-}" = package ]; then
    package=1
    shift
    command -v makensis >/dev/null 2>&1 || { echo "windows-build: makensis not found (apt-get install nsis)" >&2; exit 2; }
fi
root=$(cd "$(dirname "$0")/.." && pwd)
deps=${TACTUS_WINDOWS_DEPS:-"$root/build/windows-deps"}
jobs=${JOBS:-2}
triple=x86_64-w64-mingw32
tp="$root/third_party"
own="$root/cmake/windows-deps"

command -v $triple-gcc-posix >/dev/null 2>&1 || { echo "windows-build: $triple-gcc-posix not found (apt-get install g++-mingw-w64-x86-64)" >&2; exit 2; }
[ -f /usr/$triple/include/zlib.h ] || { echo "windows-build: no zlib for MinGW (apt-get install libz-mingw-w64-dev)" >&2; exit 2; }
mkdir -p "$deps/stamps" "$deps/build"

step_start=0
step() {  # step NAME: starts timing a step
    step_name=$1
    step_start=$(date +%s)
}
step_done() {
    echo "windows-build: $step_name: $(( $(date +%s) - step_start )) s"
}

# dep NAME VERSION SOURCE_DIR [CMAKE_ARGS...]: configure, build and install one
# library unless its stamp matches.
dep() {
    name=$1 version=$2 src=$3
    shift 3
    hashed="$tp/$name"
    [ -d "$hashed" ] || hashed=$src
    stamp="$version $( (cd "$hashed" && find . -type f | LC_ALL=C sort | xargs cat; \
        cat "$own/$name/CMakeLists.txt" 2>/dev/null; echo "$*") | sha256sum | cut -c1-16)"
    if [ -f "$deps/stamps/$name" ] && [ "$(cat "$deps/stamps/$name")" = "$stamp" ]; then
        echo "windows-build: $name $version: cached"
        return 0
    fi
    step "$name $version"
    rm -rf "$deps/build/$name"
    nice -n 5 cmake -S "$src" -B "$deps/build/$name" -G Ninja \
        -DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchain-mingw64.cmake" \
        -DTACTUS_WINDOWS_DEPS="$deps" -DCMAKE_INSTALL_PREFIX="$deps" \
        -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=OFF "$@" >"$deps/build/$name.log" 2>&1 ||
        { tail -30 "$deps/build/$name.log" >&2; exit 1; }
    nice -n 5 cmake --build "$deps/build/$name" -j"$jobs" --target install >>"$deps/build/$name.log" 2>&1 ||
        { tail -30 "$deps/build/$name.log" >&2; exit 1; }
    echo "$stamp" >"$deps/stamps/$name"
    step_done
}

# zlib comes from Debian (libz-mingw-w64-dev), in /usr/x86_64-w64-mingw32.
dep sqlite 3.40.1 "$own/sqlite"
dep md4c 0.4.8 "$own/md4c"
dep pugixml 1.13 "$tp/pugixml" -DPUGIXML_BUILD_TESTS=OFF
dep libserialport 0.1.1 "$own/libserialport"
dep hidapi 0.13.1 "$own/hidapi"
dep libzip 1.9.2 "$tp/libzip" -DBUILD_TOOLS=OFF -DBUILD_REGRESS=OFF -DBUILD_EXAMPLES=OFF \
    -DBUILD_DOC=OFF -DENABLE_COMMONCRYPTO=OFF -DENABLE_GNUTLS=OFF -DENABLE_MBEDTLS=OFF \
    -DENABLE_OPENSSL=OFF -DENABLE_WINDOWS_CRYPTO=OFF -DENABLE_BZIP2=OFF -DENABLE_LZMA=OFF \
    -DENABLE_ZSTD=OFF
# The tables stay Debian's (liblouis-data), read by the Windows program through Wine's Z: drive.
dep liblouis 3.24.0 "$own/liblouis" -DLOUIS_TABLESDIR=/usr/share/liblouis/tables
if [ $tests = 1 ]; then
    dep googletest 1.12.1 /usr/src/googletest -DBUILD_GMOCK=ON -DINSTALL_GTEST=ON
fi

# The header-only libraries, used from /usr/include through a prefix that holds
# only them (never the build machine's whole /usr/include), with their CMake
# package files copied so that they resolve to this prefix.
mkdir -p "$deps/include" "$deps/share/cmake" "$deps/share/eigen3"
ln -sfn /usr/include/nlohmann "$deps/include/nlohmann"
ln -sfn /usr/include/CLI "$deps/include/CLI"
ln -sfn /usr/include/eigen3 "$deps/include/eigen3"
cp -r /usr/share/cmake/nlohmann_json /usr/share/cmake/CLI11 "$deps/share/cmake/"
cp -r /usr/share/eigen3/cmake "$deps/share/eigen3/"

cd "$root"
if [ $tests = 1 ]; then
    # The installer's build folder with the tests switched on, so core is
    # compiled once for both (a later `package` run switches them off again
    # through the preset, and compiles nothing more). Only the named test
    # executables are built. Tests are listed when ctest runs them (under
    # Wine), not at build time.
    step "Tactus configure (tests)"
    TACTUS_WINDOWS_DEPS="$deps" nice -n 5 cmake --preset windows -DTACTUS_WINDOWS_DEPS="$deps" \
        -DTACTUS_BUILD_TESTS=ON -DCMAKE_GTEST_DISCOVER_TESTS_DISCOVERY_MODE=PRE_TEST \
        -DTACTUS_TEST_DIRS="${TACTUS_TEST_DIRS:-translate;layout;plan;edit;encode;estimate;motion;workers}" >/dev/null
    step_done
    step "Tactus tests build"
    if [ $# -eq 0 ]; then set -- translate_tests layout_tests plan_tests edit_tests encode_tests estimate_tests motion_tests workers_tests; fi
    nice -n 5 cmake --build build/windows -j"$jobs" --target "$@"
    step_done
    exit 0
fi
step "Tactus configure"
TACTUS_WINDOWS_DEPS="$deps" nice -n 5 cmake --preset windows -DTACTUS_WINDOWS_DEPS="$deps" >/dev/null
step_done
step "Tactus build"
if [ $# -eq 0 ]; then set -- tactus-cli; fi
nice -n 5 cmake --build build/windows -j"$jobs" --target "$@"
step_done
if [ $package = 1 ]; then
    step "Tactus package"
    # `all` first, at this script's -j (cpack's own build of it would use
    # every core); cpack installs into its staging folder and runs makensis.
    nice -n 5 cmake --build build/windows -j"$jobs"
    (cd build/windows && nice -n 5 cpack --config CPackConfig.cmake) >build/windows/cpack.log 2>&1 ||
        { tail -30 build/windows/cpack.log >&2; exit 1; }
    step_done
    ls -l build/windows/package/*.exe
fi
