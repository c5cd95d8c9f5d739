# Shared check of the CLI tests of generated references (sourced, not a test itself; needs fail and $work):
#   generated_block GENERATED DOC MARKER   DOC's lines between "<!-- MARKER: begin -->" and "<!-- MARKER: end -->"
#                                          are GENERATED's (a file of the program's output), else fail with the diff
#   generated_file GENERATED CHECKED_IN    CHECKED_IN is GENERATED, else fail with the diff
generated_block() {
  local generated=$1 doc=$2 marker=$3
  sed -n "/<!-- $marker: begin -->/,/<!-- $marker: end -->/p" "$doc" | sed '1d;$d' >"$work/doc_block"
  diff -u "$work/doc_block" "$generated" >"$work/diff" ||
    fail "$doc differs from $marker between its markers (regenerate it): $(head -20 "$work/diff")"
}
generated_file() {
  local generated=$1 checked_in=$2
  diff -u "$checked_in" "$generated" >"$work/diff" || fail "$checked_in is not what generates it: $(head -20 "$work/diff")"
}
