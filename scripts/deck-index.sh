#!/usr/bin/env bash
# Writes DIR/index.html, the decks' index: each deck of slides/ by its title and subtitle (its front matter), linking
# its HTML and, where it was printed, its PDF; a deck whose page in DIR is the "not built yet" one (scripts/site-slides.sh)
# is listed as such. Usage: scripts/deck-index.sh DIR   (scripts/build-slides.sh, scripts/site-slides.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
dir="$1"
entries=""
missing=0
for deck in "$root"/slides/*.md; do
  name="$(basename "$deck" .md)"
  title="$(sed -n 's/^title: *"\(.*\)"$/\1/p' "$deck" | head -1)"
  subtitle="$(sed -n 's/^subtitle: *"\(.*\)"$/\1/p' "$deck" | head -1)"
  entry="<li><a href=\"$name.html\">$title</a> <span>$subtitle</span>"
  if [ ! -f "$dir/$name.html" ] || head -c 2000 "$dir/$name.html" | grep -q "not built yet"; then
    entry+=" (not built yet)"
    missing=$((missing + 1))
  elif [ -f "$dir/$name.pdf" ]; then
    entry+=" · <a href=\"$name.pdf\">PDF</a>"
  fi
  entries+="$entry</li>"$'\n'
done
about="A deck per lab, with figures rendered by the reference solutions. Arrow keys step through a deck; each deck's
last slide runs its lab live where the decks sit beside the labs' pages (scripts/kit web, then scripts/kit serve)."
[ "$missing" -gt 0 ] && about+=" $missing of the decks are not built yet: <code>scripts/kit slides</code> builds them
(about 13 minutes: the solutions render their figures and sweeps)."
cat >"$dir/index.html" <<HTML
<!doctype html>
<html lang="en">
<head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1">
<title>GPU Shaders for Visualization: the slides</title><link rel="icon" href="data:,"></head>
<body style="font-family: sans-serif; max-width: 48em; margin: 2em auto; line-height: 1.5">
<h1>GPU Shaders for Visualization: the slides</h1>
<p>$about</p>
<ul>
$entries</ul>
</body>
</html>
HTML
