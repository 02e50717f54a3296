"""The type stubs (python/stubs/rbsim.pyi, issue 39) against the module: every name in the stubs
exists, every public name of the module has a stub, and a method's parameters in the stubs are
the ones its docstring's signature gives."""
import ast
import inspect
import re

import rbsim

from conftest import SOURCE

STUBS = SOURCE / "python" / "stubs" / "rbsim.pyi"
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


def docstring_parameters(doc):
    """The parameter names of the signature a docstring opens with: "f(a: int, b=(x, y), **c)"."""
    match = re.match(r"\s*\w+\((.*?)\)\s*(->|:|$)", doc.split("\n")[0])
    if not match:
        return None
    names, depth, current = [], 0, ""
    for ch in match.group(1) + ",":
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        if ch == "," and depth == 0:
            name = re.match(r"\s*(\*{0,2}\w+)", current)
            if name:
                names.append(name.group(1))
            current = ""
        else:
            current += ch
    return names


def test_the_stubs_parameters_are_the_docstrings():
    functions, classes, _ = stub_tree()
    checked = 0
    targets = [(getattr(rbsim, n), f) for n, f in functions.items()]
    targets += [(getattr(getattr(rbsim, c), m), f) for c, ms in classes.items() for m, f in ms.items()
                if m not in SPECIAL and not issubclass(getattr(rbsim, c), Exception)]
    for obj, stub in targets:
        if isinstance(obj, property) or any(isinstance(d, ast.Name) and d.id == "property" for d in stub.decorator_list):
            continue
        documented = docstring_parameters(inspect.getdoc(obj) or "")
        if documented is None:
            continue
        args = [a.arg for a in stub.args.args if a.arg != "self"]
        if stub.args.kwarg is not None:
            # **keys: the docstring lists the block's keys or names the block; the fixed ones lead.
            assert documented[:len(args)] == args, (stub.name, documented, args)
        else:
            assert documented == args, (stub.name, documented, args)
        checked += 1
    assert checked >= 20
