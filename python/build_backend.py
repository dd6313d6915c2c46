"""The in-tree PEP 517 build backend behind ``pip install .`` (pyproject.toml).

It configures the repository's CMake project for the interpreter running pip
(``-DPython_EXECUTABLE=sys.executable``), builds the ``_rastrace`` target, and packs the package
folder the build lays out (``<build>/python/rastrace``: the extension, ``__init__.py``, the type
stubs) into a wheel. The build folder is ``build-wheel/`` in the repository (kept, so a second
install rebuilds only what changed; ``RASTRACE_WHEEL_BUILD_DIR`` moves it).
``RASTRACE_WHEEL_PACKAGE_DIR`` packs a package folder an existing build made instead
(``build/python/rastrace`` after scripts/build.sh): no second build of the C++ project
(python/tests/test_install.py installs that way).
Debian 12 has no scikit-build-core, and meson-python would need a second build description of
the whole C++ project; this backend needs nothing but CMake and pybind11-dev.
"""

import base64
import hashlib
import os
import pathlib
import re
import shutil
import subprocess
import sys
import sysconfig
import zipfile

ROOT = pathlib.Path(__file__).resolve().parents[1]


def _version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(rastrace VERSION ([0-9.]+)", text).group(1)


def _tag():
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{python}-{python}-{platform}"


def _metadata():
    return (
        "Metadata-Version: 2.1\n"
        "Name: rastrace\n"
        f"Version: {_version()}\n"
        "Summary: GPU memory traffic of triangle orders: rendering traces, cache simulation, orderings\n"
        "Requires-Python: >=3.9\n"
        "Requires-Dist: numpy\n"
    )


def _build_package():
    prebuilt = os.environ.get("RASTRACE_WHEEL_PACKAGE_DIR")
    if prebuilt:
        package = pathlib.Path(prebuilt)
        if not any(package.glob("_rastrace*.so")):
            raise RuntimeError(f"RASTRACE_WHEEL_PACKAGE_DIR={prebuilt}: no built extension _rastrace*.so there")
        return package
    build = pathlib.Path(os.environ.get("RASTRACE_WHEEL_BUILD_DIR", ROOT / "build-wheel"))
    configure = [
        "cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release", "-DRASTRACE_PYTHON=ON",
        f"-DPython_EXECUTABLE={sys.executable}",
    ]
    env = dict(os.environ)
    if shutil.which("ccache"):
        configure += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"]
        # Paths relative to the clone: another clone's wheel build hits the same cache entries.
        env.setdefault("CCACHE_BASEDIR", str(ROOT))
    subprocess.run(configure, check=True, stdout=sys.stderr, env=env)
    subprocess.run(["cmake", "--build", str(build), "--target", "_rastrace", "-j", str(os.cpu_count() or 1)],
                   check=True, stdout=sys.stderr, env=env)
    package = build / "python" / "rastrace"
    if not any(package.glob("_rastrace*.so")):
        raise RuntimeError(f"the build made no extension in {package}: is pybind11-dev installed?")
    return package


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}\n"


def get_requires_for_build_wheel(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    info = pathlib.Path(metadata_directory) / f"rastrace-{_version()}.dist-info"
    info.mkdir(parents=True, exist_ok=True)
    (info / "METADATA").write_text(_metadata())
    return info.name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    package = _build_package()
    version = _version()
    name = f"rastrace-{version}-{_tag()}.whl"
    info = f"rastrace-{version}.dist-info"
    record = ""
    with zipfile.ZipFile(pathlib.Path(wheel_directory) / name, "w", zipfile.ZIP_DEFLATED) as wheel:
        def add(arcname, data):
            nonlocal record
            wheel.writestr(arcname, data)
            record += _record_line(arcname, data)

        for path in sorted(package.iterdir()):
            if path.is_file() and (path.suffix in (".py", ".pyi", ".so") or path.name == "py.typed"):
                add(f"rastrace/{path.name}", path.read_bytes())
        add(f"{info}/METADATA", _metadata().encode())
        add(f"{info}/WHEEL", f"Wheel-Version: 1.0\nGenerator: rastrace build_backend\nRoot-Is-Purelib: false\nTag: {_tag()}\n".encode())
        add(f"{info}/top_level.txt", b"rastrace\n")
        record += f"{info}/RECORD,,\n"
        wheel.writestr(f"{info}/RECORD", record)
    return name
