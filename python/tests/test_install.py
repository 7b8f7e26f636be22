"""`cmake --install build --prefix P` installs a package that a fresh virtual environment imports, and that finds the
engine plugins and the shipped data from where it lies (not from the build tree)."""
import os
import pathlib
import subprocess
import sys
import textwrap

import pytest

BUILD = os.environ.get("VSSW_BUILD_DIR")

# Run inside the fresh environment: the package's location, and a free vibration on the analytic model and on an
# engine plugin (ODE when built, else the first engine), under a record read from the installed data.
SCRIPT = textwrap.dedent("""
    import json, os, sys
    import vssw
    engine = "ode" if "ode" in vssw.engines() else [e for e in vssw.engines() if e != "analytic"][0]
    wall = dict(height=4, thickness=0.4, hinge=0.7)
    runs = {e: vssw.simulate(e, **wall, theta0=0.5, t_end=0.5) for e in ["analytic", engine]}
    shaken = vssw.simulate("analytic", **wall, record="records/kern1952-taft-021.at2", pga=0.3)
    print(json.dumps({"file": vssw.__file__, "version": vssw.__version__, "data": str(vssw.data_dir()),
                      "samples": {e: len(r.t) for e, r in runs.items()}, "shaken": len(shaken.t),
                      "prefix": sys.prefix, "plugins": os.environ.get("VSSW_PLUGIN_PATH")}))
""")


@pytest.mark.skipif(not BUILD, reason="VSSW_BUILD_DIR names the build tree to install (set by ctest)")
def test_an_installed_package_imports_in_a_fresh_venv(tmp_path):
    prefix = tmp_path / "prefix"
    done = subprocess.run(["cmake", "--install", BUILD, "--prefix", prefix], capture_output=True, text=True,
                          check=True)
    site = next(prefix.glob("lib/python3*/site-packages"))
    assert (site / "vssw" / "_install.py").is_file()
    assert (site / "vssw" / "py.typed").is_file() and (site / "vssw" / "_core.pyi").is_file()  # typed (PEP 561)
    assert f"vssw Python package: {site / 'vssw'}" in done.stdout
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", "--without-pip", venv], check=True)
    # A .pth file in the environment's site-packages names the installed folder (PYTHONPATH would do as well).
    (next(venv.glob("lib/python3*/site-packages")) / "vssw.pth").write_text(f"{site}\n")
    # Nothing of the build tree or the test's environment: no PYTHONPATH, no VSSW_* variables, another folder.
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH" and not k.startswith("VSSW_")}
    run = subprocess.run([venv / "bin" / "python", "-c", SCRIPT], capture_output=True, text=True, env=env,
                         cwd=tmp_path, check=False)
    assert run.returncode == 0, run.stderr
    import json

    out = json.loads(run.stdout)
    assert pathlib.Path(out["file"]).is_relative_to(site)
    assert pathlib.Path(out["prefix"]) == venv
    assert pathlib.Path(out["data"]).is_relative_to(prefix)
    assert pathlib.Path(out["plugins"]) == prefix / "lib" / "vssw" / "plugins"  # set by the package, not the test
    assert all(n > 10 for n in out["samples"].values()) and len(out["samples"]) == 2
    assert out["shaken"] > 10
