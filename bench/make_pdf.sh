#!/bin/bash
# Renders REPORT.md to REPORT.pdf (issues 26, 36) with Debian's pandoc and pdflatex
# (texlive-latex-base, texlive-latex-recommended; .ci/setup installs them). A4, 10 pt; the
# introduction and section 1 share page 1 and every later "## " section starts a new page
# (bench/report/pdf_layout.lua), so sections 1-5 of the seed's report are one page each; plots are
# placed at 200 pixels per inch, the size bench/report/plots.gp drew them for; the $...$ formulas are
# TeX and pdflatex sets them natively. Images resolve against the repository and the input's folder.
# pandoc writes LaTeX and pdflatex is run here (not through `pandoc --to pdf`), so that its log can be
# kept: tests/report/check_report_pdf.sh reads it for lines that run off the margin ("Overfull
# \hbox"), which this script also counts and warns about.
#
# usage: bash bench/make_pdf.sh [INPUT.md [OUTPUT.pdf [LOG]]]   (default REPORT.md -> REPORT.pdf;
#        LOG: where to keep pdflatex's log of its last run)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
input=${1:-$root/REPORT.md}
output=${2:-$root/REPORT.pdf}
for tool in pandoc pdflatex; do
  command -v "$tool" > /dev/null || {
    echo "make_pdf.sh: $tool not found; install the packages of .ci/setup (pandoc texlive-latex-base texlive-latex-recommended)" >&2
    exit 1
  }
done

# pdflatex's auxiliary files go to a temporary folder, not beside the report.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# SOURCE_DATE_EPOCH pins the PDF's dates to the input's commit time, so an unchanged report gives the same PDF.
export SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-$(git -C "$root" log -1 --format=%ct 2>/dev/null || echo 0)}
pandoc "$input" --from markdown-implicit_figures --to latex --standalone \
  --resource-path="$root:$(dirname "$input")" --lua-filter="$root/bench/report/pdf_layout.lua" \
  -V papersize=a4 -V geometry:margin=2cm -V fontsize=10pt -V colorlinks=true \
  -V pagestyle=plain --metadata pagetitle="rbsim report" -o "$work/report.tex"
# The images' paths are relative to the repository (or to the input's folder): pdflatex searches both.
export TEXINPUTS="$root/:$(cd "$(dirname "$input")" && pwd)/:${TEXINPUTS:-}"
# Run again while LaTeX asks for it (hyperref's PDF outline needs a second run), at most three times.
for run in 1 2 3; do
  (cd "$work" && pdflatex -interaction=nonstopmode -halt-on-error report.tex > /dev/null 2>&1) || {
    grep -A5 '^!' "$work/report.log" >&2 || tail -20 "$work/report.log" >&2
    echo "make_pdf.sh: pdflatex failed on $input (its log above)" >&2
    exit 1
  }
  grep -q 'Rerun to get' "$work/report.log" || break
done
[ -z "${3:-}" ] || cp "$work/report.log" "$3"
mv "$work/report.pdf" "$output"
echo "make_pdf.sh: wrote $output ($(pdfinfo "$output" 2>/dev/null | awk '/^Pages:/ {print $2}') pages)"
overfull=$(grep -c '^Overfull \\hbox' "$work/report.log" || true)
if [ "$overfull" -gt 0 ]; then
  echo "make_pdf.sh: WARNING: $overfull line(s) wider than the text (pdflatex's \"Overfull \\hbox\"):" >&2
  grep -A1 '^Overfull \\hbox' "$work/report.log" | grep -v '^--$' >&2
fi
