"""The type stubs (python/rbsim/__init__.pyi, issue 39) against the module: every name in the stubs
exists, every public name of the module has a stub, and a method's parameters in the stubs are
the ones its docstring's signature gives."""
import ast
import inspect
import re

import rbsim

from conftest import SOURCE

STUBS = SOURCE / "python" / "rbsim" / "__init__.pyi"
# Names the stubs define for their own annotations, not the module's.
STUB_ONLY = {"Vec3", "PathLike"}
# Special methods the stubs declare where the module has them.
SPECIAL = {"__init__", "__len__", "__eq__", "__hash__", "__enter__", "__exit__"}


def stub_tree():
    tree = ast.parse(STUBS.read_text())
    functions = {n.name: n for n in tree.body if isinstance(n, ast.FunctionDef)}
    classes = {n.name: {m.name: m for m in n.body if isinstance(m, ast.FunctionDef)}
               for n in tree.body if isinstance(n, ast.ClassDef)}
    names = {t.id for n in tree.body if isinstance(n, (ast.AnnAssign, ast.Assign))
             for t in (n.targets if isinstance(n, ast.Assign) else [n.target]) if isinstance(t, ast.Name)}
    return functions, classes, names


def public(names):
    return {n for n in names if not n.startswith("_")}


def test_every_stub_is_in_the_module_and_every_public_name_has_one():
    functions, classes, names = stub_tree()
    module_names = public(dir(rbsim)) | {"__version__"}
    assert module_names == (set(functions) | set(classes) | names) - STUB_ONLY
    for cls, members in classes.items():
        actual = public(vars(getattr(rbsim, cls))) | (SPECIAL & set(vars(getattr(rbsim, cls))))
        if issubclass(getattr(rbsim, cls), Exception):
            continue  # their attributes are set on each instance
        declared = set(members)
        assert declared - SPECIAL <= actual, (cls, declared - actual)
        assert public(actual) <= declared, (cls, public(actual) - declared)


def stub_parameters(stub):
    """(name, kind, default) of a stub's parameters, as inspect.Parameter has them."""
    a = stub.args
    positional = a.posonlyargs + a.args
    defaults = [None] * (len(positional) - len(a.defaults)) + list(a.defaults)
    out = []
    for arg, default in zip(positional, defaults):
        kind = "POSITIONAL_ONLY" if arg in a.posonlyargs else "POSITIONAL_OR_KEYWORD"
        out.append((arg.arg, kind, inspect.Parameter.empty if default is None else ast.literal_eval(default)))
    if a.vararg:
        out.append((a.vararg.arg, "VAR_POSITIONAL", inspect.Parameter.empty))
    for arg, default in zip(a.kwonlyargs, a.kw_defaults):
        out.append((arg.arg, "KEYWORD_ONLY", inspect.Parameter.empty if default is None else ast.literal_eval(default)))
    if a.kwarg:
        out.append((a.kwarg.arg, "VAR_KEYWORD", inspect.Parameter.empty))
    return out


def runtime_parameters(obj):
    return [(p.name, p.kind.name, p.default) for p in inspect.signature(obj).parameters.values()]


def test_every_call_has_the_stub_s_signature_names_kinds_and_defaults():
    """inspect.signature reads each call's text signature (its docstring's first line, pybind11 with
    signatures off); the stubs must say the same, defaults included."""
    functions, classes, _ = stub_tree()
    checked = 0
    targets = [(n, getattr(rbsim, n), f) for n, f in functions.items()]
    targets += [(f"{c}.{m}", getattr(getattr(rbsim, c), m), f) for c, ms in classes.items() for m, f in ms.items()
                if m not in SPECIAL - {"__init__"} and not issubclass(getattr(rbsim, c), Exception)]
    for name, obj, stub in targets:
        if isinstance(obj, property) or any(isinstance(d, (ast.Name, ast.Attribute)) and
                                            getattr(d, "id", getattr(d, "attr", "")) in ("property", "setter")
                                            for d in stub.decorator_list):
            continue
        runtime = runtime_parameters(obj)
        assert runtime == stub_parameters(stub), name
        checked += 1
    assert checked >= 30


def test_no_call_takes_arbitrary_keywords():
    """Every call's keys are a fixed set: none is left as **kwargs for the reader to guess."""
    functions, classes, _ = stub_tree()
    for stub in list(functions.values()) + [f for ms in classes.values() for f in ms.values()]:
        assert stub.args.kwarg is None or stub.name == "__exit__", stub.name
