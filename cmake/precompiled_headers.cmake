# elbowsim_precompile(<target> [EIGEN] [JSON] [DOCTEST])
#
# Precompiles the headers most of a target's files include (the standard library's
# common ones, and those named: Eigen, nlohmann/json, doctest), so that each
# file of the target parses them once per build, not once per file. Parsing Eigen or
# nlohmann/json costs about 2 s a file here, as much as compiling many of our files;
# CI builds the tree three times (Release, sanitizers, fuzzing), on 2 cores.
# docs/validation.md, "Sanitizers and fuzzing", has the measurement.
#
# The list is a target's own: the engine's never names a file format (its room may
# not use one, tests/layers.txt). A file still includes what it uses.
#
# Off by default; the sanitizer and fuzzing builds (.ci/sanitize, tests/fuzz/run.sh)
# turn it on. Not in the Release build, whose warnings are errors in CI: with the headers
# precompiled, GCC 12 no longer keeps its middle-end warnings (-Warray-bounds) out of the
# standard library's headers, and reports its known false positives there (bugs 105329,
# 105651) for lines such as `std::string(x) + " "`.
option(ELBOWSIM_PRECOMPILE "Precompile the common headers of each target (faster builds)" OFF)

function(elbowsim_precompile target)
  if(NOT ELBOWSIM_PRECOMPILE)
    return()
  endif()
  cmake_parse_arguments(PARSE_ARGV 1 use "EIGEN;JSON;DOCTEST" "" "")
  set(headers <algorithm> <cmath> <filesystem> <map> <memory> <optional> <stdexcept>
    <string> <vector>)
  if(use_EIGEN)
    list(APPEND headers <Eigen/Core> <Eigen/Geometry>)
  endif()
  if(use_JSON)
    list(APPEND headers <nlohmann/json.hpp>)
  endif()
  if(use_DOCTEST)
    list(APPEND headers <doctest/doctest.h>)
  endif()
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()
