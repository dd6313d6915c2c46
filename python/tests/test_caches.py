"""replay, sweep and lru_profile: the cache simulator over traces, results as numpy columns."""

import sys
import threading
import time

import numpy as np
import pytest

import rastrace
from conftest import assert_rows_equal, cli_error, cli_json

BYTE_SPEC = "size=1KiB..16KiB,line=32B/64B,assoc=2/full,policy=fifo/lru/opt,layout=linear/morton"


def test_sweep_equals_the_cli_json_row_for_row(bunny_trace):
    columns = rastrace.sweep(str(bunny_trace), BYTE_SPEC)
    rows = cli_json("sweep", bunny_trace, "--cache", BYTE_SPEC)
    assert columns.rows == 5 * 2 * 2 * 3 * 2
    assert_rows_equal(columns, rows)
    for key, value in columns.parameters.items():
        assert rows[0][key] == value, key
    pandas = pytest.importorskip("pandas")
    frame = pandas.DataFrame(columns)
    assert list(frame.columns) == [k for k in rows[0] if k in columns]


def test_vertex_cache_sweep_equals_the_cli_json(bunny_trace):
    spec = "entries=4..64,policy=fifo/lru"
    assert_rows_equal(rastrace.sweep(str(bunny_trace), spec), cli_json("sweep", bunny_trace, "--cache", spec))


def test_replay_equals_the_cli_json(bunny_trace):
    specs = ["entries=16,policy=fifo", "size=8KiB,line=64B,assoc=4,policy=lru,layout=block4", "size=4KiB,source=vertex"]
    result = rastrace.replay(str(bunny_trace), specs)
    assert set(result) == {"vertex", "texel", "vertex_buffer"}
    args = [a for spec in specs for a in ("--cache", spec)]
    rows = cli_json("replay", bunny_trace, *args)
    assert_rows_equal(result["vertex"], rows[:1])
    assert_rows_equal(result["texel"], rows[1:2])
    assert_rows_equal(result["vertex_buffer"], rows[2:3])


def test_replay_keys_every_table_by_its_kind(bunny_trace):
    """A framebuffer cache beside a vertex cache: each table under its own key (the framebuffer
    table has no source parameter, and was once filed under 'vertex', replacing that table)."""
    specs = ["entries=16,policy=fifo", "size=4KiB,source=depth"]
    result = rastrace.replay(str(bunny_trace), specs)
    assert set(result) == {"vertex", "framebuffer"}
    rows = cli_json("replay", bunny_trace, *[a for spec in specs for a in ("--cache", spec)])
    assert [row["kind"] for row in rows] == ["vertex_cache", "framebuffer_cache"]
    assert_rows_equal(result["vertex"], rows[:1])
    assert_rows_equal(result["framebuffer"], rows[1:2])


def test_lru_profile_equals_fully_associative_lru_sweeps(bunny_trace):
    profile = rastrace.lru_profile(str(bunny_trace), line="64B", layout="morton", sets=16, max_ways=8)
    sweep = rastrace.sweep(str(bunny_trace), "size=1KiB..64KiB,line=64B,assoc=full,policy=lru,layout=morton")
    for size, misses, compulsory in zip(sweep["size_bytes"], sweep["misses"], sweep["compulsory"]):
        lines = size // 64
        expected = profile["misses"][min(lines, len(profile["misses"]) - 1)]
        assert expected == misses, size
        assert profile["compulsory"] == compulsory
    assert profile["accesses"] == sweep["accesses"][0]
    # 16 sets of w ways: the set-associative LRU caches of 16 * w * 64 bytes.
    assoc = rastrace.sweep(str(bunny_trace), "size=1KiB/2KiB/4KiB/8KiB,line=64B,assoc=1/2/4/8,policy=lru,layout=morton")
    for size, ways, misses in zip(assoc["size_bytes"], assoc["assoc"], assoc["misses"]):
        if size == 16 * ways * 64:
            assert profile["set_misses"][ways - 1] == misses


