#!/usr/bin/env bash
# The test suite under AddressSanitizer and UndefinedBehaviorSanitizer: a second build in
# build-asan/ (-DROLLNOISE_SANITIZE=ON: -fsanitize=address,undefined, -fno-sanitize-recover=all),
# then ctest there. Needs the packages of scripts/setup.sh (.ci/run runs scripts/test.sh first).
#
#   bash scripts/test_sanitized.sh [ctest arguments]   e.g. -R LinearModel
#   ROLLNOISE_JOBS=1        parallel jobs of the build and of ctest (default: nproc)
#   ROLLNOISE_SANITIZE_ALL=1  also the excluded tests below (12.5 more CPU minutes)
#
# Build: the libraries, the program and the test programs as a unity build (CMakeLists.txt,
# ROLLNOISE_UNITY_BUILD: about half their compile time; `bash scripts/check_unity_names.sh --all`
# finds file-local names that clash within a layer or a test folder in ~6 min), -O1 (the usual sanitizer level) with line tables only (-g1: the reports keep file:line and
# inlined frames, and a file compiles about a third faster than with -g); no -DNDEBUG, so Eigen's
# index assertions are on, and _GLIBCXX_ASSERTIONS checks std::vector indices within the capacity,
# which AddressSanitizer cannot see. No benchmarks. Any sanitizer report ends its process with
# status 86 (the program itself exits 0, 1 or 2, and no test expects 86): a CLI test that fails
# with status 86 had a report in build-asan/rollnoise; rerun its command to see the report if the
# test does not print the output.
#
# Excluded by default: the runs whose sanitized time goes into O(n^3) dense factorisations
# done many times over as a reference (Eigen code, 20-50x slower under the sanitizers: a 1200 x 1200
# LU takes 0.08 s natively, 4 s here), while the same rollnoise functions run in the tests that
# stay. Measured on this 2-core machine (one job), the whole sanitized suite takes 27 min, these
# four 12.5 min of it:
#   LinearModel.FastSweepAgrees*, .FastSweepHessenbergAndDirect*, .EveryMeanState*,
#   NormalLoad.FastSweepEquals* (direct complex LUs and one dense Hessenberg reduction),
#   NormalLoad.LinearModelAgrees* (nine unsteady runs with a normal solve per step, 14 s in Release)
#                               the fast sweep against 15-28 direct complex LUs each on 34 x 25
#                               (170-290 s each); the sweep, exact recursion, Hessenberg form and
#                               direct solve (45 times, 15 mean states, 24 x 18) run in the other
#                               LinearModel.* and NssStress.* tests.
#   ConditioningStress.*        exact condition numbers: dense eigenvalue problems and SVDs in the
#                               test itself (80 s); its mean states are solved in SteadyStress.*.
#   Falling friction: its linear model is the dense paper form (a Hessenberg reduction per model,
#   the spectral radius by a dense eigensolver): LaplaceCoefficients.SpectralRadius* (131 s),
#   FallingFrictionModel.SweepRoutes* (69 s) and .ConstantFrictionLimits* (53 s),
#   FallingFrictionSqueal.* (63 s, a bisection of squeal runs) and
#   SquealFallingFriction.TightCurveCaseSquealsInAxialModesOnly (87 s: squeal_150m's 36 roots); the
#   same functions run sanitized in the other FallingFriction*, LaplaceCoefficients.* and
#   SquealFallingFriction.* tests.
#   SquealKalker.* (5 s in Release: a squeal run and route 1 on curve_300m_table); the same code
#   paths run sanitized in SquealRoutes.* and SquealPassivity.*.
#   StudyWheels.* (3 s in Release: a study of a profile case with two coupled wheels) and
#   WheelsetPassivity.* (squeal per wheelset on every shipped curve case); the same code paths run
#   sanitized in Study.* and ContactSetSqueal.UncoupledWheels*.
#   SquealRoutes.*WithTheFeWheel (route 1 against route 2 on curve_500m with its FE wheel: the FE
#   modes and twice the loop modes of the table wheel); the routes' code runs sanitized in the
#   table-wheel SquealRoutes test, the FE modes in WheelFe.* and LowestModesSolver.*.
#   Repeats of a computation another sanitized test makes (ctest runs each test in its own process,
#   so a study shared by several tests of one file is recomputed per test): GridStudy.* except
#   CreepCoefficientsAt1kHz* and AverageSamplingLeaves* (the same five-grid study, ~52 s each);
#   AverageSampling.UnsteadySolverAgrees* (104 s) and NonHertzianContact.LinearModelSpectra* (106 s:
#   `validate` on the S1002 patch), whose unsteady runs and linear models run sanitized in
#   CreepageSampling.UnsteadySolverAgrees*, TransientRolling.* and ValidateCommand.*;
#   postprocess_plots_smoke (173 s: the plot scripts, in Python; the commands it runs are sanitized
#   in the CLI tests).
#   The waveguide rail: RailWaveguide.{FreeRailWavenumbers,CentredVerticalReceptance,EccentricContact}*,
#   RailWaveguideReduced.*, WaveguideRailModel.*, WaveguideRailAtContact.*: dense eigenproblems of
#   n = 621 (zgeev, the Ritz basis' generalised symmetric ones); RailWaveguidePatch.*,
#   RailContactPoint.*, ReceptanceInterpolation.* and the smoke test's waveguide receptance run
#   them sanitized.
#   The sound stage's numerics: SoundPower.RadiatedPowerStays* (36 s: the 300 m bogie with the FE
#   wheel's BEM on 45 frequencies) and .WheelModesRadiate* (13 s: the FE wheel twice and its BEM);
#   the BEMs run sanitized in AxisymmetricBem.*, Bem2d.*, the stage in
#   SoundPower.TableWheelLeaves* and every noise command test. The waveguide's deforming section,
#   RailSectionSound.{ZeroWavenumber,SectionPowerMeets,AdaptiveQuadrature,HeadDistributions}*:
#   the waveguide's section modes and waves as above; its table runs sanitized in
#   RailSectionSound.TableInterpolates*. WaveguideAndBeam.* (92 s: the waveguide's receptances
#   against the beam's, dense eigenproblems as above).
#   RailSamplingCache.EveryRailEdit* (169 s: a waveguide run per edited track key); the cache's
#   reading and writing run sanitized in the other RailSamplingCache.* tests.
#   WearTransfer.LinearEqualsTheUnsteadySolver* (26 s in Release, about 5 min sanitized: nine unsteady
#   runs of 40 patch lengths each); the wear transfer and the unsteady solver run sanitized in the
#   other WearTransfer.* tests and in the unsteady solver's own.
#   WearTransfer.UnsteadySolverOverARailRoughness* (about 25 s CPU in Release: six unsteady runs of
#   30 patch lengths with two normal solves per step); the roughness path and the wheel's scheme
#   run sanitized in RoughnessRolling.* (tests/contact).
#   SquealCli.EveryRootOfSqueal300mIsReportedOnce (7 s in Release: the whole squeal_300m with both
#   routes); the roots' dedupe and own_roots_again run sanitized in Stability.Route1OnARational*.
set -euo pipefail
cd "$(dirname "$0")/.."
JOBS=${ROLLNOISE_JOBS:-$(nproc)}
EXCLUDE='LinearModel\.(FastSweepAgrees|FastSweepHessenbergAndDirect|EveryMeanState)|NormalLoad\.(FastSweepEquals|LinearModelAgrees)|ConditioningStress\.|FallingFrictionModel\.(SweepRoutes|ConstantFrictionLimits)|FallingFrictionSqueal\.|SquealFallingFriction\.TightCurveCaseSquealsInAxialModesOnly|WheelFe\.AxialFamilyNearTheUnverified|AnnularPlate\.FrequencyConverges|RailWaveguide\.(FreeRailWavenumbers|CentredVerticalReceptance|EccentricContact)|NoiseCommand\.WritesEveryWheels|WheelContact\.FourWheels|ContactSetLoop\.RailTransferToTheOtherAxle|ContactSetSqueal\.(WheelsetWithConstantFriction|NegativeCreepDamping)|SquealKalker\.|WheelFeContact\.|FeWheelLoop\.|TreadShapesFile\.Exported|RailWaveguideReduced\.|WaveguideRailModel\.|DiscreteTrack\.ToeplitzSolveEqualsDenseLu|PeriodicTrack\.ComplexFrequencyEquals|BogieNoise\.|SecondPatch\.|StudyWheels\.|WheelsetPassivity\.|DiscreteWaveguide\.|FreeRailCutOn\.|FreeRailCutOnReference\.|RingReference\.|RailSectionFile\.ShippedUic60|SquealRoutes\.Route1AndRoute2GiveTheSameEigenvaluesWithTheFeWheel|WaveguideRailAtContact\.|WaveguideBogie\.|GridStudy\.(TransientResponseAt1kHz|PhaseCorrectedCreepCoefficients|TransientAgreesWithLinearModel|MidstepCreepCoefficients)|AverageSampling\.UnsteadySolverAgrees|NonHertzianContact\.LinearModelSpectra|postprocess_plots_smoke|LaplaceCoefficients\.(SpectralRadius|BothAtOnce)|SquealTopLevel\.|ParallelWheels\.(BogieLoop|LoopsAlone)|BandLines\.|SoundPower\.(RadiatedPowerStays|WheelModesRadiate)|RailSectionSound\.ZeroWavenumber|RailSectionSound\.SectionPowerMeets|RailSectionSound\.AdaptiveQuadrature|RailSectionSound\.HeadDistributions|WaveguideAndBeam\.|RailSamplingCache\.EveryRailEdit|WearTransfer\.LinearEqualsTheUnsteadySolver|WearTransfer\.UnsteadySolverOverARailRoughness|SquealCli\.EveryRootOfSqueal300m'

