# ctest -P script: the module graph is enforced by the compiler, not by convention. A source that sees only
# physics compiles when it includes physics' declared dependency (core) and fails with "No such file" when it
# includes a module physics does not declare (level). The runtime model likewise: it compiles with the game's
# headers and does not find the shell's. And a source that sees game compiles with a public header of level
# and fails with "No such file" on one of level's internal headers.
foreach(var BUILD_DIR)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "pass -D${var}=...")
    endif()
endforeach()
# Builds `declared` (must compile) and `undeclared` (must fail for want of `missing`, and nothing else).
function(expect_boundary declared undeclared missing)
    execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${declared}
                    RESULT_VARIABLE declared_rc OUTPUT_VARIABLE declared_out ERROR_VARIABLE declared_out)
    if(NOT declared_rc EQUAL 0)
        message(FATAL_ERROR "${declared}: a declared include failed to compile:\n${declared_out}")
    endif()
    execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${undeclared}
                    RESULT_VARIABLE undeclared_rc OUTPUT_VARIABLE undeclared_out ERROR_VARIABLE undeclared_out)
    if(undeclared_rc EQUAL 0)
        message(FATAL_ERROR "${undeclared}: included ${missing} although its target does not declare it")
    endif()
    if(NOT undeclared_out MATCHES "${missing}: No such file or directory")
        message(FATAL_ERROR "${undeclared}: the undeclared include failed for another reason:\n${undeclared_out}")
    endif()
endfunction()

expect_boundary(ks_boundary_probe_declared ks_boundary_probe_undeclared "level/level.h")
expect_boundary(ks_boundary_probe_runtime_model_declared ks_boundary_probe_runtime_model_undeclared
                "shell/app_shell.h")
expect_boundary(ks_boundary_probe_public ks_boundary_probe_internal "level/level_migrate.h")
message(STATUS "module boundaries enforced: declared includes compile, undeclared includes are not found, "
               "public headers compile, internal headers are not found")
