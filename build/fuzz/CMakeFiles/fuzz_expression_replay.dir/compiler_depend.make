# Empty compiler generated dependencies file for fuzz_expression_replay.
# This may be replaced when dependencies are built.
