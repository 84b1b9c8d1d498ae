"""tribolab.bounce against `tribolab bounce ... --json`: the same dict to the last digit, arrays
of the right shapes, the CLI's error messages."""
import csv
import inspect

import numpy as np
import pytest

from conftest import assert_same_as_cli, as_keywords
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
    assert str(e.value) == as_keywords(cli.error("bounce", "simulate", "--vx", 0.5, "--vy", 4))
    with pytest.raises(ValueError) as e:
        tribolab.bounce.drop(height=-1)
    assert str(e.value) == as_keywords(cli.error("bounce", "drop", "--height", -1))


def test_unknown_keyword_is_type_error():
    for f in (tribolab.bounce.contact_time, tribolab.bounce.simulate, tribolab.bounce.drop):
        with pytest.raises(TypeError, match="unexpected keyword argument 'omgea'"):
            f(omgea=1)


def test_help_lists_the_law_with_units():
    p = inspect.signature(tribolab.bounce.simulate).parameters
    assert p["model"].default == "hunt-crossley" and p["K"].default is None and p["a"].default == 0.145
    doc = tribolab.bounce.simulate.__doc__
    assert "a : float, default 0.145" in doc and "semi-major axis, m" in doc


def test_analyze_equals_cli(cli, demo):
    f = demo / "bounce" / "ordinary.txt"
    kw = dict(track_a="A", track_b="B", time_scale=0.125)
    r = tribolab.bounce.analyze([str(f)], **kw)
    c = cli("bounce", "analyze", f, "--track-a", "A", "--track-b", "B", "--time-scale", 0.125)
    assert_same_as_cli(r, c)
    (fit,) = r["fits"]
    b = fit["body"]
    assert b["t"].shape == b["theta"].shape == b["omega"].shape and len(b["t"]) > 20
    # The tips are one rigid body: their distance is the ball's length 2a within the marking
    # noise (0.29 m for the default ball; 5 mm allows a few pixels of clicking).
    assert np.median(b["length"]) == pytest.approx(0.29, abs=5e-3)
    pre, post = fit["flight_pre"], fit["flight_post"]
    assert pre["t"].max() <= post["t"].min()  # the fitted flights lie on either side of the impact
    with pytest.raises(ValueError) as e:
        tribolab.bounce.analyze([str(f)], track_a="A", track_b="Q", time_scale=0.125)
    assert str(e.value) == as_keywords(cli.error("bounce", "analyze", f, "--track-a", "A", "--track-b", "Q", "--time-scale", 0.125))


