# DBS_BUILD_FUZZ: the libFuzzer targets of tests/fuzz. They need clang (libFuzzer ships with
# it: Debian's libclang-rt-NN-dev); with another compiler, or a clang whose libFuzzer cannot
# be linked, they are skipped with a message and the rest of the build is unchanged.
# Everything built is instrumented for them: -fsanitize=fuzzer-no-link (coverage) with
# AddressSanitizer and UndefinedBehaviorSanitizer; only the targets link libFuzzer itself.
set(DBS_FUZZ OFF)
if(NOT DBS_BUILD_FUZZ)
  return()
endif()
if(NOT (CMAKE_C_COMPILER_ID STREQUAL "Clang" AND CMAKE_CXX_COMPILER_ID STREQUAL "Clang"))
  message(STATUS "Fuzz targets skipped: they need clang as the C and C++ compiler "
    "(CC=clang CXX=clang++), not ${CMAKE_C_COMPILER_ID}/${CMAKE_CXX_COMPILER_ID}")
  return()
endif()
if(DBS_SANITIZE)
  message(FATAL_ERROR "DBS_BUILD_FUZZ brings its own sanitizers: leave DBS_SANITIZE off")
endif()
include(CheckCSourceCompiles)
set(CMAKE_REQUIRED_FLAGS "-fsanitize=fuzzer,address,undefined")
set(CMAKE_REQUIRED_LINK_OPTIONS "-fsanitize=fuzzer,address,undefined")
check_c_source_compiles([[
#include <stddef.h>
#include <stdint.h>
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { (void)data; (void)size; return 0; }
]] DBS_HAVE_LIBFUZZER)
unset(CMAKE_REQUIRED_FLAGS)
unset(CMAKE_REQUIRED_LINK_OPTIONS)
if(NOT DBS_HAVE_LIBFUZZER)
  message(STATUS "Fuzz targets skipped: ${CMAKE_C_COMPILER} cannot link libFuzzer "
    "(Debian: the libclang-rt-NN-dev package of this clang)")
  return()
endif()
set(DBS_FUZZ ON)
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
add_link_options(-fsanitize=address,undefined)
# A shared libdbs would leave the sanitizers' symbols undefined (it links with --no-undefined):
# the targets link the static library.
set(DBS_BUILD_SHARED OFF)
message(STATUS "Fuzz targets: tests/fuzz (libFuzzer, ASan, UBSan); libdbs built static for them")
