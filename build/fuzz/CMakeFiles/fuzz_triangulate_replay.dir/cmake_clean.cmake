file(REMOVE_RECURSE
  "CMakeFiles/fuzz_triangulate_replay.dir/fuzz_triangulate.cpp.o"
  "CMakeFiles/fuzz_triangulate_replay.dir/fuzz_triangulate.cpp.o.d"
  "CMakeFiles/fuzz_triangulate_replay.dir/replay_main.cpp.o"
  "CMakeFiles/fuzz_triangulate_replay.dir/replay_main.cpp.o.d"
  "fuzz_triangulate_replay"
  "fuzz_triangulate_replay.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/fuzz_triangulate_replay.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