start=$SECONDS
cmake -S . -B build-asan -DROLLNOISE_SANITIZE=ON -DROLLNOISE_UNITY_BUILD=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -D_GLIBCXX_ASSERTIONS" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1" \
  -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON >/dev/null
cmake --build build-asan -j"$JOBS"
echo "test_sanitized: build $((SECONDS - start)) s" >&2

export ASAN_OPTIONS="detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1:exitcode=86"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:exitcode=86"
args=(--test-dir build-asan --output-on-failure -j"$JOBS")
[ "${ROLLNOISE_SANITIZE_ALL:-0}" = 1 ] || args+=(-E "$EXCLUDE")
# ctest's regular expressions (KWSys) hold at most 9 parenthesised groups; one more and the
# pattern matches nothing, silently: refuse a pattern that excludes no test.
if [ "${ROLLNOISE_SANITIZE_ALL:-0}" != 1 ]; then
  all=$(ctest --test-dir build-asan -N | sed -n 's/^Total Tests: //p')
  kept=$(ctest --test-dir build-asan -N -E "$EXCLUDE" | sed -n 's/^Total Tests: //p')
  if [ "$kept" = "$all" ]; then
    echo "test_sanitized: EXCLUDE matches no test (more than 9 groups?)" >&2
    exit 2
  fi
  echo "test_sanitized: $kept of $all tests (the rest in the Release run)" >&2
fi
start=$SECONDS
status=0
ctest "${args[@]}" "$@" || status=$?
echo "test_sanitized: tests $((SECONDS - start)) s" >&2
exit $status
