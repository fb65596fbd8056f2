# robustness.cmake - the robustness tests (issue 6), included by
# CMakeLists.txt when MIST_ROBUSTNESS is ON:
#
#   stress               tests/test_stress.c: every public function over its
#                        whole domain and beyond, 1.4e8 calls (~18 s of CPU
#                        at -O2; MIST_STRESS_CALLS in the environment scales
#                        it: 1e10 is the long run, ~22 minutes)
#   fuzz_replay_<h>      the kept fuzz corpus fuzz/corpus/<h>/ through the
#                        harness fuzz/fuzz_<h>.c, built as a plain program
#   fuzz_<h>             the harness under clang's libFuzzer + ASan + UBSan
#                        for MIST_FUZZ_SECONDS over that corpus (skipped,
#                        exit 77, without clang and libFuzzer)
#   variant_<name>       a sub-build of this tree with other compiler flags
#                        (MIST_VARIANT_LIST: asan, fastmath, O0, O3, nofma)
#                        running its tests (see "Variants" below;
#                        MIST_VARIANTS; the sub-builds set it OFF: no
#                        recursion)
# and compile tests of these sources under gcc and clang, as CMakeLists.txt
# does for the others.
option(MIST_VARIANTS "Test sub-builds of mist under sanitizers and other compiler flags" ON)
set(MIST_FUZZ_SECONDS 10 CACHE STRING "Seconds each libFuzzer test runs")

set(_src ${CMAKE_CURRENT_SOURCE_DIR})

mist_program(test_stress tests/test_stress.c)
target_include_directories(test_stress PRIVATE tests)
add_test(NAME stress COMMAND test_stress)
set_tests_properties(stress PROPERTIES COST 60)      # long: start it early

set(_harnesses phase dir hfog)
if(UNIX)   # fuzz/replay.c lists directories with <dirent.h>
  foreach(h ${_harnesses})
    mist_program(replay_${h} fuzz/fuzz_${h}.c fuzz/replay.c)
    target_include_directories(replay_${h} PRIVATE tests fuzz)
    add_test(NAME fuzz_replay_${h} COMMAND replay_${h} ${_src}/fuzz/corpus/${h})
  endforeach()
endif()
if(MIST_FUZZ_SECONDS GREATER 0)
  foreach(h ${_harnesses})
    add_test(NAME fuzz_${h}
             COMMAND sh ${_src}/fuzz/run_fuzz.sh ${_src} ${CMAKE_CURRENT_BINARY_DIR}/fuzz ${h}
                     ${MIST_FUZZ_SECONDS})
    set_tests_properties(fuzz_${h} PROPERTIES SKIP_RETURN_CODE 77)
  endforeach()
endif()

# the new sources under both compilers (tests/compile/compile_check.sh
# skips a missing compiler)
foreach(cc gcc clang)
  foreach(s tests/test_stress.c fuzz/fuzz_phase.c fuzz/fuzz_dir.c fuzz/fuzz_hfog.c fuzz/replay.c)
    get_filename_component(_n ${s} NAME_WE)
    add_test(NAME compile_${cc}_${_n}
             COMMAND sh ${_src}/tests/compile/compile_check.sh ${cc} -std=c99 ${MIST_WARNINGS}
                     -I${_src}/include -I${_src}/tests -I${_src}/fuzz -fsyntax-only ${_src}/${s})
    set_tests_properties(compile_${cc}_${_n} PROPERTIES SKIP_RETURN_CODE 77)
  endforeach()
endforeach()

# Variants: this tree rebuilt with other flags, running its tests.
#
# "The whole test suite also runs under ASan/UBSan, -ffast-math, -O0, -O3
# and without FMA contraction" (issue 6), within CI's time (the README's
# test command, 2 cores: the variants run beside the main tests, ctest -j):
#   asan      -O0 -g, AddressSanitizer + UndefinedBehaviorSanitizer; this is
#             also the -O0 variant (O0 alone: MIST_VARIANT_LIST).  Every
#             test but accuracy and chi2: those two draw millions of samples
#             through the code paths that quadrature, domain, stress and the
#             replays also take, for statistics the sanitizers do not check,
#             and are the slowest under ASan (29 s and 25 s at -O1 with ASan,
#             measured on a loaded 2-core machine, against ~10 s each at
#             -O2).  The stress test at 2e6 calls.
#   fastmath  -O2 -ffast-math: every test.  The header guards itself (FAST
#             MATH in include/mist.h); what remains of -ffast-math is the
#             start-up code's flushing of subnormals (FTZ/DAZ), so the stress
#             test keeps to its MI_FAST subset (tests/mist_inv.h: finite,
#             normal-range input, tolerances that allow the flushing).
#   O3        -O3 -march=native -ffp-contract=fast (FMA contraction where
#             the host has FMA): every test.
#   nofma     -O2 -march=native -ffp-contract=off (explicit fma() where the
#             host has it, no contraction): every test.  The main build is
#             without contraction too (gcc -std=c99 implies
#             -ffp-contract=off; x86-64 without -march has no FMA).
#   O0        -O0: every test (not in the default list: asan is at -O0).
# The main build's stress test makes the 1e8 calls; the variants' make
# 5e6 (asan 2e6).  Each variant configures and builds its own tree in
# parallel with the rest (COST: started first).
if(MIST_VARIANTS AND CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
  include(CheckCCompilerFlag)
  check_c_compiler_flag(-march=native MIST_HAVE_MARCH_NATIVE)
  set(_native "")
  if(MIST_HAVE_MARCH_NATIVE)
    set(_native "-march=native")     # with FMA where the host has it
  endif()
  set(MIST_VARIANT_LIST "asan;fastmath;O3;nofma" CACHE STRING
      "The variants to test (MIST_VARIANTS): any of asan fastmath O0 O3 nofma")
  function(mist_variant name flags calls exclude)
    if(NOT name IN_LIST MIST_VARIANT_LIST)
      return()
    endif()
    add_test(NAME variant_${name}
             COMMAND sh ${_src}/tests/variant.sh ${name} ${_src}
                     ${CMAKE_CURRENT_BINARY_DIR}/variant-${name} ${CMAKE_C_COMPILER}
                     ${CMAKE_GENERATOR} "${flags}" ${calls} "${exclude}")
    set_tests_properties(variant_${name} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 900 COST 100)
  endfunction()
  # name, CMAKE_C_FLAGS, MIST_STRESS_CALLS, the tests left out (a regex)
  mist_variant(asan "-O0 -g -fsanitize=address,undefined -fno-sanitize-recover=all"
               2e6 "^(accuracy|chi2)$")
  mist_variant(fastmath "-O2 -ffast-math" 5e6 "")
  mist_variant(O3 "-O3 ${_native} -ffp-contract=fast" 5e6 "")
  mist_variant(nofma "-O2 ${_native} -ffp-contract=off" 5e6 "")
  mist_variant(O0 "-O0" 5e6 "")
endif()
