"""The package's type annotations (py.typed): every public function, method and result field annotated, and mypy
(Debian's python3-mypy) content with the package and with a user's script typed against it, and refusing a script
whose types are wrong. Skipped where mypy is not installed."""
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
