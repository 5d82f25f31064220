# SPDX-License-Identifier: GPL-3.0-or-later
# cpack runs this before it packs: the package takes the version of the
# binaries it holds, which the build wrote, not the one seen at configure time.
if(NOT EXISTS "${CPACK_RUNGSMITH_VERSION_FILE}")
    message(FATAL_ERROR "${CPACK_RUNGSMITH_VERSION_FILE} is missing: build before packing")
endif()
file(STRINGS "${CPACK_RUNGSMITH_VERSION_FILE}" CPACK_PACKAGE_VERSION LIMIT_COUNT 1)
