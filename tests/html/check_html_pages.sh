#!/usr/bin/env bash
# The web pages of a comparison and of a study in a real browser (Debian's
# chromium, headless), as check_html_report.sh does for a design's page:
#   check_html_pages.sh SWEETSPOT SOURCE_DIR OUT_DIR
# 1. `compare A B --html` and `optimize STUDY --html` (the study with
#    `--format json -o` in the same run), and the same with a name and a
#    question that are hostile markup;
# 2. each page is well-formed XML (xmllint), holds no script and fetches nothing;
# 3. chromium's rendered DOM (--dump-dom) holds the numbers of the same
#    command's `--format json`, read here with jq and rounded with awk (never
#    typed in), and the hostile strings only as text;
# 4. screenshots at desktop (1280 px) and phone (390 px) widths are not blank
#    (several times the size of an empty page's at the same width).
# Exit 77 (skipped) when chromium, xmllint or jq is missing: scripts/test installs them.
set -euo pipefail
sweetspot=$1 source=$2 out=$3
for tool in chromium xmllint jq; do
  if ! command -v "$tool" >/dev/null; then
    echo "skipped: $tool is not installed (scripts/test installs it)" >&2
    exit 77
  fi
done
rm -rf "$out" && mkdir -p "$out"
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
browse() { # chromium URL [flags...]: a private profile, no sandbox (tests may run as root), no GPU
  local url=$1
  shift
  timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars \
    --user-data-dir="$out/profile" --no-first-run --disable-extensions "$@" "$url" 2>/dev/null
}
g() { awk -v v="$1" -v s="${3:-1}" -v d="$2" 'BEGIN { printf "%.*g", d, v * s }'; }
f() { awk -v v="$1" -v s="${3:-1}" -v d="$2" 'BEGIN { printf "%.*f", d, v * s }'; }
expect_in() { # FILE PIECE [what]: a literal piece of the rendered DOM
  grep -qF -- "$2" "$1" || fail "$(basename "$1") lacks${3:+ $3}: $2"
}
row_of() { # FILE ID: the table row <tr id="ID"> of the rendered DOM, one line
  grep -F "<tr id=\"$2\">" "$1" | head -n 1
}
text() { # a string as chromium serialises text: & < > as entities, quotes as they are
  sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g' <<<"$1"
}
self_contained() { # PAGE: parses, no script, nothing from the network
  xmllint --noout "$1" 2>"$1.xmllint" || fail "$1 is not well-formed: $(head -n 3 "$1.xmllint")"
  grep -q '<script' "$1" && fail "$1 holds a script"
  grep -Eiq '(src|href)="(https?:)?//' "$1" && fail "$1 loads something from the network"
  return 0
}
hostile='<script>alert(1)</script> & "Pro" <b>'"'"'98'"'"'</b>'
hostile_sed='<script>alert(1)</script> \& \\"Pro\\" <b>'"'"'98'"'"'</b>'
hostile_text='&lt;script&gt;alert(1)&lt;/script&gt; &amp; "Pro" &lt;b&gt;'"'"'98'"'"'&lt;/b&gt;'

# --- compare ---------------------------------------------------------------
a=$source/designs/racquets/tour-100.json
b=$source/designs/racquets/tour-100-lead-at-tip.json
[ "$("$sweetspot" compare "$a" "$b" --html "$out/compare.html")" = "wrote $out/compare.html" ] ||
  fail "compare --html did not say what it wrote"
"$sweetspot" compare "$a" "$b" --format json >"$out/compare.json"
self_contained "$out/compare.html"
browse "file://$out/compare.html" --dump-dom >"$out/compare-dom.html" || fail "chromium could not render the comparison"
dom=$out/compare-dom.html
# The answer: every sentence of the differences.
while IFS= read -r sentence; do
  expect_in "$dom" "$(text "$sentence")" "the sentence"
