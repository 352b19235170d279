# Empty compiler generated dependencies file for madd_bench.
# This may be replaced when dependencies are built.
