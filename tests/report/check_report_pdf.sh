#!/bin/bash
# Renders REPORT.md with bench/make_pdf.sh into a temporary folder and checks the seed's shape
# (issues 26, 36): A4 pages, at most 5 of them; the introduction and section 1 on page 1 and
# sections 2-5 on pages 2-5, each on exactly one page (every section after the first starts a new
# page, so a section that grows past its page moves every later heading and fails the check); no
# "Extensions" section (they are in docs/extensions.md); one plot per page, placed at no more than
# 200 pixels per inch (bench/report/plots.gp draws them for that: their fonts print at 10 pt); and
# nothing wider than the text: pdflatex's log (bench/make_pdf.sh keeps it) must have no "Overfull
# \hbox" wider than 1 pt, the mark of a line, a code span, a formula, a table or an image that runs
# into the margin.
#
# usage: check_report_pdf.sh SOURCE_DIR              check REPORT.md
#        check_report_pdf.sh SOURCE_DIR --self-test  require the check to fail on two broken copies
#                                                    of REPORT.md: section 3 grown by a copy of its
#                                                    own text (the page budget), and an overlong
#                                                    unbreakable code span in section 3 (the width)
# exit 0: the shape holds (or, --self-test, both broken copies fail as they should); 1: a tool is
# missing or the render failed; 3: the shape does not hold.
set -euo pipefail

root=$1
mode=${2:-check}
for tool in pandoc pdflatex pdfinfo pdftotext pdfimages; do
  command -v "$tool" > /dev/null || {
    echo "FAIL: $tool not found. The report test needs pandoc, texlive-latex-base, texlive-latex-recommended, lmodern and poppler-utils: run .ci/setup" >&2
    exit 1
  }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

max_pages=5
max_overfull_pt=1.0  # pdflatex reports a line this much wider than the text as overfull [pt]
max_ppi=200          # an image placed smaller than this would print its plot's fonts below 10 pt

render() {  # render INPUT.md NAME: $work/NAME.pdf and pdflatex's log $work/NAME.log
  bash "$root/bench/make_pdf.sh" "$1" "$work/$2.pdf" "$work/$2.log" > "$work/$2.render" 2>&1 || {
    cat "$work/$2.render" >&2
    echo "FAIL: bench/make_pdf.sh could not render $1" >&2
    exit 1
  }
}

