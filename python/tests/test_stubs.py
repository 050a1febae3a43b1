"""The type stubs (.pyi) name what the module has, with the module's own defaults."""
import ast
import os
import re

import pytest

import tapeline
from tapeline import garment, geodesic, pattern

STUBS = os.path.join(os.path.dirname(tapeline.__file__))


def stub_functions(name):
    tree = ast.parse(open(os.path.join(STUBS, name)).read())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            out[node.name] = node
        elif isinstance(node, ast.ClassDef):
            out[node.name] = node
    return out


def stub_imports(name):
    """Names a stub re-exports (`from . import x as x`, `from .m import f as f`)."""
    tree = ast.parse(open(os.path.join(STUBS, name)).read())
    return {a.asname or a.name for node in tree.body if isinstance(node, ast.ImportFrom)
            and node.level == 1 for a in node.names}


def runtime_defaults(function):
    """name -> default text from pybind11's signature line of `function`."""
    line = function.__doc__.splitlines()[0]
    args = line[line.index("(") + 1: line.rindex(")")]
    return dict(re.findall(r"(\w+): [\w\[\], .]+ = ('[^']*'|[^,]+)", args))


MODULES = [(tapeline, "__init__.pyi"), (geodesic, "geodesic.pyi"), (pattern, "pattern.pyi"),
           (garment, "garment.pyi")]


@pytest.mark.parametrize("module, stub", MODULES)
def test_stub_names_exist_and_defaults_agree(module, stub):
    for name, node in stub_functions(stub).items():
        assert hasattr(module, name), f"{stub} names {name}, which the module lacks"
        if isinstance(node, ast.FunctionDef):
            given = runtime_defaults(getattr(module, name))
            args = node.args.args
            pairs = list(zip(args[len(args) - len(node.args.defaults):], node.args.defaults))
            pairs += [(a, d) for a, d in zip(node.args.kwonlyargs, node.args.kw_defaults) if d]
            for arg, default in pairs:
                value = ast.literal_eval(default)
                text = given.get(arg.arg)
                assert text is not None, f"{name}({arg.arg}) has no default at run time"
                assert ast.literal_eval(text if text not in ("None",) else "None") == value, (
                    f"{name}({arg.arg}): stub default {value!r}, module {text}")


# The option classes of tapeline.garment.
GARMENT_OPTIONS = ["PlacementOptions", "SewingOptions", "DrapeOptions", "RelaxOptions", "FoldOptions",
                   "DressOptions"]


def test_every_public_name_has_a_stub():
    for module, stub in MODULES:
        names = set(stub_functions(stub)) | stub_imports(stub)
        for name in module.__all__:
            assert name in names, f"{name} missing from {stub}"


def test_option_classes_in_the_stubs_have_the_runtime_fields():
    for cls in ["ExactMmpOptions", "HeatOptions", "CurvatureFlowOptions", "PointCloudOptions"]:
        node = stub_functions("geodesic.pyi")[cls]
        fields = {n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
        runtime = set(getattr(geodesic, cls)().to_dict().keys())
        assert fields <= runtime | {"target_vertices"}, (cls, fields - runtime)
    # The garment options have no to_dict: their properties are the fields, both ways.
    for cls in GARMENT_OPTIONS:
        node = stub_functions("garment.pyi")[cls]
        fields = {n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
        c = getattr(garment, cls)
        runtime = {k for k, v in vars(c).items() if isinstance(v, property)}
        assert fields == runtime, (cls, fields ^ runtime)


def test_option_docstrings_are_the_cxx_comments():
    # The comment above ExactMmpOptions::max_distance in the C++ header, read here independently.
    header = os.path.join(os.path.dirname(__file__), "..", "..", "geodesic", "include", "tapeline",
                          "geodesic", "exact_mmp_types.h")
    lines = open(header).read().splitlines()
    k = next(i for i, l in enumerate(lines) if "double max_distance" in l)
    comment = []
    while lines[k - 1].strip().startswith("///"):
        k -= 1
        comment.insert(0, lines[k].strip()[3:].strip())
    assert geodesic.ExactMmpOptions.max_distance.__doc__ == " ".join(comment)
    for cls in ["ExactMmpOptions", "HeatOptions", "CurvatureFlowOptions", "PointCloudOptions"]:
        c = getattr(geodesic, cls)
        assert c.__doc__, cls
        for field in c().to_dict():
            prop = getattr(c, field, None)
            if isinstance(prop, property):
                assert prop.__doc__, f"{cls}.{field} has no docstring"
    for cls in GARMENT_OPTIONS:
        c = getattr(garment, cls)
        assert c.__doc__, cls
        for field, prop in vars(c).items():
            if isinstance(prop, property):
                assert prop.__doc__, f"{cls}.{field} has no docstring"
