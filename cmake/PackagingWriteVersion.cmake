# SPDX-License-Identifier: GPL-3.0-or-later
# cmake -P script, run by the target rungsmith_build_version at every build:
# writes HEADER and TEXT with the build's version, touching them only when it
# changed. Input: SOURCE_DIR, PROJECT_VERSION, GIT (may be empty).

set(version ${PROJECT_VERSION})
if(GIT)
    # Only the source tree's own history counts, not that of a repository
    # around an unpacked source archive.
    execute_process(COMMAND ${GIT} -C ${SOURCE_DIR} rev-parse --show-toplevel
        OUTPUT_VARIABLE top OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE failed)
    if(NOT failed)
        file(REAL_PATH "${top}" top)
        file(REAL_PATH "${SOURCE_DIR}" source)
    endif()
    if(NOT failed AND top STREQUAL source)
        execute_process(COMMAND ${GIT} -C ${SOURCE_DIR} describe --exact-match
                                --match v${PROJECT_VERSION} HEAD
            OUTPUT_QUIET ERROR_QUIET RESULT_VARIABLE untagged)
        if(untagged)
            set(ENV{TZ} UTC)
            execute_process(COMMAND ${GIT} -C ${SOURCE_DIR} log -1 --date=format-local:%Y%m%d
                                    --format=%cd.%h
                OUTPUT_VARIABLE revision OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET
                RESULT_VARIABLE failed)
            if(NOT failed AND revision)
                set(version "${version}~git${revision}")
            endif()
        endif()
    endif()
endif()

file(CONFIGURE OUTPUT ${TEXT} CONTENT "${version}\n")
file(CONFIGURE OUTPUT ${HEADER} CONTENT "#pragma once\n#define RUNGSMITH_BUILD_VERSION \"${version}\"\n")
