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
# Issue 6: "the whole test suite also runs under ASan/UBSan, -ffast-math,
# -O0, -O3, and without FMA contraction".  CI runs the README's test
# command on 2 cores in ~4 minutes with these, so the default list is three
# variants that, with the main build, cover the five (CPU seconds measured
# with gcc 12 on this project's 2-core machine):
#   asan      -O0 -g, AddressSanitizer + UndefinedBehaviorSanitizer: the
#             sanitizer variant and the -O0 variant.
#             Every test but accuracy, chi2 and height_fog, which at -O2
#             alone take 13, 5.5 and 10 s of the suite's ~33 s, and several
#             times that at -O0 with ASan: they draw millions of samples and
#             rays through the functions that stress (2e6 calls here),
#             quadrature, the fuzz replays and the fuzz_* tests (clang ASan
#             + UBSan) also reach, for numbers the sanitizers do not check.
#             ~52 s for the whole variant (build 16 s wall).
#   fastmath  -O2 -ffast-math.  The header guards itself
#             (FAST MATH in include/mist.h); what -ffast-math still changes
#             is the start-up flushing of subnormals (FTZ/DAZ), so the
#             stress test keeps to its MI_FAST subset (tests/mist_inv.h:
#             finite, normal-range input, tolerances that allow the
#             flushing).  Not with -march=native: see FAST MATH (one
#             bit-for-bit check of test_domain fails there).  Every test
#             but fuzz_replay_hfog: its corpus is raw bit patterns (NaN,
#             inf, subnormal fields) and the harness, compiled with
#             -ffast-math itself, does not keep replayed input to the
#             MI_FAST subset: 10 of 487 inputs failed (e.g. "in-scattering
#             without extinction" at T = 0 for regress-col-nan-d).  That
#             replay runs in the main build and under asan.
#   O3        -O3 -march=native -ffp-contract=fast (contraction wherever
#             the host has FMA): every test.
# "Without FMA contraction": the main build (gcc -std=c99 means
# -ffp-contract=off, and x86-64 without -march has no FMA instruction) and
# fastmath (the header's guard sets fp-contract=off under gcc).  Explicit
# fma() on FMA hardware without contraction is nofma below, not in the
# default list: with -march=native added to asan, quadrature took 5x longer
# (34 s against 7 s of CPU at -O0 with ASan, measured).
# and on request (MIST_VARIANT_LIST), every test each:
#   O0        -O0 without sanitizers
#   nofma     -O2 -march=native -ffp-contract=off without -ffast-math
# The main build's stress test makes the 1e8 calls; the variants' 5e6
# (asan 2e6).  Each variant configures and builds its own tree beside the
# main tests (COST: the long tests start first).
if(MIST_VARIANTS AND CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
  include(CheckCCompilerFlag)
  check_c_compiler_flag(-march=native MIST_HAVE_MARCH_NATIVE)
  set(_native "")
  if(MIST_HAVE_MARCH_NATIVE)
    set(_native "-march=native")     # with FMA where the host has it
  endif()
  set(MIST_VARIANT_LIST "asan;fastmath;O3" CACHE STRING
      "The variants to test (MIST_VARIANTS): any of asan fastmath O3 O0 nofma")
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
               2e6 "^(accuracy|chi2|height_fog)$")
  mist_variant(fastmath "-O2 -ffast-math" 5e6 "^fuzz_replay_hfog$")
  mist_variant(O3 "-O3 ${_native} -ffp-contract=fast" 5e6 "")
  mist_variant(O0 "-O0" 5e6 "")
  mist_variant(nofma "-O2 ${_native} -ffp-contract=off" 5e6 "")
endif()

# The longest single jobs start first, beside the variants (ctest runs
# the highest COST first): nvcc's compile of the header (~70 s of one
# core, measured) and the main stress test.
if(TEST compile_nvcc)
  set_tests_properties(compile_nvcc PROPERTIES COST 90)
endif()