def test_lru_profile_of_four_units_equals_the_cli_hierarchys_first_level(bunny_trace):
    """units=4: every L1 size of a four-unit hierarchy at once, as `replay --level ... --units 4`."""
    profile = rastrace.lru_profile(str(bunny_trace), line="64B", layout="morton", units=4, tile=16)
    for size in ("1KiB", "4KiB", "16KiB"):
        rows = cli_json("replay", bunny_trace, "--level", f"size={size},line=64B,assoc=full,policy=lru,layout=morton",
                        "--units", "4", "--tile", "16")
        lines = int(size[:-3]) * 1024 // 64
        assert rows[0]["level"] == "L1 (4 units)"
        assert profile["misses"][min(lines, len(profile["misses"]) - 1)] == rows[0]["misses"], size
        assert profile["accesses"] == rows[0]["accesses"]
    with pytest.raises(rastrace.InputError, match="only texel accesses carry the pixel"):
        rastrace.lru_profile(str(bunny_trace), source="vertex", units=2)


def test_replays_in_two_threads_overlap(bunny_trace):
    """The GIL is released: two replays run at once while the main thread keeps running Python."""
    specs = ["size=1KiB..64KiB,assoc=1/2/4/full,policy=fifo/lru/random,layout=linear/block4/morton"]  # 252 caches
    spans, results = [None, None], [None, None]

    def work(i):
        start = time.perf_counter()
        results[i] = rastrace.replay(str(bunny_trace), specs)
        spans[i] = (start, time.perf_counter())

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    ticks = []
    for t in threads:
        t.start()
    while any(t.is_alive() for t in threads):
        ticks.append(time.perf_counter())
    for t in threads:
        t.join()
    (a0, a1), (b0, b1) = spans
    overlap = (max(a0, b0), min(a1, b1))
    assert overlap[0] < overlap[1], spans  # both replays were running at the same time
    inside = sum(overlap[0] < t < overlap[1] for t in ticks)
    assert inside > 100, (inside, overlap)  # and Python ran beside them
    assert list(results[0]["texel"]["misses"]) == list(results[1]["texel"]["misses"])


def test_missing_trace_raises_the_cli_message(tmp_path):
    missing = tmp_path / "none.rtrace"
    with pytest.raises(rastrace.InputError) as error:
        rastrace.sweep(str(missing), "size=1KiB")
    assert str(error.value) == cli_error("sweep", missing, "--cache", "size=1KiB")


def test_bad_spec_raises_the_cli_message(bunny_trace):
    with pytest.raises(rastrace.InputError) as error:
        rastrace.replay(str(bunny_trace), ["size=1KiB,ways=2"])
    assert str(error.value) == cli_error("replay", bunny_trace, "--cache", "size=1KiB,ways=2")


def test_columns_of_a_large_sweep_equal_the_small_ones_and_release_their_text(bunny_trace):
    # From 4 MiB a column lives in huge-page memory of its own (python/src/column_memory.h); the
    # sweep's workers write the text columns' cells without the GIL and count them, and the
    # references are added when the columns are handed over, released by that memory's owner.
    spec = "size=1KiB..8KiB,line=64B,assoc=full,policy=fifo/lru,layout=linear"
    small = rastrace.sweep(str(bunny_trace), spec)
    repeat = -(-(1 << 19) // small.rows)  # 2^19 rows of 8 bytes: 4 MiB
    swept = rastrace._rastrace._sweep_rows(str(bunny_trace), spec).repeated(repeat)
    large = swept.columns()
    with pytest.raises(RuntimeError, match="handed over once"):
        swept.columns()
    assert large.rows == small.rows * repeat and list(large) == list(small)
    for key, column in small.items():
        assert large[key].dtype == column.dtype, key
        assert np.array_equal(large[key].reshape(repeat, small.rows), np.tile(column, (repeat, 1))), key
    assert not large["size_bytes"].flags.owndata and large["size_bytes"].flags.writeable
    policy = large["policy"][0]  # one string object shared by the cells of that policy
    assert sys.getrefcount(policy) == 2 + large.rows // 2  # the cells, `policy`, the argument
    large["policy"][0] = "changed"
    assert large["policy"][0] == "changed" and sys.getrefcount(policy) == 1 + large.rows // 2
    del large
    assert sys.getrefcount(policy) == 2
