
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/tests/bench/bench_bisect.cpp" "tests/CMakeFiles/madd_bench.dir/bench/bench_bisect.cpp.o" "gcc" "tests/CMakeFiles/madd_bench.dir/bench/bench_bisect.cpp.o.d"
  "/work/main/tests/bench/bench_decompose.cpp" "tests/CMakeFiles/madd_bench.dir/bench/bench_decompose.cpp.o" "gcc" "tests/CMakeFiles/madd_bench.dir/bench/bench_decompose.cpp.o.d"
  "/work/main/tests/bench/bench_main.cpp" "tests/CMakeFiles/madd_bench.dir/bench/bench_main.cpp.o" "gcc" "tests/CMakeFiles/madd_bench.dir/bench/bench_main.cpp.o.d"
  "/work/main/tests/bench/bench_predicates.cpp" "tests/CMakeFiles/madd_bench.dir/bench/bench_predicates.cpp.o" "gcc" "tests/CMakeFiles/madd_bench.dir/bench/bench_predicates.cpp.o.d"
  "/work/main/tests/bench/bench_scaling.cpp" "tests/CMakeFiles/madd_bench.dir/bench/bench_scaling.cpp.o" "gcc" "tests/CMakeFiles/madd_bench.dir/bench/bench_scaling.cpp.o.d"
  "/work/main/tests/bench/bench_smoothing.cpp" "tests/CMakeFiles/madd_bench.dir/bench/bench_smoothing.cpp.o" "gcc" "tests/CMakeFiles/madd_bench.dir/bench/bench_smoothing.cpp.o.d"
  "/work/main/tests/bench/bench_triangulate.cpp" "tests/CMakeFiles/madd_bench.dir/bench/bench_triangulate.cpp.o" "gcc" "tests/CMakeFiles/madd_bench.dir/bench/bench_triangulate.cpp.o.d"
  "/work/main/tests/bench/bench_validate.cpp" "tests/CMakeFiles/madd_bench.dir/bench/bench_validate.cpp.o" "gcc" "tests/CMakeFiles/madd_bench.dir/bench/bench_validate.cpp.o.d"
  "/work/main/tests/bench/illustrate_medial.cpp" "tests/CMakeFiles/madd_bench.dir/bench/illustrate_medial.cpp.o" "gcc" "tests/CMakeFiles/madd_bench.dir/bench/illustrate_medial.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build/CMakeFiles/madd.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
