"""tribolab.bounce against `tribolab bounce ... --json`: the same dict to the last digit, arrays
of the right shapes, the CLI's error messages."""
import inspect

import numpy as np
import pytest

from conftest import assert_same_as_cli
import tribolab


def test_contact_time_equals_cli(cli):
    r = tribolab.bounce.contact_time(height=0.715, omega=-47.6, theta_deg=11.3)
    c = cli("bounce", "contact-time", "--height", 0.715, "--omega", -47.6, "--theta-deg", 11.3)
    assert_same_as_cli(r, c)
    f = r["flight"]
    assert f["t"].shape == f["gap"].shape and len(f["t"]) > 1
    assert f["t"][-1] == pytest.approx(c["t_contact"], rel=1e-9)  # the samples end at the touch, s


def test_simulate_equals_cli(cli):
    r = tribolab.bounce.simulate(vx=0.5, vy=-4, omega=40, theta_deg=30)
    c = cli("bounce", "simulate", "--vx", 0.5, "--vy", -4, "--omega", 40, "--theta-deg", 30)
    assert_same_as_cli(r, c)
    h = r["contact"]
    assert h["N"].shape == h["t"].shape and len(h["t"]) > 10
    # The steps' largest force is at most the located peak (N) and near it: the integrator's
    # steps straddle the peak (0.1 % here, 2 % allowed).
    assert 0.98 * c["peak_force"] < h["N"].max() <= c["peak_force"] * (1 + 1e-12)


def test_drop_equals_cli(cli):
    kw = dict(height=0.6, omega=-40, model="hertz", bounces=3)
    r = tribolab.bounce.drop(**kw)
    c = cli("bounce", "drop", "--height", 0.6, "--omega", -40, "--model", "hertz", "--bounces", 3)
    assert_same_as_cli(r, c)
    assert r["samples"]["t"].shape == (0,)  # no trajectory asked
    s = tribolab.bounce.drop(**kw, keep_trajectory=True)["samples"]
    assert s["y"].ndim == 1 and len(s["y"]) > 100 and np.all(np.diff(s["t"]) >= 0)  # s, in order


def test_bad_input_is_value_error_with_the_cli_message(cli):
    with pytest.raises(ValueError) as e:
        tribolab.bounce.simulate(vx=0.5, vy=4)
    assert str(e.value) == cli.error("bounce", "simulate", "--vx", 0.5, "--vy", 4)
    with pytest.raises(ValueError) as e:
        tribolab.bounce.drop(height=-1)
    assert str(e.value) == cli.error("bounce", "drop", "--height", -1)


def test_unknown_keyword_is_type_error():
    for f in (tribolab.bounce.contact_time, tribolab.bounce.simulate, tribolab.bounce.drop):
        with pytest.raises(TypeError, match="unexpected keyword argument 'omgea'"):
            f(omgea=1)


def test_help_lists_the_law_with_units():
    p = inspect.signature(tribolab.bounce.simulate).parameters
    assert p["model"].default == "hunt-crossley" and p["K"].default is None and p["a"].default == 0.145
    doc = tribolab.bounce.simulate.__doc__
    assert "a : float, default 0.145" in doc and "semi-major axis, m" in doc
