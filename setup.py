"""`pip install --no-build-isolation .` (docs/guide/install.md, "pip"): setuptools, through CMake.

The wheel is what `cmake --install --prefix P` puts into P, made for the Python that runs pip: the package vssw/ goes
to that Python's site-packages, and the rest (bin/vssw, lib/vssw/plugins, share/vssw, share/doc/vssw) to its prefix
(the wheel's data), the layout whose relative paths the package's _install.py holds. So `vssw` is on the
environment's PATH, and `import vssw` finds the same plugins and data as that program.

VSSW_PIP_BUILD_DIR=DIR installs from an existing CMake build folder, built and configured for this Python, instead of
building a new one; VSSW_PIP_WORK_DIR=DIR holds setuptools' own folders (build-pip/ by default).
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Distribution, setup
from setuptools.command.build_ext import build_ext

HERE = os.path.dirname(os.path.abspath(__file__))
WORK = os.path.abspath(os.environ.get("VSSW_PIP_WORK_DIR") or os.path.join(HERE, "build-pip"))
# The wheel's data (target folder under the prefix, files), filled in by the build below: install_data reads this list.
DATA_FILES = []


def fail(message):
    raise SystemExit(f"vssw: error: {message}")


def project_version():
    """The one version, set by project() in CMakeLists.txt."""
    with open(os.path.join(HERE, "CMakeLists.txt"), encoding="utf-8") as f:
        found = re.search(r"project\(vssw VERSION ([0-9.]+)", f.read())
    if not found:
        fail("CMakeLists.txt has no `project(vssw VERSION x.y.z)` line")
    return found[1]


def run(command):
    """One command, without a shell; stopping the build with the command's name when it fails."""
    env = {k: v for k, v in os.environ.items() if k != "DESTDIR"}
    print("vssw:", " ".join(command), flush=True)
    if subprocess.run(command, env=env, check=False).returncode != 0:
        fail(f"`{' '.join(command)}` failed (its output is above)")


def cached_python(build_dir):
    """The Python a CMake build folder was configured for (its cache's Python3_EXECUTABLE), or None."""
    try:
        with open(os.path.join(build_dir, "CMakeCache.txt"), encoding="utf-8") as f:
            found = re.search(r"^Python3_EXECUTABLE:\w+=(.*)$", f.read(), re.MULTILINE)
    except OSError:
        return None
    return found[1] if found else None


class BinaryDistribution(Distribution):
    def has_ext_modules(self):
        """The wheel holds compiled code (the module, the program, the plugins): tagged for this Python and machine."""
        return True


class CMakeBuild(build_ext):
    """Builds with CMake and stages `cmake --install`: the package into build_lib, the rest as the wheel's data."""

    def run(self):
        build_dir = self.cmake_build_dir()
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        if not glob.glob(os.path.join(build_dir, "python", "vssw", "_core" + suffix)):
            fail(f"{build_dir} holds no Python module for this Python {sys.version_info.major}."
                 f"{sys.version_info.minor} ({sys.executable}, _core{suffix}); the folder is configured for "
                 f"{cached_python(build_dir)}. CMake needs pybind11 and this Python's headers (Debian: pybind11-dev, "
                 f"python3-dev); a folder of VSSW_PIP_BUILD_DIR must be configured with "
                 f"-DPython3_EXECUTABLE={sys.executable}")
        stage = os.path.join(WORK, "stage")
        shutil.rmtree(stage, ignore_errors=True)
        run(["cmake", "--install", build_dir, "--prefix", stage, "--strip"])
        packages = glob.glob(os.path.join(stage, "lib", "python*", "site-packages", "vssw", "_install.py"))
        if len(packages) != 1:
            fail(f"`cmake --install {build_dir}` put no package under lib/pythonX.Y/site-packages of its prefix: "
                 f"is VSSW_PYTHON_INSTALL_DIR set in its cache? Leave it empty for pip")
        package = os.path.dirname(packages[0])
        target = os.path.join(self.build_lib, "vssw")
        shutil.rmtree(target, ignore_errors=True)
        shutil.copytree(package, target)
        site = os.path.dirname(package)  # the stage's site-packages: the package went to build_lib, the rest is data
        del DATA_FILES[:]
        for folder, _, files in sorted(os.walk(stage)):
            if files and os.path.commonpath([folder, site]) != site:
                DATA_FILES.append((os.path.relpath(folder, stage), [os.path.join(folder, f) for f in sorted(files)]))

    def cmake_build_dir(self):
        """VSSW_PIP_BUILD_DIR as it is built (not built again: a build folder's own tests run this while they use it);
        else a folder of its own, configured for this Python without the tests and benchmarks, and built."""
        reused = os.environ.get("VSSW_PIP_BUILD_DIR")
        if reused:
            build_dir = os.path.abspath(reused)
            if not os.path.isfile(os.path.join(build_dir, "CMakeCache.txt")):
                fail(f"VSSW_PIP_BUILD_DIR={reused} is not a CMake build folder (no CMakeCache.txt)")
            if not os.path.isfile(os.path.join(build_dir, "vssw")):
                fail(f"VSSW_PIP_BUILD_DIR={reused} holds no vssw program: build it first (cmake --build {reused})")
            return build_dir
        build_dir = os.path.join(WORK, "cmake")
        generator = ["-G", "Ninja"] if shutil.which("ninja") else []
        run(["cmake", "-S", HERE, "-B", build_dir, *generator, "-DCMAKE_BUILD_TYPE=Release", "-DVSSW_BUILD_TESTS=OFF",
             "-DVSSW_BUILD_BENCH=OFF", f"-DPython3_EXECUTABLE={sys.executable}"])
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        run(["cmake", "--build", build_dir, "--parallel", jobs])
        return build_dir


os.makedirs(WORK, exist_ok=True)
setup(
    version=project_version(),
    distclass=BinaryDistribution,
    cmdclass={"build_ext": CMakeBuild},
    packages=[],
    data_files=DATA_FILES,
    options={"build": {"build_base": WORK}, "egg_info": {"egg_base": WORK}},
)
