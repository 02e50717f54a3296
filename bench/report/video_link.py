"""Points the report's video line at the uploaded reel (issue 26; seed 004 asks for "a link to
YouTube video").

usage: python3 bench/report/video_link.py URL_FILE REPORT.md [PAGE.md ...]

In each Markdown file, the line `Video: [rbsim-demos](TARGET)` gets as TARGET the URL in URL_FILE
(bench/video_url.txt: its first line that is neither blank nor a `#` comment) or, while there is
none (nothing uploaded yet), the local reel videos/rbsim-demos.mp4, relative to that file. The line
is found and rewritten the way fill_report.py rewrites its `<!-- fig:NAME -->` blocks: one regular
expression over the whole text, the file written only if every check passed. A file without the
line is left alone; if no file has it, a note says so (exit 0). A URL that is not http(s), or that
holds a space or a parenthesis (it would end the Markdown link early), is refused (exit 1) and
nothing is written.
"""
import os
import re
import sys

LINE = re.compile(r"^(Video: \[rbsim-demos\]\()([^()\s]*)(\))[ \t]*$", re.M)
URL = re.compile(r"^https?://[^\s()<>]+$")
REEL = "videos/rbsim-demos.mp4"


def read_url(path):
    """The URL in path, or "" when it holds none (or does not exist)."""
    if not os.path.exists(path):
        return ""
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line and not line.startswith("#"):
                if not URL.match(line):
                    raise ValueError("%s: %r is not an http(s) URL without spaces or parentheses" % (path, line))
                return line
    return ""


def target_for(md_path, url, root):
    """What the link in md_path points at: the URL, else the reel relative to md_path's folder."""
    if url:
        return url
    folder = os.path.dirname(os.path.abspath(md_path))
    return os.path.relpath(os.path.join(root, REEL), folder).replace(os.sep, "/")


def rewrite(text, target):
    """(new text, number of video lines rewritten)."""
    return LINE.subn(lambda m: m.group(1) + target + m.group(3), text)


def main(argv):
    if len(argv) < 3:
        sys.exit("usage: video_link.py URL_FILE REPORT.md [PAGE.md ...]")
    url_file, pages = argv[1], argv[2:]
    root = os.path.dirname(os.path.dirname(os.path.abspath(url_file)))  # bench/video_url.txt -> the repository
    try:
        url = read_url(url_file)
    except ValueError as bad:
        sys.exit("video_link.py: nothing changed: %s" % bad)
    changed = []
    for page in pages:
        with open(page) as f:
            text = f.read()
        target = target_for(page, url, root)
        new_text, count = rewrite(text, target)
        if count == 0:
            continue
        changed.append("%s -> %s" % (page, target))
        if new_text != text:
            with open(page, "w") as f:
                f.write(new_text)
    if not changed:
        print("video_link.py: note: no line `Video: [rbsim-demos](...)` in %s; no video link written" % " ".join(pages))
    else:
        print("video_link.py: video line%s: %s (%s)" % ("s" if len(changed) > 1 else "", "; ".join(changed),
                                                        "uploaded URL from " + url_file if url else
                                                        "no URL in %s yet: the local reel" % url_file))


if __name__ == "__main__":
    main(sys.argv)
