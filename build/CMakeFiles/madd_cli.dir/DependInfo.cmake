
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/cli/cmd_check.cpp" "CMakeFiles/madd_cli.dir/cli/cmd_check.cpp.o" "gcc" "CMakeFiles/madd_cli.dir/cli/cmd_check.cpp.o.d"
  "/work/main/cli/cmd_decompose.cpp" "CMakeFiles/madd_cli.dir/cli/cmd_decompose.cpp.o" "gcc" "CMakeFiles/madd_cli.dir/cli/cmd_decompose.cpp.o.d"
  "/work/main/cli/cmd_partition.cpp" "CMakeFiles/madd_cli.dir/cli/cmd_partition.cpp.o" "gcc" "CMakeFiles/madd_cli.dir/cli/cmd_partition.cpp.o.d"
  "/work/main/cli/cmd_script.cpp" "CMakeFiles/madd_cli.dir/cli/cmd_script.cpp.o" "gcc" "CMakeFiles/madd_cli.dir/cli/cmd_script.cpp.o.d"
  "/work/main/cli/cmd_triangulate.cpp" "CMakeFiles/madd_cli.dir/cli/cmd_triangulate.cpp.o" "gcc" "CMakeFiles/madd_cli.dir/cli/cmd_triangulate.cpp.o.d"
  "/work/main/cli/main.cpp" "CMakeFiles/madd_cli.dir/cli/main.cpp.o" "gcc" "CMakeFiles/madd_cli.dir/cli/main.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build/CMakeFiles/madd.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