done < <(jq -r '.differences[].sentences[]' "$out/compare.json")
# The table side by side: each value in people's units (4 figures), SI under it (6).
check_cell() { # KEY SCALE SI_UNIT
  local key=$1 scale=$2 unit=$3 k v row
  row=$(row_of "$dom" "cmp-$key")
  [ -n "$row" ] || fail "the comparison has no row $key"
  for k in 0 1; do
    v=$(jq -r ".designs[$k].values.$key" "$out/compare.json")
    [ "$v" != null ] || fail "compare's JSON has no $key for design $k"
    grep -qF -- "<td class=\"num\">$(g "$v" 4 "$scale")<span class=\"si\">$(g "$v" 6)${unit:+ $unit}</span></td>" <<<"$row" ||
      fail "row $key lacks design $k's $(g "$v" 4 "$scale") ($(g "$v" 6) $unit): $row"
  done
}
check_cell mass_kg 1000 kg
check_cell balance_from_butt_m 100 m
check_cell cop_hand_from_tip_m 100 m
check_cell node_hand_from_tip_m 100 m
check_cell peak_wrist_force_N 1 N
check_cell apparent_cor 1 ""
# The positions under the drawings, cm from the tip to 0.1.
for key in cop node; do
  row=$(row_of "$dom" "drawing-$key")
  for k in 0 1; do
    v=$(jq -r ".designs[$k].values.${key}_hand_from_tip_m" "$out/compare.json")
    grep -qF "<td class=\"num\">$(f "$v" 1 100)</td>" <<<"$row" || fail "drawing-$key lacks $(f "$v" 1 100): $row"
  done
done
# The curve along the frame passes through each design's impact (on the 1 cm grid).
impact=$(jq -r '.designs[0].values.impact_from_tip_m' "$out/compare.json")
at=$(f "$impact" 1 100)
[ "$at" = "$(f "$(jq -r '.designs[1].values.impact_from_tip_m' "$out/compare.json")" 1 100)" ] ||
  fail "the two designs are hit at different points"
line=$(sed -n '/<table id="curve">/,/<\/table>/p' "$dom" | grep -F "<tr><td class=\"num\">$at</td>")
for k in 0 1; do
  w=$(jq -r ".designs[$k].values.peak_wrist_force_N" "$out/compare.json")
  grep -qF "<td class=\"num\">$(f "$w" 0)</td>" <<<"$line" || fail "the curve at $at cm lacks design $k's $(f "$w" 0) N: $line"
done
svgs=$(grep -o '<svg' "$dom" | wc -l)
((svgs >= 4)) || fail "the comparison has $svgs SVG pictures, expected 2 drawings and a plot twice"
echo "compare: sentences, table, positions and curve hold compare's JSON numbers; $svgs pictures"

# A design whose name is markup.
sed 's|"name": *"[^"]*"|"name": "'"$hostile_sed"'"|' "$a" >"$out/hostile.json"
grep -qF 'alert(1)' "$out/hostile.json" || fail "the hostile copy of $a has no name to replace"
"$sweetspot" compare "$out/hostile.json" "$b" --html "$out/compare-hostile.html" >/dev/null ||
  fail "compare --html failed on a hostile name"
self_contained "$out/compare-hostile.html"
browse "file://$out/compare-hostile.html" --dump-dom >"$out/compare-hostile-dom.html"
grep -q '<script' "$out/compare-hostile-dom.html" && fail "a name from a design became a script element"
grep -F '<h1 id="name">' "$out/compare-hostile-dom.html" | grep -qF "$hostile_text" ||
  fail "the hostile name is not shown as text in the comparison's heading"

# --- optimize --------------------------------------------------------------
study=$source/designs/studies/7-lead-tape-for-power.json
[ "$("$sweetspot" optimize "$study" --html "$out/study.html" --format json -o "$out/study.json")" = "wrote $out/study.html" ] ||
  fail "optimize --html did not say what it wrote"
self_contained "$out/study.html"
browse "file://$out/study.html" --dump-dom >"$out/study-dom.html" || fail "chromium could not render the study"
dom=$out/study-dom.html
expect_in "$dom" "$(text "$(jq -r .question "$study")")" "the question"
# The answer names the optimum to 4 figures, and so does the outputs' table.
best=$(jq -r '.outputs_best.rebound_speed_m_s' "$out/study.json")
start=$(jq -r '.outputs_start.rebound_speed_m_s' "$out/study.json")
sed -n '/<div class="answer">/,/<\/div>/p' "$dom" | grep -qF "is $(g "$best" 4) m/s (the starting design gives $(g "$start" 4))" ||
  fail "the answer does not give the optimum $(g "$best" 4) m/s and the start $(g "$start" 4)"
