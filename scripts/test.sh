#!/usr/bin/env bash
# README command 2 (and .ci/run): install the test dependencies, then build and run
# the whole suite twice, fuzz, and run valgrind:
#   build-asan/  clang, AddressSanitizer + UndefinedBehaviorSanitizer, warnings as
#                errors; the long oracle tests at LH_TEST_SCALE=0.2
#   build-idx64/ gcc, Release, 64-bit indices (LH_INDEX_64); the suite at LH_TEST_SCALE=0.1
#                but for the oracle cross-checks
#   build-tsan/  gcc, ThreadSanitizer: the parallel insertion's tests (test_parallel)
#   build-fuzz/  clang, libFuzzer + ASan + UBSan: every fuzz target for 30 s on a copy
#                of its corpus (scripts/fuzz.sh), two at a time
#   build/       gcc, Release, warnings as errors, benchmarks built and smoke-run;
#                first valgrind memcheck on a quick subset of its binaries, then the suite
# The Release run comes last, so the final lines are CTest's own summary; the line
# before it names the earlier stages that failed, if any. Any failure in any stage
# makes the exit status 1.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="$(nproc)"

bash scripts/deps.sh test

status=0 failed=""
fail() { status=1; failed="$failed $1"; } # stage: remember it for the summary

echo "== sanitizer build (clang, ASan+UBSan) =="
CC=clang CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DLH_SANITIZE=ON -DLH_WERROR=ON -DLH_BUILD_TESTS=ON >/dev/null
cmake --build build-asan -j "$jobs" >/dev/null
LH_TEST_SCALE=0.2 ASAN_OPTIONS=detect_leaks=1 \
  ctest --test-dir build-asan -j "$jobs" --output-on-failure || fail asan

echo "== 64-bit index build (gcc, small) =="
CC=gcc CXX=g++ cmake -S . -B build-idx64 -DLH_INDEX_64=ON -DCMAKE_BUILD_TYPE=Release \
  -DLH_WERROR=ON -DLH_BUILD_TESTS=ON >/dev/null
cmake --build build-idx64 -j "$jobs" >/dev/null
LH_TEST_SCALE=0.1 ctest --test-dir build-idx64 -j "$jobs" -LE oracle --output-on-failure || fail idx64

# The parallel phases (hull/parallel.c) under ThreadSanitizer: a data race between
# workers fails the stage (TSan's exit status 66).
echo "== thread sanitizer (gcc, TSan: the parallel insertion) =="
CC=gcc CXX=g++ cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLH_BUILD_TESTS=ON \
  -DCMAKE_C_FLAGS=-fsanitize=thread -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=thread >/dev/null
cmake --build build-tsan -j "$jobs" --target test_parallel >/dev/null
TSAN_OPTIONS=halt_on_error=1 build-tsan/tests/test_parallel workers_insert_sites \
  deferred_sites_are_inserted_afterwards sites_of_stopped_workers_are_inserted_afterwards \
  every_allocation_failure_is_survived_with_threads || fail tsan

echo "== fuzzing (clang, libFuzzer + ASan + UBSan, 30 s a target) =="
bash scripts/fuzz.sh 30 || fail fuzz

echo "== release build (gcc) =="
CC=gcc CXX=g++ cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DLH_WERROR=ON \
  -DLH_BUILD_TESTS=ON -DLH_BUILD_BENCH=ON >/dev/null
cmake --build build -j "$jobs" >/dev/null

# valgrind memcheck on the Release binaries: the quick test cases (each well under a
# minute under valgrind), the fuzz corpora through the replay drivers, and the CLI end
# to end on a small input. Only errors are printed; any error or leak fails the stage.
echo "== valgrind memcheck (quick subset of the release build) =="
vgdir="$(mktemp -d "${TMPDIR:-/tmp}/lifthull-vg.XXXXXX")"
t=build/tests lh=build/cli/lifthull
vg="valgrind -q --error-exitcode=1 --leak-check=full"
$lh points 200 -d 3 --integer 4 -o "$vgdir/p3.txt" || fail valgrind-setup
$lh points 200 -d 2 --exact-sphere -o "$vgdir/p2.txt" || fail valgrind-setup
$lh delaunay "$vgdir/p3.txt" -o "$vgdir/t3.txt" || fail valgrind-setup # for `check`: the lanes run in any order
cp tests/data/triangle/A.poly tests/data/mesh3d/u.off tests/data/mesh3d/schonhardt.off "$vgdir/" ||
  fail valgrind-setup
{
  # the slowest first (each 15-35 s under valgrind), so that the two lanes end together
  echo "$vg $t/test_hull hull_is_exactly_convex_and_closed general_position_hull_equals_delaunay_hull unit_cube_and_bad_input"
  echo "$vg $t/test_locate queries_inside_outside_and_on_sites points_on_shared_faces_get_the_smallest_simplex"
  echo "$vg $t/test_voronoi nearest_matches_brute_force circumcenters_are_empty_sphere_centres compare_distance_is_exact bad_arguments every_allocation_failure_is_survived"
  echo "$vg $t/test_delaunay furthest_site_triangulation output_depends_only_on_the_site_set smallest_inputs duplicates_are_merged_and_reported bad_input_gets_its_status the_check_rejects_what_is_not_delaunay every_allocation_failure_is_survived"
  for x in test_io_read test_cells test_io_write test_complex test_io_poly test_io_poly_errors \
           test_io_rings test_io_pslg_memory; do echo "$vg $t/$x"; done
  echo "$vg $t/test_trimesh cdt_of_triangle_files_is_exactly_valid quality_bound_met_but_at_small_input_angles"
  echo "$vg $t/test_trimesh_errors bad_input_gets_its_error_and_line the_check_rejects_what_is_not_a_cdt"
  for x in delaunay read hull check cells query poly trimesh plc_read plc_binary tetrahedralize; do
    echo "$vg $t/fuzz_${x}_replay fuzz/corpus/$x/*"
  done
  echo "$vg $lh delaunay $vgdir/p3.txt -o $vgdir/t3v.txt"
  echo "$vg $lh check $vgdir/p3.txt $vgdir/t3.txt"
  echo "$vg $lh hull $vgdir/p3.txt"
  echo "$vg $lh voronoi $vgdir/p2.txt"
  echo "$vg $lh qdelaunay i Qt TI $vgdir/p2.txt"
  echo "$vg $lh triangle -pq30Q $vgdir/A.poly"
  echo "$vg $lh mesh $vgdir/A.poly --min-angle 25 --smooth 2 -o $vgdir/A.svg"
  echo "$vg $lh tetgen -pQC $vgdir/u.off"
  echo "$vg $lh tetgen -pYQC $vgdir/schonhardt.off"
} > "$vgdir/commands"
# two at a time; a command's output is shown only when it fails
if xargs -d '\n' -P "$jobs" -I{} bash -c 'log="$(mktemp)"; if {} >"$log" 2>&1; then rm -f "$log"; else
       tail -40 "$log" >&2; rm -f "$log"; echo "valgrind: FAILED: {}" >&2; exit 1; fi' \
     < "$vgdir/commands"; then
  echo "valgrind: $(wc -l < "$vgdir/commands") runs clean"
else
  fail valgrind
fi
rm -rf "$vgdir"
if [ -n "$failed" ]; then
  echo "== stages before the release suite: FAILED:$failed (their output is above) ==" >&2
else
  echo "== stages before the release suite: asan, idx64, tsan, fuzz, valgrind passed =="
fi
ctest --test-dir build -j "$jobs" --output-on-failure || status=1
exit "$status"
