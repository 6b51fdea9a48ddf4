"""Builds ridt._core with the project's CMake build (python/CMakeLists.txt), so pip and CMake
compile the library the same way. Needs cmake, a C++20 compiler and pybind11; nothing is
downloaded: pip install --no-build-isolation --no-deps --no-index ."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        target = Path(self.get_ext_fullpath(ext.name)).resolve()
        build = Path(self.build_temp).resolve() / "cmake"
        build.mkdir(parents=True, exist_ok=True)
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DRIDT_BUILD_PYTHON=ON", "-DRIDT_BUILD_TOOLS=OFF", "-DRIDT_BUILD_TESTS=OFF", "-DRIDT_BUILD_BENCH=OFF",
            f"-DPython_EXECUTABLE={sys.executable}",
            f"-DRIDT_PYTHON_OUTPUT_DIR={build / 'package'}",
        ]
        try:
            import pybind11
            configure.append(f"-Dpybind11_DIR={pybind11.get_cmake_dir()}")
        except ImportError:
            pass
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        subprocess.check_call(configure)
        subprocess.check_call(["cmake", "--build", str(build), "--target", "ridt_python",
                               "--parallel", str(os.cpu_count() or 1)])
        built = next((build / "package").glob("_core*"))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    ext_modules=[Extension("ridt._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build/pip"}},
)
