#!/usr/bin/env bash
# The report's page in a real browser: headless Chromium renders index.html of a coarse report
# (tests/app/data/coarse_cap.json) at the page's design width; the screenshot must be the size asked for and
# show the page (not a blank or an error page): mostly white background, with text and the figures' colours.
# Laid out by the browser at that width, no table is wider than the page (none scrolls sideways), the
# contents list names every section, each link landing on its heading, and a quantity named in two tables
# with a unit column (the headline numbers, the levels behind them) has one unit.
# Where no headless browser is installed (scripts/test installs Debian's chromium; scripts/run does not) the
# test is skipped with the reason printed (exit 77, ctest's SKIP_RETURN_CODE).
set -u
skinfem=$1
browser=""
for b in chromium chromium-browser google-chrome; do
  if command -v "$b" >/dev/null 2>&1; then browser=$b; break; fi
done
if [ -z "$browser" ]; then
  echo "SKIP: no headless browser on PATH (chromium, chromium-browser, google-chrome); apt-get install chromium to run this test"
  exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if ! "$skinfem" report "$(dirname "$0")/data/coarse_cap.json" --out "$tmp/rep" >"$tmp/stdout" 2>"$tmp/stderr"; then
  echo "FAIL report:"; cat "$tmp/stderr"; exit 1
fi
width=1100 height=6000
# --no-sandbox: CI runs as root, where Chromium's sandbox refuses to start.
"$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=$width,$height \
  --screenshot="$tmp/page.png" "file://$tmp/rep/index.html" >"$tmp/browser.log" 2>&1
if [ ! -s "$tmp/page.png" ]; then echo "FAIL $browser wrote no screenshot:"; tail -5 "$tmp/browser.log"; exit 1; fi
/usr/bin/python3 - "$tmp/page.png" $width $height <<'PY'
import sys
import matplotlib.image as mpimg
import numpy as np
img = mpimg.imread(sys.argv[1])[:, :, :3]
w, h = int(sys.argv[2]), int(sys.argv[3])
bad = []
if img.shape[:2] != (h, w): bad.append(f"screenshot {img.shape[1]}x{img.shape[0]}, asked {w}x{h}")
white = np.all(img > 0.97, axis=2).mean()
colours = len(np.unique((img * 255).astype(np.uint8).reshape(-1, 3), axis=0))
# A blank page is all white; a page of text alone has grey levels only; figures bring hundreds of colours.
if not 0.5 < white < 0.995: bad.append(f"white fraction {white:.3f}: blank or not the page")
if colours < 200: bad.append(f"{colours} distinct colours: no figure rendered")
for b in bad: print("FAIL screenshot:", b)
print(f"screenshot {img.shape[1]}x{img.shape[0]}: white {white:.3f}, {colours} colours")
sys.exit(1 if bad else 0)
PY
[ $? -eq 0 ] || exit 1
# The layout as the browser computes it: a script added to a copy of the page records each table's width
# against the width it is given, and the contents list against the headings; --dump-dom prints the result.
python3 - "$tmp/rep/index.html" "$tmp/rep/probe.html" <<'PY'
import sys
page = open(sys.argv[1], encoding="utf-8").read()
probe = """<script>
const r = {wide: [], contents: [], headings: document.querySelectorAll('h2').length};
document.querySelectorAll('table').forEach((t, i) => {
  if (t.scrollWidth > t.clientWidth + 1)
    r.wide.push(`table ${i + 1} (${t.rows[0].innerText.replace(/\\s+/g, ' ').slice(0, 60)}): ${t.scrollWidth} px in ${t.clientWidth} px`);
});
// One unit per quantity: a row named in two tables with a unit column has the same unit in both.
const units = {};
r.units = [];
document.querySelectorAll('table').forEach((t, i) => {
  const head = [...t.rows[0].cells].map(c => c.innerText.trim()), u = head.indexOf('unit');
  if (u < 0) return;
  [...t.rows].slice(1).forEach(row => {
    const name = row.cells[0].innerText.trim(), unit = row.cells[u] ? row.cells[u].innerText.trim() : '';
    if (!name) return;
    if (name in units && units[name][0] !== unit)
      r.units.push(`'${name}' in '${units[name][0]}' (table ${units[name][1]}) and '${unit}' (table ${i + 1})`);
    units[name] = [unit, i + 1];
  });
});
r.unit_rows = Object.keys(units).length;
document.querySelectorAll('nav a').forEach(a => {
  const target = document.querySelector(a.getAttribute('href'));
  r.contents.push([a.innerText, target !== null && target.tagName === 'H2' && target.innerText === a.innerText]);
});
document.body.setAttribute('data-probe', JSON.stringify(r));
</script>"""
open(sys.argv[2], "w", encoding="utf-8").write(page.replace("</body>", probe + "</body>"))
PY
"$browser" --headless --no-sandbox --disable-gpu --window-size=$width,$height --dump-dom \
  "file://$tmp/rep/probe.html" >"$tmp/dom.html" 2>>"$tmp/browser.log"
/usr/bin/python3 - "$tmp/dom.html" <<'PY'
import html, json, re, sys
m = re.search(r'data-probe="([^"]*)"', open(sys.argv[1], encoding="utf-8").read())
if not m:
    sys.exit("FAIL layout: the browser ran no probe")
r = json.loads(html.unescape(m.group(1)))
bad = [f"wider than the page: {w}" for w in r["wide"]]
if len(r["contents"]) != r["headings"]:
    bad.append(f"the contents list has {len(r['contents'])} entries, the page {r['headings']} sections")
bad += [f"contents entry '{name}' does not land on its heading" for name, ok in r["contents"] if not ok]
bad += [f"two units for {u}" for u in r["units"]]
if r["unit_rows"] == 0:
    bad.append("no table with a unit column: the units were not checked")
for b in bad:
    print("FAIL layout:", b)
print(f"layout: {r['headings']} sections in the contents list, no table wider than the page, one unit for "
      f"each of {r['unit_rows']} quantities" if not bad else "")
sys.exit(1 if bad else 0)
PY
