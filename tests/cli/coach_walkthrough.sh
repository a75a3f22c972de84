#!/bin/bash
# Runs the coach's walkthrough exactly as README.md writes it (the block
# between <!-- coach-walkthrough --> and <!-- /coach-walkthrough -->), with
# the built sweetspot first on the PATH, then checks what a coach reads.
# Usage: coach_walkthrough.sh README.md DIR_OF_SWEETSPOT
set -euo pipefail
readme=$1
bin_dir=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
awk '/<!-- coach-walkthrough -->/{on=1; next} /<!-- \/coach-walkthrough -->/{on=0} on' "$readme" |
  sed '/^```/d' >"$work/walkthrough.sh"
test -s "$work/walkthrough.sh" || { echo "no walkthrough block in $readme"; exit 1; }
cd "$work"
PATH="$bin_dir:$PATH" bash -euo pipefail walkthrough.sh >out.txt 2>err.txt || {
  echo "the walkthrough failed:"; cat err.txt; exit 1; }
test ! -s err.txt || { echo "the walkthrough wrote to stderr:"; cat err.txt; exit 1; }
fail=0
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
# No escapes and no float noise in what the coach reads.
if grep -qF '\|' out.txt; then echo "a Markdown escape in the output"; fail=1; fi
exit $fail
