# Generates the OpenGL 4.5 core loader with Debian's glad at build time (offline, --reproducible).
# The loader has no built-in library loading: the active Context supplies getProcAddress.
find_program(GLAD_EXECUTABLE glad PATHS /usr/bin NO_DEFAULT_PATH REQUIRED)
set(RTLAB_GLAD_DIR ${CMAKE_BINARY_DIR}/glad)
set(RTLAB_GLAD_EXTENSIONS GL_KHR_debug,GL_ARB_texture_filter_anisotropic)
add_custom_command(
  OUTPUT ${RTLAB_GLAD_DIR}/src/gl.c ${RTLAB_GLAD_DIR}/include/glad/gl.h
  COMMAND ${CMAKE_COMMAND} -E rm -rf ${RTLAB_GLAD_DIR}
  COMMAND ${GLAD_EXECUTABLE} --quiet --reproducible --api gl:core=4.5
          --extensions ${RTLAB_GLAD_EXTENSIONS} --out-path ${RTLAB_GLAD_DIR} c
  COMMENT "Generating the GL 4.5 core loader with glad"
  VERBATIM)
add_library(rtlab_glad STATIC ${RTLAB_GLAD_DIR}/src/gl.c)
target_include_directories(rtlab_glad PUBLIC ${RTLAB_GLAD_DIR}/include)
