"""Fixtures of the Python tests: the tribolab binary (TRIBOLAB_BINARY, set by CTest) run as a
user would, to compare every function with the command line's --json output."""
import json
import os
import pathlib
import re
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("TRIBOLAB_SOURCE_DIR", pathlib.Path(__file__).parents[2]))


def _binary():
    b = os.environ.get("TRIBOLAB_BINARY")
    if not b:
        pytest.fail("TRIBOLAB_BINARY is not set (run the tests through ctest)")
    return b


def as_keywords(message):
    """A command-line error message as Python raises it: each option the core names as a field
    (docs/design.md "Errors") spelled as the keyword, `--time-scale` -> `time_scale`."""
    return re.sub(r"(?<![\w-])--([A-Za-z][\w-]*)", lambda m: m.group(1).replace("-", "_"), message)


class Cli:
    """`cli("incline", "predict", "--mu", "0.6", ...)` -> json.loads of its --json output;
    `cli.error(...)` -> the message after "tribolab: error: " (exit code must be 1)."""

    def __call__(self, *args, cwd=None):
        p = subprocess.run([_binary(), *map(str, args), "--json"], capture_output=True, text=True, cwd=cwd)
        assert p.returncode == 0, p.stderr
        return json.loads(p.stdout)

    def error(self, *args, cwd=None):
        p = subprocess.run([_binary(), *map(str, args), "--json"], capture_output=True, text=True, cwd=cwd)
        assert p.returncode == 1, (p.returncode, p.stdout, p.stderr)
        assert p.stdout == ""
        prefix = "tribolab: error: "
        lines = [line for line in p.stderr.splitlines() if line.startswith(prefix)]
        assert len(lines) == 1, p.stderr
        return lines[0][len(prefix):]


@pytest.fixture
def cli():
    return Cli()


@pytest.fixture
def demo():
    """The shipped demo data (data/demo)."""
    return SOURCE_DIR / "data" / "demo"


def json_part(result, cli_json):
    """The keys of `result` that the command line prints (the rest are the arrays)."""
    return {k: v for k, v in result.items() if k in cli_json}


def keywords_in(value):
    """`value` (JSON of the command line) with every string as Python says it: the fields the
    core names in warnings spelled as keywords (`--floor-y` -> `floor_y`, as_keywords)."""
    if isinstance(value, str):
        return as_keywords(value)
    if isinstance(value, list):
        return [keywords_in(v) for v in value]
    if isinstance(value, dict):
        return {k: keywords_in(v) for k, v in value.items()}
    return value


def assert_same_as_cli(result, cli_json):
    """Exactly the CLI's JSON (every number to the last digit; texts compared with flags spelled
    as keywords, since a warning names a field as each front end spells it) plus only numpy
    arrays (or dicts of them, nested) beside it."""
    import numpy as np

    assert keywords_in(json_part(result, cli_json)) == keywords_in(cli_json)
    assert set(cli_json) <= set(result)

    def only_arrays(v):
        if isinstance(v, dict):
            return all(only_arrays(x) for x in v.values())
        if isinstance(v, list):  # one entry per file of a series; None where a file failed
            return all(x is None or only_arrays(x) for x in v)
        return isinstance(v, np.ndarray)

    for k in set(result) - set(cli_json):
        assert only_arrays(result[k]), k
