"""Why ``import rastrace`` fails, said plainly before the extension is loaded.

The extension ``_rastrace`` is built for one interpreter (its file name carries that Python's ABI
tag, and ``_build.py``, written by the build, names its path) and imports numpy while it
initialises. Either missing, Python reports only ``No module named 'rastrace._rastrace'`` or
``ImportError: initialization failed``; this module checks both first and raises an ImportError
that names what is missing, this interpreter and the one the module was built for.
"""

import importlib.util
import pathlib
import re
import sys

_PACKAGE = pathlib.Path(__file__).resolve().parent


def _built_for():
    """The interpreter the extension was built for, as a phrase (what the package knows of it)."""
    versions = sorted({f"{m.group(1)}.{m.group(2)}"
                       for so in _PACKAGE.glob("_rastrace*.so")
                       if (m := re.search(r"\.cpython-(\d)(\d+)", so.name))})
    path = None
    try:
        from . import _build  # written by the CMake build beside the extension
        path = _build.INTERPRETER
    except ImportError:
        pass
    if not versions and path is None:
        return f"no built extension _rastrace*.so is in {_PACKAGE}"
    built = "Python " + " and ".join(versions) if versions else "another Python"
    return f"it was built for {built}" + (f" ({path})" if path else "")


def _this_interpreter():
    return f"{sys.executable} (Python {sys.version_info.major}.{sys.version_info.minor})"


def check_dependencies():
    """Raises an ImportError naming the missing piece when the extension cannot load here."""
    if importlib.util.find_spec("rastrace._rastrace") is None:
        raise ImportError(
            f"rastrace: this interpreter, {_this_interpreter()}, cannot load the extension "
            f"rastrace._rastrace: {_built_for()}. Run that interpreter, or build rastrace for this "
            f"one (cmake -DPython_EXECUTABLE={sys.executable}).")
    try:
        import numpy  # noqa: F401 (the extension's arrays are numpy arrays)
    except ImportError as error:
        raise ImportError(
            f"rastrace needs numpy, which this interpreter, {_this_interpreter()}, cannot import "
            f"({error}); {_built_for()}. Install numpy for this interpreter (Debian: apt-get "
            f"install python3-numpy for /usr/bin/python3) or run the one rastrace was built for."
        ) from error
