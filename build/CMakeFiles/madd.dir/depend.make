# Empty dependencies file for madd.
# This may be replaced when dependencies are built.
