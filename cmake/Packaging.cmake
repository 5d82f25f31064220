# SPDX-License-Identifier: GPL-3.0-or-later
# Installation in the standard places and the Debian package (cpack -G DEB).
# README.md, "Building and installing the package", says how to use them.
# The install rules of the two programs are in app/CMakeLists.txt.

# The AppStream id names the desktop entry, the metainfo and the icon; the IDE
# tells Wayland the same (setDesktopFileName in app/gui/main.cpp).
set(RUNGSMITH_APP_ID io.github.rungsmith.Rungsmith)
set(RUNGSMITH_HOMEPAGE_URL "https://github.com/rungsmith/rungsmith"
    CACHE STRING "Project home page: the package's Homepage, AppStream's links and screenshots")
set(RUNGSMITH_PACKAGE_MAINTAINER
    "Rungsmith maintainers <maintainers@users.noreply.h-seed-1067484c.example>"
    CACHE STRING "The Debian package's Maintainer field")

set(_packaging ${PROJECT_SOURCE_DIR}/packaging)
set(_generated ${CMAKE_BINARY_DIR}/packaging)
set(_datadir ${CMAKE_INSTALL_DATADIR})
set(_docdir ${CMAKE_INSTALL_DATADIR}/doc/rungsmith)

# The translations are compiled into the programs (qt_add_translations in
# ui/CMakeLists.txt embeds them under :/i18n), so there are none to install.

# The IDE opens the first example itself (compiled in); these are for users to
# copy and for rungsmith-cli.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/resources/examples/
    DESTINATION ${_datadir}/rungsmith/examples FILES_MATCHING PATTERN "*.sps" PATTERN "*.scn"
    PATTERN "*.prop")

# The file types are the command line's as much as the IDE's.
install(FILES ${_packaging}/rungsmith-mime.xml
    DESTINATION ${_datadir}/mime/packages RENAME rungsmith.xml)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/resources/icons/mimetypes/
    DESTINATION ${_datadir}/icons/hicolor/scalable/mimetypes FILES_MATCHING PATTERN "*.svg")

if(RUNGSMITH_BUILD_GUI)
    install(FILES ${_packaging}/${RUNGSMITH_APP_ID}.desktop
        DESTINATION ${_datadir}/applications)
    configure_file(${_packaging}/${RUNGSMITH_APP_ID}.metainfo.xml.in
        ${_generated}/${RUNGSMITH_APP_ID}.metainfo.xml @ONLY)
    install(FILES ${_generated}/${RUNGSMITH_APP_ID}.metainfo.xml
        DESTINATION ${_datadir}/metainfo)
    install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/rungsmith.svg
        DESTINATION ${_datadir}/icons/hicolor/scalable/apps RENAME ${RUNGSMITH_APP_ID}.svg)
endif()

# Debian wants a copyright file and a changelog in every package; the
# changelog is compressed without a time stamp, so that it is the same
# whoever builds it.
install(FILES ${_packaging}/copyright DESTINATION ${_docdir})
add_custom_command(OUTPUT ${_generated}/changelog.gz
    COMMAND ${CMAKE_COMMAND} -E copy ${_packaging}/changelog ${_generated}/changelog
    COMMAND gzip -9nf ${_generated}/changelog
    DEPENDS ${_packaging}/changelog
    VERBATIM)
add_custom_target(rungsmith_changelog ALL DEPENDS ${_generated}/changelog.gz)
install(FILES ${_generated}/changelog.gz DESTINATION ${_docdir})

# Man pages: help2man turns each program's own --help and --version into its
# page, so the page lists exactly the verbs and options the program takes.
# packaging/<program>.h2m adds what --help does not say (exit status, files).
find_program(RUNGSMITH_HELP2MAN help2man)
if(RUNGSMITH_HELP2MAN)
    set(RUNGSMITH_MAN_PAGES ON)
    set(_pages)
    foreach(program rungsmith-cli rungsmith)
        if(NOT TARGET ${program})
            continue()
        endif()
        # English help whatever the builder's locale and saved language; the
        # IDE needs no display to print it.
        add_custom_command(OUTPUT ${_generated}/${program}.1.gz
            COMMAND ${CMAKE_COMMAND} -E env LC_ALL=C.UTF-8 LANGUAGE= QT_QPA_PLATFORM=offscreen
                    XDG_CONFIG_HOME=${_generated}/help2man-config
                    ${RUNGSMITH_HELP2MAN} --no-info
                    --include ${_packaging}/${program}.h2m
                    --output ${_generated}/${program}.1 $<TARGET_FILE:${program}>
            COMMAND gzip -9nf ${_generated}/${program}.1
            DEPENDS ${program} ${_packaging}/${program}.h2m
            VERBATIM)
        list(APPEND _pages ${_generated}/${program}.1.gz)
    endforeach()
    add_custom_target(rungsmith_man_pages ALL DEPENDS ${_pages})
    install(FILES ${_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
    set(RUNGSMITH_MAN_PAGES OFF)
    message(STATUS "help2man not found: no man pages, and no package test")
endif()

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME rungsmith)
set(CPACK_PACKAGE_VENDOR "The Rungsmith developers")
set(CPACK_PACKAGE_CONTACT ${RUNGSMITH_PACKAGE_MAINTAINER})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "IDE for Pluto safety PLCs")
set(CPACK_PACKAGE_DESCRIPTION
    "Rungsmith reads and writes the text language of the Pluto family of safety
PLCs as the manuals define it, shows every statement as a ladder network and
checks programs with messages that point at the offending line and column.
It compiles projects to the documented image (.hps, Intel HEX) and simulates
several units on one bus on virtual time with scenario tests (.scn).
.
The package holds the IDE (rungsmith), the command line for pipelines
(rungsmith-cli), example projects, and the desktop, MIME and AppStream files.")
set(CPACK_DEBIAN_PACKAGE_SECTION electronics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE ${RUNGSMITH_HOMEPAGE_URL})
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Qt's own dialogs in German and Swedish.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS qt6-translations-l10n)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_STRIP_FILES ON)
# cpack reads the version the last build wrote (see PackagingVersion.cmake).
set(CPACK_RUNGSMITH_VERSION_FILE ${RUNGSMITH_VERSION_FILE})
set(CPACK_PROJECT_CONFIG_FILE ${CMAKE_CURRENT_LIST_DIR}/PackagingCPackProject.cmake)
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_BINARY_DIR}/package)
include(CPack)
