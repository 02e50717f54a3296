"""`pip install .` (issue 39): builds the module `rbsim` with the project's CMake build, the same
one `cmake --build` runs (the target rbsim_python alone), and installs it with the program's
shaders and assets in <prefix>/share/rbsim, where the module finds them (app/render/data_dir.h).
The interpreter that runs pip is the one the module is built for.

The package (issue 57): rbsim/ (python/rbsim: __init__.py, the stubs __init__.pyi, py.typed) with
the compiled rbsim._rbsim in it. It renders (rbsim.Renderer) by default, as `cmake` builds it;
RBSIM_PYTHON_RENDER=OFF in the environment builds it physics-only, from the engine-only
configuration (RBSIM_BUILD_APP=OFF): no GL, LLVM, image or video library linked, nor needed to build."""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(rbsim VERSION ([0-9.]+)", text).group(1)


def data_files():
    """(share/rbsim/<folder>, [files]) for every folder of shaders/ and assets/."""
    out = []
    for top in ("shaders", "assets"):
        for folder, _, files in os.walk(ROOT / top):
            if files:
                relative = pathlib.Path(folder).relative_to(ROOT)
                out.append((str(pathlib.Path("share/rbsim") / relative),
                            [str(pathlib.Path(folder, f).relative_to(ROOT)) for f in sorted(files)]))
    return out


def renders():
    """False when RBSIM_PYTHON_RENDER is OFF (or 0, NO, FALSE) in the environment."""
    return os.environ.get("RBSIM_PYTHON_RENDER", "ON").upper() not in ("OFF", "0", "NO", "FALSE")


def configure(build):
    physics_only = [] if renders() else ["-DRBSIM_BUILD_APP=OFF", "-DRBSIM_PYTHON_RENDER=OFF"]
    done = subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                           f"-DPython_EXECUTABLE={sys.executable}", "-DRBSIM_BUILD_TESTS=OFF",
                           "-DRBSIM_BUILD_BENCH=OFF", *physics_only], capture_output=True, text=True)
    print(done.stdout, done.stderr, sep="\n")
    if done.returncode != 0:
        sys.exit("setup.py: CMake could not configure rbsim (its message is above)")
    if "rbsim: Python module for" not in done.stdout:
        sys.exit(f"setup.py: no Python module can be built for {sys.executable}: it needs python3-dev, "
                 "python3-numpy and pybind11-dev (apt-get install), and NumPy visible to it (a venv made "
                 "with --system-site-packages)")


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        # RBSIM_CMAKE_BUILD_DIR: a build tree configured already (README's build/): its module is built
        # there and packaged, instead of building everything again in a tree of pip's own.
        given = os.environ.get("RBSIM_CMAKE_BUILD_DIR")
        build = pathlib.Path(given).resolve() if given else pathlib.Path(self.build_temp).resolve() / "cmake"
        if given and not (build / "CMakeCache.txt").is_file():
            sys.exit(f"setup.py: RBSIM_CMAKE_BUILD_DIR={given} is not a configured CMake build tree (no CMakeCache.txt)")
        if not given:
            configure(build)
        elif ("RBSIM_PYTHON_RENDER:BOOL=ON" in (build / "CMakeCache.txt").read_text()) != renders():
            sys.exit(f"setup.py: RBSIM_CMAKE_BUILD_DIR={given} was not configured with RBSIM_PYTHON_RENDER="
                     f"{'ON' if renders() else 'OFF'} as the environment asks")
        jobs = str(os.cpu_count() or 2)
        subprocess.run(["cmake", "--build", str(build), "--target", "rbsim_python", "-j", jobs], check=True)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = sorted((build / "python" / "rbsim").glob("_rbsim*.so"))
        if not built:
            sys.exit(f"setup.py: the CMake build made no module in {build / 'python' / 'rbsim'}")
        if not built[0].name.endswith(suffix):
            sys.exit(f"setup.py: {built[0]} is not for this interpreter ({sys.executable} loads *{suffix}); "
                     "leave RBSIM_CMAKE_BUILD_DIR unset to build one for it")
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


# setuptools' own build folder is build-pip/, apart from the CMake build/ that README's commands use.
# The package rbsim is python/rbsim with its stubs and py.typed (PEP 561), the extension inside it.
setup(version=project_version(), ext_modules=[Extension("rbsim._rbsim", sources=[])], cmdclass={"build_ext": CMakeBuild},
      data_files=data_files(), options={"build": {"build_base": "build-pip"}},
      packages=["rbsim"], package_dir={"rbsim": "python/rbsim"}, package_data={"rbsim": ["__init__.pyi", "py.typed"]},
      py_modules=[])
