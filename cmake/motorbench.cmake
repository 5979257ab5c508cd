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
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} INTERFACE ${ARGN})
  endif()
endfunction()
