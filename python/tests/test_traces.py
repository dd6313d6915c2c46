"""open_trace: a trace chunk by chunk, records as numpy structured arrays."""

import csv

import numpy as np
import pytest

import rastrace
from conftest import cli, cli_error


def test_trace_equals_its_csv_export(bunny_trace, tmp_path):
    exported = tmp_path / "bunny.csv"
    cli("trace", "convert", bunny_trace, exported)
    vertex_rows, texel_rows, draw = [], [], None
    with open(exported) as f:
        lines = (line for line in f if not line.startswith("#"))
        for row in csv.DictReader(lines):
            if row["event"] == "begin_draw":
                draw = int(row["draw"])
            elif row["event"] == "vertex":
                vertex_rows.append((draw, int(row["vertex"]), int(row["primitive_start"])))
            elif row["event"] == "texel":
                texel_rows.append(tuple(int(row[k]) for k in ("texture", "level", "x", "y", "pixel_x", "pixel_y", "triangle")))

    trace = rastrace.open_trace(str(bunny_trace))
    assert trace.records("vertex") == len(vertex_rows) and trace.records("texel") == len(texel_rows)
    vertices, texels = [], []
    for chunk in trace:
        if chunk.kind == "vertex":
            r = chunk.records
            vertices.extend(zip([chunk.draw] * len(r), r["vertex"].tolist(), r["primitive_start"].astype(int).tolist()))
        elif chunk.kind == "texel":
            assert chunk.first_record == len(texels)
            texels.extend(map(tuple, chunk.records.tolist()))
    assert vertices == vertex_rows
    assert texels == texel_rows

    whole = trace.read("texel")
    assert whole.dtype.names == ("texture", "level", "x", "y", "pixel_x", "pixel_y", "triangle")
    # The C++ TexelAccess, 16 bytes: 16-bit texture numbers and texel coordinates.
    assert whole.dtype.itemsize == 16
    assert [whole.dtype[name] for name in whole.dtype.names] == [np.dtype(t) for t in ("u2", "u1", "u2", "u2", "u2", "u2", "u4")]
    assert len(whole) == len(texel_rows) and tuple(whole[-1].tolist()) == texel_rows[-1]
    assert trace.metadata["scene"] == "builtin:bunny"


def test_chunks_of_one_kind(bunny_trace):
    trace = rastrace.open_trace(str(bunny_trace))
    kinds = {chunk.kind for chunk in trace.chunks("vertex")}
    assert kinds == {"vertex"}
    assert sum(len(c) for c in trace.chunks("vertex")) == trace.records("vertex")


def test_truncated_trace_raises_the_cli_message(bunny_trace, tmp_path):
    broken = tmp_path / "broken.rtrace"
    broken.write_bytes(bunny_trace.read_bytes()[:5000])
    with pytest.raises(rastrace.InputError) as error:
        rastrace.open_trace(str(broken))
    assert str(error.value) == cli_error("trace", "info", broken)
