"""The binding mechanism (python/src/bind.hpp, tribolab/_commands.py) on a command made to test
it: defaults from the C++ struct, keywords, types, errors, GIL, JSON numbers, arrays."""
import inspect
import json

import numpy as np
import pytest

import tribolab
from tribolab import _selftest


def test_defaults_come_from_the_options_struct():
    sig = inspect.signature(_selftest.echo)
    # The member initializers of SelftestOptions / SelftestGroup (python/src/selftest.hpp).
    assert sig.parameters["g"].default == 9.81
    assert sig.parameters["mu"].default is None
    assert sig.parameters["n"].default == 3
    assert sig.parameters["model"].default == "B"
    assert sig.parameters["values"].default == []
    assert sig.parameters["files"].kind is inspect.Parameter.POSITIONAL_OR_KEYWORD
    assert sig.parameters["g"].kind is inspect.Parameter.KEYWORD_ONLY
    echo = _selftest.echo([])["echo"]
    assert echo == {"files": [], "g": 9.81, "n": 3, "model": "B", "flag": False, "values": [], "mu": None}


def test_keywords_reach_the_nested_fields():
    r = _selftest.echo(["a.txt", "b.txt"], g=9.5, mu=0.25, n=7, model="A", flag=True, values=[1, 2.5])
    assert r["echo"] == {"files": ["a.txt", "b.txt"], "g": 9.5, "n": 7, "model": "A", "flag": True,
                         "values": [1.0, 2.5], "mu": 0.25}


def test_input_error_is_value_error_with_the_cli_message():
    with pytest.raises(ValueError) as e:
        _selftest.echo([], n=0)
    # InputError(field("n"), ...): one line, the field named as the keyword (the command line
    # would print --n).
    assert str(e.value) == "n: must be in [1, 100], got 0 second line"


def test_unknown_keyword_and_wrong_type_are_type_errors():
    with pytest.raises(TypeError, match="unexpected keyword argument 'nn'"):
        _selftest.echo([], nn=1)
    with pytest.raises(TypeError, match="unexpected keyword argument 'nn'"):
        _selftest._ext._echo(nn=1)  # the extension checks too, without the wrapper
    with pytest.raises(TypeError, match="n must be int, got str"):
        _selftest.echo([], n="3")
    with pytest.raises(TypeError):
        _selftest.echo()  # the positional argument is required


def test_call_runs_without_the_gil():
    assert _selftest.echo([])["gil_held"] is False


def test_json_converter_is_exact():
    text = ('{"a": 0.1, "b": 1e-310, "c": 12345678901234567, "d": -3, "e": null, "f": true, '
            '"g": [1.5, "x", {"h": 2.2250738585072014e-308}], "i": 0.30000000000000004}')
    assert _selftest.to_python(text) == json.loads(text)
    # Every double survives nlohmann's dump -> json.loads and the converter alike.
    values = [0.1, 1 / 3, 2 / 3, 1e300, -7.25e-5, 5e-324, 1.7976931348623157e308, 123456.789]
    dumped = _selftest.dump(json.dumps(values))
    assert json.loads(dumped) == values == _selftest.to_python(dumped)
    assert isinstance(_selftest.to_python("3"), int) and isinstance(_selftest.to_python("3.0"), float)


def test_arrays_have_the_shape_of_the_result():
    g = _selftest.echo([], rows=4, cols=5)["grid"]
    assert isinstance(g, np.ndarray) and g.dtype == np.float64 and g.shape == (4, 5)
    assert g[1, 0] == 5.0  # row-major


def test_help_reads_well():
    doc = _selftest.echo.__doc__
    assert "g : float, default 9.81" in doc
    assert "an acceleration with a default, m/s^2" in doc  # the /// comment of the field
    assert "mu : float or None, default None" in doc
    assert "ValueError" in doc


def test_package_imports_every_area():
    assert {"incline", "bounce", "track"} <= set(dir(tribolab))


def test_threads_calling_before_numpy_is_imported_do_not_deadlock():
    # Issue 26: two threads calling tribolab before anyone imported numpy hung forever (pybind11
    # looked numpy's C API up lazily, in a static that one thread initialised under a released GIL
    # while the other waited on it holding the GIL). A fresh interpreter: pytest has numpy loaded.
    import subprocess
    import sys
    script = (
        "import sys, threading\n"
        "from tribolab import _selftest\n"
        "out = []\n"
        "def call():\n"
        "    for _ in range(20):\n"
        "        out.append(_selftest.echo([], rows=3, cols=2)['grid'].shape)\n"
        "ts = [threading.Thread(target=call) for _ in range(4)]\n"
        "[t.start() for t in ts]\n"
        "[t.join() for t in ts]\n"
        "print(len(out))\n")
    # 60 s: the script takes ~0.3 s; a deadlock never ends, so any generous bound tells them apart.
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "80"
