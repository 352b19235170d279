# CMake generated Testfile for 
# Source directory: /work/main/fuzz
# Build directory: /work/main/build/fuzz
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
add_test([=[fuzz_decompose_replay]=] "/work/main/build/fuzz/fuzz_decompose_replay" "/work/main/data" "/work/main/data/bad" "/work/main/fuzz/corpus/fuzz_decompose")
set_tests_properties([=[fuzz_decompose_replay]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/main/fuzz/CMakeLists.txt;14;add_test;/work/main/fuzz/CMakeLists.txt;0;")
add_test([=[fuzz_expression_replay]=] "/work/main/build/fuzz/fuzz_expression_replay" "/work/main/data" "/work/main/data/bad" "/work/main/fuzz/corpus/fuzz_expression")
set_tests_properties([=[fuzz_expression_replay]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/main/fuzz/CMakeLists.txt;14;add_test;/work/main/fuzz/CMakeLists.txt;0;")
add_test([=[fuzz_metis_replay]=] "/work/main/build/fuzz/fuzz_metis_replay" "/work/main/data" "/work/main/data/bad" "/work/main/fuzz/corpus/fuzz_metis")
set_tests_properties([=[fuzz_metis_replay]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/main/fuzz/CMakeLists.txt;14;add_test;/work/main/fuzz/CMakeLists.txt;0;")
add_test([=[fuzz_poly_replay]=] "/work/main/build/fuzz/fuzz_poly_replay" "/work/main/data" "/work/main/data/bad" "/work/main/fuzz/corpus/fuzz_poly")
set_tests_properties([=[fuzz_poly_replay]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/main/fuzz/CMakeLists.txt;14;add_test;/work/main/fuzz/CMakeLists.txt;0;")
add_test([=[fuzz_script_replay]=] "/work/main/build/fuzz/fuzz_script_replay" "/work/main/data" "/work/main/data/bad" "/work/main/fuzz/corpus/fuzz_script")
set_tests_properties([=[fuzz_script_replay]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/main/fuzz/CMakeLists.txt;14;add_test;/work/main/fuzz/CMakeLists.txt;0;")
add_test([=[fuzz_triangulate_replay]=] "/work/main/build/fuzz/fuzz_triangulate_replay" "/work/main/data" "/work/main/data/bad" "/work/main/fuzz/corpus/fuzz_triangulate")
set_tests_properties([=[fuzz_triangulate_replay]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/main/fuzz/CMakeLists.txt;14;add_test;/work/main/fuzz/CMakeLists.txt;0;")
