# Dear ImGui's GLFW and OpenGL3 platform backends. Debian's libimgui-dev 1.86 ships the core as a
# library (libimgui.a, pkg-config imgui) but the backends only as example sources, so the build
# compiles them from the package's copy. The OpenGL3 backend normally brings its own GL loader;
# IMGUI_IMPL_OPENGL_LOADER_CUSTOM turns that off and glad's header (forced in first) supplies the
# entry points, so the UI draws through the same pointers as the rest of rtlab (never libGL).
set(RTLAB_IMGUI_BACKEND_SOURCE_DIR "/usr/share/doc/libimgui-dev/examples/backends" CACHE PATH
  "Directory holding imgui_impl_glfw.cpp and imgui_impl_opengl3.cpp (Debian libimgui-dev)")
set(RTLAB_IMGUI_BACKEND_DIR "/usr/include/imgui/backends")
set(RTLAB_IMGUI_BACKENDS
  ${RTLAB_IMGUI_BACKEND_SOURCE_DIR}/imgui_impl_glfw.cpp
  ${RTLAB_IMGUI_BACKEND_SOURCE_DIR}/imgui_impl_opengl3.cpp)
foreach(_src IN LISTS RTLAB_IMGUI_BACKENDS)
  if(NOT EXISTS ${_src})
    message(FATAL_ERROR "${_src} not found: install libimgui-dev (scripts/setup.sh)")
  endif()
endforeach()
set_source_files_properties(${RTLAB_IMGUI_BACKENDS} PROPERTIES
  COMPILE_DEFINITIONS "IMGUI_IMPL_OPENGL_LOADER_CUSTOM"
  COMPILE_OPTIONS "-include;glad/gl.h;-w")
