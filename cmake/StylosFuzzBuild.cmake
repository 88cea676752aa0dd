# STYLOS_FUZZ=ON: only the Qt-free core and the libFuzzer harnesses (tests/fuzz), with clang's libFuzzer,
# AddressSanitizer and UndefinedBehaviorSanitizer (docs/fuzzing.md). Assertions stay on (no NDEBUG): a
# reader that lets bad input reach an assertion is a bug the fuzzer must see.
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "STYLOS_FUZZ=ON needs clang with libFuzzer: configure with -DCMAKE_CXX_COMPILER=clang++")
endif()
string(TOUPPER "${CMAKE_BUILD_TYPE}" stylos_fuzz_config)
set(CMAKE_CXX_FLAGS_${stylos_fuzz_config} "")
add_compile_options(-O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer-no-link,address,undefined
                    -fno-sanitize-recover=all)
add_link_options(-fsanitize=address,undefined)
add_subdirectory(core)
add_subdirectory(tests/fuzz)
