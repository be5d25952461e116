# Empty dependencies file for gembem.
# This may be replaced when dependencies are built.
