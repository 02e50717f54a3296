"""The examples in examples/python run, each in its own folder, and write their PNG."""
import subprocess
import sys

import matplotlib.image as mpimg
import pytest

from conftest import SOURCE

EXAMPLES = sorted((SOURCE / "examples" / "python").glob("*.py"))


def test_there_are_examples():
    assert {p.stem for p in EXAMPLES} >= {"dzhanibekov", "restitution_sweep", "falling_stack"}


@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.stem)
def test_example_runs_and_writes_its_png(example, tmp_path):
    done = subprocess.run([sys.executable, str(example), "--out", str(tmp_path)], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    png = tmp_path / f"{example.stem}.png"
    assert png.is_file(), done.stdout
    image = mpimg.imread(png)
    assert image.shape[0] > 300 and image.shape[1] > 600
    assert image[..., :3].std() > 0.05  # a plot, not a blank page


def test_readme_example_runs_and_prints_the_free_fall(tmp_path):
    text = (SOURCE / "README.md").read_text()
    code = text.split("```python\n", 1)[1].split("```", 1)[0]
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["[0.5", "0.77375", "0.", "]"]
    assert (tmp_path / "videos" / "ball.mp4").stat().st_size > 0


def test_first_contact_closes_in_on_the_free_fall_time(tmp_path):
    """examples/python/first_contact.py: each rewind with an 8 times finer step brackets t* =
    sqrt(2 gap / g) closer, the last within a step of it (the solver may push a step early)."""
    import re
    done = subprocess.run([sys.executable, str(SOURCE / "examples" / "python" / "first_contact.py"), "--out",
                           str(tmp_path)], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    predicted = float(re.search(r"t\* = ([0-9.]+) s", done.stdout).group(1))
    brackets = [(float(a), float(b)) for a, b in re.findall(r"step \[([0-9.]+), ([0-9.]+)\]", done.stdout)]
    assert len(brackets) == 4
    gaps = [predicted - start for start, _ in brackets]
    assert all(g > 0 for g in gaps) and all(b < a for a, b in zip(gaps, gaps[1:]))
    start, end = brackets[-1]
    assert start <= predicted <= end + (end - start)
    assert re.search(r"exact: kinetic energy ([0-9.]+) J -> \1 J", done.stdout)  # the saved state replays alike
