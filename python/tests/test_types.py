"""The package's type annotations (py.typed): every public function, method and result field annotated, and mypy
(Debian's python3-mypy) content with the package and with a user's script typed against it, and refusing a script
whose types are wrong. Skipped where mypy is not installed."""
import ast
import dataclasses
import inspect
import os
import pathlib
import subprocess
import sys
import typing

import pytest

import vssw

HERE = pathlib.Path(__file__).resolve().parent
PACKAGE = pathlib.Path(vssw.__file__).resolve().parent
# mypy's cache in the build folder (a cold check of the package and numpy's stubs takes tens of seconds, a warm one
# a few): CTest gives the folder, by hand a temporary one.
CACHE = pathlib.Path(os.environ.get("VSSW_BUILD_DIR", "/tmp")) / "mypy-cache"
mypy_missing = subprocess.run([sys.executable, "-c", "import mypy"], capture_output=True, check=False).returncode != 0


def mypy(*targets):
    """mypy over the built package (found from MYPYPATH, as a user's site-packages holds it) and the targets."""
    env = {**os.environ, "MYPYPATH": str(PACKAGE.parent)}
    done = subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", str(CACHE), "--no-error-summary",
                           "--check-untyped-defs", *targets], capture_output=True, text=True, env=env, check=False)
    return done.returncode, done.stdout + done.stderr


def test_the_package_says_it_is_typed():
    assert (PACKAGE / "py.typed").is_file()
    assert (PACKAGE / "_core.pyi").is_file()  # the compiled module's interface


def public_callables():
    for name in vssw.__all__:
        value = getattr(vssw, name)
        if inspect.isfunction(value):
            yield f"vssw.{name}", value
        elif inspect.isclass(value) and not issubclass(value, BaseException):
            for member, attribute in vars(value).items():
                if member.startswith("_") and member != "__getitem__":
                    continue
                if isinstance(attribute, property):
                    yield f"vssw.{name}.{member}", attribute.fget
                elif inspect.isfunction(attribute):
                    yield f"vssw.{name}.{member}", attribute
    for name in vssw.cli.__all__:
        value = getattr(vssw.cli, name)
        if inspect.isfunction(value):
            yield f"vssw.cli.{name}", value


def test_every_public_function_method_and_field_is_annotated():
    unannotated = []
    for name, function in public_callables():
        hints = typing.get_type_hints(function)
        parameters = [p for p in inspect.signature(function).parameters if p != "self"]
        unannotated += [f"{name}({p})" for p in parameters if p not in hints]
        if "return" not in hints:
            unannotated.append(f"{name} -> ?")
    for name in vssw.__all__:
        value = getattr(vssw, name)
        if dataclasses.is_dataclass(value):
            typing.get_type_hints(value)  # every field's annotation resolves
    assert not unannotated, f"not annotated: {unannotated}"


def test_an_unannotated_function_is_found():
    def helper(x, y: int):  # the check above must name both holes
        return x

    vssw.helper_for_the_test = helper  # type: ignore[attr-defined]
    vssw.__all__.append("helper_for_the_test")
    try:
        with pytest.raises(AssertionError, match=r"helper_for_the_test\(x\).*helper_for_the_test -> \?"):
            test_every_public_function_method_and_field_is_annotated()
    finally:
        vssw.__all__.remove("helper_for_the_test")
        del vssw.helper_for_the_test


def signature_parameters(doc):
    """The parameter names in pybind11's generated signature, the first line of a function's __doc__:
    name(a: T, b: Dict[str, float] = 0.0) -> R; a type's or a default's own commas are inside brackets."""
    inside = doc.splitlines()[0].split("(", 1)[1].rsplit(") ->", 1)[0]
    names, depth, start = [], 0, 0
    for i, char in enumerate(inside + ","):
        depth += (char in "[({") - (char in "])}")
        if char == "," and depth == 0:
            names.append(inside[start:i].split(":")[0].strip())
            start = i + 1
    return [n for n in names if n and n != "self"]


def stub_mismatches(stub):
    """Each function of the stub (and each class's __init__) whose parameter names differ from the compiled
    function's, as "name: stub [...] != module [...]"; a function the module lacks as "name: not in the module"."""
    from vssw import _core

    wrong = []
    for node in ast.parse(stub).body:
        function, owner = node, None
        if isinstance(node, ast.ClassDef):
            function = next((f for f in node.body if isinstance(f, ast.FunctionDef) and f.name == "__init__"), None)
            owner = node.name
        if not isinstance(function, ast.FunctionDef):
            continue
        name = owner or function.name
        compiled = getattr(_core, name, None)
        if compiled is None:
            wrong.append(f"{name}: not in the module")
            continue
        stubbed = [a.arg for a in function.args.args + function.args.kwonlyargs if a.arg != "self"]
        generated = signature_parameters((compiled.__init__ if owner else compiled).__doc__)
        if stubbed != generated:
            wrong.append(f"{name}: stub {stubbed} != module {generated}")
    return wrong


def test_the_stub_names_the_compiled_functions_parameters():
    # _core.pyi is written by hand: held to the signatures pybind11 generates from python/core.cpp.
    from vssw import _core

    stub = (PACKAGE / "_core.pyi").read_text(encoding="utf-8")
    assert stub_mismatches(stub) == []
    stubbed = {node.name for node in ast.parse(stub).body if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    assert stubbed == {name for name in dir(_core) if not name.startswith("_") and callable(getattr(_core, name))}


def test_a_stub_with_a_wrong_parameter_name_is_found():
    stub = (PACKAGE / "_core.pyi").read_text(encoding="utf-8")
    assert "theta0: float, t_end" in stub
    wrong = stub.replace("theta0: float, t_end", "theta: float, t_end", 1)
    assert [m.split(":")[0] for m in stub_mismatches(wrong)] == ["simulate"]
    renamed = stub.replace("overburden_eccentricity: float = ...", "eccentricity: float = ...", 1)
    assert [m.split(":")[0] for m in stub_mismatches(renamed)] == ["WallArgs"]


@pytest.mark.skipif(mypy_missing, reason="mypy is not installed (Debian: python3-mypy)")
def test_mypy_accepts_the_package_and_a_script_typed_against_it():
    code, output = mypy(str(PACKAGE), str(HERE / "typed" / "uses_the_api.py"))
    assert code == 0, output


@pytest.mark.skipif(mypy_missing, reason="mypy is not installed (Debian: python3-mypy)")
def test_mypy_refuses_a_script_whose_types_are_wrong():
    script = HERE / "typed" / "misuses_the_api.py"
    code, output = mypy(str(script))
    assert code == 1, output
    wrong = [i + 1 for i, line in enumerate(script.read_text().splitlines()) if "# error: " in line]
    found = sorted({int(line.split(":")[1]) for line in output.splitlines() if ": error:" in line})
    assert found == wrong, output
