#!/usr/bin/env bash
# Puts the decks beside the web pages: SITE/slides/ gets every deck built in SLIDES (its HTML and PDF,
# scripts/build-slides.sh), and for a deck not built there a page that says how to build it, then the decks' index
# (scripts/deck-index.sh), so that every "Slides" link of the site answers whether or not the decks (13 minutes of
# sweeps) were built. Usage: scripts/site-slides.sh SITE SLIDES   (scripts/kit web and slides, tests/web/check_web.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
site="$1"
slides="$2"
[ -f "$site/index.html" ] || { echo "site-slides: $site holds no site (scripts/kit web builds it)" >&2; exit 2; }
mkdir -p "$site/slides"
built=0
for deck in "$root"/slides/*.md; do
  name="$(basename "$deck" .md)"
  rm -f "$site/slides/$name.pdf"
  if [ -f "$slides/$name.html" ]; then
    cp "$slides/$name.html" "$site/slides/"
    [ -f "$slides/$name.pdf" ] && cp "$slides/$name.pdf" "$site/slides/"
    built=$((built + 1))
    continue
  fi
  title="$(sed -n 's/^title: *"\(.*\)"$/\1/p' "$deck" | head -1)"
  cat >"$site/slides/$name.html" <<HTML
<!doctype html>
<html lang="en">
<head><meta charset="utf-8"><title>$title: not built yet</title><link rel="icon" href="data:,"></head>
<body style="font-family: sans-serif; max-width: 48em; margin: 2em auto; line-height: 1.5">
<h1>$title</h1>
<p>This deck is not built yet. <code>scripts/kit slides</code> builds every deck (about 13 minutes: the reference
solutions render its figures and sweeps) and puts it here, beside the labs' pages; its Markdown,
<code>slides/$name.md</code>, reads in any repository browser.</p>
<p><a href="../index.html">The labs</a></p>
</body>
</html>
HTML
done
"$root/scripts/deck-index.sh" "$site/slides"
echo "site-slides: $built of $(ls "$root"/slides/*.md | wc -l) decks built into $site/slides/"
