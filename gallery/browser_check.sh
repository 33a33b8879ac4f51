#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# The gallery in a real browser: writes the gallery with locus_gallery, opens its index.html in
# headless Chromium (Debian package `chromium`) through a check page, and fails unless every
# figure loads and none is blank. Usage: browser_check.sh <locus_gallery> <work_dir>.
# The check page (written next to index.html, which stays as users see it) loads index.html in
# an iframe; when every <img> has settled it records, per figure: naturalWidth and height > 0,
# the number of drawn SVG elements (path, line, polyline, polygon, circle, ellipse, rect, text)
# in the file, and the number of non-background pixels of the figure rasterised by the browser
# onto a canvas. Chromium's --dump-dom prints the resulting page; this script reads its verdict.
# File access between the local pages needs --allow-file-access-from-files; nothing leaves the
# machine (no network, a fresh profile, no sync or updates). Exit 77 (CTest SKIP_RETURN_CODE)
# when chromium is not installed.
set -euo pipefail
gallery=$1
work=$2
browser=""
for b in chromium chromium-browser; do
  if command -v "$b" >/dev/null 2>&1; then
    browser=$(command -v "$b")
    break
  fi
done
if [ -z "$browser" ]; then
  echo "SKIPPED: headless Chromium not found (Debian: apt-get install chromium; scripts/test" \
    "installs it)"
  exit 77
fi

rm -rf "$work"
mkdir -p "$work/out" "$work/profile"
"$gallery" "$work/out" >"$work/gallery.log" 2>&1 || {
  cat "$work/gallery.log"
  echo "FAIL: locus_gallery failed"
  exit 1
}
figures=$(grep -c '<img src="' "$work/out/index.html" || true)
if [ "$figures" -lt 1 ]; then
  echo "FAIL: index.html lists no figure"
  exit 1
fi

cat >"$work/out/browser_check.html" <<'EOF'
<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>gallery check</title></head>
<body>
<iframe id="page" src="index.html" style="width:1200px;height:800px"></iframe>
<pre id="verdict">PENDING</pre>
<script>
"use strict";
const drawn = "path, line, polyline, polygon, circle, ellipse, rect, text";
function report(lines) {
  document.getElementById("verdict").textContent = "\n" + lines.join("\n") + "\n";
}
function inkOf(img) {
  const w = Math.min(img.naturalWidth, 600), h = Math.min(img.naturalHeight, 600);
  const c = document.createElement("canvas");
  c.width = w; c.height = h;
  const g = c.getContext("2d");
  g.fillStyle = "#ffffff";
  g.fillRect(0, 0, w, h);
  g.drawImage(img, 0, 0, w, h);
  const d = g.getImageData(0, 0, w, h).data;
  let ink = 0;
  for (let i = 0; i < d.length; i += 4) {
    if (d[i] < 240 || d[i + 1] < 240 || d[i + 2] < 240) ++ink;
  }
  return ink;
}
function elementsOf(src) {
  const x = new XMLHttpRequest();
  x.open("GET", src, false);
  x.overrideMimeType("image/svg+xml");
  x.send();
  const doc = new DOMParser().parseFromString(x.responseText, "image/svg+xml");
  if (doc.getElementsByTagName("parsererror").length) return -1;
  return doc.querySelectorAll(drawn).length;
}
function check() {
  const lines = [];
  let bad = 0;
  let imgs;
  try {
    imgs = Array.from(document.getElementById("page").contentDocument.querySelectorAll("figure img"));
  } catch (e) {
    report(["RESULT error cannot read index.html: " + e]);
    return;
  }
  for (const img of imgs) {
    const src = img.getAttribute("src");
    let ok = img.complete && img.naturalWidth > 0 && img.naturalHeight > 0;
    let elements = -1, ink = 0;
    try {
      elements = elementsOf(src);
      if (ok) ink = inkOf(img);
    } catch (e) {
      ok = false;
    }
    ok = ok && elements > 0 && ink >= 20;
    if (!ok) ++bad;
    lines.push("FIGURE " + (ok ? "ok" : "BAD") + " " + src + " size=" + img.naturalWidth + "x" +
               img.naturalHeight + " elements=" + elements + " ink=" + ink);
  }
  lines.push("RESULT figures=" + imgs.length + " bad=" + bad);
  report(lines);
}
window.addEventListener("load", check);
</script>
</body></html>
EOF

# --virtual-time-budget lets the page settle (images, the load handler) before the DOM is dumped.
timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync \
  --disable-extensions --disable-dev-shm-usage --allow-file-access-from-files \
  --user-data-dir="$work/profile" --virtual-time-budget=30000 \
  --dump-dom "file://$work/out/browser_check.html" >"$work/dom.html" 2>"$work/chromium.log" || {
  tail -20 "$work/chromium.log"
  echo "FAIL: chromium did not finish"
  exit 1
}
grep -E '^(FIGURE|RESULT)' "$work/dom.html" | sed 's/<\/pre>.*//' >"$work/verdict.txt" || true
grep -E '^FIGURE BAD' "$work/verdict.txt" || true
result=$(grep -E '^RESULT' "$work/verdict.txt" || true)
echo "${result:-RESULT missing (see $work/dom.html)}"
expected="RESULT figures=$figures bad=0"
if [ "$result" != "$expected" ]; then
  echo "FAIL: expected '$expected' ($figures figures in index.html)"
  exit 1
fi
echo "ok: $figures figures load in Chromium and none is blank"
