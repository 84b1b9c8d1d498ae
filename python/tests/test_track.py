"""tribolab.track against `tribolab track ... --json` on the shipped demo data: the same dict to
the last digit, arrays of the right shape, the CLI's error messages."""
import numpy as np
import pytest

from conftest import assert_same_as_cli, as_keywords
import tribolab

THROW = "data/demo/bounce/ordinary.txt"  # Tracker export, tracks A and B (tips of the ball), 165 frames


@pytest.fixture(autouse=True)
def in_source_dir(monkeypatch):
    from conftest import SOURCE_DIR
    monkeypatch.chdir(SOURCE_DIR)  # paths in the JSON are as given, relative


def test_load_equals_cli():
    r = tribolab.track.load(THROW, time_scale=0.125)
    cli_json = __import__("conftest").Cli()("track", "import", THROW, "--time-scale", "0.125")
    assert_same_as_cli(r, cli_json)
    a = r["points"]["A"]
    assert a["t"].shape == a["x"].shape == (cli_json["tracks"]["A"]["points"],)
    assert a["frame"].dtype.kind == "i"
    assert a["t"].min() == cli_json["tracks"]["A"]["t_min"]  # s, after the time scale


def test_kinematics_equals_cli(tmp_path):
    out = str(tmp_path / "k.csv")
    for method in ("tracker", "savgol"):
        r = tribolab.track.kinematics(THROW, track="A", method=method, out=out)
        cli_json = __import__("conftest").Cli()("track", "kinematics", THROW, "--track", "A",
                                               "--method", method, "--out", out)
        assert_same_as_cli(r, cli_json)
        rows = r["rows"]
        assert rows["vx"].shape == (cli_json["points"],)
        # Tracker's stencils give no standard errors (NaN), Savitzky-Golay does.
        assert np.isnan(rows["sigma_vx"]).all() == (method == "tracker")


def test_rigid_body_equals_cli():
    r = tribolab.track.rigid_body(THROW, track_a="A", track_b="B", time_scale=0.125)
    cli_json = __import__("conftest").Cli()("track", "rigid-body", THROW, "--track-a", "A",
                                           "--track-b", "B", "--time-scale", "0.125")
    assert_same_as_cli(r, cli_json)
    rows = r["rows"]
    assert rows["theta"].shape == (cli_json["frames"],)
    assert np.allclose(rows["length"].mean(), cli_json["length_mean"], rtol=1e-12, atol=0)  # same sum, m


def test_kinematics_time_range_equals_cli(tmp_path):
    out = str(tmp_path / "k.csv")
    r = tribolab.track.kinematics(THROW, track="A", t_from=1.0, t_to=3.0, out=out)
    cli_json = __import__("conftest").Cli()("track", "kinematics", THROW, "--track", "A",
                                           "--from", "1.0", "--to", "3.0", "--out", out)
    assert_same_as_cli(r, cli_json)
    assert r["rows"]["t"].min() >= 1.0 and r["rows"]["t"].max() <= 3.0


def test_rotation_equals_cli(tmp_path):
    import math
    marks = tmp_path / "wheel.csv"
    lines = ["track,frame,t,x,y"]
    for i in range(40):  # a mark 0.3 m from (0.4, 0.5) at 22.7 rad/s, 30 fps, a 1 mm wobble
        t = i / 30
        lines.append(f"mark,{i},{t!r},{0.4 + 0.3 * math.cos(22.7 * t) + 0.001 * math.sin(7 * i)!r},"
                     f"{0.5 + 0.3 * math.sin(22.7 * t) + 0.001 * math.cos(5 * i)!r}")
    marks.write_text("\n".join(lines) + "\n")
    r = tribolab.track.rotation(str(marks))
    cli_json = __import__("conftest").Cli()("track", "rotation", str(marks))
    assert_same_as_cli(r, cli_json)
    assert abs(r["omega"] - 22.7) < 4 * r["sigma_omega"]
    assert r["rows"]["theta"].shape == (40,)


def test_bad_input_is_value_error_with_the_cli_message(tmp_path, cli):
    out = str(tmp_path / "k.csv")
    with pytest.raises(ValueError) as e:
        tribolab.track.kinematics(THROW, track="A", method="savgol", window=2, out=out)
    assert str(e.value) == as_keywords(cli.error("track", "kinematics", THROW, "--track", "A", "--method", "savgol",
                                     "--window", "2", "--out", out))
    with pytest.raises(ValueError) as e:
        tribolab.track.rigid_body(THROW, track_a="A", track_b="nope")
    assert str(e.value) == as_keywords(cli.error("track", "rigid-body", THROW, "--track-a", "A", "--track-b", "nope"))
    missing = str(tmp_path / "missing.avi")
    with pytest.raises(ValueError) as e:
        tribolab.track.video(missing, out=out, start=["p=10,10"])
    assert str(e.value) == as_keywords(cli.error("track", "video", missing, "--out", out, "--start", "p=10,10"))


def test_unknown_keyword_is_type_error():
    for f in (tribolab.track.load, tribolab.track.kinematics, tribolab.track.rigid_body, tribolab.track.video):
        with pytest.raises(TypeError, match="unexpected keyword argument 'time_scal'"):
            f(THROW, time_scal=1)


def test_defaults_are_the_cli_defaults():
    import inspect
    p = inspect.signature(tribolab.track.kinematics).parameters
    assert (p["method"].default, p["window"].default, p["order"].default, p["impacts"].default) == \
        ("tracker", 7, 2, "auto")
    assert inspect.signature(tribolab.track.load).parameters["time_scale"].default == 1.0


def test_a_lost_track_is_warned_naming_the_keywords_that_help(tmp_path, cli):
    # The core names the options that help as fields (numerics/error.hpp); Python spells them as
    # its keywords (max_gap, ellipse_min_score), never the command line's --max-gap, and no
    # field mark (a control character) is left in the text. The same film as
    # cli/track_video_test.cpp: a ball leaving a 160 px view, given up after max_gap=1 lost frames.
    import csv

    film, truth = str(tmp_path / "ball.avi"), str(tmp_path / "truth.csv")
    r = tribolab.bounce.render(out=film, truth=truth, size="160x120", fps=60, height=0.5, vx=3, after=0.3,
                               scale=0.006, background="plain")
    ox, oy = r["origin_px"]
    x, y = [(float(p["x"]), float(p["y"])) for p in csv.DictReader(open(truth)) if p["track"] == "ball"][6]
    origin, ellipse = f"{ox},{oy}", f"ball={ox + x / 0.006},{oy - y / 0.006}@6"  # frame 6: the whole ball in view
    out = str(tmp_path / "e.csv")
    result = tribolab.track.video(film, scale=0.006, origin=origin, ellipse=[ellipse], max_gap=1, out=out)
    [warning] = result["warnings"]
    assert warning.startswith("track 'ball': lost"), warning
    assert "given up after more than max_gap (1) lost frames" in warning, warning
    assert "a lower ellipse_min_score" in warning, warning
    assert "--" not in warning and "\x1e" not in warning and "\x1f" not in warning, warning
    cli_json = cli("track", "video", film, "--scale", "0.006", "--origin", origin, "--ellipse", ellipse,
                   "--max-gap", "1", "--out", out)
    assert warning == as_keywords(cli_json["warnings"][0])
