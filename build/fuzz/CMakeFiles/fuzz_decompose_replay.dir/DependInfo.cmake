
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/fuzz/fuzz_decompose.cpp" "fuzz/CMakeFiles/fuzz_decompose_replay.dir/fuzz_decompose.cpp.o" "gcc" "fuzz/CMakeFiles/fuzz_decompose_replay.dir/fuzz_decompose.cpp.o.d"
  "/work/main/fuzz/replay_main.cpp" "fuzz/CMakeFiles/fuzz_decompose_replay.dir/replay_main.cpp.o" "gcc" "fuzz/CMakeFiles/fuzz_decompose_replay.dir/replay_main.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build/CMakeFiles/madd.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
