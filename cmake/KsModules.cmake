# A module is common/<name>/: an OBJECT library ks_<name> whose sources are the folder's .cpp files.
# Modules list the modules they use; the closure is kept so a module's tests can be linked on their own
# (ks_tests_<name>) while another module is still being written.
#
# The build enforces the module graph: common/ itself is on no include path. Each module gets a folder of
# its own (build/module_includes/<name>/) holding links to itself and to the modules of its closure only, so
# `#include "render/..."` from physics fails to compile ("No such file") instead of linking by accident.
#
# It enforces each module's own border too: headers listed as INTERNAL in ks_module(...) are seen by the
# module's sources and its tests (tests/<name>/) only. In every include folder a module with internal headers
# appears as a folder of links to its other headers, one per file; its own sources and tests also get
# build/module_includes/<name>.internal/, which links the whole module.
set_property(GLOBAL PROPERTY KS_MODULES "")

# Unity builds (CMake's UNITY_BUILD): a target's sources compile in batches of eight, one translation unit a
# batch, because most of a source's compile time is the headers it shares with its neighbours (the numbers:
# docs/building.md, "Build times"). Two files of one target that define the same name in anonymous
# namespaces clash in a batch: give the helper a name of its own or share it. -DKS_UNITY=OFF compiles file by
# file (what include checks want).
option(KS_UNITY "Compile each target's sources in batches (unity build)" ON)
function(ks_unity target)
    if(KS_UNITY)
        set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
    endif()
endfunction()

# Links the public headers of module `name` into `dir`/<name>: the whole folder when it has no internal
# headers, else one link per header that is not internal.
function(ks_link_public_headers dir name)
    get_property(internal GLOBAL PROPERTY KS_INTERNAL_ks_${name})
    if(NOT internal)
        file(CREATE_LINK ${CMAKE_SOURCE_DIR}/common/${name} ${dir}/${name} SYMBOLIC)
        return()
    endif()
    file(MAKE_DIRECTORY ${dir}/${name})
    file(GLOB headers CONFIGURE_DEPENDS LIST_DIRECTORIES false RELATIVE ${CMAKE_SOURCE_DIR}/common/${name}
         ${CMAKE_SOURCE_DIR}/common/${name}/*)
    foreach(header IN LISTS headers)
        if(NOT header MATCHES "\\.cpp$" AND NOT header IN_LIST internal)
            file(CREATE_LINK ${CMAKE_SOURCE_DIR}/common/${name}/${header} ${dir}/${name}/${header} SYMBOLIC)
        endif()
    endforeach()
endfunction()

# A folder that shows only `modules` (ks_<name> targets and their closures), each by its public headers.
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
        ks_link_public_headers(${dir} ${name})
    endforeach()
    set(${out_dir} ${dir} PARENT_SCOPE)
endfunction()

# For targets outside common/ (the editor model, tools): see exactly the headers of `modules` and theirs.
function(ks_target_sees_modules target)
    ks_module_include_folder(dir ${target} ${ARGN})
    target_include_directories(${target} PRIVATE ${dir})
endfunction()

# The folder that shows module `name` whole, internal headers included (empty when it has none): for the
# module's own sources and its tests.
function(ks_module_internal_folder out_dir name)
    get_property(internal GLOBAL PROPERTY KS_INTERNAL_ks_${name})
    if(internal)
        set(${out_dir} ${CMAKE_BINARY_DIR}/module_includes/${name}.internal PARENT_SCOPE)
    else()
        set(${out_dir} "" PARENT_SCOPE)
    endif()
endfunction()

# Every INTERNAL header exists, and no public header includes one (a user of the public header could not
# compile it).
function(ks_check_internal_headers name)
    get_property(internal GLOBAL PROPERTY KS_INTERNAL_ks_${name})
    set(folder ${CMAKE_SOURCE_DIR}/common/${name})
    foreach(header IN LISTS internal)
        if(NOT EXISTS ${folder}/${header})
            message(FATAL_ERROR "ks_module(${name} INTERNAL ${header}): common/${name}/${header} does not exist")
        endif()
    endforeach()
    file(GLOB headers CONFIGURE_DEPENDS RELATIVE ${folder} ${folder}/*.h)
    foreach(header IN LISTS headers)
        if(header IN_LIST internal)
            continue()
        endif()
        file(STRINGS ${folder}/${header} includes REGEX "^#include \"${name}/")
        foreach(line IN LISTS includes)
            string(REGEX REPLACE "^#include \"${name}/([^\"]+)\".*" "\\1" included "${line}")
            if(included IN_LIST internal)
                message(FATAL_ERROR "common/${name}/${header} is public but includes the internal header "
                                    "${name}/${included}: include it from the .cpp instead, or list "
                                    "${header} as INTERNAL too")
            endif()
        endforeach()
    endforeach()
endfunction()

function(ks_module name)
    cmake_parse_arguments(ARG "" "" "DEPS;INTERNAL" ${ARGN})
    # Transitive closure of module dependencies (third-party interface targets are left to CMake).
    set(closure ks_${name})
    foreach(dep IN LISTS ARG_DEPS)
        get_property(dep_closure GLOBAL PROPERTY KS_CLOSURE_${dep})
        list(APPEND closure ${dep_closure})
    endforeach()
    list(REMOVE_DUPLICATES closure)
    set_property(GLOBAL PROPERTY KS_CLOSURE_ks_${name} "${closure}")
    set_property(GLOBAL PROPERTY KS_INTERNAL_ks_${name} "${ARG_INTERNAL}")
    ks_check_internal_headers(${name})
    # A user of the module sees what the module sees, less its internal headers: its public headers include
    # its dependencies' public headers and nothing internal.
    ks_module_include_folder(include_dir ${name} ks_${name})
    ks_module_internal_folder(internal_dir ${name})
    if(internal_dir)
        file(REMOVE_RECURSE ${internal_dir})
        file(MAKE_DIRECTORY ${internal_dir})
        file(CREATE_LINK ${CMAKE_SOURCE_DIR}/common/${name} ${internal_dir}/${name} SYMBOLIC)
    endif()
    file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/common/${name}/*.cpp)
    if(sources)
        add_library(ks_${name} OBJECT ${sources})
        ks_unity(ks_${name})
        target_include_directories(ks_${name} PUBLIC ${include_dir})
        if(internal_dir)
            target_include_directories(ks_${name} PRIVATE ${internal_dir})
        endif()
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
