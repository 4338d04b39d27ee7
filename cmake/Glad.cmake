# GL entry points come through a glad loader generated at configure time by Debian's python3-glad
# (--reproducible: the Khronos XML shipped in the package, never fetched). The same loader serves
# OSMesa (OSMesaGetProcAddress) and GLFW (glfwGetProcAddress), so no direct libGL symbol is used.
find_program(GLAD_EXECUTABLE glad REQUIRED)
set(GLAD_OUT ${CMAKE_BINARY_DIR}/glad)
if(NOT EXISTS ${GLAD_OUT}/src/gl.c)
  execute_process(
    COMMAND ${GLAD_EXECUTABLE} --api gl:core=4.5 --extensions "" --out-path ${GLAD_OUT}
            --reproducible --quiet c
    RESULT_VARIABLE glad_result OUTPUT_QUIET ERROR_QUIET)
  if(NOT glad_result EQUAL 0 OR NOT EXISTS ${GLAD_OUT}/src/gl.c)
    message(FATAL_ERROR "glad failed to generate the GL 4.5 core loader (python3-glad installed?)")
  endif()
endif()
add_library(tlab_glad STATIC ${GLAD_OUT}/src/gl.c)
target_include_directories(tlab_glad SYSTEM PUBLIC ${GLAD_OUT}/include)
set_target_properties(tlab_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
