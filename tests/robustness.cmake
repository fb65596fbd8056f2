# robustness.cmake - the robustness tests (issue 6), included by
# CMakeLists.txt when MIST_ROBUSTNESS is ON:
#
#   stress               tests/test_stress.c: every public function over its
#                        whole domain and beyond, 1.3e8 calls (~15 s at -O2;
#                        MIST_STRESS_CALLS in the environment scales it)
#   fuzz_replay_<h>      the kept fuzz corpus fuzz/corpus/<h>/ through the
#                        harness fuzz/fuzz_<h>.c, built as a plain program
#   fuzz_<h>             the harness under clang's libFuzzer + ASan + UBSan
#                        for MIST_FUZZ_SECONDS over that corpus (skipped,
#                        exit 77, without clang and libFuzzer)
#   variant_<name>       a sub-build of this tree with other compiler flags
#                        (MIST_VARIANT_LIST: asan, fastmath, O0, O3, nofma)
#                        running the numeric tests (MIST_VARIANTS; the
#                        sub-builds set it OFF: no recursion)
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

# Variants: this tree rebuilt with other flags, running the numeric tests.
if(MIST_VARIANTS AND CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
  include(CheckCCompilerFlag)
  check_c_compiler_flag(-march=native MIST_HAVE_MARCH_NATIVE)
  set(_native "")
  if(MIST_HAVE_MARCH_NATIVE)
    set(_native "-march=native")     # with FMA where the host has it
  endif()
  set(_numeric "^(accuracy|quadrature|chi2|domain|fits|mie|height_fog|stress|fuzz_replay_.*)$")
  set(MIST_VARIANT_LIST "asan;fastmath;O0;O3;nofma" CACHE STRING
      "The variants to test (MIST_VARIANTS): any of asan fastmath O0 O3 nofma")
  function(mist_variant name flags calls tests)
    if(NOT name IN_LIST MIST_VARIANT_LIST)
      return()
    endif()
    add_test(NAME variant_${name}
             COMMAND sh ${_src}/tests/variant.sh ${name} ${_src}
                     ${CMAKE_CURRENT_BINARY_DIR}/variant-${name} ${CMAKE_C_COMPILER}
                     ${CMAKE_GENERATOR} "${flags}" ${calls} "${tests}")
    set_tests_properties(variant_${name} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 900 COST 100)
  endfunction()
  # name, CMAKE_C_FLAGS, MIST_STRESS_CALLS, the tests (a regex of names)
  mist_variant(asan "-O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all"
               5e6 "${_numeric}")
  # -ffast-math assumes no NaN and no infinity and flushes subnormals to
  # zero, so this variant runs the subset where that holds: the stress test
  # limits itself to finite input in the normal range, |g| <= 1 - 2^-10 and
  # w_d = 1 or <= 1 - 2^-10, with wider tolerances (MI_FAST in
  # tests/mist_inv.h), and these are left out (measured, gcc 12, clang 14):
  #   domain, mie   feed NaN and +-inf on purpose (the documented bad
  #                 input); gcc -ffinite-math-only treats those values as
  #                 impossible and drops the rest of main() after the first
  #                 such check: both programs crash (SIGSEGV, running off the
  #                 end of main)
  #   fuzz_replay_* the kept corpus is raw bit patterns, mostly NaN, inf and
  #                 subnormals
  #   height_fog    (the uncommitted tests/test_height_fog.c of the time)
  #                 ~700 checks miss the bar by ~30 eps at h = 40 scale
  #                 heights: -fassociative-math folds the compensated
  #                 exponent (TwoSum, the double-T quotient) away (they pass
  #                 with -fno-associative-math); 24 multi-layer checks at
  #                 length +inf get a NaN bound (no infinity under
  #                 -ffinite-math-only)
  # and under clang also
  #   quadrature    "hg_eval equals draine_eval at alpha = 0" and "pdf ==
  #                 eval" compare two inlined copies of one formula bit for
  #                 bit, which clang evaluates differently (~1700 checks);
  #                 near |g| = 1 the densities miss the float128 bar 33x
  #                 (1/(4 pi) (1 - g) reassociated to 1/(4 pi) - g/(4 pi))
  #   fits          "d = NaN gives the d -> 0 limit" (NaN input)
  if(CMAKE_C_COMPILER_ID MATCHES "Clang")
    set(_fast "^(accuracy|chi2|stress)$")
  else()
    set(_fast "^(accuracy|quadrature|chi2|fits|stress)$")
  endif()
  mist_variant(fastmath "-O2 -ffast-math" 1e7 "${_fast}")
  mist_variant(O0 "-O0" 5e6 "${_numeric}")
  mist_variant(O3 "-O3 ${_native} -ffp-contract=fast" 1e7 "${_numeric}")
  mist_variant(nofma "-O2 ${_native} -ffp-contract=off" 1e7 "${_numeric}")
endif()
