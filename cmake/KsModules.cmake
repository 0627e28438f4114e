# A module is common/<name>/: an OBJECT library ks_<name> whose sources are the folder's .cpp files.
# Modules list the modules they use; the closure is kept so a module's tests can be linked on their own
# (ks_tests_<name>) while another module is still being written.
#
# The build enforces the module graph: common/ itself is on no include path. Each module gets a folder of
# its own (build/module_includes/<name>/) holding links to itself and to the modules of its closure only, so
# `#include "render/..."` from physics fails to compile ("No such file") instead of linking by accident.
set_property(GLOBAL PROPERTY KS_MODULES "")

# A folder that shows only `modules` (ks_<name> targets and their closures), as links to common/<name>.
function(ks_module_include_folder out_dir folder_name)
    set(dir ${CMAKE_BINARY_DIR}/module_includes/${folder_name})
    file(REMOVE_RECURSE ${dir})
    file(MAKE_DIRECTORY ${dir})
    set(visible "")
    foreach(module IN LISTS ARGN)
        get_property(closure GLOBAL PROPERTY KS_CLOSURE_${module})
        list(APPEND visible ${closure})
    endforeach()
    list(REMOVE_DUPLICATES visible)
    foreach(target IN LISTS visible)
        string(REGEX REPLACE "^ks_" "" name ${target})
        file(CREATE_LINK ${CMAKE_SOURCE_DIR}/common/${name} ${dir}/${name} SYMBOLIC)
    endforeach()
    set(${out_dir} ${dir} PARENT_SCOPE)
endfunction()

# For targets outside common/ (the editor model, tools): see exactly the headers of `modules` and theirs.
function(ks_target_sees_modules target)
    ks_module_include_folder(dir ${target} ${ARGN})
    target_include_directories(${target} PRIVATE ${dir})
endfunction()

function(ks_module name)
    cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
    # Transitive closure of module dependencies (third-party interface targets are left to CMake).
    set(closure ks_${name})
    foreach(dep IN LISTS ARG_DEPS)
        get_property(dep_closure GLOBAL PROPERTY KS_CLOSURE_${dep})
        list(APPEND closure ${dep_closure})
    endforeach()
    list(REMOVE_DUPLICATES closure)
    set_property(GLOBAL PROPERTY KS_CLOSURE_ks_${name} "${closure}")
    # A user of the module sees what the module sees: its public headers include its dependencies'.
    ks_module_include_folder(include_dir ${name} ks_${name})
    file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/common/${name}/*.cpp)
    if(sources)
        add_library(ks_${name} OBJECT ${sources})
        target_include_directories(ks_${name} PUBLIC ${include_dir})
        target_compile_options(ks_${name} PRIVATE ${KS_WARNINGS})
        target_link_libraries(ks_${name} PUBLIC ${ARG_DEPS})
    else() # a module with headers only (or none yet)
        add_library(ks_${name} INTERFACE)
        target_include_directories(ks_${name} INTERFACE ${include_dir})
        target_link_libraries(ks_${name} INTERFACE ${ARG_DEPS})
    endif()
    set_property(GLOBAL APPEND PROPERTY KS_MODULES ks_${name})
endfunction()

# ks_common: the static library holding every module's objects.
function(ks_bundle_common)
    get_property(modules GLOBAL PROPERTY KS_MODULES)
    add_library(ks_common STATIC)
    target_link_libraries(ks_common PUBLIC ${modules} Threads::Threads)
endfunction()

# Link only what module <name> needs (its closure of module objects).
function(ks_link_module_closure target name)
    get_property(closure GLOBAL PROPERTY KS_CLOSURE_ks_${name})
    target_link_libraries(${target} PRIVATE ${closure} Threads::Threads)
endfunction()
