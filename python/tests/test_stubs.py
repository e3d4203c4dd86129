"""The type stubs (__init__.pyi, py.typed) are installed and name what the package has."""

import __future__
import ast
import sys
import types
import typing
from pathlib import Path

import numpy as np

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


def stub_namespace(monkeypatch):
    """The stubs executed as a module, annotations left as text (they name classes defined
    later); typing_extensions, where it is not installed, is the standard typing of 3.11."""
    try:
        import typing_extensions  # noqa: F401
    except ImportError:
        monkeypatch.setitem(sys.modules, "typing_extensions", typing)
    namespace = {"__name__": "mdrsim_stubs"}
    source = (PACKAGE / "__init__.pyi").read_text()
    exec(compile(source, "__init__.pyi", "exec", flags=__future__.annotations.compiler_flag), namespace)
    return namespace


def short(value):
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def conforms(value, hint, namespace, path):
    """None where `value` is of the stub's type `hint`, else where and why not: lists, dicts
    and tuples item by item, a stub class member by member, a NumPy array by its dtype."""
    origin, args = typing.get_origin(hint), typing.get_args(hint)
    if hint is typing.Any:
        return None
    if hint is None or hint is type(None):
        return None if value is None else f"{path}: {short(value)} is not None"
    if origin in (typing.Union, types.UnionType):
        misses = [conforms(value, arg, namespace, path) for arg in args]
        return None if None in misses else "; ".join(misses)
    if origin is typing.Literal:
        return None if value in args else f"{path}: {short(value)} is not one of {args}"
    if origin is typing.NotRequired:
        return conforms(value, args[0], namespace, path)
    if origin is np.ndarray:
        dtype = typing.get_args(args[1])[0]
        if not isinstance(value, np.ndarray):
            return f"{path}: {type(value).__name__} is not an ndarray"
        return None if dtype is typing.Any or value.dtype == dtype else (
            f"{path}: dtype {value.dtype}, the stub says {dtype}")
    if origin is list:
        if not isinstance(value, list):
            return f"{path}: {type(value).__name__} is not a list"
        return next((m for i, v in enumerate(value)
                     if (m := conforms(v, args[0], namespace, f"{path}[{i}]"))), None)
    if origin is tuple:
        if not isinstance(value, tuple):
            return f"{path}: {type(value).__name__} is not a tuple"
        items = args[:1] * len(value) if args[1:] == (Ellipsis,) else args
        if len(items) != len(value):
            return f"{path}: {len(value)} items, the stub says {len(items)}"
        return next((m for i, (v, a) in enumerate(zip(value, items))
                     if (m := conforms(v, a, namespace, f"{path}[{i}]"))), None)
    if origin is dict:
        if not isinstance(value, dict):
            return f"{path}: {type(value).__name__} is not a dict"
        return next((m for k, v in value.items()
                     if (m := conforms(k, args[0], namespace, f"{path} key {k!r}")
                         or conforms(v, args[1], namespace, f"{path}[{k!r}]"))), None)
    if typing.is_typeddict(hint):
        if not isinstance(value, dict):
            return f"{path}: {type(value).__name__} is not a dict"
        hints = typing.get_type_hints(hint, namespace, include_extras=True)
        # Its text annotations hide NotRequired from __required_keys__: read it from each hint.
        required = {k for k, h in hints.items() if typing.get_origin(h) is not typing.NotRequired}
        missing = required - value.keys()
        if missing or value.keys() - hints.keys():
            return f"{path}: keys {sorted(value)}, the stub says {sorted(hints)}"
        return next((m for k, v in value.items()
                     if (m := conforms(v, hints[k], namespace, f"{path}[{k!r}]"))), None)
    if hint is float:  # PEP 484: an int is acceptable where a float is expected
        ok = isinstance(value, (float, int)) and not isinstance(value, bool)
        return None if ok else f"{path}: {short(value)} is not a float"
    if hint is int:
        ok = isinstance(value, int) and not isinstance(value, bool)
        return None if ok else f"{path}: {short(value)} is not an int"
    if namespace.get(hint.__name__) is hint:  # a class of the stubs: the runtime class by name
        if type(value).__name__ != hint.__name__:
            return f"{path}: {type(value).__name__} is not {hint.__name__}"
        return stub_class_mismatch(value, hint, namespace, path)
    return None if isinstance(value, hint) else f"{path}: {short(value)} is not {hint}"


def stub_class_mismatch(instance, stub_class, namespace, path):
    """The first member of `instance` (an annotated attribute or a property of the stub class)
    whose value is not of the stub's type."""
    members = dict(typing.get_type_hints(stub_class, namespace))
    for name, member in vars(stub_class).items():
        if isinstance(member, property):
            members[name] = typing.get_type_hints(member.fget, namespace)["return"]
    for name, hint in members.items():
        if miss := conforms(getattr(instance, name), hint, namespace, f"{path}.{name}"):
            return miss
    return None


def test_stub_types_are_the_run_time_types(monkeypatch):
    # Every property and attribute of the stubs' classes against the value it has at run time:
    # a sweep's rows (dicts of str to float, int, bool, str or None), a friction program's
    # stages, jumps and trajectory, a continuum run's empty jumps, a scene.
    namespace = stub_namespace(monkeypatch)
    fretting = mdrsim.Scene.from_file("scenes/programs/fretting_parabola.toml").set(
        "discretization.springs", 400)
    plain = mdrsim.Scene.from_file("scenes/fig2_fixed_load.toml").set("discretization.springs",
                                                                        200)
    instances = {
        "Scene": [plain, fretting],
        "Material": [plain.material],
        "Result": [mdrsim.run(fretting), mdrsim.run(plain), mdrsim.run(plain, method="continuum")],
        "SweepResult": [mdrsim.sweep(plain, {"material.poisson_ratio": [0.0, 0.3],
                                             "detachment.criterion": ["mode-mixed"]}),
                        mdrsim.sweep(fretting, {"friction.coefficient": [0.3]})],
    }
    assert any(r.jumps for r in instances["Result"])
    assert any(r.stages for r in instances["Result"])
    for name, values in instances.items():
        for index, value in enumerate(values):
            miss = stub_class_mismatch(value, namespace[name], namespace, f"{name} {index}")
            assert miss is None, miss


def test_sweep_rows_stub_is_a_list_of_dicts(monkeypatch):
    namespace = stub_namespace(monkeypatch)
    rows = typing.get_type_hints(namespace["SweepResult"].rows.fget, namespace)["return"]
    assert typing.get_origin(rows) is list
    assert typing.get_origin(typing.get_args(rows)[0]) is dict
