# ctest -P script: the module graph is enforced by the compiler, not by convention. A source that sees only
# physics compiles when it includes physics' declared dependency (core) and fails with "No such file" when it
# includes a module physics does not declare (level). A source that sees game compiles with a public header of
# level and fails with "No such file" on one of level's internal headers.
foreach(var BUILD_DIR)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "pass -D${var}=...")
    endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ks_boundary_probe_declared
                RESULT_VARIABLE declared_rc OUTPUT_VARIABLE declared_out ERROR_VARIABLE declared_out)
if(NOT declared_rc EQUAL 0)
    message(FATAL_ERROR "a declared include failed to compile:\n${declared_out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ks_boundary_probe_undeclared
                RESULT_VARIABLE undeclared_rc OUTPUT_VARIABLE undeclared_out ERROR_VARIABLE undeclared_out)
if(undeclared_rc EQUAL 0)
    message(FATAL_ERROR "physics code included level/level.h although physics does not declare level")
endif()
if(NOT undeclared_out MATCHES "level/level.h: No such file or directory")
    message(FATAL_ERROR "the undeclared include failed for another reason:\n${undeclared_out}")
endif()
# A module's own border: game declares level, so it sees level's public headers, but not the ones level lists
# as INTERNAL.
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ks_boundary_probe_public
                RESULT_VARIABLE public_rc OUTPUT_VARIABLE public_out ERROR_VARIABLE public_out)
if(NOT public_rc EQUAL 0)
    message(FATAL_ERROR "a public header of a declared module failed to compile:\n${public_out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ks_boundary_probe_internal
                RESULT_VARIABLE internal_rc OUTPUT_VARIABLE internal_out ERROR_VARIABLE internal_out)
if(internal_rc EQUAL 0)
    message(FATAL_ERROR "game code included level/level_reader.h although level lists it as INTERNAL")
endif()
if(NOT internal_out MATCHES "level/level_reader.h: No such file or directory")
    message(FATAL_ERROR "the internal include failed for another reason:\n${internal_out}")
endif()
message(STATUS "module boundaries enforced: declared include compiles, undeclared include is not found, "
               "public header compiles, internal header is not found")
