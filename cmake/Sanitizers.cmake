# SPDX-License-Identifier: GPL-3.0-or-later
# The sanitizer build (preset "asan"): every target with AddressSanitizer and
# UBSan, any finding fatal, and with libFuzzer's coverage hooks so that the
# fuzz targets (tests/fuzz) can link libFuzzer. Needs clang.
if(NOT RUNGSMITH_SANITIZE)
    return()
endif()
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "RUNGSMITH_SANITIZE needs clang (libFuzzer); use the asan preset")
endif()
add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all
    -fno-omit-frame-pointer -fsanitize=fuzzer-no-link)
add_link_options(-fsanitize=address,undefined)
