"""Shared fixtures: the command line to compare against, the real data, one rendered trace."""

import json
import os
import pathlib
import subprocess

import pytest

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
BINARY = os.environ.get("RASTRACE_BINARY", str(REPOSITORY / "build" / "apps" / "rastrace"))
DATA = pathlib.Path(os.environ.get("RASTRACE_DATA_DIR", str(REPOSITORY / "data")))


def cli(*args, check=True):
    """Runs the rastrace command line; returns the completed process (text output)."""
    result = subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True)
    if check and result.returncode != 0:
        raise AssertionError(f"rastrace {' '.join(map(str, args))}: {result.stderr}")
    return result


def cli_json(*args):
    """The rows of a command's --format json output."""
    return json.loads(cli(*args, "--format", "json").stdout)


def cli_error(*args):
    """The message the command line prints for bad input (exit code 1), without 'rastrace: '."""
    result = cli(*args, check=False)
    assert result.returncode == 1, result
    message = result.stderr.strip()
    assert message.startswith("rastrace: ")
    return message[len("rastrace: "):]


def assert_rows_equal(columns, rows):
    """Columns from Python equal the command line's JSON rows, row for row and column for column."""
    keys = list(columns.keys())
    assert columns.rows == len(rows)
    for i, row in enumerate(rows):
        for key in keys:
            value = columns[key][i]
            expected = row[key]
            if expected is None:
                assert value != value, (i, key)  # NaN
            elif isinstance(expected, float):
                assert float(value) == expected, (i, key, value, expected)
            else:
                assert value == expected, (i, key, value, expected)


@pytest.fixture(scope="session")
def bunny_trace(tmp_path_factory):
    """builtin:bunny at 128x128 in tipsy order, rendered once with its trace."""
    path = tmp_path_factory.mktemp("trace") / "bunny.rtrace"
    import rastrace

    rastrace.render("builtin:bunny", trace=str(path), size="128x128", order="tipsy")
    return path
