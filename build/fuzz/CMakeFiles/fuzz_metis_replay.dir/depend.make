# Empty dependencies file for fuzz_metis_replay.
# This may be replaced when dependencies are built.
