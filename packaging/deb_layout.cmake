# CPack pre-build script (CPACK_PRE_BUILD_SCRIPTS in cmake/KsPackage.cmake): what the Debian package does
# differently from `cmake --install`, in CPack's staging folder.
#   - The programs move from usr/bin to usr/games: Debian installs games there (policy 11.11; lintian's
#     package-section-games-but-contains-no-game is an error). Both move together (the editor starts the
#     game found beside it); their data is still found as <their folder>/../share/killswitch.
#   - The DejaVu fonts become links to Debian's fonts-dejavu-core (a dependency), the same files: no
#     duplicate copy (lintian's duplicate-font-file).
set(staging "")
foreach(var CPACK_TEMPORARY_INSTALL_DIRECTORY CPACK_TEMPORARY_DIRECTORY)
    if(DEFINED ${var} AND IS_DIRECTORY "${${var}}/usr/bin")
        set(staging "${${var}}")
        break()
    endif()
endforeach()
if(staging STREQUAL "")
    message(FATAL_ERROR "deb_layout.cmake: no usr/bin in CPack's staging folder "
                        "(CPACK_TEMPORARY_INSTALL_DIRECTORY='${CPACK_TEMPORARY_INSTALL_DIRECTORY}', "
                        "CPACK_TEMPORARY_DIRECTORY='${CPACK_TEMPORARY_DIRECTORY}')")
endif()

file(MAKE_DIRECTORY "${staging}/usr/games")
foreach(program killswitch killswitch-editor)
    file(RENAME "${staging}/usr/bin/${program}" "${staging}/usr/games/${program}")
endforeach()
file(GLOB left "${staging}/usr/bin/*")
if(left)
    message(FATAL_ERROR "deb_layout.cmake: unexpected files left in usr/bin: ${left}")
endif()
file(REMOVE_RECURSE "${staging}/usr/bin")

set(fonts "${staging}/usr/share/killswitch/assets/fonts")
foreach(font DejaVuSans.ttf DejaVuSans-Bold.ttf DejaVuSansMono.ttf)
    if(NOT EXISTS "${fonts}/${font}")
        message(FATAL_ERROR "deb_layout.cmake: ${fonts}/${font} is not installed (cmake/KsInstall.cmake)")
    endif()
    file(REMOVE "${fonts}/${font}")
    file(CREATE_LINK "../../../fonts/truetype/dejavu/${font}" "${fonts}/${font}" SYMBOLIC)
endforeach()
message(STATUS "Debian layout: programs in /usr/games, fonts from fonts-dejavu-core")
