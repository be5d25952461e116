# Columns of CSV files by name, for the shell tests (sourced): a test names the columns it reads,
# so a column added to or moved in steps.csv, host_steps.csv or a state file breaks no test.
#   csv_awk [-v VAR=VALUE ...] 'PROGRAM' FILE... [VAR=VALUE ...]
# is awk -F, on PROGRAM in which col("name") is the number of the column so named in the header
# (the first line) of the file being read: $col("iterations") is that row's iterations, and
# $col("x") = 1.5 sets it (with OFS=,). The header line goes to PROGRAM as well. A name the header
# lacks stops awk with exit status 2 and says which (END rules do not override it).
csv_awk() {
  local opts=()
  while [ "${1:-}" = -v ]; do opts+=(-v "$2"); shift 2; done
  awk -F, "${opts[@]}" '
    function col(name) {
      if (!(name in csv_c)) {
        printf "csv_awk: %s has no column \"%s\"\n", FILENAME, name > "/dev/stderr"; csv_missing = 1; exit 2
      }
      return csv_c[name]
    }
    FNR == 1 { split("", csv_c); for (csv_k = 1; csv_k <= NF; csv_k++) csv_c[$csv_k] = csv_k }
    END { if (csv_missing) exit 2 }
  '"$1" "${@:2}"
}
