"""rastrace from Python: the engine behind the ``rastrace`` command line.

The functions are named after the subcommands and run the same code:

- ``load_mesh``, ``load_scene``: meshes and scenes (files, ``builtin:NAME``, ``grid:WxH``)
- ``reorder``: a triangle ordering, as a numpy index array; ``algorithms()`` lists them
- ``vcache``: post-transform vertex-cache statistics under a cache spec
- ``render``: a frame with live vertex and texture caches, optionally written as a trace
- ``open_trace``: a trace file, chunk by chunk, records as numpy structured arrays
- ``replay``, ``sweep``: caches over a trace; results are ``Columns`` (dicts of numpy columns that
  ``pandas.DataFrame`` takes as is, keyed like the JSON output)
- ``lru_profile``: the one-pass LRU profiles of a trace as arrays

Bad input raises ``rastrace.InputError`` (a ``ValueError``) with the command line's message.
Long calls release the GIL, so threads run them in parallel.
"""

from ._columns import Columns
from ._import_check import check_dependencies as _check_dependencies

_check_dependencies()

from ._rastrace import (  # noqa: E402 (after the check, which explains a failed import)
    InputError,
    Mesh,
    Scene,
    TraceChunk,
    TraceFile,
    __version__,
    algorithms,
    load_mesh,
    load_scene,
    lru_profile,
    open_trace,
    render,
    reorder,
    replay,
    sweep,
    vcache,
)

__all__ = [
    "Columns",
    "InputError",
    "Mesh",
    "Scene",
    "TraceChunk",
    "TraceFile",
    "__version__",
    "algorithms",
    "load_mesh",
    "load_scene",
    "lru_profile",
    "open_trace",
    "render",
    "reorder",
    "replay",
    "sweep",
    "vcache",
]
