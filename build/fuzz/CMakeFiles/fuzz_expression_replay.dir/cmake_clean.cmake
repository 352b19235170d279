file(REMOVE_RECURSE
  "CMakeFiles/fuzz_expression_replay.dir/fuzz_expression.cpp.o"
  "CMakeFiles/fuzz_expression_replay.dir/fuzz_expression.cpp.o.d"
  "CMakeFiles/fuzz_expression_replay.dir/replay_main.cpp.o"
  "CMakeFiles/fuzz_expression_replay.dir/replay_main.cpp.o.d"
  "fuzz_expression_replay"
  "fuzz_expression_replay.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/fuzz_expression_replay.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
