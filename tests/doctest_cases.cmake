# Writes one ctest test per doctest case of a test executable (run after each link,
# by elbowsim_doctest_cases in tests/CMakeLists.txt):
#   cmake -D EXECUTABLE=<test program> -D PREFIX=<name prefix> -D OUT=<ctest file>
#         -P doctest_cases.cmake
# Each test is named "<PREFIX>: <case>" and runs `<program> --test-case=<case>`. The
# properties (labels, environment, timeout, the one-case check) come from the variables
# case_* that the including file sets when ctest reads it.
#
# Not doctest_discover_tests (Debian's doctest.cmake): it splits the case list as a CMake
# list, so a case named with ';' or '[' becomes pieces that match no case, and a doctest
# run that matches no case passes. Here the output is cut into lines as text, every
# line is checked, and the count is checked against doctest's own.
cmake_minimum_required(VERSION 3.20)

foreach(variable EXECUTABLE PREFIX OUT)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "doctest_cases.cmake: -D ${variable}=... is missing")
  endif()
endforeach()

execute_process(COMMAND "${EXECUTABLE}" --list-test-cases
  OUTPUT_VARIABLE output ERROR_VARIABLE errors RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "doctest_cases.cmake: ${EXECUTABLE} --list-test-cases failed (${result}):\n"
    "${output}${errors}")
endif()

# The cases of the doctest suite "long" (TEST_CASE(... * doctest::test_suite("long"))):
# the numbers' long runs, labelled "long" too. .ci/sanitize leaves them out (ctest -LE
# long); the Release suite runs them.
execute_process(COMMAND "${EXECUTABLE}" --list-test-cases --test-suite=long
  OUTPUT_VARIABLE long_output ERROR_VARIABLE errors RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "doctest_cases.cmake: ${EXECUTABLE} --list-test-cases --test-suite=long "
    "failed (${result}):\n${long_output}${errors}")
endif()
set(long_cases "\n${long_output}")

set(script "")
set(seen "\n")  # every case name so far, lower case, one a line: doctest filters ignore case
set(count 0)
set(expected -1)
set(rest "${output}")
while(NOT rest STREQUAL "")
  string(FIND "${rest}" "\n" end)
  if(end EQUAL -1)
    set(line "${rest}")
    set(rest "")
  else()
    string(SUBSTRING "${rest}" 0 ${end} line)
    math(EXPR end "${end} + 1")
    string(SUBSTRING "${rest}" ${end} -1 rest)
  endif()
  if(line MATCHES "^\\[doctest\\] unskipped test cases passing the current filters: ([0-9]+)")
    set(expected ${CMAKE_MATCH_1})
  endif()
  if(line STREQUAL "" OR line MATCHES "^\\[doctest\\] " OR line MATCHES "^=+$")
    continue()
  endif()
  set(name "${PREFIX}: ${line}")
  if(name MATCHES "\\]==\\]")
    message(FATAL_ERROR "doctest_cases.cmake: the case \"${line}\" contains ]==]")
  endif()
  string(TOLOWER "${line}" lower)
  string(FIND "${seen}" "\n${lower}\n" found)
  if(NOT found EQUAL -1)
    message(FATAL_ERROR "doctest_cases.cmake: two cases named \"${line}\" (doctest ignores case)")
  endif()
  string(APPEND seen "${lower}\n")
  # doctest's filters split at commas; an escaped one is part of the name.
  string(REPLACE "," "\\," filter "${line}")
  set(labels "\${case_label}")
  string(FIND "${long_cases}" "\n${line}\n" found)
  if(NOT found EQUAL -1)
    set(labels "\${case_label};long")
  endif()
  string(APPEND script
    "add_test([==[${name}]==] \"${EXECUTABLE}\" [==[--test-case=${filter}]==])\n"
    "set_tests_properties([==[${name}]==] PROPERTIES LABELS \"${labels}\"\n"
    "  WORKING_DIRECTORY \"\${case_directory}\" ENVIRONMENT \"\${case_environment}\"\n"
    "  FAIL_REGULAR_EXPRESSION \"\${case_not_one}\")\n"
    "if(case_timeout)\n"
    "  set_tests_properties([==[${name}]==] PROPERTIES TIMEOUT \"\${case_timeout}\")\n"
    "endif()\n")
  math(EXPR count "${count} + 1")
endwhile()

if(NOT count EQUAL expected)
  message(FATAL_ERROR "doctest_cases.cmake: read ${count} cases from ${EXECUTABLE}, "
    "which lists ${expected}")
endif()
file(WRITE "${OUT}" "${script}")
