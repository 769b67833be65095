"""Build of erd._erd: the library's sources (kernel/, algorithms/, api/), the erd program's (cli/,
for `python3 -m erd`, main left out) and the binding (python/src/) in one extension module.

The flags are the Makefile's where they change code generation (-O2, -fno-math-errno,
-fno-trapping-math; Python's own -fwrapv is undone) so the extension computes what build/erd does.
-g0 drops Python's default -g: a third less compile time in make test, the same code.
"""
import glob
import os
import sys

from setuptools import setup
from pybind11.setup_helpers import ParallelCompile, Pybind11Extension, build_ext

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

if not os.path.exists(os.path.join(ROOT, "api", "erd.h")):
    sys.exit("erd: setup.py builds from a checkout of the erd repository (../api/erd.h is missing)")
if not os.path.exists("/usr/include/stb/stb_image.h"):
    sys.exit("erd: the erd program's PNG support needs stb_image.h: apt-get install libstb-dev")


def files(*patterns):
    """Paths relative to this folder, as setuptools wants them in setup() arguments."""
    return sorted(os.path.relpath(p, HERE) for pat in patterns for p in glob.glob(os.path.join(ROOT, pat)))


class BuildExt(build_ext):
    """Compiles from absolute paths, so objects land under the build folder (named after the
    source's full path) and not beside the Makefile's objects through '..'."""

    def build_extension(self, ext):
        ext.sources = [os.path.join(HERE, s) for s in ext.sources]
        ext.depends = [os.path.join(HERE, s) for s in ext.depends]
        super().build_extension(ext)


sources = files("kernel/*.cpp", "algorithms/*/*.cpp", "api/*.cpp", "imageio/*.cpp", "cli/*.cpp",
                "third_party/stb_glue.cpp", "python/src/*.cpp")
headers = files("kernel/*.h", "algorithms/*/*.h", "api/*.h", "imageio/*.h", "cli/*.h", "third_party/*.h",
                "python/src/*.h")


def needs_recompile(obj, src):
    """Recompile when the source or a header it includes (gcc's -MMD list) is newer than the object."""
    try:
        with open(os.path.splitext(obj)[0] + ".d") as f:
            deps = f.read().split(":", 1)[1].replace("\\\n", " ").split()
        built = os.path.getmtime(obj)
        return any(os.path.getmtime(d) > built for d in deps)
    except (OSError, IndexError):
        return True


ParallelCompile("ERD_BUILD_JOBS", default=2, needs_recompile=needs_recompile).install()

ext = Pybind11Extension(
    "erd._erd",
    sources,
    include_dirs=[ROOT],
    depends=headers,
    define_macros=[("ERD_CLI_NO_MAIN", "1")],
    libraries=["tiff", "z"],
    extra_compile_args=["-O2", "-g0", "-fno-math-errno", "-fno-trapping-math", "-fno-wrapv", "-MMD"],
    cxx_std=17,
)

setup(packages=["erd"], package_data={"erd": ["*.pyi", "py.typed"]}, ext_modules=[ext],
      cmdclass={"build_ext": BuildExt})
