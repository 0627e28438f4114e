# ctest -P script (tooling/desktop_files): what the package gives a desktop is valid, and the manual pages
# stay true to the programs.
#   - the menu entries (packaging/*.desktop) pass desktop-file-validate;
#   - the AppStream metadata (configured into build/packaging/) passes appstreamcli validate (offline; the
#     ids are the desktop files' names, not reverse-DNS, while the project has no domain: that one tag is
#     an info);
#   - the manual pages render with groff without a warning, and document every option the program's --help
#     names (so a new option without a manual entry fails here).
# Tools from run.sh's PACKAGES: desktop-file-utils, appstream, groff-base.
foreach(var SOURCE_DIR BUILD_DIR BIN_DIR)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "pass -D${var}=...")
    endif()
endforeach()
foreach(tool desktop-file-validate appstreamcli groff)
    find_program(${tool}_path ${tool})
    if(NOT ${tool}_path)
        message(FATAL_ERROR "${tool} is not installed: ./run.sh test installs it (run.sh PACKAGES)")
    endif()
endforeach()

function(expect_clean what)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0 OR NOT err STREQUAL "")
        message(FATAL_ERROR "${what}: exit ${rc}\n${out}${err}")
    endif()
endfunction()

foreach(entry killswitch killswitch-editor)
    expect_clean("desktop-file-validate packaging/${entry}.desktop" ${desktop-file-validate_path}
                 ${SOURCE_DIR}/packaging/${entry}.desktop)
    expect_clean("appstreamcli validate build/packaging/${entry}.metainfo.xml" ${appstreamcli_path} validate
                 --no-net --override=cid-desktopapp-is-not-rdns=info ${BUILD_DIR}/packaging/${entry}.metainfo.xml)
endforeach()

# Each page: groff's warnings (-ww) are errors; then each --option of `program help_args` is in the page.
function(check_page page program)
    set(file ${BUILD_DIR}/packaging/${page})
    expect_clean("groff -man -ww on build/packaging/${page}" ${groff_path} -man -ww -z -Tutf8 ${file})
    file(READ ${file} text)
    foreach(help_args IN LISTS ARGN)
        string(REPLACE " " ";" help_args "${help_args}")
        execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY ${BIN_DIR}/${program} ${help_args}
                        RESULT_VARIABLE rc OUTPUT_VARIABLE help ERROR_VARIABLE help)
        if(NOT rc EQUAL 0)
            message(FATAL_ERROR "${program} ${help_args} failed (${rc}):\n${help}")
        endif()
        string(REGEX MATCHALL "--[a-z][a-z0-9-]*" options "${help}")
        list(REMOVE_DUPLICATES options)
        foreach(option IN LISTS options)
            string(REPLACE "-" "\\-" escaped "${option}") # roff spells a hyphen \-
            string(FIND "${text}" "${escaped}" at)
            if(at EQUAL -1)
                message(FATAL_ERROR "packaging/${page}.in does not document ${option}, which "
                                    "`${program} ${help_args}` lists: add it to the page's OPTIONS")
            endif()
        endforeach()
    endforeach()
endfunction()
check_page(killswitch.6 killswitch "--help" "--headless --help")
check_page(killswitch-editor.1 killswitch-editor "--help")
message(STATUS "desktop entries, AppStream metadata and manual pages are valid and complete")
