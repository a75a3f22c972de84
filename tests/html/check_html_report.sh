#!/usr/bin/env bash
# The HTML report in a real browser (Debian's chromium, headless):
#   check_html_report.sh SWEETSPOT DESIGN OUT_DIR
# 1. writes the report of DESIGN, and of a copy whose name is hostile markup;
# 2. the page is well-formed XML (xmllint), so no tag is left open;
# 3. chromium's rendered DOM (--dump-dom) holds the numbers `sweetspot evaluate
#    --format json` gives, rounded here with awk (not read from the page), and
#    the hostile name only as text; the maps over the string bed are there
#    and the numbers under them are those of `sweetspot map --format csv`;
# 4. screenshots at desktop (1280 px) and phone (390 px) widths are not blank:
#    a blank page's PNG is almost all one colour and compresses to a few kB,
#    so each must be several times the size of chromium's screenshot of an
#    empty page at the same width (measured here, not assumed), and as wide
#    as asked.
# Exit 77 (skipped) when chromium or xmllint is missing: scripts/test installs them.
set -euo pipefail
sweetspot=$1 design=$2 out=$3
for tool in chromium xmllint; do
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

# chromium URL [extra flags...]: a private profile, no sandbox (tests may run
# as root), no GPU; its own chatter on stderr is dropped.
browse() {
  local url=$1
  shift
  timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars \
    --user-data-dir="$out/profile" --no-first-run --disable-extensions "$@" "$url" 2>/dev/null
}

# 1. The reports.
"$sweetspot" report "$design" --html "$out/report.html" 2>/dev/null || fail "report --html failed"
sed 's|"name": *"[^"]*"|"name": "<script>alert(1)</script> \& \\"Pro\\" <b>'"'"'98'"'"'</b>"|' \
  "$design" >"$out/hostile.json"
grep -q 'alert(1)' "$out/hostile.json" || fail "the hostile copy of $design has no name to replace"
"$sweetspot" report "$out/hostile.json" --html "$out/hostile.html" 2>/dev/null ||
  fail "report --html failed on the hostile name"

# 2. Well-formed.
for page in report hostile; do
  xmllint --noout "$out/$page.html" 2>"$out/$page.xmllint" ||
    fail "$page.html is not well-formed: $(head -n 3 "$out/$page.xmllint")"
done
grep -q '<script' "$out/report.html" && fail "the page holds a script"
grep -Eiq '(src|href)="(https?:)?//' "$out/report.html" && fail "the page loads something from the network"

# 3. The rendered DOM holds the numbers.
browse "file://$out/report.html" --dump-dom >"$out/dom.html" || fail "chromium could not render the page"
"$sweetspot" evaluate "$design" --format json >"$out/evaluate.json"
value() { # the output NAME from evaluate's JSON
  sed -n "s/^ *\"$1\": *\\([-0-9.e+]*\\),\\{0,1\\}\$/\\1/p" "$out/evaluate.json" | head -n 1
}
fixed() { awk -v v="$1" -v s="$2" -v d="$3" 'BEGIN { printf "%.*f", d, v * s }'; }
expect() { # a literal piece of the rendered DOM
  grep -qF -- "$1" "$out/dom.html" || fail "the rendered page lacks: $1"
}
cop=$(value cop_hand_from_tip_m)
node=$(value node_hand_from_tip_m)
wrist=$(value peak_wrist_force_N)
length=$(value length_m)
[ -n "$cop" ] && [ -n "$node" ] && [ -n "$wrist" ] || fail "evaluate gave no COP, node or wrist force"
half_cm() { # reports/summary's rounding of a position: to 0.5 cm, "30.5 cm" or "30 cm"
  awk -v v="$1" 'BEGIN { h = int(v * 200 + 0.5) / 2; if (h == int(h)) printf "%d cm", h; else printf "%.1f cm", h }'
}
from_butt() { awk -v l="$length" -v c="$1" 'BEGIN { printf "%.17g", l - c }'; }
# The answer's sentences name the COP and the node as the summary rounds them.
expect "$(half_cm "$cop") from the tip"
expect "$(half_cm "$node") from the tip"
# The positions under the drawing, from the tip and from the butt, to 0.1 cm.
expect "<td class=\"num\">$(fixed "$cop" 100 1)</td><td class=\"num\">$(fixed "$(from_butt "$cop")" 100 1)</td></tr>"
expect "<td class=\"num\">$(fixed "$node" 100 1)</td><td class=\"num\">$(fixed "$(from_butt "$node")" 100 1)</td></tr>"
# Every output, to four significant figures.
expect "<tr id=\"out-peak_wrist_force_N\"><td>peak wrist force</td><td class=\"num\">$(awk -v v="$wrist" 'BEGIN { printf "%.4g", v }')</td><td>N</td>"
expect "Length $(fixed "$length" 100 1) cm"
# The drawings and the plots (two layouts each) are in the DOM.
svgs=$(grep -o '<svg' "$out/dom.html" | wc -l)
((svgs >= 6)) || fail "the rendered page has $svgs SVG pictures, expected the 2 drawings and 2 plots twice"

