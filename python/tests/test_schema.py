"""The two front ends against each other (docs/design.md "Options and results: declared once"):
every command of `tribolab schema --json` has a Python function with the same options as
keywords, so a field bound in one front end and not the other fails here. The differences
that remain are listed below, each with its reason; shrink the lists, never grow them."""
import inspect
import json
import math
import subprocess

import pytest

import tribolab
from conftest import _binary

# Commands of the command line that are not Python functions: the demo writes a folder of
# reports (a program, not a computation), the schema describes the command line itself.
# studio is a server for a browser page (its analyses are these same functions), not a function.
NOT_IN_PYTHON = {"demo", "schema", "studio"}

# Command-line options without a keyword (or keywords without an option), by command.
CLI_ONLY = {
    "*": {"json"},  # --json: the function returns the dict anyway
}
PYTHON_ONLY = {
    "bounce drop": {"keep_trajectory"},  # a notebook keeps the samples without a file (FieldRole::notebook)
    # A series of files runs on every core on the command line, which has no --threads for it
    # (yet); a notebook may limit it.
    "bounce analyze": {"threads"},
    "incline analyze": {"threads"},
    "incline mu-from-slide": {"threads"},
}


@pytest.fixture(scope="module")
def schema():
    p = subprocess.run([_binary(), "schema", "--json"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout)["commands"]


# `import` is a Python keyword: `track import` is tribolab.track.load.
PYTHON_NAME = {"track import": "track load"}


def python_function(command):
    area, _, name = PYTHON_NAME.get(command, command).partition(" ")
    module = getattr(tribolab, area, None)
    return getattr(module, name.replace("-", "_"), None) if module else None


def keyword_of(option):
    return option.lstrip("-").replace("-", "_")


def test_every_command_is_in_python_but_the_listed(schema):
    missing = {c["command"] for c in schema if python_function(c["command"]) is None}
    assert missing == NOT_IN_PYTHON


def test_every_option_is_a_keyword_and_every_keyword_an_option(schema):
    mismatches = {}
    for c in schema:
        f = python_function(c["command"])
        if f is None:
            continue
        params = inspect.signature(f).parameters.values()
        # The command line's positional arguments (FILE, FILES) are Python's positional parameters.
        positional = [o for o in c["options"] if o["positional"]]
        py_positional = [p for p in params if p.kind is inspect.Parameter.POSITIONAL_OR_KEYWORD]
        options = ({keyword_of(o["name"]) for o in c["options"] if not o["positional"]}
                   - CLI_ONLY["*"] - CLI_ONLY.get(c["command"], set()))
        keywords = {p.name for p in params if p.kind is inspect.Parameter.KEYWORD_ONLY} - PYTHON_ONLY.get(c["command"], set())
        if options != keywords or len(positional) != len(py_positional):
            mismatches[c["command"]] = {"cli only": sorted(options - keywords), "python only": sorted(keywords - options),
                                        "positional": [len(positional), len(py_positional)]}
    assert mismatches == {}


def test_declared_fields_give_python_their_default_and_unit(schema):
    for c in schema:
        if not c["declared"] or c["command"] in NOT_IN_PYTHON:
            continue
        f = python_function(c["command"])
        params = inspect.signature(f).parameters
        for field in c["fields"]:
            p = params[field["python_keyword"]]
            if field["role"] != "input_files":
                # JSON has no infinity nor NaN: an unbounded default (track kinematics' t_from = -inf)
                # or a "not given" one (track rotation's pivot_x = nan) is null there; nor has it
                # tuples: a range (lo, hi, count) or a shard (i, N) is a list there.
                not_finite = isinstance(p.default, float) and not math.isfinite(p.default) and field["default"] is None
                default = list(p.default) if isinstance(p.default, tuple) else p.default
                assert not_finite or default == field["default"], (c["command"], field["name"])
            if field["unit"]:
                assert f"{field['name']} : " in f.__doc__ and field["unit"] in f.__doc__


def test_a_warning_names_the_keyword_not_the_flag(demo):
    # Without floor_y the floor is estimated; the warning names the field as Python spells it.
    r = tribolab.bounce.analyze([str(demo / "bounce" / "ordinary.txt")], track_a="A", track_b="B", time_scale=0.125)
    text = " ".join(r["warnings"])
    assert "floor_y" in text and "--floor-y" not in text
    assert "\x1e" not in text and "\x1f" not in text