for output in rebound_speed_m_s:1 peak_wrist_force_N:1 swingweight_kg_cm2:1 cop_hand_from_tip_m:100 mass_kg:1000; do
  name=${output%:*} scale=${output#*:}
  row=$(row_of "$dom" "out-$name")
  for at in start best; do
    v=$(jq -r ".outputs_$at.$name" "$out/study.json")
    grep -qF "<td class=\"num\">$(g "$v" 4 "$scale")</td>" <<<"$row" || fail "out-$name lacks the $at's $(g "$v" 4 "$scale"): $row"
  done
done
# The variables: bounds, start and best as the file writes them (6 figures).
n=$(jq '.variables | length' "$out/study.json")
for ((i = 0; i < n; i++)); do
  row=$(row_of "$dom" "var-$((i + 1))")
  for field in min max start best; do
    v=$(jq -r ".variables[$i].$field" "$out/study.json")
    grep -qF "<span class=\"si\">$(g "$v" 6)</span>" <<<"$row" || fail "var-$((i + 1)) lacks its $field $(g "$v" 6): $row"
  done
done
# The convergence table ends at the optimum.
last=$(sed -n '/<table id="convergence">/,/<\/table>/p' "$dom" | grep '^<tr><td' | tail -n 1)
grep -qF "<td class=\"num\">$(g "$best" 6)</td></tr>" <<<"$last" || fail "the convergence table ends at $last, not $(g "$best" 6)"
# The best design's lead in the drawing's table.
mass=$(jq -r '.variables[1].best' "$out/study.json")
grep -qF "$(f "$mass" 1 1000) g at" <<<"$(row_of "$dom" drawing-lead)" || fail "the drawing's table lacks the best lead, $(f "$mass" 1 1000) g"
svgs=$(grep -o '<svg' "$dom" | wc -l)
((svgs >= 4)) || fail "the study's page has $svgs SVG pictures, expected 2 drawings and a plot twice"
echo "optimize: answer, outputs, variables and convergence hold the same run's JSON numbers; $svgs pictures"

# A study whose name and question are markup (its design beside it).
cp "$source/designs/studies/$(jq -r .design "$study")" "$out/"
jq --arg h "$hostile" '.name = $h | .question = $h' "$study" >"$out/hostile-study.json"
"$sweetspot" optimize "$out/hostile-study.json" --html "$out/study-hostile.html" >/dev/null ||
  fail "optimize --html failed on a hostile name"
self_contained "$out/study-hostile.html"
browse "file://$out/study-hostile.html" --dump-dom >"$out/study-hostile-dom.html"
grep -q '<script' "$out/study-hostile-dom.html" && fail "a study's name became a script element"
grep -F '<h1 id="name">' "$out/study-hostile-dom.html" | grep -qF "$hostile_text" ||
  fail "the hostile study name is not shown as text in the heading"

# --- screenshots -------------------------------------------------------------
printf '<!DOCTYPE html><html><head><meta charset="utf-8"><title>empty</title></head><body></body></html>\n' >"$out/empty.html"
for width in 1280 390; do
  browse "file://$out/empty.html" --window-size="$width,2400" --screenshot="$out/empty-$width.png" >/dev/null
  empty=$(stat -c %s "$out/empty-$width.png")
  for page in compare study; do
    browse "file://$out/$page.html" --window-size="$width,2400" --screenshot="$out/$page-$width.png" >/dev/null
    file "$out/$page-$width.png" | grep -q "PNG image data, $width x 2400" ||
      fail "the $width px screenshot of $page is not a $width x 2400 PNG: $(file "$out/$page-$width.png")"
    size=$(stat -c %s "$out/$page-$width.png")
    ((size > 8 * empty)) || fail "the $width px screenshot of $page looks blank: $size bytes against $empty"
    echo "screenshot $width px: $size bytes (an empty page: $empty bytes): $out/$page-$width.png"
  done
done
echo "ok: the comparison's and the study's pages render in chromium with their JSON's numbers"
