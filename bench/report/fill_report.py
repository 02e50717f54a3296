"""Rewrites the generated blocks of REPORT.md from the CSVs of bench/results/ (issue 11).

usage: python3 bench/report/fill_report.py REPORT.md RESULTS_DIR

A block is the text between `<!-- fig:NAME -->` and `<!-- /fig:NAME -->`; its content is replaced
by what figures.FIGURES[NAME] makes of the CSVs. A block whose data is missing stops the script
(exit 1) and REPORT.md is left untouched, except the blocks of figures.OPTIONAL, whose CSVs other
work produces: those are replaced by a notice saying the CSV does not exist yet, with a warning.
A marker without a figure, or a figure without a marker, is an error too.
"""
import re
import sys

import figures
from results import MissingData

BLOCK = re.compile(r"(<!-- fig:([a-z0-9_]+) -->\n)(.*?)(<!-- /fig:\2 -->)", re.S)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: fill_report.py REPORT.md RESULTS_DIR")
    report_path, results = sys.argv[1:]
    with open(report_path) as f:
        text = f.read()
    opened = set(re.findall(r"<!-- fig:([a-z0-9_]+) -->", text))
    seen, errors = set(), []

    def fill(match):
        name = match.group(2)
        seen.add(name)
        make = figures.FIGURES.get(name)
        if make is None:
            errors.append("REPORT.md has a block fig:%s that no figure fills" % name)
            return match.group(0)
        try:
            body = make(results)
        except MissingData as missing:
            if name not in figures.OPTIONAL:
                errors.append("fig:%s: %s" % (name, missing))
                return match.group(0)
            print("fill_report.py: WARNING: fig:%s skipped: %s" % (name, missing), file=sys.stderr)
            body = "*Not generated yet: %s. `bash bench/make_report.sh` fills this block once it exists.*" % missing
        return match.group(1) + body.rstrip("\n") + "\n" + match.group(4)

    new_text = BLOCK.sub(fill, text)
    for name in sorted(opened - seen):
        errors.append("fig:%s is opened but never closed" % name)
    for name in sorted(set(figures.FIGURES) - opened):
        errors.append("figure %s has no block in REPORT.md" % name)
    if errors:
        sys.exit("fill_report.py: REPORT.md not changed:\n  " + "\n  ".join(errors))
    with open(report_path, "w") as f:
        f.write(new_text)
    print("fill_report.py: filled %d blocks: %s" % (len(seen), " ".join(sorted(seen))))


if __name__ == "__main__":
    main()
