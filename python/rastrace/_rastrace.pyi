"""Type stubs of the extension rastrace._rastrace (python/src). Docstrings: help(rastrace.NAME)."""

from typing import Iterator, Optional, Sequence, Union
import os

import numpy as np
import numpy.typing as npt

from ._columns import Columns

__version__: str

class InputError(ValueError):
    """Bad input; the message is the command line's (after 'rastrace: ')."""

class Mesh:
    name: str
    vertex_count: int
    face_count: int
    positions: npt.NDArray[np.float32]  # (vertices, 3)
    normals: npt.NDArray[np.float32]  # (vertices, 3) or (0, 3)
    uvs: npt.NDArray[np.float32]  # (vertices, 2) or (0, 2)
    indices: npt.NDArray[np.uint32]  # (faces, 3)
    face_material: npt.NDArray[np.uint32]  # (faces,) or (0,)

class Scene:
    name: str
    width: int
    height: int
    meshes: list[Mesh]
    texture_count: int

MeshLike = Union[Mesh, str, os.PathLike[str]]

def load_mesh(spec: str) -> Mesh:
    """A mesh file (OFF, PLY, OBJ, glTF, ...), builtin:NAME (merged into one mesh) or grid:WxH."""

def load_scene(spec: str) -> Scene:
    """builtin:NAME, a JSON scene or a mesh file framed by a default camera."""

def algorithms() -> dict[str, str]:
    """Every triangle ordering: name -> description."""

def reorder(mesh: MeshLike, algo: str, cache: int = 16, policy: str = "fifo", seed: int = 1,
            time_budget: float = 60.0, texgroup_base: str = "strip") -> npt.NDArray[np.uint32]:
    """The triangle list (3 indices per face) with the faces in the algorithm's order."""

def vcache(mesh: Union[MeshLike, npt.ArrayLike], cache: str = "entries=8/12/16/20/24/32,policy=fifo",
           algo: str = "all", target: int = 0, seed: int = 1, time_budget: float = 60.0,
           accounting: str = "misses", time: bool = False) -> Columns:
    """Vertex-cache statistics: `rastrace vcache`'s table, or the rows of one index list."""

def render(scene: str, output: str = "", trace: str = "", vcache: str = "entries=16,policy=fifo",
           tcache: str = "size=16KiB,line=64B,assoc=4,policy=lru,layout=block4", order: str = "original",
           order_cache: int = 16, size: str = "", filter: str = "trilinear", wrap: str = "repeat",
           raster: str = "scanline", cull: str = "none", lighting: bool = False, lod_formula: str = "lengths",
           vipm: str = "", lod: str = "") -> Columns:
    """One frame with live caches (one row); the image is the result's `image` attribute."""

class TraceChunk:
    kind: str  # vertex, texel or address
    first_record: int
    draw: int
    primitive: str
    restart_index: int
    starts_draw: bool
    ends_draw: bool
    records: np.ndarray  # structured: see open_trace
    def __len__(self) -> int: ...

class TraceFile:
    path: str
    metadata: dict
    file_bytes: int
    def records(self, kind: str) -> int: ...
    def __len__(self) -> int: ...
    def chunk(self, index: int) -> TraceChunk: ...
    def chunks(self, kind: Optional[str] = None) -> Iterator[TraceChunk]: ...
    def __iter__(self) -> Iterator[TraceChunk]: ...
    def read(self, kind: str) -> np.ndarray: ...

def open_trace(path: str) -> TraceFile:
    """A rastrace trace, chunk by chunk; records as numpy structured arrays."""

def replay(trace: str, caches: Sequence[str], keep_vertex_cache: bool = False) -> dict[str, Columns]:
    """Every cache of the specs in one pass: {'vertex'|'texel'|'vertex_buffer'|'address'|'framebuffer'|'sectored'|'hierarchy': Columns}."""

def sweep(trace: str, cache: str = "size=1KiB..64KiB", threads: int = 0, keep_vertex_cache: bool = False) -> Columns:
    """Every combination of the spec over the trace, in parallel, as `rastrace sweep`."""

def lru_profile(trace: str, line: str = "64B", layout: str = "linear", source: str = "", texel: str = "4B",
                align: str = "4KiB", stride: str = "32B", sets: int = 0, max_ways: int = 16, units: int = 1,
                tile: int = 16) -> dict:
    """histogram, misses[c] for every fully associative size c (lines), set_misses[w-1] with sets;
    with units > 1, sums over texture units dealt screen tiles (a hierarchy's first level)."""
