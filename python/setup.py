"""Builds the module _superpack and the checker superpack-verify with the repository's CMake
build (one directory up) and puts both into the package. SUPERPACK_BUILD_DIR names an existing
build directory to reuse (e.g. build after `make`; a relative path is taken from the repository's
root); without it a build directory of its own, build-python/, is configured for this interpreter."""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

REPOSITORY = pathlib.Path(__file__).resolve().parent.parent


class BuildWithCMake(build_py):
    def run(self):
        super().run()
        reused = os.environ.get("SUPERPACK_BUILD_DIR")
        build = REPOSITORY / (reused or "build-python")
        if not reused:
            subprocess.run(["cmake", "-S", str(REPOSITORY), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                            f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", str(build), "-j", str(os.cpu_count() or 2), "--target",
                        "superpack_python_package"], check=True)
        package = pathlib.Path(self.build_lib) / "superpack"
        built = build / "python" / "superpack"
        for path in built.iterdir():
            if path.name.startswith("_superpack.") or path.name == "superpack-verify":
                shutil.copy2(path, package / path.name)


class BinaryDistribution(Distribution):
    """The wheel holds compiled code: tagged for this platform and interpreter."""

    def has_ext_modules(self):
        return True


setup(cmdclass={"build_py": BuildWithCMake}, distclass=BinaryDistribution)
