# mb_library(NAME [DEPS ...]): a static library from every .cpp in the current folder, or an
# INTERFACE library while the folder has only headers. Public include root is the repo root,
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
if(MB_PCH AND NOT TARGET mb_pch)
  add_library(mb_pch STATIC ${PROJECT_SOURCE_DIR}/cmake/pch.cpp)
  target_link_libraries(mb_pch PUBLIC nlohmann_json::nlohmann_json)
  target_precompile_headers(mb_pch PRIVATE <nlohmann/json.hpp> <algorithm> <cmath> <cstdint>
    <filesystem> <fstream> <functional> <map> <memory> <optional> <set> <sstream> <string>
    <vector>)
endif()

# Unity builds (-DMB_UNITY=ON, scripts/test.sh sets it for a new folder): a target's .cpp files
# compiled MB_UNITY_BATCH at a time as one translation unit, so the headers they share (tinygltf,
# nlohmann/json, GLM, gtest) are parsed once per batch instead of once per file. Inlining across
# the files of a batch can change, so the code bench and time measure (MB_MEASURED_DIRS) is
# built file by file in the measuring build and joins batches only in the quick -O1 test build
# (MB_QUICK_BUILD=ON), which measures nothing. Files that define an implementation macro
# (tinygltf's, stb's) or re-include themselves per SIMD target (Highway's HWY_TARGET_INCLUDE)
# stay on their own, and so does a file whose first line is "// MB_UNITY_ALONE" (a test whose
# file-local helpers, load/render/kCases, are named as in other tests of its room).
option(MB_UNITY "Unity builds (batches of MB_UNITY_BATCH files) where they do not touch measured code" OFF)
set(MB_UNITY_BATCH 8 CACHE STRING "Files per unity batch (MB_UNITY=ON)")

# mb_unity(TARGET MEASURED): TARGET's sources in unity batches when MB_UNITY allows it.
function(mb_unity target measured)
  if(NOT MB_UNITY OR (measured AND NOT MB_QUICK_BUILD))
    return()
  endif()
  get_target_property(srcs ${target} SOURCES)
  get_target_property(dir ${target} SOURCE_DIR)
  foreach(src ${srcs})
    if(NOT IS_ABSOLUTE "${src}")
      set(src "${dir}/${src}")
    endif()
    if(src MATCHES "\\.cpp$" AND EXISTS "${src}")
      file(STRINGS "${src}" alone REGEX "HWY_TARGET_INCLUDE|#define [A-Z_]+_IMPLEMENTATION|^// MB_UNITY_ALONE")
      if(alone)
        set_source_files_properties("${src}" TARGET_DIRECTORY ${target} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
      endif()
    endif()
  endforeach()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${MB_UNITY_BATCH})
endfunction()

function(mb_library name)
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(srcs)
    add_library(${name} STATIC ${srcs})
    target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} PUBLIC ${ARGN})
    file(RELATIVE_PATH dir ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
    set(measured FALSE)
    foreach(m ${MB_MEASURED_DIRS})
      if(dir STREQUAL m OR dir MATCHES "^${m}/")
        set(measured TRUE)
      endif()
    endforeach()
    if(MB_PCH AND NOT measured)
      target_precompile_headers(${name} REUSE_FROM mb_pch)
    endif()
    mb_unity(${name} ${measured})
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} INTERFACE ${ARGN})
  endif()
endfunction()
