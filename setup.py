"""pip install . : CMake builds the module `kerf` and the programs kerf-forces and kerf-dem; they go into the
environment pip installs into (a venv: V/lib/pythonX.Y/site-packages/kerf*.so, V/bin/kerf-forces, V/bin/kerf-dem,
the bundled data in V/share/kerf/data, where the programs and the module find it: include/kerf/install.hpp).

Environment: KERF_CMAKE_ARGS (more -D options for CMake's configure, e.g. -DKERF_NATIVE_ARCH=OFF for a wheel that
runs on other machines), KERF_PIP_BUILD_DIR (the CMake build directory, kept between installs so that a second
install rebuilds only what changed; default under build/pip), CMAKE_BUILD_PARALLEL_LEVEL (compile jobs).
"""
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).parent.resolve()
VERSION = re.search(r"^project\(kerf VERSION ([0-9]+\.[0-9]+\.[0-9]+)", (ROOT / "CMakeLists.txt").read_text(),
                    re.M).group(1)


class CMakeBuild(build_ext):
    """Configures, builds and installs (into a staging prefix) the CMake project; the module goes to the wheel's
    library directory, the programs and the data to its data files (relative to the install prefix)."""

    def build_extension(self, ext):
        temp = pathlib.Path(self.build_temp).resolve()
        build = pathlib.Path(os.environ.get("KERF_PIP_BUILD_DIR") or temp / "cmake").resolve()
        stage = temp / "stage"
        configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     f"-DPython3_EXECUTABLE={sys.executable}", "-DKERF_BUILD_TESTS=OFF", "-DKERF_BUILD_BENCH=OFF",
                     "-DKERF_PYTHON_INSTALL_DIR=python"]
        try:
            import pybind11
            configure.append(f"-Dpybind11_DIR={pybind11.get_cmake_dir()}")
        except ImportError:
            pass  # Debian's pybind11-dev: CMake finds it by itself
        if not (build / "CMakeCache.txt").exists() and shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        configure += shlex.split(os.environ.get("KERF_CMAKE_ARGS", ""))
        env = dict(os.environ)
        env.setdefault("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.check_call(configure, env=env)
        subprocess.check_call(["cmake", "--build", str(build), "--target", "kerf_python", "kerf-forces", "kerf-dem"],
                              env=env)
        shutil.rmtree(stage, ignore_errors=True)
        for component in ("programs", "python"):
            subprocess.check_call(["cmake", "--install", str(build), "--prefix", str(stage), "--component", component])

        library = pathlib.Path(self.get_ext_fullpath(ext.name)).parent.resolve()
        library.mkdir(parents=True, exist_ok=True)
        for item in (stage / "python").iterdir():  # kerf.cpython-XY-....so, its stand-in kerf.py, kerf/*.py
            if item.is_dir():
                shutil.copytree(item, library / item.name, dirs_exist_ok=True)
            else:
                shutil.copy2(item, library / item.name)
        data_files = self.distribution.data_files  # install_data reads this list after the build
        for directory in sorted({p.parent for p in stage.rglob("*") if p.is_file()}):
            relative = directory.relative_to(stage)
            if relative.parts[0] != "python":
                data_files.append((str(relative), sorted(str(p) for p in directory.iterdir() if p.is_file())))


setup(
    version=VERSION,
    packages=[],  # no package discovery in the repository's folders: the module is the extension
    py_modules=[],
    ext_modules=[Extension("kerf", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    data_files=[],
    options={"build": {"build_base": "build/pip"}},
    zip_safe=False,
)
