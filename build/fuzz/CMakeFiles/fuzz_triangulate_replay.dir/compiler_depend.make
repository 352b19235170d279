# Empty compiler generated dependencies file for fuzz_triangulate_replay.
# This may be replaced when dependencies are built.
