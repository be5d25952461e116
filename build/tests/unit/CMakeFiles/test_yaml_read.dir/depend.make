# Empty dependencies file for test_yaml_read.
# This may be replaced when dependencies are built.
