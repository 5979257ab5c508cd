# mb_library(NAME [DEPS ...]): a static library from every .cpp in the current folder, or an
# INTERFACE library while the folder has only headers. Public include root is the repo root,
# so code includes "pipelines/scene/scene.h", "shaders/pga.glsl" and so on.
function(mb_library name)
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(srcs)
    add_library(${name} STATIC ${srcs})
    target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} PUBLIC ${ARGN})
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} INTERFACE ${ARGN})
  endif()
endfunction()
