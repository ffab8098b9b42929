# Targets for the two pieces that Debian ships as sources or generators rather than ready
# libraries: the glad GL loader and Dear ImGui's OpenGL3 backend.

# glad 2: a GL 3.3 core loader generated offline from the gl.xml inside python3-glad. One
# loader serves both context providers (GLFW window and OSMesa), so nothing links libGL.
find_program(GLAD_EXE glad REQUIRED)
set(GLAD_DIR ${CMAKE_BINARY_DIR}/glad)
add_custom_command(
  OUTPUT ${GLAD_DIR}/src/gl.c ${GLAD_DIR}/include/glad/gl.h
  COMMAND ${GLAD_EXE} --quiet --api gl:core=3.3 --extensions "" --reproducible --out-path ${GLAD_DIR} c
  COMMENT "Generating the glad GL 3.3 core loader"
  VERBATIM)
add_library(glad STATIC ${GLAD_DIR}/src/gl.c)
target_include_directories(glad SYSTEM PUBLIC ${GLAD_DIR}/include)
set_target_properties(glad PROPERTIES POSITION_INDEPENDENT_CODE ON)

# The prebuilt OpenGL3 backend inside libimgui.a loads GL through libGL only and fails under
# OSMesa, so compile Debian's shipped source against glad. An OBJECT library always precedes
# the archive on the link line, so this copy wins.
set(IMGUI_BACKEND_SRC /usr/share/doc/libimgui-dev/examples/backends)
if(NOT EXISTS ${IMGUI_BACKEND_SRC}/imgui_impl_opengl3.cpp)
  message(FATAL_ERROR "imgui_impl_opengl3.cpp not found in ${IMGUI_BACKEND_SRC} (package libimgui-dev)")
endif()
add_library(imgui_gl3_backend OBJECT ${IMGUI_BACKEND_SRC}/imgui_impl_opengl3.cpp)
target_compile_definitions(imgui_gl3_backend PRIVATE IMGUI_IMPL_OPENGL_LOADER_CUSTOM)
target_compile_options(imgui_gl3_backend PRIVATE "SHELL:-include glad/gl.h")
target_include_directories(imgui_gl3_backend SYSTEM PUBLIC /usr/include/imgui/backends)
target_link_libraries(imgui_gl3_backend PUBLIC PkgConfig::IMGUI glad)
