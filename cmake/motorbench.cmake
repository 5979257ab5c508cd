# mb_library(NAME [DEPS ...]): a static library from every .cpp in the current folder, or an
# INTERFACE library while the folder has only headers. Public include root is the repo root,
# so code includes "pipelines/scene/scene.h", "shaders/pga.glsl" and so on.
#
# Every static library reuses one precompiled header (mb_pch, below): nlohmann/json, included
# by most harness headers, and the standard headers nearly every file includes, parsed once
# instead of once per file. A precompiled header is the same text included first, so no
# generated instruction changes (the measuring build keeps its flags); MB_PCH=OFF turns it off.
option(MB_PCH "Precompile nlohmann/json and the common standard headers" ON)
if(MB_PCH AND NOT TARGET mb_pch)
  add_library(mb_pch STATIC ${PROJECT_SOURCE_DIR}/cmake/pch.cpp)
  target_link_libraries(mb_pch PUBLIC nlohmann_json::nlohmann_json)
  target_precompile_headers(mb_pch PRIVATE <nlohmann/json.hpp> <algorithm> <cmath> <cstdint>
    <filesystem> <fstream> <functional> <map> <memory> <optional> <set> <sstream> <string>
    <vector>)
endif()

function(mb_library name)
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(srcs)
    add_library(${name} STATIC ${srcs})
    target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} PUBLIC ${ARGN})
    if(MB_PCH)
      target_precompile_headers(${name} REUSE_FROM mb_pch)
    endif()
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} INTERFACE ${ARGN})
  endif()
endfunction()
