# SPDX-License-Identifier: MIT
# Run at build time (POST_BUILD of a test executable) by formflow_gtest_suites(): lists
# the executable's GoogleTest cases and writes a ctest include file with one test per
# test *suite* (`--gtest_filter=Suite.*`), named PREFIX.Suite (two folders may have a
# suite of the same name). Inputs: EXECUTABLE, OUTPUT, PREFIX, LABEL, PROCESSORS (the
# cores each entry keeps busy: 1 for a test process, the rank count for one that starts
# mpirun). No timeout of its own: the caller's ctest --timeout applies (./test 900 s,
# the sanitizers' 1800 s).
execute_process(COMMAND "${EXECUTABLE}" --gtest_list_tests
                OUTPUT_VARIABLE listing RESULT_VARIABLE status TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests failed (${status})")
endif()
string(REPLACE ";" "\\;" listing "${listing}")
string(REPLACE "\n" ";" lines "${listing}")
set(suite "")
set(count 0)
set(script "")
# One entry per suite; COST = its number of cases, so that ctest -j starts the largest
# groups first and no long group is left alone at the end.
if(NOT PROCESSORS)
  set(PROCESSORS 1)
endif()
macro(flush_suite)
  if(NOT suite STREQUAL "")
    string(APPEND script
      "add_test([=[${PREFIX}.${suite}]=] [=[${EXECUTABLE}]=] [=[--gtest_filter=${suite}.*]=])\n"
      "set_tests_properties([=[${PREFIX}.${suite}]=] PROPERTIES LABELS [=[${LABEL}]=] COST ${count}"
      " PROCESSORS ${PROCESSORS})\n")
  endif()
endmacro()
foreach(line IN LISTS lines)
  if(line MATCHES "^([^ #][^ ]*)\\.")
    flush_suite()
    set(suite "${CMAKE_MATCH_1}")
    set(count 0)
  elseif(line MATCHES "^  [^ ]")
    math(EXPR count "${count} + 1")
  endif()
endforeach()
flush_suite()
file(WRITE "${OUTPUT}" "${script}")
