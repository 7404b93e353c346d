# SPDX-License-Identifier: BSD-3-Clause
# every verb's --help ends with examples of that verb (apps/flexrock/verb_examples.hpp), and the
# options an example uses are the verb's own
source "$(dirname "$0")/common.sh"
run "$FLEXROCK" --help
expect_rc 0 "flexrock --help"
verbs=$(awk '/^Subcommands:/{on=1; next} /^$/{on=0} on && /^  [a-z]/{print $1}' "$WORK/out")
[ -n "$verbs" ] || fail "no verbs in flexrock --help: $(cat "$WORK/out")"
for v in $verbs; do
  run "$FLEXROCK" "$v" --help
  expect_rc 0 "flexrock $v --help"
  expect_in "$WORK/out" "Examples:"
  examples=$(sed -n '/^Examples:/,$p' "$WORK/out" | tail -n +2 | sed 's/  *#.*//')
  [ -n "$examples" ] || fail "flexrock $v --help: no example lines"
  while IFS= read -r line; do
    case "$line" in
      "flexrock $v "* | "mpirun "*"flexrock $v "*) ;;
      *) fail "flexrock $v --help: an example of another verb: '$line'" ;;
    esac
    # every option of the example is one the verb's help lists
    for opt in $(grep -oE '(^| )--?[a-z][a-z-]*' <<<"$line" | tr -d ' '); do
      [ "$opt" = "-n" ] && continue  # mpirun's
      grep -qE -- "(^|[ ,])$opt([ ,=]|$)" "$WORK/out" || fail "flexrock $v: example option $opt is not in its --help"
    done
  done <<<"$examples"
done
echo "ok"
