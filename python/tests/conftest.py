"""Shared fixtures: the repository's scenes and, where it is built, the mdrsim command."""

import os
import shutil
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SCENES = ROOT / "scenes"


def cli_path():
    """The mdrsim command to compare with: $MDRSIM_CLI, else build/apps/mdrsim, else PATH."""
    for candidate in (os.environ.get("MDRSIM_CLI"), ROOT / "build" / "apps" / "mdrsim",
                      shutil.which("mdrsim")):
        if candidate and Path(candidate).is_file() and os.access(candidate, os.X_OK):
            return str(candidate)
    return None


@pytest.fixture
def cli():
    path = cli_path()
    if path is None:
        pytest.skip("the mdrsim command is not built (set MDRSIM_CLI)")
    return path


@pytest.fixture(autouse=True)
def at_repository_root(monkeypatch):
    """Scene paths in messages are the ones given: run from the repository root as the
    command line examples do."""
    monkeypatch.chdir(ROOT)
