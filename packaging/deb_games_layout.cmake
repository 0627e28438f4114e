# CPack pre-build script (CPACK_PRE_BUILD_SCRIPTS in cmake/KsPackage.cmake): Debian installs games' programs
# in /usr/games (policy 11.11; lintian's package-section-games-but-contains-no-game is an error), while
# `cmake --install` keeps the usual <prefix>/bin. Both programs move together (the editor starts the game
# found beside it); their data is still found as <their folder>/../share/killswitch, i.e. /usr/share/killswitch.
set(staging "")
foreach(var CPACK_TEMPORARY_INSTALL_DIRECTORY CPACK_TEMPORARY_DIRECTORY)
    if(DEFINED ${var} AND IS_DIRECTORY "${${var}}/usr/bin")
        set(staging "${${var}}")
        break()
    endif()
endforeach()
if(staging STREQUAL "")
    message(FATAL_ERROR "deb_games_layout.cmake: no usr/bin in CPack's staging folder "
                        "(CPACK_TEMPORARY_INSTALL_DIRECTORY='${CPACK_TEMPORARY_INSTALL_DIRECTORY}', "
                        "CPACK_TEMPORARY_DIRECTORY='${CPACK_TEMPORARY_DIRECTORY}')")
endif()
file(MAKE_DIRECTORY "${staging}/usr/games")
foreach(program killswitch killswitch-editor)
    file(RENAME "${staging}/usr/bin/${program}" "${staging}/usr/games/${program}")
endforeach()
file(GLOB left "${staging}/usr/bin/*")
if(left)
    message(FATAL_ERROR "deb_games_layout.cmake: unexpected files left in usr/bin: ${left}")
endif()
file(REMOVE_RECURSE "${staging}/usr/bin")
message(STATUS "packaged the programs in /usr/games")
