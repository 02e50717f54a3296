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
