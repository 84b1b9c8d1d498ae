"""Errors name the keyword, not the command line's flag (docs/design.md "Errors"): the core
names fields, each front end spells them (`--time-scale` on the command line, `time_scale`
here), and output paths are checked before any work as the command line checks them."""
import re

import pytest

import tribolab

from conftest import SOURCE_DIR

THROW = str(SOURCE_DIR / "data" / "demo" / "bounce" / "ordinary.txt")


def _raises_naming(keyword, fn, *args, **kw):
    with pytest.raises(ValueError) as e:
        fn(*args, **kw)
    message = str(e.value)
    assert "--" not in message, message  # no command-line flag
    assert re.search(rf"(?<![\w-]){keyword}(?![\w-])", message), message
    return message


def test_errors_of_several_functions_name_the_keyword(tmp_path):
    out = str(tmp_path / "k.csv")
    m = _raises_naming("order", tribolab.track.kinematics, THROW, track="A", method="savgol", order=9, out=out)
    assert m == "order must be 1..6, got 9"
    _raises_naming("time_scale", tribolab.bounce.analyze, [THROW], track_a="A", track_b="B", time_scale=-1)
    _raises_naming("track_a", tribolab.bounce.analyze, [THROW], track_a="A", track_b="A")
    _raises_naming("phi_deg", tribolab.incline.predict, mu=0.634, phi_deg=95, v0=2.62)
    _raises_naming("vy", tribolab.bounce.simulate, vx=0.5, vy=4)
    _raises_naming("slip_scale", tribolab.bounce.simulate, vx=0.5, vy=-4, friction="regularized", slip_scale=-1)
    _raises_naming("impact", tribolab.bounce.analyze, [THROW], track_a="A", track_b="B", time_scale=0.125, impact=9)
    m = _raises_naming("start", tribolab.track.video, THROW, out=out)
    assert m == "nothing to track: give start, ellipse or from_track"


def test_output_paths_are_checked_before_any_work(tmp_path):
    same = str(tmp_path / "same.html")
    m = _raises_naming("report", tribolab.incline.simulate, mu=0.3, phi_deg=20, v0=2, out=same, report=same)
    assert m == f"out and report name the same file '{same}'; choose two names"
    _raises_naming("report", tribolab.incline.predict, mu=0.3, phi_deg=20, v0=2, report=str(tmp_path / "r.txt"))
    m = _raises_naming("out", tribolab.track.kinematics, THROW, track="A", out=str(tmp_path / "missing" / "k.csv"))
    assert "does not exist" in m
    m = _raises_naming("out", tribolab.track.load, THROW, out=THROW)
    assert "is also the input file" in m
    assert not (tmp_path / "same.html").exists() and not (tmp_path / "r.txt").exists()


def test_a_bool_is_no_number(tmp_path):
    # Regression (issue 26): mu=True was taken as 1.0.
    with pytest.raises(TypeError, match=r"simulate\(\): mu must be float, got bool"):
        tribolab.bounce.simulate(vx=0.5, vy=-4, mu=True)
    with pytest.raises(TypeError, match="got bool"):
        tribolab.incline.predict(mu=0.634, phi_deg=False, v0=2.62)
    assert tribolab.bounce.simulate(vx=0.5, vy=-4, mu=1)["e"] > 0  # an int is a number


def test_a_path_with_a_nul_is_refused_not_cut_short(tmp_path):
    # Regression (issue 26): "run.csv\0.txt" opened (or wrote) "run.csv".
    out = str(tmp_path / "k.csv")
    with pytest.raises(ValueError, match="out contains a NUL character"):
        tribolab.incline.simulate(mu=0.3, phi_deg=20, v0=2, out=out + "\0.txt")
    assert not (tmp_path / "k.csv").exists()
    with pytest.raises(ValueError, match="NUL"):
        tribolab.track.kinematics(THROW + "\0x", track="A", out=out)


def test_a_subnormal_is_a_value_error(tmp_path):
    # Regression (issue 26): K=1e-320 raised RuntimeError where ValueError is documented.
    _raises_naming("K", tribolab.bounce.simulate, vx=0.5, vy=-4, K=1e-320)
