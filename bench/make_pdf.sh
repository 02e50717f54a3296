#!/bin/bash
# Renders REPORT.md to REPORT.pdf (issue 26) with Debian's pandoc and pdflatex (texlive-latex-base,
# texlive-latex-recommended; .ci/setup installs them). A4, 10 pt; each "## " section starts a new
# page (bench/report/pdf_layout.lua), so sections 1-5 of the seed's report are one page each; the
# $...$ formulas are TeX and pdflatex sets them natively. Images resolve against the repository.
#
# usage: bash bench/make_pdf.sh [INPUT.md [OUTPUT.pdf]]   (default REPORT.md -> REPORT.pdf)
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
pandoc "$input" --from markdown-implicit_figures --to pdf --pdf-engine=pdflatex \
  --resource-path="$root:$(dirname "$input")" --lua-filter="$root/bench/report/pdf_layout.lua" \
  -V papersize=a4 -V geometry:margin=2cm -V fontsize=10pt -V colorlinks=true \
  -V pagestyle=plain --metadata pagetitle="rbsim report" \
  --pdf-engine-opt=-output-directory="$work" -o "$work/out.pdf"
mv "$work/out.pdf" "$output"
echo "make_pdf.sh: wrote $output ($(pdfinfo "$output" 2>/dev/null | awk '/^Pages:/ {print $2}') pages)"
