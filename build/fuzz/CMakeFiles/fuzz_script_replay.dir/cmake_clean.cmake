file(REMOVE_RECURSE
  "CMakeFiles/fuzz_script_replay.dir/fuzz_script.cpp.o"
  "CMakeFiles/fuzz_script_replay.dir/fuzz_script.cpp.o.d"
  "CMakeFiles/fuzz_script_replay.dir/replay_main.cpp.o"
  "CMakeFiles/fuzz_script_replay.dir/replay_main.cpp.o.d"
  "fuzz_script_replay"
  "fuzz_script_replay.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/fuzz_script_replay.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
