"""Builds the Python module madd with CMake (docs/python.md, "Installing").

The package's Python files are cli/python/madd/; its compiled core
madd._madd is the CMake target madd_python, built here with only the
library and the module (no CLI, tests or install rules), for the Python
that runs this script.
"""
import glob
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.path.join(os.path.abspath(self.build_temp), "cmake")
        subprocess.check_call([
            "cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DMADD_PYTHON=ON",
            "-DMADD_BUILD_CLI=OFF", "-DMADD_BUILD_TESTS=OFF", "-DMADD_BUILD_BENCH=OFF", "-DMADD_INSTALL=OFF",
            f"-DPython_EXECUTABLE={sys.executable}",
        ])
        subprocess.check_call(["cmake", "--build", build, "--target", "madd_python", "-j", str(os.cpu_count() or 2)])
        built = glob.glob(os.path.join(build, "python", "madd", "_madd*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one compiled module in {build}/python/madd, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    packages=["madd"],
    package_dir={"madd": "cli/python/madd"},
    package_data={"madd": ["*.pyi", "py.typed"]},
    ext_modules=[CMakeExtension("madd._madd")],
    cmdclass={"build_ext": CMakeBuild},
)
