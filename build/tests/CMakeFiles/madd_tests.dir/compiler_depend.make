# Empty compiler generated dependencies file for madd_tests.
# This may be replaced when dependencies are built.
