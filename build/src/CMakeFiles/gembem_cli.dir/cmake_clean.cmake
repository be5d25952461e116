file(REMOVE_RECURSE
  "../gembem"
  "../gembem.pdb"
  "CMakeFiles/gembem_cli.dir/cli/cmd_bem.c.o"
  "CMakeFiles/gembem_cli.dir/cli/cmd_bem.c.o.d"
  "CMakeFiles/gembem_cli.dir/cli/cmd_run.c.o"
  "CMakeFiles/gembem_cli.dir/cli/cmd_run.c.o.d"
  "CMakeFiles/gembem_cli.dir/cli/main.c.o"
  "CMakeFiles/gembem_cli.dir/cli/main.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/gembem_cli.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
