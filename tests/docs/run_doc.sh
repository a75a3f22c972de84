#!/bin/bash
# Runs a Markdown document as a reader would: every shell block in it, in
# order, exactly as written, and checks that every relative link resolves.
#
#   run_doc.sh [--opening-block-not-run] DOC SOURCE_DIR BIN_DIR [CHECK_SCRIPT]
#
# Shell blocks are fenced ```sh (or bash, shell, console). Each runs with
# `bash -euo pipefail` in one scratch folder shared by the document's blocks
# (so a later block sees the files an earlier one wrote), with the built
# sweetspot first on the PATH and `designs/` a link to the source tree's, so
# that a command written for the repository's root runs as written. The line
# before a block may say what to expect of it:
#   <!-- exit N -->          the block ends with status N (else 0, with
#                            nothing on standard error)
#   <!-- not run: REASON --> the block is not run (say why)
# A fenced block (``` or ```text) preceded by `<!-- output -->` shows what the
# shell block before it prints: each of its lines must appear in that block's
# standard output or error.
# --opening-block-not-run: the block that opens the file is not run (the
# README's own two commands, which build and test this very tree).
# Links: every [text](target), src="target" and href="target" outside code
# that is not a URL must name a file or folder that exists, relative to DOC;
# a #fragment into a Markdown file must name one of its headings (GitHub's
# rule: lower case, punctuation dropped, spaces to hyphens).
# CHECK_SCRIPT, when given, runs last in the scratch folder as
# `bash CHECK_SCRIPT DOC`, with the blocks' standard output in out.txt.
set -euo pipefail
skip_opening=0
if [ "${1:-}" = "--opening-block-not-run" ]; then
  skip_opening=1
  shift
fi
doc=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
source_dir=$(cd "$2" && pwd)
bin_dir=$(cd "$3" && pwd)
check=${4:+$(cd "$(dirname "$4")" && pwd)/$(basename "$4")}
doc_dir=$(dirname "$doc")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0

# --- Links --------------------------------------------------------------------
# The headings of a Markdown file as GitHub's anchors, one a line.
anchors_of() {
  awk '/^```/{code=!code; next} !code && /^#+ /{
         h=$0; sub(/^#+ +/, "", h); h=tolower(h)
         gsub(/[^a-z0-9 _-]/, "", h); gsub(/ /, "-", h); print h }' "$1"
}
# Every link target outside fenced code and inline code, one a line.
links_of() {
  awk '/^```/{code=!code; next} !code {
         line=$0; gsub(/`[^`]*`/, "", line)
         while (match(line, /\]\([^)]+\)/)) {
           print substr(line, RSTART + 2, RLENGTH - 3); line=substr(line, RSTART + RLENGTH) }
         while (match(line, /(src|href)="[^"]+"/)) {
           t=substr(line, RSTART, RLENGTH); sub(/^[a-z]+="/, "", t); sub(/"$/, "", t); print t
           line=substr(line, RSTART + RLENGTH) } }' "$1"
}
links=0
while IFS= read -r link; do
  case $link in http://* | https://* | mailto:*) continue ;; esac
  links=$((links + 1))
  path=${link%%#*}
  fragment=
  [ "$path" = "$link" ] || fragment=${link#*#}
  target=$doc
  [ -z "$path" ] || target=$doc_dir/$path
  if [ ! -e "$target" ]; then
    echo "$(basename "$doc"): broken link: $link (no $path)"
    fail=1
  elif [ -n "$fragment" ] && [[ $target == *.md ]] && ! anchors_of "$target" | grep -qxF -- "$fragment"; then
    echo "$(basename "$doc"): broken link: $link (no heading #$fragment in $path)"
    fail=1
  fi
done < <(links_of "$doc")

# --- Shell blocks -------------------------------------------------------------
# Writes block-N.sh (N = 1, 2, ...) and a manifest line per block:
#   run N LINE STATUS | skip N LINE | output N LINE (N: the shell block shown)
awk -v dir="$work" -v skip_opening="$skip_opening" '
  function marker(s) { return s ~ /^<!-- .* -->$/ }
  /^```/ && !inside {
    inside=1; lang=$0; sub(/^```/, "", lang); sub(/ .*/, "", lang); start=NR
    if (lang ~ /^(sh|bash|shell|console)$/) {
      kind="shell"; n++; file=dir "/block-" n ".sh"; printf "" > file
      if (skip_opening && NR == 1) print "skip", n, NR
      else if (previous ~ /^<!-- not run: .+ -->$/) print "skip", n, NR
      else if (previous ~ /^<!-- exit [0-9]+ -->$/) { s=previous; gsub(/[^0-9]/, "", s); print "run", n, NR, s }
      else if (marker(previous)) { print "bad", n, NR; }
      else print "run", n, NR, 0
    } else if (previous == "<!-- output -->") {
      kind="output"; m++; file=dir "/output-" m ".txt"; printf "" > file; print "output", n, NR, m
    } else kind="other"
    next
  }
  /^```/ && inside { inside=0; if (kind != "other") close(file); previous=""; next }
  inside { if (kind != "other") print > file; next }
  /[^ ]/ { previous=$0 }
' "$doc" >"$work/manifest"

mkdir "$work/run"
ln -s "$source_dir/designs" "$work/run/designs"
: >"$work/out.txt"
ran=0
while read -r kind n line rest; do
  case $kind in
    bad)
      echo "$(basename "$doc"):$line: a shell block after a comment that is neither <!-- exit N --> nor <!-- not run: REASON -->"
      fail=1 ;;
    skip) ;;
    run)
      ran=$((ran + 1))
      status=0
      (cd "$work/run" && PATH="$bin_dir:$PATH" bash -euo pipefail "$work/block-$n.sh" \
        >"$work/out-$n.txt" 2>"$work/err-$n.txt") || status=$?
      cat "$work/out-$n.txt" >>"$work/out.txt"
      if [ "$status" != "$rest" ]; then
        echo "$(basename "$doc"):$line: the block ended with status $status, not $rest:"
        sed 's/^/  /' "$work/err-$n.txt"
        fail=1
      elif [ "$rest" = 0 ] && [ -s "$work/err-$n.txt" ]; then
        echo "$(basename "$doc"):$line: the block wrote to standard error:"
        sed 's/^/  /' "$work/err-$n.txt"
        fail=1
      fi ;;
    output)
      shown=$work/output-$rest.txt
      if [ ! -f "$work/out-$n.txt" ]; then
        echo "$(basename "$doc"):$line: output shown for a block that was not run"
        fail=1
        continue
      fi
      while IFS= read -r expected; do
        [ -n "$expected" ] || continue
        cat "$work/out-$n.txt" "$work/err-$n.txt" | grep -qF -- "$expected" || {
          echo "$(basename "$doc"):$line: the block above does not print: $expected"
          fail=1
        }
      done <"$shown" ;;
  esac
done <"$work/manifest"

if [ -n "$check" ]; then
  cp "$work/out.txt" "$work/run/out.txt"
  (cd "$work/run" && bash "$check" "$doc") || fail=1
fi
echo "$(basename "$doc"): $ran shell blocks run, $links links checked"
exit $fail
