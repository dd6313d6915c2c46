"""`pip install` of the repository: the wheel python/build_backend.py packs installs and imports.

pip runs the in-tree backend offline (no build isolation, no index) on the package folder this
build made (RASTRACE_WHEEL_PACKAGE_DIR: no second CMake build), installs it into a temporary
folder and a clean interpreter (-I: no PYTHONPATH, no user site) imports it from there. The full
`pip install .` from a fresh clone, CMake build included, is verified by hand (docs/PERFORMANCE.md,
"Python: a sweep result into pandas", and README.md's install step).
"""

import os
import pathlib
import subprocess
import sys

import pytest

import rastrace
from conftest import REPOSITORY

pytest.importorskip("pip")


def test_pip_install_of_the_built_module_imports_in_a_clean_interpreter(tmp_path):
    target = tmp_path / "site"
    env = dict(os.environ, RASTRACE_WHEEL_PACKAGE_DIR=str(pathlib.Path(rastrace.__file__).parent),
               PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    env.pop("PYTHONPATH", None)
    subprocess.run([sys.executable, "-m", "pip", "install", "--quiet", "--no-build-isolation", "--no-deps",
                    "--no-cache-dir", "--no-compile", "--target", str(target), str(REPOSITORY)],
                   check=True, capture_output=True, env=env, cwd=tmp_path)
    assert sorted(p.name for p in (target / "rastrace").iterdir() if p.suffix != ".so") == [
        "__init__.py", "_build.py", "_columns.py", "_import_check.py", "_rastrace.pyi", "py.typed"]
    probe = ("import sys; sys.path.insert(0, sys.argv[1]); import rastrace; "
             "mesh = rastrace.load_mesh('builtin:bunny'); "
             "print(rastrace.__file__, rastrace.__version__, mesh.face_count)")
    result = subprocess.run([sys.executable, "-I", "-c", probe, str(target)], check=True, capture_output=True,
                            text=True, env=env, cwd=tmp_path)
    path, version, faces = result.stdout.split()
    assert pathlib.Path(path) == target / "rastrace" / "__init__.py"
    assert version == rastrace.__version__
    assert int(faces) == rastrace.load_mesh("builtin:bunny").face_count
    dist_info = list(target.glob("rastrace-*.dist-info"))
    assert [d.name for d in dist_info] == [f"rastrace-{version}.dist-info"]
    assert "Requires-Dist: numpy" in (dist_info[0] / "METADATA").read_text()
