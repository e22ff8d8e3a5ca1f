"""Builds polydecomp._core with the project's CMake build (pyproject.toml holds the metadata).

The extension is CMake's target pd_python, built in POLYDECOMP_BUILD_DIR (default: build/, the Release
build `make` makes, which it configures when it is missing) and copied into the wheel; after `make`
only the module itself is compiled. Setuptools' own files go to build/setuptools/.
"""

import os
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = Path(os.environ.get("POLYDECOMP_BUILD_DIR", SOURCE / "build")).resolve()
        jobs = str(os.cpu_count() or 1)
        if not (build / "CMakeCache.txt").exists():
            subprocess.run(["cmake", "-S", str(SOURCE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                            f"-DPYTHON_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "pd_python", "-j", jobs], check=True)
        built = build / "python" / "polydecomp" / ("_core" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.exists():  # the build folder was configured for another Python
            sys.exit(f"error: {build} holds no module for this Python ({built.name}); "
                     "set POLYDECOMP_BUILD_DIR to a new folder")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(ext_modules=[CMakeExtension("polydecomp._core")], cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": str(SOURCE / "build" / "setuptools")}})
