# ./run.sh package: killswitch_<version>_amd64.deb from the install tree (cmake/KsInstall.cmake) under /usr,
# built by CPack's DEB generator (cpack -G DEB in build/). Dependencies come from the shared libraries the
# executables link (dpkg-shlibdeps, from dpkg-dev); lintian checks the result (docs/building.md).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME killswitch)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "The Killswitch team")
set(CPACK_PACKAGE_CONTACT "Killswitch maintainers <maintainers@users.noreply.h-seed-e2b4c9a8.example>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_BINARY_DIR}/package)
set(CPACK_STRIP_FILES ON)
# Only the install rules of this project (no third-party ones), into one package.
set(CPACK_INSTALL_CMAKE_PROJECTS "${CMAKE_BINARY_DIR};Killswitch;ALL;/")

# In the package only: the programs in usr/games (Debian's games layout), the fonts linked to
# fonts-dejavu-core's copies (packaging/deb_layout.cmake).
set(CPACK_PRE_BUILD_SCRIPTS ${CMAKE_SOURCE_DIR}/packaging/deb_layout.cmake)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # killswitch_0.9.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Besides the shared libraries: the fonts the package links to (the same files as assets/fonts/).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core")
set(CPACK_DEBIAN_PACKAGE_SECTION games)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${CPACK_PACKAGE_CONTACT}")
# Software OpenGL (Mesa) is enough to play; without it a machine with no GL driver cannot start the game.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libgl1-mesa-dri")
if(KS_HOMEPAGE_URL)
    set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "${KS_HOMEPAGE_URL}")
endif()
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "first-person shooter against rogue robots, with a level editor")
# The extended description: lines under 80 characters (lintian), "." for an empty line.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "Killswitch puts you in a virtual disaster simulator whose robots went rogue:
fight them, shoot exploding gas cylinders, open doors, toggle lights and reach
the control panel to end the simulation. Every sound is generated and placed
in 3D, so robots can be found by ear.
.
The package also holds killswitch-editor, the level editor: build levels with
level logic (triggers, spawners, objectives), play-test them, and let a bot
play them many times to report win rates and where players get hurt.")
include(CPack)
