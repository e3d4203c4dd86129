"""The type stubs (__init__.pyi, py.typed) are installed and name what the package has."""

import ast
from pathlib import Path

import mdrsim

PACKAGE = Path(mdrsim.__file__).parent


def stub():
    return ast.parse((PACKAGE / "__init__.pyi").read_text())


def test_stubs_and_py_typed_are_installed_with_the_package():
    assert (PACKAGE / "py.typed").is_file()
    assert (PACKAGE / "__init__.pyi").is_file()


def test_stubs_name_every_public_name_and_nothing_else():
    tree = stub()
    named = {n.name for n in tree.body if isinstance(n, (ast.ClassDef, ast.FunctionDef))}
    named |= {t.id for n in tree.body if isinstance(n, ast.AnnAssign) for t in [n.target]}
    assert set(mdrsim.__all__) <= named
    internal = {"Trajectory", "__version__"}  # a TypedDict of the stubs; the version
    assert named - set(mdrsim.__all__) <= internal


def test_stub_classes_have_their_members_at_run_time():
    scene = mdrsim.Scene.from_file("scenes/fig2_fixed_load.toml")
    result = mdrsim.run(scene)
    instances = {"Scene": scene, "Result": result, "State": result.critical,
                 "StageEnd": result.stages[0], "Material": scene.material,
                 "Work": mdrsim.Work(0.0, 0.0), "Parameter": mdrsim.Parameter(),
                 "SweepResult": mdrsim.sweep(scene.set("discretization.springs", 200),
                                             {"material.poisson_ratio": [0.0]})}
    for node in stub().body:
        if not isinstance(node, ast.ClassDef) or node.name not in instances:
            continue
        for member in node.body:
            name = getattr(member, "name", None) or getattr(getattr(member, "target", None),
                                                             "id", None)
            if name and name != "__init__":
                assert hasattr(instances[node.name], name), f"{node.name}.{name}"
