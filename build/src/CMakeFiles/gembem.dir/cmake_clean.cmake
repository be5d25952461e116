file(REMOVE_RECURSE
  "CMakeFiles/gembem.dir/core/status.c.o"
  "CMakeFiles/gembem.dir/core/status.c.o.d"
  "CMakeFiles/gembem.dir/scene/yaml_read.c.o"
  "CMakeFiles/gembem.dir/scene/yaml_read.c.o.d"
  "libgembem.a"
  "libgembem.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/gembem.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
