"""python/examples/first.py (the README's library example) runs and prints what the README shows."""

import subprocess
import sys

from conftest import REPO

EXAMPLE = REPO / "python" / "examples" / "first.py"
OUTPUT = """drop_cube: 6/6 expectations pass, rests at z = 0.0500 m
final hash fbbefe2f3ebe53fc
frame 40: contact [2] (2: grasp), replay identical: True
"""


def test_example_output():
    assert len(EXAMPLE.read_text().splitlines()) <= 15
    out = subprocess.run([sys.executable, str(EXAMPLE)], cwd=REPO, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout == OUTPUT


def test_readme_shows_the_example():
    readme = (REPO / "python" / "README.md").read_text()
    assert EXAMPLE.read_text() in readme and OUTPUT in readme
