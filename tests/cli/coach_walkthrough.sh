#!/bin/bash
# What a coach reads after the README's walkthrough: tests/docs/run_doc.sh
# runs every shell block of README.md exactly as written, in an empty folder
# with the built sweetspot first on the PATH, then this script in that folder
# (the blocks' standard output in out.txt, their files beside it).
# Usage (by run_doc.sh): coach_walkthrough.sh README.md
set -euo pipefail
readme=$1
fail=0
# The README opens with the two commands, exactly.
opening=$(head -n 4 "$readme")
expected_opening='```sh
scripts/run     # install what is missing, build, reproduce the paper into reports/
scripts/test    # install what is missing, build, run the whole test suite
```'
[ "$opening" = "$expected_opening" ] || { echo "README.md does not open with the two commands"; fail=1; }
expect() {  # expect FILE TEXT: TEXT must appear in FILE
  grep -qF -- "$2" "$1" || { echo "missing in $1: $2"; fail=1; }
}
# The answer first, in centimetres from the tip.
expect out.txt "Held in the hand, this racquet has two sweet spots: the centre of percussion,"
expect out.txt "apart, the node nearer the tip."
expect out.txt "At the centre of the strings, about 18 cm from the tip (no impact was given"
# Inputs echoed as given.
expect out.txt '`/strings/tension_lb` = 52 lb'
expect out.txt '| 318 | g | `mass_kg` |'
# compare states the tape's effect in words.
expect out.txt "Club racquet + 10 g at 12 against Club racquet: 10 g of added mass 0.5 cm from the tip"
expect out.txt "The hand-held centre of percussion moves"
expect out.txt "toward the tip"
# A looser string bed, in the unit the coach gave.
expect out.txt "strings at 48 lb instead of 52 lb"
expect compared.csv "name,source,mass_kg"
# The page opens with the same answer.
expect racquet.html "Held in the hand, this racquet has two sweet spots"
expect racquet-out.json '"cop_hand_from_tip_cm"'
# tune: the lead at each place, and the tuned racquet written as a design file.
expect out.txt "| under the grip (9 cm from the butt) |"
expect racquet-tuned.json '"name": "Club racquet (tuned)"'
# What the README quotes of the output is what the program prints: each
# quoted passage ("> ..."), cut at its ellipses, appears in the output.
flat=$(tr '\n' ' ' <out.txt | tr -s ' ')
while IFS= read -r fragment; do
  fragment=$(echo "$fragment" | sed 's/^ *//; s/ *$//')
  [ ${#fragment} -gt 20 ] || continue
  case $flat in *"$fragment"*) ;; *) echo "the README quotes what the output does not say: $fragment"; fail=1 ;; esac
done < <(awk '/^> /{sub(/^> /, ""); printf "%s ", $0; quoted=1; next} quoted{print ""; quoted=0}' "$readme" |
         sed 's/…/\n/g')
# No escapes and no float noise in what the coach reads.
if grep -qF '\|' out.txt; then echo "a Markdown escape in the output"; fail=1; fi
exit $fail
