file(REMOVE_RECURSE
  "CMakeFiles/test_yaml_read.dir/test_yaml_read.c.o"
  "CMakeFiles/test_yaml_read.dir/test_yaml_read.c.o.d"
  "test_yaml_read"
  "test_yaml_read.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_yaml_read.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
