"""Rewrites the generated blocks of REPORT.md and docs/*.md from the CSVs of bench/results/ (issue 11).

usage: python3 bench/report/fill_report.py RESULTS_DIR FILE.md [FILE.md ...]

A block is the text between `<!-- fig:NAME -->` and `<!-- /fig:NAME -->`; its content is replaced
by what figures.FIGURES[NAME] makes of the CSVs. The blocks may sit in any of the files (issue 26
moved the long tables from REPORT.md to docs/); every figure must have a block in one of them. A
block whose data is missing stops the script (exit 1) and no file is changed, except the blocks of
figures.OPTIONAL, whose CSVs other work produces: those are replaced by a notice saying the CSV
does not exist yet, with a warning. A marker without a figure, a block opened and never closed, or a
figure without a marker is an error too.
"""
import re
import sys

import figures
from results import MissingData

BLOCK = re.compile(r"(<!-- fig:([a-z0-9_]+) -->\n)(.*?)(<!-- /fig:\2 -->)", re.S)


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: fill_report.py RESULTS_DIR FILE.md [FILE.md ...]")
    results, paths = sys.argv[1], sys.argv[2:]
    seen, errors, new_texts = set(), [], {}
    for path in paths:
        with open(path) as f:
            text = f.read()
        opened = set(re.findall(r"<!-- fig:([a-z0-9_]+) -->", text))
        seen_here = set()

        def fill(match, path=path, seen_here=seen_here):
            name = match.group(2)
            seen_here.add(name)
            make = figures.FIGURES.get(name)
            if make is None:
                errors.append("%s has a block fig:%s that no figure fills" % (path, name))
                return match.group(0)
            try:
                body = make(results)
            except MissingData as missing:
                if name not in figures.OPTIONAL:
                    errors.append("%s: fig:%s: %s" % (path, name, missing))
                    return match.group(0)
                print("fill_report.py: WARNING: fig:%s skipped: %s" % (name, missing), file=sys.stderr)
                body = "*Not generated yet: %s. `bash bench/make_report.sh` fills this block once it exists.*" % missing
            return match.group(1) + body.rstrip("\n") + "\n" + match.group(4)

        new_texts[path] = BLOCK.sub(fill, text)
        for name in sorted(opened - seen_here):
            errors.append("%s: fig:%s is opened but never closed" % (path, name))
        seen |= seen_here
    for name in sorted(set(figures.FIGURES) - seen):
        errors.append("figure %s has no block in %s" % (name, " ".join(paths)))
    if errors:
        sys.exit("fill_report.py: no file changed:\n  " + "\n  ".join(errors))
    for path, text in new_texts.items():
        with open(path, "w") as f:
            f.write(text)
    print("fill_report.py: filled %d blocks: %s" % (len(seen), " ".join(sorted(seen))))


if __name__ == "__main__":
    main()
