#!/usr/bin/env bash
# Builds OpenRTM-aist C++ 2.0.x for the end-to-end tests on real OpenRTM-aist (examples' OpenRtmCppTest)
# from a checkout of https://github.com/OpenRTM/OpenRTM-aist (e.g. tag v2.0.2), with omniORB from
# Debian's packages, into one prefix per observer build:
#
#   ROOT/default    OBSERVER_ENABLE=OFF, the project's default: only the FSM4RTC RTC::ComponentObserver,
#                   the module ComponentObserverConsumer.so (the test runs it with and without preloading it)
#   ROOT/observer   OBSERVER_ENABLE=ON: the legacy OpenRTM::ComponentObserver in the library as well
#
# and into each, the example components of examples/openrtm-cpp and fsm_microwave, the checkout's StaticFsm Microwave machine. A prefix already built is kept;
# the components are rebuilt only when their sources changed (cmake decides).
#
#   scripts/openrtm-cpp.sh CHECKOUT [ROOT]     ROOT defaults to ~/.cache/rtcoord/openrtm-cpp
#
# Then: RTCOORD_OPENRTM_CPP=ROOT mvn -B -ntp verify -pl examples -am -Dtest=OpenRtmCppTest
set -euo pipefail

checkout="$(realpath "${1:?usage: scripts/openrtm-cpp.sh CHECKOUT [ROOT]}")"
root="${2:-${XDG_CACHE_HOME:-$HOME/.cache}/rtcoord/openrtm-cpp}"
components="$(cd "$(dirname "$0")/../examples/openrtm-cpp" && pwd)"
[ -f "$checkout/src/lib/rtm/Manager.cpp" ] || { echo "openrtm-cpp: $checkout is not an OpenRTM-aist C++ checkout" >&2; exit 1; }

# omniORB 4.2 from Debian (the library and headers, the IDL compiler, omniNames), and what the build
# runs: cmake, g++, pkg-config, python3 (OpenRTM-aist's stub wrapper).
missing=()
for package in libomniorb4-dev omniidl omniorb-nameserver uuid-dev cmake g++ pkg-config python3; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed' || missing+=("$package")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "openrtm-cpp: installing ${missing[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
fi

# The two builds share most objects: with ccache (used by OpenRTM-aist's CMakeLists when present),
# paths under / are hashed relative to the build directory, so the second build reuses the first's.
export CCACHE_BASEDIR=/

build_openrtm() { # VARIANT OBSERVER_ENABLE
  local prefix="$root/$1" build="$root/build/$1" started
  if [ -x "$prefix/bin/rtcd2" ]; then
    echo "openrtm-cpp: $prefix is built"
    return
  fi
  started=$(date +%s)
  echo "openrtm-cpp: building OpenRTM-aist into $prefix (OBSERVER_ENABLE=$2)"
  rm -rf "$build"
  mkdir -p "$build"
  # No examples or documents: the tests run our components; utils gives rtcd2 and rtm-skelwrapper.
  cmake -S "$checkout" -B "$build" -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_BUILD_TYPE= \
    -DOBSERVER_ENABLE="$2" -DEXAMPLES_ENABLE=OFF -DDOCUMENTS_ENABLE=OFF -DUTILS_ENABLE=ON \
    -DCMAKE_INSTALL_RPATH="$prefix/lib" -DCMAKE_INSTALL_RPATH_USE_LINK_PATH=ON >"$build.log" 2>&1 \
    || { echo "openrtm-cpp: cmake failed, see $build.log" >&2; exit 1; }
  nice -n 10 cmake --build "$build" -j2 >>"$build.log" 2>&1 \
    || { echo "openrtm-cpp: the build failed, see $build.log" >&2; exit 1; }
  cmake --install "$build" >>"$build.log" 2>&1 || { echo "openrtm-cpp: install failed, see $build.log" >&2; exit 1; }
  rm -rf "$build"
  echo "openrtm-cpp: $1 built in $(( $(date +%s) - started )) s"
}

build_components() { # VARIANT
  local prefix="$root/$1" build="$root/build/components-$1"
  # A build directory configured from another clone of this project cannot be reused.
  grep -qxF "CMAKE_HOME_DIRECTORY:INTERNAL=$components" "$build/CMakeCache.txt" 2>/dev/null || rm -rf "$build"
  mkdir -p "$build"
  cmake -S "$components" -B "$build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_INSTALL_PREFIX="$prefix" \
    -DCMAKE_INSTALL_RPATH="$prefix/lib" -DSTATICFSM_SOURCES="$checkout/examples/StaticFsm" >"$build.log" 2>&1 \
    || { echo "openrtm-cpp: cmake of the components failed, see $build.log" >&2; exit 1; }
  nice -n 10 cmake --build "$build" -j2 >>"$build.log" 2>&1 \
    && cmake --install "$build" >>"$build.log" 2>&1 \
    || { echo "openrtm-cpp: the components did not build, see $build.log" >&2; exit 1; }
}

build_openrtm default OFF
build_openrtm observer ON
build_components default
build_components observer
echo "openrtm-cpp: RTCOORD_OPENRTM_CPP=$root"
