# CMake generated Testfile for 
# Source directory: /work/main/tests
# Build directory: /work/main/build/tests
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
add_test([=[madd_tests]=] "/work/main/build/tests/madd_tests")
set_tests_properties([=[madd_tests]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/main/tests/CMakeLists.txt;16;add_test;/work/main/tests/CMakeLists.txt;0;")
add_test([=[consumers]=] "/usr/bin/cmake" "-E" "env" "CXX=/usr/bin/c++" "MADD_CONFIG=Release" "MADD_CONSUMER_CXX_FLAGS=" "sh" "/work/main/tests/consumers/run.sh" "/work/main/build")
set_tests_properties([=[consumers]=] PROPERTIES  RUN_SERIAL "TRUE" TIMEOUT "900" _BACKTRACE_TRIPLES "/work/main/tests/CMakeLists.txt;33;add_test;/work/main/tests/CMakeLists.txt;0;")
add_test([=[madd_cli_static]=] "sh" "/work/main/tests/consumers/check_static.sh" "/work/main/build/madd")
set_tests_properties([=[madd_cli_static]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/main/tests/CMakeLists.txt;42;add_test;/work/main/tests/CMakeLists.txt;0;")
