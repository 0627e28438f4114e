# ctest -P script (tooling/install_tree): `cmake --install` into a fresh prefix inside the build folder, then
# the installed executables run from another working directory and find their data in
# <prefix>/share/killswitch, not in the source tree the prefix sits in: --version of both, the bot wins
# levels/main.json headless, and with the installed main.json gone the error names the installed path.
# The layout a desktop needs (menu entries, icons, manual pages, metadata, copyright) is checked too.
foreach(var SOURCE_DIR BUILD_DIR)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "pass -D${var}=...")
    endif()
endforeach()
set(prefix ${BUILD_DIR}/install-test)
set(data ${prefix}/share/killswitch)
file(REMOVE_RECURSE ${prefix})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake --install ${BUILD_DIR} --prefix ${prefix} failed:\n${out}")
endif()

set(expected
    bin/killswitch bin/killswitch-editor
    share/killswitch/levels/main.json share/killswitch/levels/campaign.json share/killswitch/levels/lockdown.json
    share/killswitch/levels/dojo.json share/killswitch/assets/shaders/pbr.frag
    share/killswitch/assets/models/robot.gltf share/killswitch/assets/animations/robot.json
    share/killswitch/assets/sounds/rifle_shot.wav share/killswitch/assets/textures/particles/fire.png
    share/killswitch/assets/fonts/DejaVuSans.ttf share/killswitch/assets/fonts/LICENSE-DejaVu.txt
    share/applications/killswitch.desktop share/applications/killswitch-editor.desktop
    share/metainfo/killswitch.metainfo.xml share/metainfo/killswitch-editor.metainfo.xml
    share/man/man6/killswitch.6.gz share/man/man1/killswitch-editor.1.gz
    share/doc/killswitch/copyright share/doc/killswitch/changelog.gz)
foreach(size 16 24 32 48 64 128 256)
    foreach(name killswitch killswitch-editor)
        list(APPEND expected share/icons/hicolor/${size}x${size}/apps/${name}.png)
    endforeach()
endforeach()
# The editor's shipped prefabs, once the tree has them.
file(GLOB prefabs RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/prefabs/*.json)
foreach(prefab IN LISTS prefabs)
    list(APPEND expected share/killswitch/${prefab})
endforeach()
foreach(file IN LISTS expected)
    if(NOT EXISTS ${prefix}/${file})
        message(FATAL_ERROR "the install tree lacks ${file} (install rules: cmake/KsInstall.cmake)")
    endif()
endforeach()
# Sources and generator notes are not data.
foreach(file share/killswitch/assets/generator share/killswitch/assets/CMakeLists.txt
        share/killswitch/assets/icons share/killswitch/levels/source share/killswitch/levels/README.md)
    if(EXISTS ${prefix}/${file})
        message(FATAL_ERROR "${file} was installed but is no run-time data (cmake/KsInstall.cmake)")
    endif()
endforeach()

# Run from a folder with no assets/ or levels/, with no data override and no display.
set(elsewhere ${prefix}/elsewhere)
file(MAKE_DIRECTORY ${elsewhere})
set(run ${CMAKE_COMMAND} -E env --unset=KS_DATA_DIR --unset=DISPLAY --unset=WAYLAND_DISPLAY)
foreach(program killswitch killswitch-editor)
    execute_process(COMMAND ${run} ${prefix}/bin/${program} --version WORKING_DIRECTORY ${elsewhere}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
    if(NOT rc EQUAL 0 OR NOT out MATCHES "^${program} [0-9]+\\.[0-9]+\\.[0-9]+\n$")
        message(FATAL_ERROR "installed ${program} --version: exit ${rc}, printed \"${out}\"")
    endif()
endforeach()

execute_process(COMMAND ${run} ${prefix}/bin/killswitch --headless --autoplay --seed 1 --seconds 200
                WORKING_DIRECTORY ${elsewhere} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "(^|\n)win after")
    message(FATAL_ERROR "the installed killswitch --headless --autoplay did not win levels/main.json "
                        "(exit ${rc}):\n${out}")
endif()
string(STRIP "${out}" summary)
message(STATUS "installed game, run from ${elsewhere}: ${summary}")

# The windowed game draws its menu with the installed shaders and fonts: any warning (a missing or unreadable
# installed file) fails. Mesa leaks at GL start-up, so LeakSanitizer is off here as for the GL suites.
if(NOT DEFINED ENV{DISPLAY})
    message(FATAL_ERROR "no DISPLAY: the installed game's window cannot be checked (./run.sh test runs the "
                        "tests under xvfb-run)")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=KS_DATA_DIR "ASAN_OPTIONS=$ENV{ASAN_OPTIONS}:detect_leaks=0"
                        ${prefix}/bin/killswitch --screen menu --width 640 --height 360 --frames 3
                        --screenshot ${elsewhere}/menu.png
                WORKING_DIRECTORY ${elsewhere} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT EXISTS ${elsewhere}/menu.png OR out MATCHES "\\[(warning|error)\\]")
    message(FATAL_ERROR "the installed game's menu (exit ${rc}) did not draw cleanly:\n${out}")
endif()

# Without the installed level the game must name the installed path (it did not read the source tree's).
file(RENAME ${data}/levels/main.json ${data}/levels/main.json.moved)
execute_process(COMMAND ${run} ${prefix}/bin/killswitch --headless --autoplay --seconds 1
                WORKING_DIRECTORY ${elsewhere} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 2 OR NOT out MATCHES "share/killswitch/levels/main.json")
    message(FATAL_ERROR "with ${data}/levels/main.json gone the installed game should fail naming it; "
                        "exit ${rc}:\n${out}")
endif()
file(REMOVE_RECURSE ${prefix})
message(STATUS "install tree complete; installed binaries find ${data} from another folder")