# The maps over the string bed: three heat maps, and every row of the table
# under them is a point of `sweetspot map --format csv` (same 50 x 50 grid,
# same level: auto), rounded here with awk. The page assumes a 100 sq in head
# when the file gives none, so the CSV is of a copy that gives that head.
expect '<section id="maps">'
for quantity in power shock feel; do
  grep -q "<figure id=\"map-$quantity\"><svg" "$out/dom.html" || fail "the rendered page lacks the $quantity map"
done
if grep -q 'headsize_sq_in' "$design"; then
  cp "$design" "$out/headed.json"
else
  sed 's|"implement": *{|"implement": { "headsize_sq_in": 100,|' "$design" >"$out/headed.json"
fi
"$sweetspot" map "$out/headed.json" --format csv >"$out/map.csv" || fail "sweetspot map failed"
sed -n '/<table id="map-numbers">/,/<\/table>/p' "$out/dom.html" | grep '^<tr><td' >"$out/map-rows.html" || true
rows=$(wc -l <"$out/map-rows.html")
((rows >= 20)) || fail "the maps' table has $rows rows, expected a subsample of the grid"
# A row as the page writes it: cm to 0.1, the COR to 0.001, the force to 1 N
# (the energy column is left out: it is rounded to significant figures).
awk -F, 'NR > 1 { printf "<tr><td class=\"num\">%.1f</td><td class=\"num\">%.1f</td><td class=\"num\">%.3f</td><td class=\"num\">%.0f</td>\n", $2 * 100, $3 * 100, $5, $6 }' \
  "$out/map.csv" >"$out/map-expected.txt"
matched=$(grep -cFf "$out/map-expected.txt" "$out/map-rows.html" || true)
((matched == rows)) || fail "only $matched of the maps' $rows table rows are points of sweetspot map's CSV"
echo "maps: $rows table rows, each a point of sweetspot map's CSV"

# The hostile name is text, never markup.
browse "file://$out/hostile.html" --dump-dom >"$out/hostile-dom.html" || fail "chromium could not render the hostile page"
grep -q '<script' "$out/hostile-dom.html" && fail "a name from the file became a script element"
grep -qF '<h1 id="name">&lt;script&gt;alert(1)&lt;/script&gt; &amp; "Pro" &lt;b&gt;'"'"'98'"'"'&lt;/b&gt;</h1>' \
  "$out/hostile-dom.html" || fail "the hostile name is not shown as text in the heading"

# 4. Screenshots, not blank.
printf '<!DOCTYPE html><html><head><meta charset="utf-8"><title>empty</title></head><body></body></html>\n' >"$out/empty.html"
for width in 1280 390; do
  browse "file://$out/report.html" --window-size="$width,2400" --screenshot="$out/report-$width.png" >/dev/null
  browse "file://$out/empty.html" --window-size="$width,2400" --screenshot="$out/empty-$width.png" >/dev/null
  file "$out/report-$width.png" | grep -q "PNG image data, $width x 2400" ||
    fail "the $width px screenshot is not a $width x 2400 PNG: $(file "$out/report-$width.png")"
  page=$(stat -c %s "$out/report-$width.png")
  empty=$(stat -c %s "$out/empty-$width.png")
  ((page > 8 * empty)) ||
    fail "the $width px screenshot looks blank: $page bytes against $empty for an empty page"
  echo "screenshot $width px: $page bytes (an empty page: $empty bytes): $out/report-$width.png"
done
echo "ok: the HTML report renders in chromium with the numbers of evaluate"
