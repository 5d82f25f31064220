# SPDX-License-Identifier: GPL-3.0-or-later
# The version the binaries print and the package carries (docs in README.md,
# "Building and installing the package"). A commit tagged v<project version>
# is that release; any other commit is a development build,
# <project version>~git<commit date>.<short hash>, which Debian sorts before
# the release it leads to. The version is read at build time, so a build after
# a commit is named after that commit without configuring again; only the two
# mains, which include the generated header, compile again when it changes.

find_package(Git QUIET)
set(RUNGSMITH_GENERATED_DIR ${CMAKE_BINARY_DIR}/generated)
set(RUNGSMITH_VERSION_HEADER ${RUNGSMITH_GENERATED_DIR}/RungsmithBuildVersion.h)
set(RUNGSMITH_VERSION_FILE ${RUNGSMITH_GENERATED_DIR}/version.txt)

add_custom_target(rungsmith_build_version
    COMMAND ${CMAKE_COMMAND}
        -DSOURCE_DIR=${CMAKE_SOURCE_DIR}
        -DPROJECT_VERSION=${PROJECT_VERSION}
        -DGIT=${GIT_EXECUTABLE}
        -DHEADER=${RUNGSMITH_VERSION_HEADER}
        -DTEXT=${RUNGSMITH_VERSION_FILE}
        -P ${CMAKE_CURRENT_LIST_DIR}/PackagingWriteVersion.cmake
    BYPRODUCTS ${RUNGSMITH_VERSION_HEADER} ${RUNGSMITH_VERSION_FILE}
    VERBATIM)

# Gives TARGET the macro RUNGSMITH_BUILD_VERSION from RungsmithBuildVersion.h.
function(rungsmith_build_version target)
    add_dependencies(${target} rungsmith_build_version)
    target_include_directories(${target} PRIVATE ${RUNGSMITH_GENERATED_DIR})
endfunction()
