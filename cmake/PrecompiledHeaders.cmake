# Precompiled headers: the standard library and the header-only libraries
# every stage parses (nlohmann/json, GoogleTest, CLI11, Qt) are compiled once
# per build and reused by every target of the same kind, instead of being
# parsed again in each of several hundred translation units. Off by default:
# measured on core it saved little (its files spend their time instantiating
# and optimising templates, not parsing; bench/ci/RESULTS.md), and with it
# GCC 12 at -O2 reports false -Warray-bounds errors inside libstdc++'s
# std::string (app/cups/discovery.cpp, core/spool/spool.cpp), which the same
# files without it do not.
# SPDX-License-Identifier: GPL-3.0-or-later
option(TACTUS_PCH "Precompile the heavy headers (see above: off by default)" OFF)

set(TACTUS_PCH_STD
  <algorithm> <array> <atomic> <chrono> <cmath> <cstddef> <cstdint> <cstdio> <cstdlib> <cstring>
  <deque> <expected> <filesystem> <fstream> <functional> <iostream> <limits> <map> <memory>
  <mutex> <optional> <random> <set> <span> <sstream> <string> <string_view> <thread> <tuple>
  <unordered_map> <utility> <variant> <vector>)

# tactus_pch_group(name headers... [LINK libs...]): an object library whose
# only job is to compile the precompiled header that tactus_use_pch(target
# name) reuses. Targets that reuse it must compile with the same options
# (GCC refuses a header built with others: -Winvalid-pch, an error here).
function(tactus_pch_group name)
  cmake_parse_arguments(G "" "" "HEADERS;LINK" ${ARGN})
  if(NOT TACTUS_PCH)
    return()
  endif()
  set(anchor ${CMAKE_BINARY_DIR}/pch/${name}.cpp)
  file(WRITE ${anchor} "// The anchor of the ${name} precompiled header.\n")
  add_library(${name} OBJECT ${anchor})
  target_precompile_headers(${name} PRIVATE ${G_HEADERS})
  target_link_libraries(${name} PRIVATE tactus_warnings ${G_LINK})
endfunction()

function(tactus_use_pch target group)
  if(TACTUS_PCH AND TARGET ${group})
    target_precompile_headers(${target} REUSE_FROM ${group})
  endif()
endfunction()
