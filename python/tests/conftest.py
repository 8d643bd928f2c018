"""Shared set-up: the repository's top folder (every test runs there, as the tool's examples do)
and the tool the bindings are held against ($HS_TOOL, default build/handspring)."""

import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
TOOL = Path(os.environ.get("HS_TOOL", REPO / "build" / "handspring")).resolve()


def catalog():
    """Every catalog scenario, as a path relative to the top folder."""
    return sorted(str(p.relative_to(REPO)) for p in (REPO / "scenarios").rglob("*.yaml")
                  if not any(part.startswith(".") for part in p.relative_to(REPO).parts))


def tool(*args):
    """Runs the tool from the top folder: CompletedProcess with text stdout and stderr."""
    return subprocess.run([str(TOOL), *map(str, args)], cwd=REPO, capture_output=True, text=True)


@pytest.fixture(autouse=True)
def at_top(monkeypatch):
    monkeypatch.chdir(REPO)