def test_analyze_several_files_is_the_cli_series(cli, demo, tmp_path):
    # seed 001 experiment 2: several bounces, per-file floor heights, as `bounce analyze F1 F2 ...`.
    files = sorted((demo / "bounce_series").glob("*.txt"))[:3]
    assert len(files) == 3
    out = tmp_path / "bounces.csv"
    r = tribolab.bounce.analyze([str(f) for f in files], track_a="A", track_b="B", time_scale=0.125,
                                floor_y=[0.0], contact_duration=[0.004, 0.004, 0.004], bounces_out=str(out),
                                threads=2)
    out_cli = tmp_path / "bounces_cli.csv"
    c = cli("bounce", "analyze", *files, "--track-a", "A", "--track-b", "B", "--time-scale", 0.125,
            "--floor-y", 0, "--contact-duration", "0.004,0.004,0.004", "--bounces-out", out_cli)
    r_json = {k: v for k, v in r.items() if k != "fits"}
    r_json["summary"] = dict(r_json["summary"], bounces_out=str(out_cli))  # the file named differs
    assert r_json == c
    assert out.read_text() == out_cli.read_text()
    # A table a naive CSV reader opens (issue 27): the column line first, each row's file named.
    with open(out, newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [row["file"] for row in rows] == [str(f) for f in files]
    assert all(float(row["vy_in"]) < 0 for row in rows)
    assert len(r["fits"]) == 3 and all(f is not None for f in r["fits"])
    assert r["summary"]["n_runs"] == 3
    with pytest.raises(ValueError, match="contact_duration: gives 2 values for 3 files"):
        tribolab.bounce.analyze([str(f) for f in files], track_a="A", track_b="B", contact_duration=[0.004, 0.004])


def test_fit_equals_cli(cli, demo):
    f = demo / "bounce" / "table.csv"
    r = tribolab.bounce.fit(str(f), fix=["n=1.5"])
    c = cli("bounce", "fit", f, "--fix", "n=1.5")
    assert_same_as_cli(r, c)
    t = r["table"]
    assert t["vx_in"].shape == t["vx_pred"].shape == t["omega_pred"].shape and len(t["vx_in"]) > 3


def test_sweep_map_is_shaped_by_its_axes(cli, tmp_path):
    kw = dict(theta_deg=(100, 160, 4), omega=(30, 50, 3), threads=1)
    r = tribolab.bounce.sweep(out=str(tmp_path / "py.csv"), **kw)
    c = cli("bounce", "sweep", "--theta-deg", "100:160:4", "--omega", "30:50:3", "--threads", 1,
            "--out", tmp_path / "cli.csv")
    assert without_paths(r) == without_paths(c)
    assert list(r["axes"]) == ["theta_deg", "omega"]
    assert r["axes"]["theta_deg"].tolist() == [100, 120, 140, 160]
    e = r["map"]["e"]
    assert e.shape == (4, 3)
    # The map is the command's CSV, cell for cell (the last axis fastest).
    rows = list(csv.DictReader(line for line in open(tmp_path / "cli.csv") if not line.startswith("#")))
    assert [float(x["e"]) for x in rows] == e.ravel().tolist()
    with pytest.raises(ValueError) as err:
        tribolab.bounce.sweep(out=str(tmp_path / "bad.csv"), theta_deg=(100, 160, 0), omega=(30, 50, 3))
    assert str(err.value) == as_keywords(cli.error("bounce", "sweep", "--theta-deg", "100:160:0", "--omega", "30:50:3",
                                       "--out", tmp_path / "bad.csv"))
    with pytest.raises(TypeError):
        tribolab.bounce.sweep(out=str(tmp_path / "x.csv"), theta_deg="100:160:4", omega=(30, 50, 3))


def test_sweep_without_out_returns_the_same_map_and_keeps_no_file(tmp_path, monkeypatch):
    """out= is optional: the map comes back as arrays, its CSV lived in a removed temporary
    folder (before, the sweep refused to run: "out: an output file is required")."""
    import tempfile
    monkeypatch.setenv("TMPDIR", str(tmp_path))  # std::filesystem::temp_directory_path reads it
    tempfile.tempdir = None
    kw = dict(theta_deg=(100, 160, 4), omega=(30, 50, 3), threads=1)
    r = tribolab.bounce.sweep(**kw)
    kept = tribolab.bounce.sweep(out=str(tmp_path / "kept.csv"), **kw)
    assert r["out"] is None
    assert r["map"]["e"].tolist() == kept["map"]["e"].tolist()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["kept.csv"]


def test_sweep_plain_csv_reads_with_a_naive_csv_reader(tmp_path):
    """plain_csv= (--plain-csv): csv.DictReader reads it as it is, cell for cell the map."""
    r = tribolab.bounce.sweep(theta_deg=(100, 160, 4), omega=(30, 50, 3), threads=1,
                              plain_csv=str(tmp_path / "plain.csv"))
    rows = list(csv.DictReader(open(tmp_path / "plain.csv")))
    assert [float(x["e"]) for x in rows] == r["map"]["e"].ravel().tolist()
    assert (tmp_path / "plain.csv.meta.txt").read_text().startswith("# tribolab-sweep v")


def test_sweep_refuses_more_threads_than_it_may_start(cli, tmp_path):
    # Issue 26: threads=100000 killed the interpreter (std::terminate); now the CLI's error.
    with pytest.raises(ValueError, match=r"threads: must be 0 \(all cores\) to 1024, got 100000"):
        tribolab.bounce.sweep(out=str(tmp_path / "t.csv"), theta_deg=(100, 160, 4), omega=(30, 50, 3),
                              threads=100000)
    assert not list(tmp_path.iterdir())


def without_paths(j):
    """A sweep's JSON without the arrays, the key naming its output file and its timing (they
    differ by design)."""
    return {k: v for k, v in j.items() if k not in ("out", "axes", "map", "seconds", "cells_per_second")}


def test_synth_video_and_table_equal_cli(cli, tmp_path):
    # `bounce synth-video` and `synth-table` in Python (issue 23): the same files and keys.
    for name, kw, flags, files in [
            ("synth_video", dict(height=0.5, omega=20.0, seed=4), ["--height", 0.5, "--omega", 20, "--seed", 4], ("a.txt", "b.txt")),
            ("synth_table", dict(rows=6, seed=2), ["--rows", 6, "--seed", 2], ("a.csv", "b.csv"))]:
        a, b = tmp_path / files[0], tmp_path / files[1]
        r = getattr(tribolab.bounce, name)(out=str(a), **kw)
        c = cli("bounce", name.replace("_", "-"), *flags, "--out", b)
        assert {k: v for k, v in r.items() if k in c and k != "out"} == {k: v for k, v in c.items() if k != "out"}
        assert a.read_text() == b.read_text()
    assert r["table"]["vx_in"].shape == (6,)


def test_sweep_shards_and_merge_are_the_whole_map(tmp_path):
    # bounce.sweep(shard=...) and bounce.merge (issue 23): two shards joined are the unsharded
    # file byte for byte, as on the command line.
    kw = dict(theta_deg=(100, 120, 2), omega=(30, 40, 2), threads=1)
    whole = tmp_path / "whole.csv"
    tribolab.bounce.sweep(out=str(whole), **kw)
    parts = [tmp_path / f"s{i}.csv" for i in range(2)]
    for i, p in enumerate(parts):
        tribolab.bounce.sweep(out=str(p), shard=(i, 2), **kw)
    merged = tmp_path / "merged.csv"
    r = tribolab.bounce.merge([str(p) for p in parts], out=str(merged))
    assert r["shards"] == 2 and r["cells"] == 4
    assert merged.read_bytes() == whole.read_bytes()
    with pytest.raises(ValueError, match="shard"):
        tribolab.bounce.sweep(out=str(tmp_path / "bad.csv"), shard=(2, 2), **kw)
    # The command line's spelling "i/N" too (app/sweep/sweep_text.hpp), with its message.
    text = tmp_path / "s1_text.csv"
    tribolab.bounce.sweep(out=str(text), shard="1/2", **kw)
    assert text.read_bytes() == parts[1].read_bytes()
    with pytest.raises(ValueError) as err:
        tribolab.bounce.sweep(out=str(tmp_path / "bad.csv"), shard="1", **kw)
    assert str(err.value) == "shard: expected i/N with whole numbers 0 <= i < N (e.g. 0/4), got '1'"


def test_render_equals_cli(cli, tmp_path):
    # `bounce render` in Python (issue 23): the same keys and truth as the command line.
    kw = ["--size", "160x120", "--fps", 100, "--height", 0.3, "--after", 0.05, "--supersample", 1]
    r = tribolab.bounce.render(out=str(tmp_path / "py.avi"), size="160x120", fps=100.0, height=0.3, after=0.05,
                               supersample=1, truth=str(tmp_path / "py.csv"))
    c = cli("bounce", "render", *kw, "--out", tmp_path / "cli.avi", "--truth", tmp_path / "cli.csv")
    skip = ("out", "truth_file")
    assert {k: v for k, v in r.items() if k in c and k not in skip} == {k: v for k, v in c.items() if k not in skip}
    assert (tmp_path / "py.csv").read_text() == (tmp_path / "cli.csv").read_text()
    assert r["truth_tracks"]["ball"]["t"].shape == (r["frames"],)
