"""examples/yang_texture_misses.py end to end: its rows equal `rastrace texsweep`'s."""

import subprocess
import sys

import pytest

from conftest import REPOSITORY, cli_json

pandas = pytest.importorskip("pandas")
pytest.importorskip("matplotlib")


def test_yang_example_reproduces_texsweep(tmp_path):
    subprocess.run([sys.executable, str(REPOSITORY / "examples" / "yang_texture_misses.py"), "-o", str(tmp_path),
                    "--size", "160x160"], check=True, capture_output=True)
    assert (tmp_path / "yang-fig9.png").stat().st_size > 10000
    rows = pandas.read_csv(tmp_path / "yang-fig9.csv")
    # texsweep's JSON carries two kinds of rows: the texture-cache sweep and the frame traffic.
    expected = [row for row in cli_json("texsweep", "builtin:bunny", "--order", "strip,texgroup", "--raster",
                                        "scanline", "--resolution", "160x160", "--tcache",
                                        "size=1KiB..64KiB,line=64B,assoc=full,policy=lru,layout=linear")
                if row["kind"] == "texture_sweep"]
    assert len(rows) == len(expected) == 14
    for row, want in zip(rows.itertuples(), expected):
        assert (row.order, row.size_bytes, row.accesses, row.misses) == (
            want["order"], want["size_bytes"], want["accesses"], want["misses"])
        assert round(row.vertex_acmr, 3) == round(want["vertex_acmr"], 3)
