#!/usr/bin/env bash
# The hostile harness tested on itself: runs tests/hostile/self/harness.tsv,
# whose cases each break one rule the harness enforces (NaN on stdout or in a
# file written, two lines of refusal, a message without its path, a file that
# should have been left alone, a raw failure, a wrong exit), and compares what
# it reports with harness.expected, line for line.
#
#   tests/hostile/self/check_harness.sh SWEETSPOT WORKDIR
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
(($# == 2)) || { echo "usage: $0 SWEETSPOT WORKDIR" >&2; exit 2; }
got=$(bash "$here/../run_hostile.sh" "$1" "$2" "$here/harness.tsv")
if ! diff <(printf '%s\n' "$got") "$here/harness.expected"; then
  echo "hostile harness: its report differs from harness.expected (above: < got, > expected)"
  exit 1
fi
echo "hostile harness: every rule caught, every good case passed"
