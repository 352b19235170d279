file(REMOVE_RECURSE
  "CMakeFiles/fuzz_decompose_replay.dir/fuzz_decompose.cpp.o"
  "CMakeFiles/fuzz_decompose_replay.dir/fuzz_decompose.cpp.o.d"
  "CMakeFiles/fuzz_decompose_replay.dir/replay_main.cpp.o"
  "CMakeFiles/fuzz_decompose_replay.dir/replay_main.cpp.o.d"
  "fuzz_decompose_replay"
  "fuzz_decompose_replay.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/fuzz_decompose_replay.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
