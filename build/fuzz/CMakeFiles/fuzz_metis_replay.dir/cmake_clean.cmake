file(REMOVE_RECURSE
  "CMakeFiles/fuzz_metis_replay.dir/fuzz_metis.cpp.o"
  "CMakeFiles/fuzz_metis_replay.dir/fuzz_metis.cpp.o.d"
  "CMakeFiles/fuzz_metis_replay.dir/replay_main.cpp.o"
  "CMakeFiles/fuzz_metis_replay.dir/replay_main.cpp.o.d"
  "fuzz_metis_replay"
  "fuzz_metis_replay.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/fuzz_metis_replay.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
