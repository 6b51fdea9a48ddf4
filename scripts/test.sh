#!/usr/bin/env bash
# Every test: the Release build (with CGAL comparisons), the same suite under AddressSanitizer
# and UndefinedBehaviorSanitizer (the adversarial sets at a tenth of their size there), the
# threaded tests under ThreadSanitizer, ridt-mpi on 1 to 8 ranks, the Python package (pip, wheel, pytest), a consumer project that uses find_package(ridt), 10^7
# points through the serial and every threaded method (scripts/large.sh). Both suites replay the
# fuzz corpora with a fixed number of seeded mutations (fuzz/replay.cpp), so every run of a
# commit tests the same inputs; the open-ended search for new faults, with the libFuzzer build
# of the same targets (clang), is scripts/fuzz.sh SECONDS.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh test
jobs=$(nproc)
# Every build below through ccache (CMake reads these variables): pip's build of the package
# compiles the same sources with the same flags as the Release build, and takes its objects.
export CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache
# Paths taken relative to the checkout, so that a clone elsewhere (a clean clone for a test run)
# finds the objects a clone at another path compiled.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1

echo "== Layout: file and function sizes, src/ private to the library and its tests (at ${SECONDS} s)"
/usr/bin/python3 scripts/layout.py

echo "== Release build and tests (at ${SECONDS} s)"
# Every option said, not left to the cache: scripts/demo.sh configures the same build/ with
# the tests off. An empty test run is an error, never a pass.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DRIDT_BUILD_TESTS=ON \
  -DRIDT_BUILD_BENCH=ON -DRIDT_BUILD_TOOLS=ON -DRIDT_BUILD_PYTHON=ON -DPython_EXECUTABLE=/usr/bin/python3 \
  -DRIDT_SANITIZE= >/dev/null
cmake --build build -j "$jobs"
# The distributed tool's tests (tests/mpi_test.sh) run only where it was built: never skipped.
[ -x build/ridt-mpi ] || { echo "ridt-mpi was not built: is MPI installed (scripts/deps.sh test)?" >&2; exit 1; }
# The adversarial sets at 0.3 of their size (full size: RIDT_ADVERSARIAL_SCALE unset, a few
# minutes more); the Python tests once, below, on what pip installed.
RIDT_ADVERSARIAL_SCALE=0.3 ctest --test-dir build -j "$jobs" --output-on-failure --no-tests=error -E '^python$'

echo "== Python: pip wheel, and the wheel installed into a virtual environment; the tests on what pip installed (at ${SECONDS} s)"
rm -rf build/venv build/wheels
/usr/bin/python3 -m venv --system-site-packages build/venv
# The wheel is built once (what "pip install ." builds too) and installed: one compile, not two.
build/venv/bin/pip wheel -q --no-build-isolation --no-deps --no-index -w build/wheels .
build/venv/bin/pip install -q --no-deps --no-index build/wheels/ridt-*.whl
ls build/wheels/ridt-*.whl
(cd python/tests && ../../build/venv/bin/python -c "import ridt, sys; assert 'venv' in ridt.__file__, ridt.__file__" &&
  ../../build/venv/bin/python -m pytest -q -p no:cacheprovider .)

echo "== scipy's own tests (Delaunay, Voronoi, ConvexHull, SphericalVoronoi, LinearND, NearestND, CloughTocher, griddata) against ridt (at ${SECONDS} s)"
# The test files of the scipy installed on the machine, with scipy's 2-D classes replaced by
# ridt's (python/scipy_suite/ridt_scipy.py); exceptions only as python/scipy_suite/exceptions.txt
# lists them. Missing files are an error, not a skip.
scipy_tests=$(/usr/bin/python3 -c "import os, scipy; print(os.path.dirname(scipy.__file__))")
(cd python/scipy_suite && PYTHONPATH="$PWD" ../../build/venv/bin/python -m pytest -q -p no:cacheprovider -p ridt_scipy \
  "$scipy_tests/spatial/tests/test_qhull.py" "$scipy_tests/interpolate/tests/test_interpnd.py" \
  "$scipy_tests/interpolate/tests/test_ndgriddata.py" "$scipy_tests/spatial/tests/test_spherical_voronoi.py")

echo "== AddressSanitizer + UndefinedBehaviorSanitizer (at ${SECONDS} s)"
# CGAL's comparisons run in the Release suite above; here they would add minutes of template
# compilation under the sanitizers and check CGAL's code more than ridt's. So does ridt-mpi's
# test (tests/mpi_test.sh, a minute of ranks that must run alone): its code is a few hundred
# lines over the library and the formats, which this suite checks.
# -O1, as the sanitizers' authors advise: it compiles in three quarters of -O2's time, and the
# tests then run about as long.
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" \
  -DRIDT_SANITIZE=address,undefined,float-cast-overflow \
  -DRIDT_BUILD_TESTS=ON -DRIDT_BUILD_TOOLS=ON -DRIDT_BUILD_BENCH=OFF -DRIDT_BUILD_MPI=OFF \
  -DCMAKE_DISABLE_FIND_PACKAGE_CGAL=ON >/dev/null
cmake --build build-asan -j "$jobs"
UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 RIDT_ADVERSARIAL_SCALE=0.1 \
  ctest --test-dir build-asan -j "$jobs" --output-on-failure --no-tests=error

echo "== ThreadSanitizer: the threaded tests (at ${SECONDS} s)"
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRIDT_SANITIZE=thread \
  -DRIDT_BUILD_BENCH=OFF -DRIDT_BUILD_TOOLS=OFF >/dev/null
cmake --build build-tsan -j "$jobs" --target ridt_thread_tests
TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:die_after_fork=0 build-tsan/tests/ridt_thread_tests

echo "== Install and find_package(ridt) (at ${SECONDS} s)"
rm -rf build/install build/consumer
cmake --install build --prefix build/install >/dev/null
cmake -S tests/consumer -B build/consumer -G Ninja -DCMAKE_PREFIX_PATH="$PWD/build/install" >/dev/null
cmake --build build/consumer
build/consumer/consumer

echo "== 10^7 uniform points: serial and every threaded method, each output validated (at ${SECONDS} s)"
scripts/large.sh 10000000 2 quick  # fails unless every output is valid

echo "all tests passed"
