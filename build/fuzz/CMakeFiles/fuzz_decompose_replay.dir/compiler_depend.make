# Empty compiler generated dependencies file for fuzz_decompose_replay.
# This may be replaced when dependencies are built.
