# robustness.cmake - the robustness tests, included by
# CMakeLists.txt when MIST_ROBUSTNESS is ON:
#
#   stress               tests/test_stress.c: every public function over its
#                        whole domain and beyond, 1.07e8 calls (~9 s of CPU
#                        at -O3; MIST_STRESS_CALLS in the environment scales
#                        it: 1e10 is the long run, ~14 minutes at ~80 ns a
#                        call)
#   fuzz_replay_<h>      the kept fuzz corpus fuzz/corpus/<h>/ through the
#                        harness fuzz/fuzz_<h>.c, built as a plain program
#   fuzz_<h>             the harness under clang's libFuzzer + ASan + UBSan
#                        for MIST_FUZZ_SECONDS over that corpus (skipped,
#                        exit 77, without clang and libFuzzer)
#   variant_<name>       a sub-build of this tree with other compiler flags
#                        (MIST_VARIANT_LIST: asan, fastmath, O0, O3, nofma)
#                        running its tests, accuracy, chi2 and height_fog
#                        with MIST_TEST_QUICK=MIST_VARIANT_QUICK (see
#                        "Variants" below;
#                        MIST_VARIANTS; the sub-builds set it OFF: no
#                        recursion)
# and compile tests of these sources under gcc and clang, as CMakeLists.txt
# does for the others.
option(MIST_VARIANTS "Test sub-builds of mist under sanitizers and other compiler flags" ON)
# 2 s a harness: in CI these runs are a smoke test of the harnesses and the
# sanitizer build (10 s runs ~17000 inputs of fuzz_phase under ASan); the
# long runs of fuzz/README.md are where fuzzing finds things
set(MIST_FUZZ_SECONDS 2 CACHE STRING "Seconds each libFuzzer test runs")
# -O0 (the long runs of fuzz/README.md take -O1): the build is most of such
# a short test, fuzz_hfog's 6.6 s at -O1
# against 1.8 s at -O0, fuzz_phase's 4.5 against 1.4 (clang 14); at -O0 the
# 3 s run half the inputs (5147 against 10101 for fuzz_hfog, the kept
# corpus included, measured), and ASan + UBSan see the code unoptimised.
set(MIST_FUZZ_OPT -O0 CACHE STRING "clang's optimisation level for the libFuzzer tests")

set(_src ${CMAKE_CURRENT_SOURCE_DIR})

mist_program(test_stress tests/test_stress.c)
target_include_directories(test_stress PRIVATE tests)
add_test(NAME stress COMMAND test_stress)
set_tests_properties(stress PROPERTIES COST 60)      # long: start it early

set(_harnesses phase dir hfog mie)   # mie: include/mist_mie.h
if(UNIX)   # fuzz/replay.c lists directories with <dirent.h>
  foreach(h ${_harnesses})
    mist_program(replay_${h} fuzz/fuzz_${h}.c fuzz/replay.c)
    target_include_directories(replay_${h} PRIVATE tests fuzz)
    add_test(NAME fuzz_replay_${h} COMMAND replay_${h} ${_src}/fuzz/corpus/${h})
  endforeach()
endif()
# Every harness also runs live for MIST_FUZZ_SECONDS (fuzz_mie since its
# four mist_mie_average findings were fixed: scaled sums and the length
# domain [MIST_MIE_LEN_MIN, MIST_MIE_LEN_MAX]; 300 s of it found nothing
# more).
set(_live ${_harnesses})
if(MIST_FUZZ_SECONDS GREATER 0)
  foreach(h ${_live})
    add_test(NAME fuzz_${h}
             COMMAND sh ${_src}/fuzz/run_fuzz.sh ${_src} ${CMAKE_CURRENT_BINARY_DIR}/fuzz ${h}
                     ${MIST_FUZZ_SECONDS} ${MIST_FUZZ_OPT})
    # COST: started among the long tests, not last (with no cost ctest ran
    # them after everything else, and fuzz_hfog, 12 s with its build, was
    # the suite's tail: one core idle for ~10 s)
    set_tests_properties(fuzz_${h} PROPERTIES SKIP_RETURN_CODE 77 COST 30)
  endforeach()
endif()

