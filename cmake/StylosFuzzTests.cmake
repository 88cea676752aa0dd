# The fuzz harnesses in the normal build (docs/fuzzing.md). When clang++ with libFuzzer is found, a second
# CMake tree of the same sources (STYLOS_FUZZ=ON, clang; build/fuzz) is an ExternalProject that
# `cmake --build build` builds: the core and the harnesses only. Each harness then gets a ctest test (label
# "fuzz") that runs it STYLOS_FUZZ_SECONDS on its seed corpus (scripts/fuzz-corpus.sh, a fixture) and
# fails on any crash, leak, sanitizer report or timeout. Without clang the tests say so and are skipped.
option(STYLOS_FUZZ_TESTS "Build the libFuzzer harnesses with clang++ when found, and run each briefly in ctest" ON)
set(STYLOS_FUZZ_SECONDS 5 CACHE STRING "Seconds each harness runs in the test suite")
set(STYLOS_FUZZ_JOBS 2 CACHE STRING "Parallel compile jobs of the fuzz tree")

set(stylos_fuzz_bin "${PROJECT_BINARY_DIR}/fuzz/bin")
if(STYLOS_FUZZ_TESTS)
  find_program(STYLOS_FUZZ_CLANGXX NAMES clang++ clang++-16 clang++-15 clang++-14)
  if(STYLOS_FUZZ_CLANGXX AND NOT DEFINED STYLOS_FUZZ_HAVE_LIBFUZZER)
    set(check "${PROJECT_BINARY_DIR}/CMakeFiles/fuzz-check")
    file(WRITE "${check}/check.cpp" "#include <cstddef>\n#include <cstdint>\nextern \"C\" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }\n")
    execute_process(COMMAND "${STYLOS_FUZZ_CLANGXX}" -fsanitize=fuzzer,address,undefined check.cpp -o check
                    WORKING_DIRECTORY "${check}" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
    if(rc EQUAL 0)
      set(STYLOS_FUZZ_HAVE_LIBFUZZER ON CACHE INTERNAL "clang++ links -fsanitize=fuzzer,address,undefined")
    else()
      set(STYLOS_FUZZ_HAVE_LIBFUZZER OFF CACHE INTERNAL "clang++ links -fsanitize=fuzzer,address,undefined")
    endif()
  endif()
endif()

if(STYLOS_FUZZ_TESTS AND STYLOS_FUZZ_HAVE_LIBFUZZER)
  message(STATUS "Fuzz harnesses: built with ${STYLOS_FUZZ_CLANGXX} in ${PROJECT_BINARY_DIR}/fuzz")
  include(ExternalProject)
  ExternalProject_Add(stylos_fuzz
    SOURCE_DIR "${PROJECT_SOURCE_DIR}"
    BINARY_DIR "${PROJECT_BINARY_DIR}/fuzz"
    PREFIX "${PROJECT_BINARY_DIR}/fuzz-prefix"
    CMAKE_GENERATOR "${CMAKE_GENERATOR}"
    CMAKE_ARGS -DSTYLOS_FUZZ=ON -DCMAKE_BUILD_TYPE=Fuzz "-DCMAKE_CXX_COMPILER=${STYLOS_FUZZ_CLANGXX}"
               "-DCMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}"
    BUILD_COMMAND "${CMAKE_COMMAND}" --build <BINARY_DIR> -j "${STYLOS_FUZZ_JOBS}"
    BUILD_ALWAYS ON
    INSTALL_COMMAND ""
    USES_TERMINAL_BUILD ON)
else()
  message(STATUS "Fuzz harnesses: not built (no clang++ with libFuzzer; the fuzz tests will be skipped)")
endif()

set(stylos_fuzz_corpus "${PROJECT_BINARY_DIR}/fuzz-corpus")
add_test(NAME fuzz_corpus
  COMMAND bash "${PROJECT_SOURCE_DIR}/scripts/fuzz-corpus.sh" "${stylos_fuzz_corpus}" "${STYLOS_SHARED_DATA}" "${stylos_fuzz_bin}")
set_tests_properties(fuzz_corpus PROPERTIES FIXTURES_SETUP fuzz_corpus LABELS fuzz SKIP_RETURN_CODE 77 TIMEOUT 120)
file(STRINGS "${PROJECT_SOURCE_DIR}/tests/fuzz/harnesses.txt" stylos_fuzz_lines REGEX "^[A-Za-z]")
foreach(line IN LISTS stylos_fuzz_lines)
  string(REGEX MATCH "^[A-Za-z0-9]+" name "${line}")
  add_test(NAME fuzz_${name}
    COMMAND bash "${PROJECT_SOURCE_DIR}/scripts/fuzz-run.sh" ${name} "${stylos_fuzz_corpus}"
            "${PROJECT_BINARY_DIR}/fuzz-work" "${stylos_fuzz_bin}" -max_total_time=${STYLOS_FUZZ_SECONDS})
  set_tests_properties(fuzz_${name} PROPERTIES FIXTURES_REQUIRED fuzz_corpus LABELS fuzz SKIP_RETURN_CODE 77
                       TIMEOUT 120)
endforeach()
