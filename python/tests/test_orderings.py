"""reorder and vcache: the orderings and the vertex-cache table of the command line."""

import numpy as np
import pytest

import rastrace
from conftest import DATA, assert_rows_equal, cli_error, cli_json

FANDISK = str(DATA / "meshes" / "fandisk.off")


def test_algorithms_lists_tipsy():
    assert "tipsy" in rastrace.algorithms()


def test_reorder_is_a_permutation_of_the_faces():
    mesh = rastrace.load_mesh(FANDISK)
    indices = rastrace.reorder(mesh, "tipsy", cache=16)
    assert indices.dtype == np.uint32 and indices.shape == (3 * mesh.face_count,)
    ordered = sorted(map(tuple, indices.reshape(-1, 3)))
    assert ordered == sorted(map(tuple, mesh.indices))


def test_vcache_equals_the_cli_json():
    cache = "entries=12/16,policy=fifo/lru"
    columns = rastrace.vcache(FANDISK, cache=cache, algo="original,tipsy,forsyth")
    rows = cli_json("vcache", FANDISK, "--algo", "original,tipsy,forsyth", "--cache", cache, "--no-time")
    assert_rows_equal(columns, rows)


def test_vcache_of_a_reordered_index_list_equals_the_ordering_row():
    mesh = rastrace.load_mesh(FANDISK)
    indices = rastrace.reorder(mesh, "tipsy", cache=16)
    own = rastrace.vcache(indices, cache="entries=16,policy=fifo")
    table = rastrace.vcache(mesh, cache="entries=16", algo="tipsy")
    assert own["misses"][0] == table["misses"][0]
    assert round(float(own["acmr"][0]), 3) == round(float(table["acmr"][0]), 3)


def test_bad_cache_spec_raises_the_cli_message():
    with pytest.raises(rastrace.InputError) as error:
        rastrace.vcache(FANDISK, cache="entries=0")
    assert str(error.value) == cli_error("vcache", FANDISK, "--cache", "entries=0")
