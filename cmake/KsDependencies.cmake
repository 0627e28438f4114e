# Every dependency is a Debian package found here; nothing is downloaded.
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)
find_package(glm REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(doctest REQUIRED)

add_library(ks_glm INTERFACE)
target_link_libraries(ks_glm INTERFACE glm::glm)
# Radians everywhere, depth 0..1 not needed (GL default), experimental for gtx quaternion helpers.
target_compile_definitions(ks_glm INTERFACE GLM_FORCE_RADIANS GLM_ENABLE_EXPERIMENTAL)

add_library(ks_json INTERFACE)
target_link_libraries(ks_json INTERFACE nlohmann_json::nlohmann_json)

# stb from libstb-dev: headers plus libstb, which carries the compiled implementations.
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
add_library(ks_stb INTERFACE)
target_link_libraries(ks_stb INTERFACE PkgConfig::STB)

# zlib from zlib1g-dev: the screenshot writer (render/png_writer.h) deflates with it.
find_package(ZLIB REQUIRED)
add_library(ks_zlib INTERFACE)
target_link_libraries(ks_zlib INTERFACE ZLIB::ZLIB)

# assimp from libassimp-dev: the modelio module reads designers' models with it (window-free, so every build
# needs it), and render loads the project's own models.
find_package(assimp REQUIRED)
add_library(ks_assimp INTERFACE)
if(TARGET assimp::assimp)
    target_link_libraries(ks_assimp INTERFACE assimp::assimp)
else()
    target_link_libraries(ks_assimp INTERFACE ${ASSIMP_LIBRARIES})
    target_include_directories(ks_assimp SYSTEM INTERFACE ${ASSIMP_INCLUDE_DIRS})
endif()

if(KS_BUILD_GL)
    set(OpenGL_GL_PREFERENCE GLVND)
    find_package(OpenGL REQUIRED)
    pkg_check_modules(GLFW3 REQUIRED IMPORTED_TARGET glfw3)
    pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)
    pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)

    add_library(ks_gl INTERFACE)
    target_link_libraries(ks_gl INTERFACE PkgConfig::EPOXY PkgConfig::GLFW3 OpenGL::GL)

    # libimgui.a from libimgui-dev carries the GLFW and OpenGL3 backends; its pkg-config lists stb/glfw/epoxy.
    add_library(ks_imgui INTERFACE)
    target_include_directories(ks_imgui SYSTEM INTERFACE ${IMGUI_INCLUDE_DIRS})
    target_link_libraries(ks_imgui INTERFACE ${IMGUI_LINK_LIBRARIES} PkgConfig::GLFW3 PkgConfig::EPOXY ${CMAKE_DL_LIBS})
endif()

# Recast/Detour from librecast-dev: Debian ships headers and shared libraries but no CMake or pkg-config
# file, so they are found by name. SYSTEM includes: their headers are not held to our warnings.
find_path(RECAST_INCLUDE_DIR Recast.h PATH_SUFFIXES recastnavigation REQUIRED)
find_library(RECAST_LIBRARY Recast REQUIRED)
find_library(DETOUR_LIBRARY Detour REQUIRED)
add_library(ks_recast INTERFACE)
target_include_directories(ks_recast SYSTEM INTERFACE ${RECAST_INCLUDE_DIR})
target_link_libraries(ks_recast INTERFACE ${RECAST_LIBRARY} ${DETOUR_LIBRARY})

# OpenAL Soft from libopenal-dev (pkg-config "openal"): only the audio module links it.
pkg_check_modules(OPENAL REQUIRED IMPORTED_TARGET openal)
add_library(ks_openal INTERFACE)
target_link_libraries(ks_openal INTERFACE PkgConfig::OPENAL)

# Qhull from libqhull-dev (reentrant libqhull_r, CMake config Qhull::qhull_r): only the brush module links it,
# for the convex hull of a point cloud (an imported target's headers are SYSTEM includes already).
find_package(Qhull REQUIRED CONFIG)
add_library(ks_qhull INTERFACE)
target_link_libraries(ks_qhull INTERFACE Qhull::qhull_r)

# meshoptimizer from libmeshoptimizer-dev (CMake config meshoptimizer::meshoptimizer): only the modelio module
# links it, for a designer's model's levels of detail (modelio/model_lod.h).
find_package(meshoptimizer REQUIRED CONFIG)
add_library(ks_meshoptimizer INTERFACE)
target_link_libraries(ks_meshoptimizer INTERFACE meshoptimizer::meshoptimizer)
