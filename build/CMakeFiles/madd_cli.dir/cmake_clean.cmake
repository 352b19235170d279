file(REMOVE_RECURSE
  "CMakeFiles/madd_cli.dir/cli/cmd_check.cpp.o"
  "CMakeFiles/madd_cli.dir/cli/cmd_check.cpp.o.d"
  "CMakeFiles/madd_cli.dir/cli/cmd_decompose.cpp.o"
  "CMakeFiles/madd_cli.dir/cli/cmd_decompose.cpp.o.d"
  "CMakeFiles/madd_cli.dir/cli/cmd_partition.cpp.o"
  "CMakeFiles/madd_cli.dir/cli/cmd_partition.cpp.o.d"
  "CMakeFiles/madd_cli.dir/cli/cmd_script.cpp.o"
  "CMakeFiles/madd_cli.dir/cli/cmd_script.cpp.o.d"
  "CMakeFiles/madd_cli.dir/cli/cmd_triangulate.cpp.o"
  "CMakeFiles/madd_cli.dir/cli/cmd_triangulate.cpp.o.d"
  "CMakeFiles/madd_cli.dir/cli/main.cpp.o"
  "CMakeFiles/madd_cli.dir/cli/main.cpp.o.d"
  "madd"
  "madd.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/madd_cli.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
