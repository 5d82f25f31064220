# SPDX-License-Identifier: GPL-3.0-or-later
# Warnings are errors in our own code; third-party headers come in as system includes.
function(rungsmith_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror)
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        # GCC 12 reports -Wrestrict falsely inside std::string at -O2/-O3 (GCC bug 105329).
        target_compile_options(${target} PRIVATE -Wno-restrict)
        # Through a precompiled header GCC 12 no longer treats the standard
        # library's inlined code as a system header's, and reports that bug's
        # relatives inside std::string copies too. Clang keeps these checks.
        target_compile_options(${target} PRIVATE -Wno-array-bounds -Wno-stringop-overread
                                                 -Wno-stringop-overflow)
    endif()
endfunction()
