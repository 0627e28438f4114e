# cmake --install: the two executables in bin/, their data in share/killswitch/ (found at run time as
# <prefix>/bin/../share/killswitch by common/core/paths.cpp), and what a desktop needs: menu entries, icons,
# manual pages, AppStream metadata, the copyright file and changelog (packaging/, docs/building.md "Install").
# The Debian package (cmake/KsPackage.cmake) is this tree under /usr, the programs in /usr/games.
set(KS_INSTALL_DATADIR share/killswitch)
set(KS_PACKAGING_DIR ${CMAKE_SOURCE_DIR}/packaging)
set(KS_PACKAGING_OUT ${CMAKE_BINARY_DIR}/packaging)
# The release date of this version: the AppStream release and the manual pages' footer.
set(KS_RELEASE_DATE 2026-11-28)
# The project has no public web page yet; give one to add the Homepage field and the AppStream link.
set(KS_HOMEPAGE_URL "" CACHE STRING "Homepage of the Debian package and the AppStream metadata (empty: none)")
set(KS_METAINFO_HOMEPAGE "")
if(KS_HOMEPAGE_URL)
    set(KS_METAINFO_HOMEPAGE "\n  <url type=\"homepage\">${KS_HOMEPAGE_URL}</url>")
endif()

if(KS_BUILD_GL)
    install(TARGETS killswitch killswitch-editor RUNTIME DESTINATION bin)
endif()

# What the executables read through ks::paths: assets/ (shaders, textures, models, sounds, fonts, clips)
# and the shipped levels with the campaign. The generator's sources and notes stay behind; the icons go to
# the icon theme instead.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/assets/ DESTINATION ${KS_INSTALL_DATADIR}/assets
        PATTERN generator EXCLUDE
        PATTERN icons EXCLUDE
        PATTERN CMakeLists.txt EXCLUDE
        PATTERN designer_sounds.txt EXCLUDE)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/levels/ DESTINATION ${KS_INSTALL_DATADIR}/levels
        FILES_MATCHING PATTERN "*.json"
        PATTERN source EXCLUDE)
# The editor's shipped prefabs (prefabs/*.json, read from the data folder's prefabs/), where the tree has them.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/prefabs/ DESTINATION ${KS_INSTALL_DATADIR}/prefabs OPTIONAL
        FILES_MATCHING PATTERN "*.json")

# The changelog (Debian's format, shipped as changelog.gz) must name this version first: a release bumps both.
file(STRINGS ${KS_PACKAGING_DIR}/changelog ks_changelog_head LIMIT_COUNT 1)
if(NOT ks_changelog_head MATCHES "^killswitch \\(${PROJECT_VERSION}\\) ")
    message(FATAL_ERROR "packaging/changelog:1: the newest entry is \"${ks_changelog_head}\", but the project "
                        "version is ${PROJECT_VERSION} (CMakeLists.txt, project()); add an entry "
                        "\"killswitch (${PROJECT_VERSION}) unstable; urgency=medium\" on top")
endif()

# Manual pages and AppStream metadata carry the version: configured here, then the pages gzipped as Debian
# wants (-n: no name or time stamp inside, so the bytes are reproducible).
configure_file(${KS_PACKAGING_DIR}/killswitch.6.in ${KS_PACKAGING_OUT}/killswitch.6 @ONLY)
configure_file(${KS_PACKAGING_DIR}/killswitch-editor.1.in ${KS_PACKAGING_OUT}/killswitch-editor.1 @ONLY)
configure_file(${KS_PACKAGING_DIR}/killswitch.metainfo.xml.in ${KS_PACKAGING_OUT}/killswitch.metainfo.xml @ONLY)
configure_file(${KS_PACKAGING_DIR}/killswitch-editor.metainfo.xml.in
               ${KS_PACKAGING_OUT}/killswitch-editor.metainfo.xml @ONLY)
configure_file(${KS_PACKAGING_DIR}/changelog ${KS_PACKAGING_OUT}/changelog COPYONLY)
foreach(page killswitch.6 killswitch-editor.1 changelog)
    execute_process(COMMAND gzip -9nkf ${KS_PACKAGING_OUT}/${page} RESULT_VARIABLE gzip_result)
    if(NOT gzip_result EQUAL 0)
        message(FATAL_ERROR "gzip -9nkf ${KS_PACKAGING_OUT}/${page} failed (${gzip_result}): is gzip installed?")
    endif()
endforeach()

install(FILES ${KS_PACKAGING_DIR}/killswitch.desktop ${KS_PACKAGING_DIR}/killswitch-editor.desktop
        DESTINATION share/applications)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/assets/icons/hicolor DESTINATION share/icons)
install(FILES ${KS_PACKAGING_OUT}/killswitch.metainfo.xml ${KS_PACKAGING_OUT}/killswitch-editor.metainfo.xml
        DESTINATION share/metainfo)
install(FILES ${KS_PACKAGING_OUT}/killswitch.6.gz DESTINATION share/man/man6)
install(FILES ${KS_PACKAGING_OUT}/killswitch-editor.1.gz DESTINATION share/man/man1)
install(FILES ${KS_PACKAGING_DIR}/copyright ${KS_PACKAGING_OUT}/changelog.gz DESTINATION share/doc/killswitch)
