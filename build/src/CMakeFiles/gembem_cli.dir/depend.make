# Empty dependencies file for gembem_cli.
# This may be replaced when dependencies are built.
