# Empty dependencies file for madd_cli.
# This may be replaced when dependencies are built.
