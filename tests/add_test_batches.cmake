# Run after a test program is built (cmake -P): lists its tests and writes the
# file ctest reads to run them. A test of SOLO_FILE (the longest, by their ctest
# names) runs alone, as gtest_discover_tests would add it; the others run in
# batches of at most BATCH of one suite, one process each ("Suite.batch2"), so a
# suite's Vulkan context (tests/gpu_fixture.h) and the process's start are paid
# once a batch, not once a test: 0.74 s a GPU test under the sanitizers.
#   -D PROGRAM=exe -D OUTPUT=file.cmake -D ENVIRONMENT=a=1;b= -D BATCH=n -D SOLO_FILE=f -D WORKDIR=dir
cmake_minimum_required(VERSION 3.25)
execute_process(COMMAND "${PROGRAM}" --gtest_list_tests OUTPUT_VARIABLE listing RESULT_VARIABLE rc TIMEOUT 60)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} --gtest_list_tests failed (${rc}):\n${listing}")
endif()
file(STRINGS "${SOLO_FILE}" solo_lines REGEX "^[0-9]+ ")
set(solo "")
foreach(line IN LISTS solo_lines)
  string(REGEX REPLACE "^[0-9]+ " "" name "${line}")
  list(APPEND solo "${name}")
endforeach()

set(script "")
set(batch "")
set(batches 0)
set(suite "")
function(add_one name filter skips)
  string(APPEND script "add_test([==[${name}]==] [==[${PROGRAM}]==] [==[--gtest_filter=${filter}]==])\n"
                       "set_tests_properties([==[${name}]==] PROPERTIES ENVIRONMENT [==[${ENVIRONMENT}]==]"
                       " WORKING_DIRECTORY [==[${WORKDIR}]==]${skips})\n")
  set(script "${script}" PARENT_SCOPE)
endfunction()
macro(flush_batch)
  if(batch)
    math(EXPR batches "${batches} + 1")
    list(JOIN batch ":" filter)
    add_one("${suite}batch${batches}" "${filter}" "")
    set(batch "")
  endif()
endmacro()

string(REPLACE "\n" ";" lines "${listing}")
foreach(line IN LISTS lines)
  if(line MATCHES "^([^ #][^ ]*\\.)")  # a suite: "Suite." or "Prefix/Suite.  # TypeParam = ..."
    flush_batch()
    set(suite "${CMAKE_MATCH_1}")
    set(batches 0)
  elseif(line MATCHES "^  ([^ ]+)( +# GetParam\\(\\) = (.*))?$")
    set(test "${suite}${CMAKE_MATCH_1}")
    # ctest's name, as gtest_discover_tests gives it: a parameter's index is its value.
    set(name "${test}")
    if(NOT "${CMAKE_MATCH_3}" STREQUAL "")
      string(REGEX REPLACE "/[0-9]+$" "/${CMAKE_MATCH_3}" name "${test}")
    endif()
    if(name IN_LIST solo)
      add_one("${name}" "${test}" [==[ SKIP_REGULAR_EXPRESSION [=[\[  SKIPPED \]]=]]==])
    else()
      list(APPEND batch "${test}")
      list(LENGTH batch size)
      if(size GREATER_EQUAL BATCH)
        flush_batch()
      endif()
    endif()
  endif()
endforeach()
flush_batch()
file(WRITE "${OUTPUT}.new" "${script}")
file(RENAME "${OUTPUT}.new" "${OUTPUT}")
