# ctest -P script: the module graph is enforced by the compiler, not by convention. A source that sees only
# physics compiles when it includes physics' declared dependency (core) and fails with "No such file" when it
# includes a module physics does not declare (level).
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
message(STATUS "module boundaries enforced: declared include compiles, undeclared include is not found")
