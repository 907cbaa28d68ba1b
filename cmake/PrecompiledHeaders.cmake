# Precompiled headers, only where the numbers pay (docs/build-times.md): a third-party header that
# costs 3-4 s of CPU to parse and is included by every file of many targets (GoogleTest, in the
# tests). Loading a precompiled header is not free (0.5-1 s per file for one of 90 MB, and building
# it 8-10 s), so the standard library and GLM alone, which parse in 1-2 s, and nlohmann-json and
# CLI11, whose files spend most of their 10-20 s compiling the library's templates and inline
# functions rather than parsing it, are left out.
# Only headers from outside the project go in, so a layer still cannot see the headers of a layer
# above it. -DSHADOWLAB_PCH=OFF turns them off (e.g. to check every file includes what it uses).
option(SHADOWLAB_PCH "Precompile the heavy third-party headers" ON)

# shadowlab_precompile(TARGET HEADER...)
function(shadowlab_precompile target)
  if(SHADOWLAB_PCH)
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()

# shadowlab_reuse_precompiled(TARGET FROM): TARGET compiles with FROM's precompiled header (the same
# compiler flags are needed; GCC says where they differ, -Winvalid-pch).
function(shadowlab_reuse_precompiled target from)
  if(SHADOWLAB_PCH)
    target_precompile_headers(${target} REUSE_FROM ${from})
  endif()
endfunction()

# shadowlab_precompiled_header_owner(NAME HEADERS header... [LINK target...] [OPTIONS option...]):
# an object library whose only job is to build a precompiled header that other targets reuse
# (shadowlab_reuse_precompiled); OPTIONS are the compile options its users share.
function(shadowlab_precompiled_header_owner name)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "" "HEADERS;LINK;OPTIONS")
  set(anchor ${CMAKE_CURRENT_BINARY_DIR}/${name}.cpp)
  file(CONFIGURE OUTPUT ${anchor} CONTENT "// Anchor of a precompiled header that other targets reuse.\n")
  add_library(${name} OBJECT ${anchor})
  target_link_libraries(${name} PRIVATE ${ARG_LINK})
  target_compile_options(${name} PRIVATE ${ARG_OPTIONS})
  shadowlab_precompile(${name} ${ARG_HEADERS})
endfunction()
