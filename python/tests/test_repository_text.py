"""What the example scenes' comments and docs/friction.md cite: files the repository has, and
no issue numbers (what a scene shows is said in words; its history is in git)."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SCENES = sorted((ROOT / "scenes").rglob("*.toml"))
# A repository path: one of the source folders, then a path (a module may omit .cpp/.hpp).
PATH = re.compile(r"(?<![\w/.])((?:engine|tests|scripts|python|docs|bench|examples|apps|profiles|"
                  r"detachment|controllers|friction)/[\w./-]*[\w/])")


def comments(path):
    return [line for line in path.read_text().splitlines() if line.lstrip().startswith("#")]


def missing(paths):
    return [p for p in paths
            if not any((ROOT / (p + ext)).exists() for ext in ("", ".cpp", ".hpp", ".py"))]


def test_scene_comments_cite_no_issue_numbers():
    cited = [f"{scene.relative_to(ROOT)}: {line}" for scene in SCENES for line in comments(scene)
             if re.search(r"\bissues? \d", line, re.IGNORECASE)]
    assert cited == []


def test_scene_comments_and_friction_docs_cite_files_that_exist():
    assert len(SCENES) > 30
    cited = {p for scene in SCENES for line in comments(scene) for p in PATH.findall(line)}
    # docs/friction.md: its paths in backticks; results/ and build/ are what the main job and
    # a build write, not the repository's.
    cited |= {p for code in re.findall(r"`([^`]*)`", (ROOT / "docs" / "friction.md").read_text())
              for p in PATH.findall(code)}
    assert "engine/reference/branch_reference" in cited
    assert missing(cited) == []
