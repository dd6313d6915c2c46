"""render: a frame with live caches, as `rastrace render` draws it."""

import numpy as np
import pytest

import rastrace
from conftest import assert_rows_equal, cli_error, cli_json


def test_render_equals_the_cli(tmp_path):
    args = dict(size="96x96", order="tipsy", vcache="entries=16,policy=lru", tcache="size=4KiB,line=32B,assoc=2,policy=fifo,layout=morton")
    frame = rastrace.render("builtin:grid", output=str(tmp_path / "py.png"), **args)
    rows = cli_json("render", "builtin:grid", "-o", tmp_path / "cli.png", "--size", "96x96", "--order", "tipsy",
                    "--vcache", args["vcache"], "--tcache", args["tcache"])
    assert_rows_equal(frame, rows)
    assert frame.image.shape == (96, 96, 4) and frame.image.dtype == np.uint8
    assert (tmp_path / "py.png").exists()
    assert frame["texel_accesses"][0] > 0


def test_unknown_order_raises_the_cli_message(tmp_path):
    with pytest.raises(rastrace.InputError) as error:
        rastrace.render("builtin:grid", order="no-such-order")
    assert str(error.value) == cli_error("render", "builtin:grid", "-o", tmp_path / "x.png", "--order", "no-such-order")
