# mb_library(NAME [DEPS ...] [FOLDERS SUB ...]): a static library from every .cpp in the current
# folder and in its sub-folders SUB (a room's stages, e.g. pipelines/scene/gltf), or an
# INTERFACE library while they have only headers. Public include root is the repo root,
# so code includes "pipelines/scene/scene.h", "shaders/pga.glsl" and so on.
#
# The harness's static libraries reuse one precompiled header (mb_pch, below): nlohmann/json,
# included by most harness headers, and the standard headers nearly every file includes, parsed
# once instead of once per file (report_document.cpp: 6.4 s of CPU instead of 12.7). Not in the
# rooms whose code bench and time measure (MB_MEASURED_DIRS): the flags stay the same with a
# PCH, but GCC's register and scheduling choices may not (3 of 10 files compared differed, the
# Highway and bench kernels did not), so that code is compiled exactly as before. MB_PCH=OFF
# turns it off everywhere.
option(MB_PCH "Precompile nlohmann/json and the common standard headers" ON)
set(MB_MEASURED_DIRS pipelines kernels shaders harness/bench harness/timing harness/render)

# mb_unmeasured(TARGET): TARGET's code is neither measured nor heavy at run time (the harness
# rooms that time nothing spend it in processes, GL and files; most test code starts processes
# and compares what they wrote), so the quick build (MB_QUICK_BUILD, scripts/test.sh), which
# measures nothing, compiles it at -O0: GCC's code generation is most of such a file's compile.
# A PCH a target reuses must be made at the same level (GCC ignores one made at another).
function(mb_unmeasured target)
  if(MB_QUICK_BUILD)
    target_compile_options(${target} PRIVATE -O0)
  endif()
endfunction()
if(MB_PCH AND NOT TARGET mb_pch)
  add_library(mb_pch STATIC ${PROJECT_SOURCE_DIR}/cmake/pch.cpp)
  target_link_libraries(mb_pch PUBLIC nlohmann_json::nlohmann_json)
  target_precompile_headers(mb_pch PRIVATE <nlohmann/json.hpp> <algorithm> <cmath> <cstdint>
    <filesystem> <fstream> <functional> <map> <memory> <optional> <set> <sstream> <string>
    <vector>)
  mb_unmeasured(mb_pch)  # only the rooms that time nothing reuse it (below)
endif()

# Unity builds (-DMB_UNITY=ON, scripts/test.sh sets it for a new folder): a target's .cpp files
# compiled up to MB_UNITY_BATCH at a time as one translation unit, so the headers they share
# (tinygltf, nlohmann/json, GLM, gtest) are parsed once per batch instead of once per file.
# Inlining across the files of a batch can change, so the code bench and time measure
# (MB_MEASURED_DIRS) is built file by file in the measuring build and joins batches only in the
# quick -O1 test build (MB_QUICK_BUILD=ON), which measures nothing. cmake/unity_groups.py fills
# the batches: never two files that define the same file-local name (a load/render/kCases helper
# in an anonymous namespace) in one batch, and alone the files that define an implementation
# macro (tinygltf's, stb's), re-include themselves per SIMD target (Highway's
# HWY_TARGET_INCLUDE) or start with the line "// MB_UNITY_ALONE".
option(MB_UNITY "Unity builds (batches of MB_UNITY_BATCH files) where they do not touch measured code" OFF)
set(MB_UNITY_BATCH 8 CACHE STRING "Files per unity batch (MB_UNITY=ON)")
find_package(Python3 COMPONENTS Interpreter)

# mb_unity(TARGET MEASURED): TARGET's sources in unity batches when MB_UNITY allows it.
function(mb_unity target measured)
  if(NOT MB_UNITY OR (measured AND NOT MB_QUICK_BUILD))
    return()
  endif()
  if(NOT Python3_Interpreter_FOUND)
    message(WARNING "MB_UNITY=ON needs python3 (cmake/unity_groups.py): ${target} is built file by file")
    return()
  endif()
  get_target_property(srcs ${target} SOURCES)
  get_target_property(dir ${target} SOURCE_DIR)
  set(cpps "")
  foreach(src ${srcs})
    if(NOT IS_ABSOLUTE "${src}")
      set(src "${dir}/${src}")
    endif()
    if(src MATCHES "\\.cpp$" AND EXISTS "${src}")
      list(APPEND cpps "${src}")
    endif()
  endforeach()
  if(NOT cpps)
    return()
  endif()
  # Grouped at configure time: an edit that adds a clash to a configured unity folder fails its
  # batch (scripts/build_fallback.sh says so); `cmake .` in the folder groups the files again.
  execute_process(COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/cmake/unity_groups.py ${PROJECT_SOURCE_DIR}
    ${MB_UNITY_BATCH} ${cpps}
    OUTPUT_VARIABLE groups RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake/unity_groups.py failed for ${target}")
  endif()
  string(STRIP "${groups}" groups)
  string(REPLACE "\n" ";" groups "${groups}")
  foreach(src group IN ZIP_LISTS cpps groups)
    if(group STREQUAL "-")
      set_source_files_properties("${src}" TARGET_DIRECTORY ${target} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    else()
      set_source_files_properties("${src}" TARGET_DIRECTORY ${target} PROPERTIES UNITY_GROUP "${target}_${group}")
    endif()
  endforeach()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
endfunction()

function(mb_library name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "FOLDERS")
  set(globs ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  foreach(sub ${arg_FOLDERS})
    list(APPEND globs ${CMAKE_CURRENT_SOURCE_DIR}/${sub}/*.cpp)
  endforeach()
  file(GLOB srcs CONFIGURE_DEPENDS ${globs})
  if(srcs)
    add_library(${name} STATIC ${srcs})
    target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} PUBLIC ${arg_UNPARSED_ARGUMENTS})
    file(RELATIVE_PATH dir ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
    set(measured FALSE)
    foreach(m ${MB_MEASURED_DIRS})
      if(dir STREQUAL m OR dir MATCHES "^${m}/")
        set(measured TRUE)
      endif()
    endforeach()
    if(NOT measured)
      mb_unmeasured(${name})
      if(MB_PCH)
        target_precompile_headers(${name} REUSE_FROM mb_pch)
      endif()
    endif()
    mb_unity(${name} ${measured})
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} INTERFACE ${arg_UNPARSED_ARGUMENTS})
  endif()
endfunction()
