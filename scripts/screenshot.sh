#!/bin/bash
# Screenshots of the answer with headless Chromium at 1400x900, for a closing note or
# a review: report.html's first screen, and claims.md's answer block (claims.md through Debian's
# python3-markdown, tables on, into one page beside claims.md so its image paths resolve).
#   scripts/screenshot.sh [RESULTS_DIR]   (default: results) -> RESULTS_DIR/screens/*.png
set -euo pipefail
DIR=${1:-results}
SCREENS="$DIR/screens"
PY=/usr/bin/python3  # Debian's python, where python3-markdown lives (scripts/setup.sh)
[ -x "$PY" ] || PY=python3
CHROMIUM=$(command -v chromium || command -v chromium-browser || true)
[ -n "$CHROMIUM" ] || { echo "screenshot: chromium not installed (scripts/setup.sh installs it)" >&2; exit 2; }
for f in report.html claims.md; do
  [ -s "$DIR/$f" ] || { echo "screenshot: $DIR/$f missing (scripts/reproduce.sh writes it)" >&2; exit 2; }
done
mkdir -p "$SCREENS"
PROFILE=$(mktemp -d)
ANSWER="$DIR/.claims_answer.html"
trap 'rm -rf "$PROFILE" "$ANSWER"' EXIT

# claims.md from its start through the answer block: the question, the lines, and the design-space
# figure with its caption when there is one (else up to the next paragraph after the table).
"$PY" - "$DIR/claims.md" "$ANSWER" <<'PY'
import re, sys
import markdown
text = open(sys.argv[1], encoding="utf-8").read()
m = (re.search(r"\n## The answer\n.*?!\[Design space\]\([^)]*\)\n\n(\*[^\n]*\*\n)?", text, re.S)
     or re.search(r"\n## The answer\n.*?\n\|[^\n]*\|\n(?!\|)", text, re.S))
if not m:
    sys.exit("screenshot: claims.md has no answer block (claims --report report.json writes one)")
body = markdown.markdown(text[: m.end()], extensions=["tables"])
style = ("body{font:14px/1.45 system-ui,sans-serif;max-width:1250px;margin:1.5em auto;padding:0 1em;color:#222}"
         "table{border-collapse:collapse;font-size:13px}th,td{border:1px solid #ccc;padding:3px 7px;text-align:left;"
         "vertical-align:top}th{background:#f0f0f3}img{max-width:600px}")
open(sys.argv[2], "w", encoding="utf-8").write(
    f"<!doctype html><html><head><meta charset='utf-8'><style>{style}</style></head><body>{body}</body></html>")
PY

shot() {  # shot PAGE PNG
  timeout 120 "$CHROMIUM" --headless --no-sandbox --disable-gpu --no-first-run --hide-scrollbars \
    --user-data-dir="$PROFILE" --virtual-time-budget=10000 --window-size=1400,900 \
    --screenshot="$(realpath "$2")" "file://$(realpath "$1")" 2>/dev/null >/dev/null
  [ -s "$2" ] || { echo "screenshot: chromium wrote no $2" >&2; exit 1; }
  echo "screenshot: $2"
}
shot "$DIR/report.html" "$SCREENS/report_first_screen.png"
shot "$ANSWER" "$SCREENS/claims_answer.png"