check() {  # check NAME: prints every violation; returns 3 if there is one
  local pdf=$work/$1.pdf log=$work/$1.log bad=0 pages size
  pages=$(pdfinfo "$pdf" | awk '/^Pages:/ {print $2}')
  size=$(pdfinfo "$pdf" | grep '^Page size:')
  case $size in
    *"(A4)"*) ;;
    *) echo "page size is not A4: $size"; bad=1 ;;
  esac
  if [ "$pages" -gt $max_pages ]; then
    echo "$pages pages: the seed asks for about 4-5 (at most $max_pages here, one for each section)"; bad=1
  fi
  # heading (a line of its own in pdftotext's output) and the page it must start on; 0: nowhere
  local expected=("rbsim — report:1" "1 Particle systems:1" "2 Rigid body unconstrained motion:2"
                  "3 Broad phase:3" "4 Narrow phase:4" "5 Contact modelling and collision response:5"
                  "Extensions:0")
  local texts=() page
  for ((page = 1; page <= pages; page++)); do
    # The page's text first, then the search: piped into grep -q, which exits at the first match,
    # pdftotext could die of SIGPIPE while still writing, and pipefail then failed the match.
    texts[page]=$(pdftotext -f "$page" -l "$page" "$pdf" -)
  done
  for entry in "${expected[@]}"; do
    local heading=${entry%:*} want=${entry##*:} found=""
    for ((page = 1; page <= pages; page++)); do
      if grep -qxF "$heading" <<< "${texts[page]}"; then found=$page; break; fi
    done
    if [ "$want" = 0 ]; then
      if [ -n "$found" ]; then
        echo "heading \"$heading\" is on page $found: it belongs in docs/, not in the report"; bad=1
      else
        echo "ok: no \"$heading\" heading"
      fi
    elif [ -z "$found" ]; then
      echo "heading \"$heading\" is not in the PDF"; bad=1
    elif [ "$found" != "$want" ]; then
      echo "\"$heading\" starts on page $found, expected page $want (each of sections 1-5 has one page)"; bad=1
    else
      echo "ok: \"$heading\" on page $found"
    fi
  done
  # One plot per section's page, none shrunk below the size it was drawn for.
  local images
  images=$(pdfimages -list "$pdf" | awk 'NR > 2')
  for ((page = 1; page <= pages && page <= max_pages; page++)); do
    local count
    count=$(awk -v p="$page" '$1 == p' <<< "$images" | wc -l)
    [ "$count" = 1 ] || { echo "page $page has $count images, expected one plot"; bad=1; }
  done
  while read -r page x_ppi; do
    [ -n "$page" ] || continue
    if awk -v a="$x_ppi" -v b=$max_ppi 'BEGIN { exit !(a > b + 0.5) }'; then
      echo "an image on page $page is placed at $x_ppi pixels per inch, more than $max_ppi: its text prints too small"; bad=1
    fi
  done < <(awk '{print $1, $13}' <<< "$images")
  # Nothing wider than the text: "Overfull \hbox (12.3pt too wide) in paragraph at lines 80--84",
  # followed by the start of the line's text.
  local overfull
  overfull=$(awk -v max=$max_overfull_pt '
    /^Overfull \\hbox \(/ { width = $3; sub(/^\(/, "", width); sub(/pt$/, "", width)
                            if (width + 0 > max) { print; getline; print "    " $0 } }' "$log")
  if [ -n "$overfull" ]; then
    echo "text runs off the margin (pdflatex's overfull lines wider than $max_overfull_pt pt; line numbers of the LaTeX pandoc made of the report):"
    echo "$overfull"
    bad=1
  else
    echo "ok: nothing wider than the text (no overfull line over $max_overfull_pt pt)"
  fi
  echo "$pages pages, $size"
  return $(( bad ? 3 : 0 ))
}

if [ "$mode" = --self-test ]; then
  # 1. Section 3's paragraphs again before section 4: about two thirds of a page more.
  # 2. An unbreakable code span of 120 characters in section 3, which no line can hold.
  python3 - "$root/REPORT.md" "$work/grown.md" "$work/wide.md" <<'PY'
import sys
text = open(sys.argv[1]).read()
start, end = text.index("\n## 3 Broad phase\n"), text.index("\n## 4 Narrow phase\n")
section = text[start:end].split("\n", 2)[2]
open(sys.argv[2], "w").write(text[:end] + "\n" + section + text[end:])
anchor = text.index("\n**Method.**", start) + 1
wide = "`build/bench/" + "x" * 120 + "` runs the benchmark.\n\n"
open(sys.argv[3], "w").write(text[:anchor] + wide + text[anchor:])
PY
  failed=0
  for case in grown:"starts on page" wide:"runs off the margin"; do
    name=${case%%:*} symptom=${case#*:}
    render "$work/$name.md" "$name"
    if check "$name" > "$work/$name.check"; then
      cat "$work/$name.check"
      echo "FAIL: the broken copy \"$name\" of REPORT.md passed the check" >&2
      failed=1
    elif ! grep -q "$symptom" "$work/$name.check"; then
      cat "$work/$name.check"
      echo "FAIL: the broken copy \"$name\" failed the check, but not with \"$symptom\"" >&2
      failed=1
    else
      grep "$symptom" -A2 "$work/$name.check" | head -3
      echo "ok: the broken copy \"$name\" fails the check (\"$symptom\")"
    fi
  done
  [ $failed = 0 ] || exit 3
else
  render "$root/REPORT.md" report
  check report || { echo "FAIL: REPORT.pdf is not in the seed's shape (see above)" >&2; exit 3; }
fi
