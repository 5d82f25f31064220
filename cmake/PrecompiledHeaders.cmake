# SPDX-License-Identifier: GPL-3.0-or-later
# Precompiled headers where parsing is much of a translation unit's time: the
# IDE's sources (Qt Widgets) and the test programs (GoogleTest), 15-20 % of
# their compile (docs/reliability.md, "CI time"). The core gains nothing: its
# time goes to optimising, not to reading the standard headers. The IDE's
# header holds QWidget only, not all of <QtWidgets>: every translation unit
# loads the whole header, and a 300 MB one cost more to load than it saved.
#   rungsmith_precompile(target WIDGETS|TESTS|WIDGET_TESTS)
set(RUNGSMITH_PCH_STANDARD
    <algorithm> <array> <cstdint> <functional> <map> <memory> <optional> <set>
    <string> <string_view> <utility> <variant> <vector>)

function(rungsmith_precompile target kind)
    set(headers ${RUNGSMITH_PCH_STANDARD})
    if(kind STREQUAL "WIDGETS" OR kind STREQUAL "WIDGET_TESTS")
        # For the IDE's targets only: Qt's keywords (emit) clash with core names.
        list(APPEND headers <QWidget>)
    endif()
    if(kind STREQUAL "TESTS" OR kind STREQUAL "WIDGET_TESTS")
        list(APPEND headers <gtest/gtest.h>)
    endif()
    if(kind STREQUAL "WIDGET_TESTS")
        list(APPEND headers <QTest>)
    endif()
    target_precompile_headers(${target} PRIVATE ${headers})
endfunction()
