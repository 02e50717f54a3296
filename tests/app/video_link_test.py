"""bench/report/video_link.py (issue 26): the report's `Video: [rbsim-demos](...)` line links the
URL in bench/video_url.txt, or the local reel while there is none; no line, no change.

usage: python3 tests/app/video_link_test.py REPO_ROOT
"""
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.getcwd()
SCRIPT = os.path.join(ROOT, "bench", "report", "video_link.py")
HEAD = "# Report\n\nSome text.\n\n"
TAIL = "\nMore text, and `Video: [rbsim-demos](x)` quoted inside a line stays.\n"


class VideoLink(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name
        os.makedirs(os.path.join(self.root, "bench"))
        os.makedirs(os.path.join(self.root, "docs"))
        self.url_file = os.path.join(self.root, "bench", "video_url.txt")
        self.report = os.path.join(self.root, "REPORT.md")
        self.page = os.path.join(self.root, "docs", "video.md")

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, path, text):
        with open(path, "w") as f:
            f.write(text)

    def read(self, path):
        with open(path) as f:
            return f.read()

    def run_script(self, *pages):
        return subprocess.run([sys.executable, SCRIPT, self.url_file] + list(pages), capture_output=True, text=True)

    def test_url_replaces_the_placeholder_and_a_later_url_replaces_that(self):
        self.write(self.url_file, "# comment\n\nhttps://youtu.be/abc123\n")
        self.write(self.report, HEAD + "Video: [rbsim-demos](VIDEO_URL)\n" + TAIL)
        result = self.run_script(self.report)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(self.read(self.report), HEAD + "Video: [rbsim-demos](https://youtu.be/abc123)\n" + TAIL)
        self.write(self.url_file, "https://www.youtube.com/watch?v=xyz&t=0\n")
        self.assertEqual(self.run_script(self.report).returncode, 0)
        self.assertEqual(self.read(self.report),
                         HEAD + "Video: [rbsim-demos](https://www.youtube.com/watch?v=xyz&t=0)\n" + TAIL)

    def test_no_url_links_the_local_reel_relative_to_each_page(self):
        self.write(self.url_file, "# nothing uploaded yet\n")
        self.write(self.report, HEAD + "Video: [rbsim-demos](VIDEO_URL)\n" + TAIL)
        self.write(self.page, "Video: [rbsim-demos](https://youtu.be/old)\n")
        result = self.run_script(self.report, self.page)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(self.read(self.report), HEAD + "Video: [rbsim-demos](videos/rbsim-demos.mp4)\n" + TAIL)
        self.assertEqual(self.read(self.page), "Video: [rbsim-demos](../videos/rbsim-demos.mp4)\n")
        self.assertIn("local reel", result.stdout)

    def test_without_the_line_nothing_changes_and_a_note_says_so(self):
        self.write(self.url_file, "https://youtu.be/abc123\n")
        self.write(self.report, HEAD + TAIL)
        result = self.run_script(self.report)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(self.read(self.report), HEAD + TAIL)
        self.assertIn("note: no line", result.stdout)

    def test_a_url_that_would_break_the_link_is_refused(self):
        self.write(self.report, HEAD + "Video: [rbsim-demos](VIDEO_URL)\n" + TAIL)
        for bad in ["youtu.be/abc", "https://youtu.be/a b", "https://youtu.be/a)b", "ftp://x/y"]:
            self.write(self.url_file, bad + "\n")
            result = self.run_script(self.report)
            self.assertEqual(result.returncode, 1, bad)
            self.assertIn("nothing changed", result.stderr)
            self.assertEqual(self.read(self.report), HEAD + "Video: [rbsim-demos](VIDEO_URL)\n" + TAIL)


if __name__ == "__main__":
    unittest.main()
