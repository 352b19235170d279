file(REMOVE_RECURSE
  "CMakeFiles/fuzz_poly_replay.dir/fuzz_poly.cpp.o"
  "CMakeFiles/fuzz_poly_replay.dir/fuzz_poly.cpp.o.d"
  "CMakeFiles/fuzz_poly_replay.dir/replay_main.cpp.o"
  "CMakeFiles/fuzz_poly_replay.dir/replay_main.cpp.o.d"
  "fuzz_poly_replay"
  "fuzz_poly_replay.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/fuzz_poly_replay.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