# the new sources under both compilers (tests/compile/compile_check.sh
# skips a missing compiler)
foreach(cc gcc clang)
  foreach(s tests/test_stress.c fuzz/fuzz_phase.c fuzz/fuzz_dir.c fuzz/fuzz_hfog.c fuzz/fuzz_mie.c
              fuzz/replay.c)
    get_filename_component(_n ${s} NAME_WE)
    add_test(NAME compile_${cc}_${_n}
             COMMAND sh ${_src}/tests/compile/compile_check.sh ${cc} -std=c99 ${MIST_WARNINGS}
                     -I${_src}/include -I${_src}/tests -I${_src}/fuzz -fsyntax-only ${_src}/${s})
    set_tests_properties(compile_${cc}_${_n} PROPERTIES SKIP_RETURN_CODE 77)
  endforeach()
endforeach()

# Variants: this tree rebuilt with other flags, running its tests.
#
# The whole test suite also runs under ASan/UBSan, -ffast-math, -O0, -O3,
# and without FMA contraction.  The README's test command runs on 2 cores
# within a few minutes, so the default list is three variants that, with
# the main build, cover the five; they are most of the suite's CPU time
# (~270 s of CPU for the three, ctest -R '^variant_' -j2).  asan is the
# longest job:
#   asan      -O0 -g, AddressSanitizer + UndefinedBehaviorSanitizer: the
#             sanitizer variant and the -O0 variant.  Every test (but the
#             compile and consumer tests, as in every variant: their flags
#             are their own; and the *_native builds, MIST_TEST_NATIVE=OFF:
#             accuracy_nold is the double samplers without long double here;
#             accuracy_nold_native and batch_native had taken 31 and 21 s
#             of the 123 s its tests ran in, and -march=native slowed
#             ASan's quadrature 5x, see below; and batch:
#             batch_nold walks the same blocks, remainders and arrays, the
#             batch forms' indexing, which is what ASan checks there, and
#             the stress run calls the batch forms of this configuration;
#             batch took 7.8 s of CPU here; and the tests whose code the
#             others run here and whose own work is arithmetic: quadrature,
#             fits, fits_mie (closed forms and fits evaluated), chi2 (the
#             samplers: accuracy, stress), height_fog (the height fog:
#             hfog_path, the stress run, fuzz_hfog's live ASan + UBSan
#             run), accuracy_nold (same_samples still runs its build),
#             furnace (the public samplers, as accuracy): 38, 21, 19, 11,
#             10, 9, 9 s under ASan).  batch_nold stays: built with
#             -march=native -fno-math-errno it is asan's only build of the
#             vectorised kernels (mist__draine_vk, the fma branches) and
#             their stack blocks, and of n = 0 and n >= 1024 (in quick
#             mode for mist_draine_sample_n and mist_phase_sample_n, the
#             batch forms whose code depends on n there: test_batch.c),
#             which the stress run's batches (n 1 to 80) do not reach),
#             with
#             MIST_TEST_QUICK=MIST_VARIANT_QUICK (16): accuracy, chi2 and
#             height_fog draw a sixteenth of their random points and samples,
#             but never below each count's floor (mt_scale's lo: chi2 keeps
#             half the scalar and a quarter of the direction samples, where
#             its negative controls are still rejected, see test_chi2.c),
#             every fixed edge case and grid in full.  Measured (s under
#             ASan, gcc 12, one at a time, quick 4 -> 8): accuracy 13.3 ->
#             8.8, accuracy_nold 16.7 -> 9.7, height_fog 11.3 -> 10.0, chi2
#             6.3 -> 5.9 (earlier, full size -> 4: accuracy 31 -> 12, chi2
#             11.6 -> 5.5, height_fog 17.7 -> 11).  Stress makes 2e6 calls
#             here.
#   fastmath  -O2 -ffast-math.  The header guards itself
#             (FAST MATH in include/mist.h); what -ffast-math still changes
#             is the start-up flushing of subnormals (FTZ/DAZ), so the
#             stress test keeps to its MI_FAST subset (tests/mist_inv.h:
#             finite, normal-range input, tolerances that allow the
#             flushing), and so do the fuzz harnesses replaying the corpus
#             (fuzz_hfog.c reads its raw-bits "direct" records through the
#             generators there; replayed raw, 13 of the 549 inputs failed).
#             Not with -march=native: see FAST MATH (one bit-for-bit check
#             of test_domain fails there).  Every test but the *_native
#             builds (fast math with FMA: the main build's fastmath_* tests
#             and the mie_fastmath test), quick 16.
#   O3        -O3 -march=native -ffp-contract=fast (contraction wherever
#             the host has FMA): every test (as asan; its *_native builds
#             would repeat its own flags) but accuracy_nold, quick 16: where
#             fma is one instruction MIST_NO_LONG_DOUBLE changes only the
#             double Draine samplers' long double fallback, taken after 64
#             unsettled double-double steps or a NaN residual
#             (mist__draine_ddfin returning 0: mist__draine_solve and
#             mist__phase_try, include/mist.h), so with -march=native on
#             a host with FMA it repeats accuracy (on one without, the main
#             build's accuracy_nold runs the same Dekker path without
#             contraction, which there is none to do; it is still built:
#             same_samples compares its
#             fingerprint; 3.1 s of the 16 s of CPU O3's tests took).  batch_nold stays: with
#             -fno-math-errno (MIST_BENCH_FLAGS) it is O3's only build of
#             the vectorised kernels, and the only one anywhere under
#             contraction.
# The main build runs accuracy, chi2 and height_fog at full size (no
# MIST_TEST_QUICK): the variants check that other flags change nothing,
# the main build carries the statistical power.
# "Without FMA contraction": the main build (gcc -std=c99 means
# -ffp-contract=off, and x86-64 without -march has no FMA instruction) and
# fastmath (the header's guard sets fp-contract=off under gcc).  Explicit
# fma() on FMA hardware without contraction is nofma below, not in the
# default list: with -march=native added to asan, quadrature took 5x longer
# (34 s against 7 s of CPU at -O0 with ASan, measured).
# and on request (MIST_VARIANT_LIST), every test each, MIST_TEST_QUICK=16:
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
  # asan by default; fastmath and O3 with the slow tests (MIST_TEST_SLOW),
  # the main build's *_fastmath and *_contract programs standing in for them
  if(MIST_TEST_SLOW)
    set(_variants "asan;fastmath;O3")
  else()
    set(_variants "asan")
  endif()
  set(MIST_VARIANT_LIST "${_variants}" CACHE STRING
      "The variants to test (MIST_VARIANTS): any of asan fastmath O3 O0 nofma")
  set(MIST_VARIANT_QUICK 16 CACHE STRING
      "MIST_TEST_QUICK for the variants' accuracy, chi2 and height_fog tests (1: full size)")
  function(mist_variant name flags calls exclude native)
    if(NOT name IN_LIST MIST_VARIANT_LIST)
      return()
    endif()
    add_test(NAME variant_${name}
             COMMAND sh ${_src}/tests/variant.sh ${name} ${_src}
                     ${CMAKE_CURRENT_BINARY_DIR}/variant-${name} ${CMAKE_C_COMPILER}
                     ${CMAKE_GENERATOR} "${flags}" ${calls} "${exclude}" "${MIST_VARIANT_QUICK}"
                     ${native})
    set_tests_properties(variant_${name} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 900 COST 100)
    if(NOT name STREQUAL "asan")
      set_tests_properties(variant_${name} PROPERTIES LABELS slow)
    endif()
  endfunction()
  # name, CMAKE_C_FLAGS, MIST_STRESS_CALLS, the tests left out (a regex),
  # MIST_TEST_NATIVE (the *_native builds: off where the variant's flags
  # would make them a repeat, O3 and nofma, or where -march=native costs
  # more than it finds, asan: see above)
  mist_variant(asan "-O0 -g -fsanitize=address,undefined -fno-sanitize-recover=all" 2e6
               "^(batch|tab_nold|quadrature|fits|fits_mie|furnace|accuracy_nold|chi2|height_fog)$"
               OFF)
  mist_variant(fastmath "-O2 -ffast-math" 5e6 "" OFF)
  mist_variant(O3 "-O3 ${_native} -ffp-contract=fast" 5e6 "^(accuracy_nold|tab_nold)$" OFF)
  mist_variant(O0 "-O0" 5e6 "" ON)
  mist_variant(nofma "-O2 ${_native} -ffp-contract=off" 5e6 "" OFF)
endif()

# The longest single jobs start first, beside the variants (ctest runs
# the highest COST first): nvcc's compile of the header (~70 s of one
# core, measured) and the main stress test.
if(TEST compile_nvcc)
  set_tests_properties(compile_nvcc PROPERTIES COST 90)
endif()
