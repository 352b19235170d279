# Empty dependencies file for fuzz_script_replay.
# This may be replaced when dependencies are built.
