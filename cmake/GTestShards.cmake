# shadowlab_gtest(TARGET [SHARDS n] [PREFIX p] [LABELS label...] [COST c])
#
# Registers a GoogleTest executable with CTest as SHARDS processes, each running its share of the
# cases (GoogleTest's own sharding: GTEST_TOTAL_SHARDS, GTEST_SHARD_INDEX), not as one process per
# case. Measured on a fresh build (2 cores, llvmpipe): a process per case spent most of its time
# starting, not testing (an EGL context, LLVM's relocations, fresh pages, ASan's shadow memory):
# the 79 render cases took 67 s of CTest time one by one and 17.5 s in one process, the 152
# sanitized loader cases 41 s and 6.5 s. Shards keep both cores busy.
#
# -DSHADOWLAB_TEST_PER_CASE=ON registers every case as its own CTest test instead
# (gtest_discover_tests), for `ctest -R Suite.Case`; in the default build one case runs as
# `build/tests/<suite>/<executable> --gtest_filter=Suite.Case`.
option(SHADOWLAB_TEST_PER_CASE "Register every GoogleTest case as its own CTest test" OFF)

function(shadowlab_gtest target)
  cmake_parse_arguments(arg "" "SHARDS;PREFIX;COST" "LABELS" ${ARGN})
  if(NOT arg_SHARDS)
    set(arg_SHARDS 1)
  endif()
  if(SHADOWLAB_TEST_PER_CASE)
    gtest_discover_tests(${target} TEST_PREFIX "${arg_PREFIX}" DISCOVERY_TIMEOUT 120
                         PROPERTIES LABELS "${arg_LABELS}")
    return()
  endif()
  math(EXPR last "${arg_SHARDS} - 1")
  foreach(index RANGE ${last})
    set(name ${arg_PREFIX}${target})
    if(arg_SHARDS GREATER 1)
      math(EXPR number "${index} + 1")
      string(APPEND name ".${number}of${arg_SHARDS}")
    endif()
    add_test(NAME ${name} COMMAND ${target})
    set_tests_properties(${name} PROPERTIES LABELS "${arg_LABELS}" TIMEOUT 600
                         ENVIRONMENT "GTEST_TOTAL_SHARDS=${arg_SHARDS};GTEST_SHARD_INDEX=${index}")
    if(arg_COST)
      set_tests_properties(${name} PROPERTIES COST ${arg_COST})
    endif()
  endforeach()
endfunction()
