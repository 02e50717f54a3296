#!/bin/bash
# Renders REPORT.md with bench/make_pdf.sh into a temporary folder and checks the seed's shape
# (issue 26): A4 pages, the introduction on page 1, sections 1-5 each on exactly one page (pages
# 2-6, since every section starts a new page) and the extensions from page 7, so a section that
# grows past its page moves every later heading and fails the check.
#
# usage: check_report_pdf.sh SOURCE_DIR              check REPORT.md
#        check_report_pdf.sh SOURCE_DIR --self-test  grow section 3 by a copy of its own text and
#                                                    require the check to fail on the page budget
# exit 0: the shape holds; 1: a tool is missing or the render failed; 3: the shape does not hold.
set -euo pipefail

root=$1
mode=${2:-check}
for tool in pandoc pdflatex pdfinfo pdftotext; do
  command -v "$tool" > /dev/null || {
    echo "FAIL: $tool not found. The report test needs pandoc, texlive-latex-base, texlive-latex-recommended, lmodern and poppler-utils: run .ci/setup" >&2
    exit 1
  }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

input=$root/REPORT.md
if [ "$mode" = --self-test ]; then
  # Section 3's paragraphs again before section 4: about two thirds of a page more.
  python3 - "$input" "$work/REPORT.md" <<'PY'
import sys
text = open(sys.argv[1]).read()
start, end = text.index("\n## 3 Broad phase\n"), text.index("\n## 4 Narrow phase\n")
section = text[start:end].split("\n", 2)[2]
open(sys.argv[2], "w").write(text[:end] + "\n" + section + text[end:])
PY
  input=$work/REPORT.md
fi

bash "$root/bench/make_pdf.sh" "$input" "$work/REPORT.pdf" > "$work/render.log" 2>&1 || {
  cat "$work/render.log" >&2
  echo "FAIL: bench/make_pdf.sh could not render $input" >&2
  exit 1
}

check() {  # prints every violation; returns 3 if there is one
  local pdf=$1 bad=0 pages size
  pages=$(pdfinfo "$pdf" | awk '/^Pages:/ {print $2}')
  size=$(pdfinfo "$pdf" | grep '^Page size:')
  case $size in
    *"(A4)"*) ;;
    *) echo "page size is not A4: $size"; bad=1 ;;
  esac
  # heading (a line of its own in pdftotext's output) and the page it must start on
  local expected=("rbsim — report:1" "1 Particle systems:2" "2 Rigid body unconstrained motion:3"
                  "3 Broad phase:4" "4 Narrow phase:5" "5 Contact modelling and collision response:6"
                  "Extensions:7")
  for entry in "${expected[@]}"; do
    local heading=${entry%:*} want=${entry##*:} found=""
    for ((page = 1; page <= pages; page++)); do
      # The page's text first, then the search: piped into grep -q, which exits at the first match,
      # pdftotext could die of SIGPIPE while still writing, and pipefail then failed the match.
      local text
      text=$(pdftotext -f "$page" -l "$page" "$pdf" -)
      if grep -qxF "$heading" <<< "$text"; then found=$page; break; fi
    done
    if [ -z "$found" ]; then
      echo "heading \"$heading\" is not in the PDF"; bad=1
    elif [ "$found" != "$want" ]; then
      echo "\"$heading\" starts on page $found, expected page $want (each of sections 1-5 has one page)"; bad=1
    else
      echo "ok: \"$heading\" on page $found"
    fi
  done
  echo "$pages pages, $size"
  return $(( bad ? 3 : 0 ))
}

if [ "$mode" = --self-test ]; then
  if check "$work/REPORT.pdf" > "$work/check.log"; then
    cat "$work/check.log"
    echo "FAIL: section 3 grown by a copy of itself still passed the page budget check" >&2
    exit 3
  fi
  grep -q 'starts on page' "$work/check.log" || { cat "$work/check.log"; echo "FAIL: the check failed, but not on the page budget" >&2; exit 3; }
  cat "$work/check.log"
  echo "ok: the grown section 3 fails the page budget"
else
  check "$work/REPORT.pdf" || { echo "FAIL: REPORT.pdf is not in the seed's shape (see above)" >&2; exit 3; }
fi
