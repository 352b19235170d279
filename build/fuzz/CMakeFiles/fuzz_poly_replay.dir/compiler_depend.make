# Empty compiler generated dependencies file for fuzz_poly_replay.
# This may be replaced when dependencies are built.
