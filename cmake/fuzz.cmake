# The checker's mutation fuzz test (NOTES.md 8.8): the checker's sources compiled again with
# AddressSanitizer and UndefinedBehaviorSanitizer (any report aborts), a mutation driver, and only
# what the checker links (MPFI, MPFR, GMP, nlohmann-json). `make test` (ctest) runs a short
# budget; `make fuzz` runs the same executable with a long one. Included from CMakeLists.txt after
# the checker's target exists: its sources and its include directory (only checker/) are reused.
get_target_property(CHECKER_SOURCES superpack_checker SOURCES)
get_target_property(CHECKER_INCLUDES superpack_checker INTERFACE_INCLUDE_DIRECTORIES)
file(GLOB FUZZ_SOURCES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/fuzz/*.cpp)
add_executable(superpack_checker_fuzz ${CHECKER_SOURCES} ${FUZZ_SOURCES})
target_include_directories(superpack_checker_fuzz PRIVATE ${CHECKER_INCLUDES})
set(SUPERPACK_SANITIZERS -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
target_compile_options(superpack_checker_fuzz PRIVATE ${SUPERPACK_SANITIZERS} -g)
target_link_options(superpack_checker_fuzz PRIVATE ${SUPERPACK_SANITIZERS})
target_link_libraries(superpack_checker_fuzz PRIVATE nlohmann_json::nlohmann_json ${MPFI_LIBRARY} ${MPFR_LIBRARY}
                      ${GMPXX_LIBRARY} ${GMP_LIBRARY})

set(FUZZ_ARGUMENTS ${CMAKE_SOURCE_DIR}/proofs ${CMAKE_SOURCE_DIR}/tests/data/fuzz_reference.json)
# The short run: 28 mutations (two of each kind) per certificate, or as many as start within 1 s
# of processor time (one of each of the costly certificates).
add_test(NAME checker_fuzz COMMAND superpack_checker_fuzz ${FUZZ_ARGUMENTS})
set_tests_properties(checker_fuzz PROPERTIES
  ENVIRONMENT "SUPERPACK_FUZZ_SEED=1;SUPERPACK_FUZZ_COUNT=28;SUPERPACK_FUZZ_SECONDS=1")
