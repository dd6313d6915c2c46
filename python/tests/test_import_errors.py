"""``import rastrace`` where it cannot work says what is missing and which interpreter the module
was built for, instead of Python's bare ``ImportError: initialization failed``.

Each case runs a fresh interpreter: numpy made unimportable (``sys.modules['numpy'] = None``, what
an interpreter without numpy gives), and a copy of the package whose extension carries another
Python's ABI tag (what a different interpreter sees).
"""

import pathlib
import shutil
import subprocess
import sys

import rastrace
from rastrace import _build

PACKAGE = pathlib.Path(rastrace.__file__).parent
THIS = f"{sys.executable} (Python {sys.version_info.major}.{sys.version_info.minor})"
BUILT_FOR = f"Python {sys.version_info.major}.{sys.version_info.minor} ({_build.INTERPRETER})"


def import_error(prelude, path):
    probe = f"import sys; sys.path.insert(0, {str(path)!r}); {prelude}; import rastrace"
    result = subprocess.run([sys.executable, "-I", "-c", probe], capture_output=True, text=True)
    assert result.returncode == 1, result.stdout + result.stderr
    return result.stderr.strip().splitlines()[-1]


def test_the_build_names_the_interpreter_it_built_the_extension_for():
    assert pathlib.Path(_build.INTERPRETER).resolve() == pathlib.Path(sys.executable).resolve()
    assert _build.VERSION.startswith(f"{sys.version_info.major}.{sys.version_info.minor}.")


def test_without_numpy_the_error_names_numpy_this_interpreter_and_the_one_built_for():
    last = import_error("sys.modules['numpy'] = None", PACKAGE.parent)
    assert last.startswith("ImportError: rastrace needs numpy, which this interpreter, " + THIS), last
    assert "cannot import" in last and "initialization failed" not in last, last
    assert "it was built for " + BUILT_FOR in last, last
    assert "python3-numpy" in last, last


def test_an_extension_built_for_another_python_is_named_with_its_version(tmp_path):
    copy = tmp_path / "rastrace"
    shutil.copytree(PACKAGE, copy)
    (so,) = copy.glob("_rastrace*.so")
    so.rename(copy / "_rastrace.cpython-399-x86_64-linux-gnu.so")
    last = import_error("pass", tmp_path)
    assert last.startswith("ImportError: rastrace: this interpreter, " + THIS + ", cannot load the extension"), last
    assert "it was built for Python 3.99 (" + _build.INTERPRETER + ")" in last, last
    assert "-DPython_EXECUTABLE=" + sys.executable in last, last


def test_a_package_without_its_extension_says_where_it_looked(tmp_path):
    copy = tmp_path / "rastrace"
    shutil.copytree(PACKAGE, copy, ignore=shutil.ignore_patterns("_rastrace*.so", "_build.py"))
    last = import_error("pass", tmp_path)
    assert f"no built extension _rastrace*.so is in {copy.resolve()}" in last, last
