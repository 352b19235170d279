file(REMOVE_RECURSE
  "CMakeFiles/madd_bench.dir/bench/bench_bisect.cpp.o"
  "CMakeFiles/madd_bench.dir/bench/bench_bisect.cpp.o.d"
  "CMakeFiles/madd_bench.dir/bench/bench_decompose.cpp.o"
  "CMakeFiles/madd_bench.dir/bench/bench_decompose.cpp.o.d"
  "CMakeFiles/madd_bench.dir/bench/bench_main.cpp.o"
  "CMakeFiles/madd_bench.dir/bench/bench_main.cpp.o.d"
  "CMakeFiles/madd_bench.dir/bench/bench_predicates.cpp.o"
  "CMakeFiles/madd_bench.dir/bench/bench_predicates.cpp.o.d"
  "CMakeFiles/madd_bench.dir/bench/bench_scaling.cpp.o"
  "CMakeFiles/madd_bench.dir/bench/bench_scaling.cpp.o.d"
  "CMakeFiles/madd_bench.dir/bench/bench_smoothing.cpp.o"
  "CMakeFiles/madd_bench.dir/bench/bench_smoothing.cpp.o.d"
  "CMakeFiles/madd_bench.dir/bench/bench_triangulate.cpp.o"
  "CMakeFiles/madd_bench.dir/bench/bench_triangulate.cpp.o.d"
  "CMakeFiles/madd_bench.dir/bench/bench_validate.cpp.o"
  "CMakeFiles/madd_bench.dir/bench/bench_validate.cpp.o.d"
  "CMakeFiles/madd_bench.dir/bench/illustrate_medial.cpp.o"
  "CMakeFiles/madd_bench.dir/bench/illustrate_medial.cpp.o.d"
  "madd_bench"
  "madd_bench.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/madd_bench.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
