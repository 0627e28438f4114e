# A module is common/<name>/: an OBJECT library ks_<name> whose sources are the folder's .cpp files.
# Modules list the modules they use; the closure is kept so a module's tests can be linked on their own
# (ks_tests_<name>) while another module is still being written.
set_property(GLOBAL PROPERTY KS_MODULES "")

function(ks_module name)
    cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
    file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/common/${name}/*.cpp)
    if(sources)
        add_library(ks_${name} OBJECT ${sources})
        target_include_directories(ks_${name} PUBLIC ${CMAKE_SOURCE_DIR}/common)
        target_compile_options(ks_${name} PRIVATE ${KS_WARNINGS})
        target_link_libraries(ks_${name} PUBLIC ${ARG_DEPS})
    else() # a module with headers only (or none yet)
        add_library(ks_${name} INTERFACE)
        target_include_directories(ks_${name} INTERFACE ${CMAKE_SOURCE_DIR}/common)
        target_link_libraries(ks_${name} INTERFACE ${ARG_DEPS})
    endif()
    # Transitive closure of module dependencies (third-party interface targets are left to CMake).
    set(closure ks_${name})
    foreach(dep IN LISTS ARG_DEPS)
        get_property(dep_closure GLOBAL PROPERTY KS_CLOSURE_${dep})
        list(APPEND closure ${dep_closure})
    endforeach()
    list(REMOVE_DUPLICATES closure)
    set_property(GLOBAL PROPERTY KS_CLOSURE_ks_${name} "${closure}")
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
