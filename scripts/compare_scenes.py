#!/usr/bin/env python3
"""Runs every scene under scenes/ (all its folders) with two mdrsim builds and compares the JSON.

    python3 scripts/compare_scenes.py BEFORE_MDRSIM AFTER_MDRSIM [OUT_DIR] [--accuracy] [--added PATH]...

Each scene runs as `mdrsim run SCENE --json OUT --log-level off` (with --accuracy also with
`--set discretization.extrapolation=richardson` and with `--set discretization.rtol=1e-4
--set solver.method="event"`, the routes that combine rows); the fields that time the run
(wall_time_s, ...) are dropped (a program's clock, `time`, `start_time`, `end_time`, is kept), everything else must be equal exactly (floats bit for
bit). `--added PATH` (repeatable) lets the JSON path PATH (e.g. $.scene.solver.max_events) be
added by AFTER: a key a newer build records, and nothing else, is then no difference. Prints one
line per scene (same / DIFFERENT with the differing JSON paths) and exits 1 if
any scene differs or fails in one build only.
"""
import json
import pathlib
import subprocess
import sys


# The run's own timing, which no two runs share; every other field is a number of the model.
WALL_CLOCK_KEYS = {"wall_time_s"}


def strip_time(value):
    if isinstance(value, dict):
        return {k: strip_time(v) for k, v in value.items() if k not in WALL_CLOCK_KEYS}
    if isinstance(value, list):
        return [strip_time(v) for v in value]
    return value


def differences(a, b, path="$"):
    if type(a) is not type(b):
        return [path]
    if isinstance(a, dict):
        out = []
        for key in sorted(set(a) | set(b)):
            if key not in a or key not in b:
                out.append(f"{path}.{key} ({'added' if key not in a else 'removed'})")
            else:
                out += differences(a[key], b[key], f"{path}.{key}")
        return out
    if isinstance(a, list):
        if len(a) != len(b):
            return [f"{path} (length {len(a)} -> {len(b)})"]
        out = []
        for i, (x, y) in enumerate(zip(a, b)):
            out += differences(x, y, f"{path}[{i}]")
        return out
    return [] if a == b else [f"{path} ({a!r} -> {b!r})"]


VARIANTS = {
    "row": [],
    "richardson": ["--set", "discretization.extrapolation=richardson"],
    # method = "event": the row's rtol (rtol alone takes the continuum route on the shorthand).
    "rtol": ["--set", "discretization.rtol=1e-4", "--set", 'solver.method="event"'],
}


def run(mdrsim, scene, out, extra):
    proc = subprocess.run([mdrsim, "run", str(scene), "--json", str(out), "--log-level", "off"] +
                          extra, capture_output=True, text=True)
    if not out.exists():
        return proc.returncode, None
    return proc.returncode, strip_time(json.loads(out.read_text()))


def main():
    argv = sys.argv[1:]
    added_ok = set()
    while "--added" in argv:
        i = argv.index("--added")
        added_ok.add(argv[i + 1])
        del argv[i:i + 2]
    args = [a for a in argv if a != "--accuracy"]
    variants = list(VARIANTS) if "--accuracy" in sys.argv else ["row"]
    if len(args) < 2:
        sys.exit(__doc__)
    before, after = args[0], args[1]
    out_dir = pathlib.Path(args[2] if len(args) > 2 else "compare_scenes_out")
    out_dir.mkdir(parents=True, exist_ok=True)
    root = pathlib.Path(__file__).resolve().parent.parent
    scenes = sorted((root / "scenes").rglob("*.toml"))
    failed = 0
    runs = 0
    for scene in scenes:
        for variant in variants:
            runs += 1
            name = scene.relative_to(root / "scenes").as_posix().replace("/", "_") + "_" + variant
            label = f"{scene.relative_to(root)} [{variant}]"
            code_a, a = run(before, scene, out_dir / f"before_{name}.json", VARIANTS[variant])
            code_b, b = run(after, scene, out_dir / f"after_{name}.json", VARIANTS[variant])
            if code_a != code_b:
                print(f"DIFFERENT {label}: exit {code_a} -> {code_b}")
                failed += 1
            elif a is None:
                print(f"same      {label} (no JSON, exit {code_a})")
            elif a == b or not [d for d in differences(a, b)
                                if d.split(" (")[0] not in added_ok or "(added)" not in d]:
                print(f"same      {label}" + ("" if a == b else " (but the keys --added allows)"))
            else:
                failed += 1
                diff = differences(a, b)
                print(f"DIFFERENT {label}: {len(diff)} fields")
                for d in diff[:12]:
                    print(f"    {d}")
                if len(diff) > 12:
                    print(f"    ... {len(diff) - 12} more")
    print(f"{runs} runs of {len(scenes)} scenes, {failed} different")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
