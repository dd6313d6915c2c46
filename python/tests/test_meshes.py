"""load_mesh and load_scene: the loaders of the command line, geometry as numpy arrays."""

import json

import numpy as np
import pytest

import rastrace
from conftest import DATA, cli, cli_error


def test_load_mesh_matches_info():
    mesh = rastrace.load_mesh(str(DATA / "meshes" / "fandisk.off"))
    info = json.loads(cli("info", DATA / "meshes" / "fandisk.off", "--json").stdout)
    assert mesh.vertex_count == info["vertices"]
    assert mesh.face_count == info["faces"]
    assert mesh.positions.shape == (mesh.vertex_count, 3) and mesh.positions.dtype == np.float32
    assert mesh.indices.shape == (mesh.face_count, 3) and mesh.indices.dtype == np.uint32
    assert mesh.indices.max() < mesh.vertex_count


def test_grid_spec():
    mesh = rastrace.load_mesh("grid:16x16")
    assert (mesh.vertex_count, mesh.face_count) == (289, 512)


def test_load_scene_builtin_spider():
    scene = rastrace.load_scene("builtin:spider")
    assert scene.texture_count >= 1
    assert sum(m.face_count for m in scene.meshes) == rastrace.load_mesh("builtin:spider").face_count


def test_missing_mesh_raises_the_cli_message():
    with pytest.raises(rastrace.InputError) as error:
        rastrace.load_mesh("no/such/mesh.off")
    assert str(error.value) == cli_error("info", "no/such/mesh.off")
