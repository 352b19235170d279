
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/tests/balance_test.cpp" "tests/CMakeFiles/madd_tests.dir/balance_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/balance_test.cpp.o.d"
  "/work/main/tests/bisect_test.cpp" "tests/CMakeFiles/madd_tests.dir/bisect_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/bisect_test.cpp.o.d"
  "/work/main/tests/decompose_test.cpp" "tests/CMakeFiles/madd_tests.dir/decompose_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/decompose_test.cpp.o.d"
  "/work/main/tests/expression_test.cpp" "tests/CMakeFiles/madd_tests.dir/expression_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/expression_test.cpp.o.d"
  "/work/main/tests/grading_test.cpp" "tests/CMakeFiles/madd_tests.dir/grading_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/grading_test.cpp.o.d"
  "/work/main/tests/graph_test.cpp" "tests/CMakeFiles/madd_tests.dir/graph_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/graph_test.cpp.o.d"
  "/work/main/tests/hostile_test.cpp" "tests/CMakeFiles/madd_tests.dir/hostile_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/hostile_test.cpp.o.d"
  "/work/main/tests/medial_test.cpp" "tests/CMakeFiles/madd_tests.dir/medial_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/medial_test.cpp.o.d"
  "/work/main/tests/metrics_test.cpp" "tests/CMakeFiles/madd_tests.dir/metrics_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/metrics_test.cpp.o.d"
  "/work/main/tests/output_formats_test.cpp" "tests/CMakeFiles/madd_tests.dir/output_formats_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/output_formats_test.cpp.o.d"
  "/work/main/tests/output_test.cpp" "tests/CMakeFiles/madd_tests.dir/output_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/output_test.cpp.o.d"
  "/work/main/tests/poly_io_test.cpp" "tests/CMakeFiles/madd_tests.dir/poly_io_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/poly_io_test.cpp.o.d"
  "/work/main/tests/predicates_test.cpp" "tests/CMakeFiles/madd_tests.dir/predicates_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/predicates_test.cpp.o.d"
  "/work/main/tests/regression_test.cpp" "tests/CMakeFiles/madd_tests.dir/regression_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/regression_test.cpp.o.d"
  "/work/main/tests/script_test.cpp" "tests/CMakeFiles/madd_tests.dir/script_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/script_test.cpp.o.d"
  "/work/main/tests/smoothing_test.cpp" "tests/CMakeFiles/madd_tests.dir/smoothing_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/smoothing_test.cpp.o.d"
  "/work/main/tests/test_main.cpp" "tests/CMakeFiles/madd_tests.dir/test_main.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/test_main.cpp.o.d"
  "/work/main/tests/triangulation_test.cpp" "tests/CMakeFiles/madd_tests.dir/triangulation_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/triangulation_test.cpp.o.d"
  "/work/main/tests/validate_test.cpp" "tests/CMakeFiles/madd_tests.dir/validate_test.cpp.o" "gcc" "tests/CMakeFiles/madd_tests.dir/validate_test.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build/CMakeFiles/madd.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
