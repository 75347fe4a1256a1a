# Checking builds, off by default; -Werror is on in CI (CI=true, as setup.sh and test.sh
# run there), the sanitizers and fuzzers are turned on by scripts/test.sh's stage 2.
#   FLEETMAP_WERROR    -Werror on top of -Wall -Wextra (g++ and clang++)
#   FLEETMAP_SANITIZE  AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer
#                      in every target; the first report aborts the program
#   FLEETMAP_FUZZ      libFuzzer targets in fuzz/ (clang only; implies FLEETMAP_SANITIZE)
set(FLEETMAP_WERROR_DEFAULT OFF)
if("$ENV{CI}" STREQUAL "true")
  set(FLEETMAP_WERROR_DEFAULT ON)
endif()
option(FLEETMAP_WERROR "Treat compiler warnings as errors" ${FLEETMAP_WERROR_DEFAULT})
option(FLEETMAP_SANITIZE "Build with -fsanitize=address,undefined" OFF)
option(FLEETMAP_FUZZ "Build the libFuzzer targets in fuzz/ (clang only)" OFF)

if(FLEETMAP_WERROR)
  add_compile_options(-Werror)
endif()

if(FLEETMAP_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "FLEETMAP_FUZZ needs clang++ (libFuzzer), got ${CMAKE_CXX_COMPILER_ID}: "
                        "configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  # A fuzzer without ASan misses most memory errors, and the libraries it links are
  # instrumented for it, so every program then needs the sanitizer runtime too.
  set(FLEETMAP_SANITIZE ON CACHE BOOL "Build with -fsanitize=address,undefined" FORCE)
endif()

if(FLEETMAP_SANITIZE)
  set(FLEETMAP_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=undefined)
  # -O2 -g1 after the build type's -O3: reports with line numbers and usable stacks; -O2
  # keeps the localization tests on the real maps within the CI budget.
  add_compile_options(${FLEETMAP_SANITIZER_FLAGS} -fno-omit-frame-pointer -O2 -g1)
  add_link_options(${FLEETMAP_SANITIZER_FLAGS})
endif()
