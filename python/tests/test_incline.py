"""tribolab.incline against `tribolab incline ... --json`: the same dict to the last digit, arrays
of the right shapes, the CLI's error messages."""
import numpy as np
import pytest

from conftest import assert_same_as_cli, as_keywords
import tribolab

LAUNCH = dict(mu=0.634, phi_deg=20.96, v0=2.62)
ARGS = ["--mu", 0.634, "--phi-deg", 20.96, "--v0", 2.62]


def test_predict_equals_cli(cli):
    r = tribolab.incline.predict(**LAUNCH)
    assert_same_as_cli(r, cli("incline", "predict", *ARGS))
    assert r["trajectory"]["x"].shape == (401,)  # the header's 401 samples


def test_simulate_equals_cli(cli, tmp_path):
    out = str(tmp_path / "run.csv")  # the command line requires --out
    r = tribolab.incline.simulate(**LAUNCH, dt=0.01, out=out)
    assert_same_as_cli(r, cli("incline", "simulate", *ARGS, "--dt", 0.01, "--out", out))
    assert r["trajectory"]["t"].ndim == 1 and len(r["trajectory"]["t"]) > 10


def test_families_are_2d(cli, tmp_path):
    out = str(tmp_path / "fam.csv")
    r = tribolab.incline.families(mu=0.634, phi_deg=20.96, vary="v0", values=[1, 2, 3], samples=50, out=out)
    assert_same_as_cli(r, cli("incline", "families", "--mu", 0.634, "--phi-deg", 20.96, "--vary", "v0",
                              "--values", "1,2,3", "--samples", 50, "--out", out))
    assert r["curves"]["x"].shape == (3, 50)  # (len(values), samples)


def test_mu_from_stop_equals_cli(cli):
    kw = dict(phi_deg=10.37, x_stop=0.214, y_stop=-0.036, sigma_phi_deg=0.1, sigma_pos=0.002)
    r = tribolab.incline.mu_from_stop(**kw)
    assert r == cli("incline", "mu-from-stop", "--phi-deg", 10.37, "--x-stop", 0.214, "--y-stop", -0.036,
                    "--sigma-phi-deg", 0.1, "--sigma-pos", 0.002)


def test_bad_input_is_value_error_with_the_cli_message(cli):
    with pytest.raises(ValueError) as e:
        tribolab.incline.predict(mu=0.634, phi_deg=95, v0=2.62)
    assert str(e.value) == as_keywords(cli.error("incline", "predict", "--mu", 0.634, "--phi-deg", 95, "--v0", 2.62))


def test_unknown_keyword_is_type_error():
    with pytest.raises(TypeError, match="unexpected keyword argument 'phi'"):
        tribolab.incline.predict(mu=0.6, phi=20, v0=1)


def test_analyze_equals_cli(cli, demo):
    f = demo / "incline" / "run_20.96deg.txt"
    r = tribolab.incline.analyze([str(f)], phi_deg=[20.96])
    c = cli("incline", "analyze", f, "--phi-deg", 20.96)
    assert_same_as_cli(r, c)
    (fit,) = r["fits"]
    assert fit["data"]["t"].shape == (c["n_points"],)
    # Model B's residuals are the data minus the fit: their rms is the reported rms residual
    # (m; the fit's own number, computed over x and y together).
    rms = np.sqrt(np.mean(np.concatenate([fit["residual_x_b"], fit["residual_y_b"]]) ** 2))
    assert rms == pytest.approx(c["rms_residual"], rel=1e-6)
    with pytest.raises(ValueError) as e:
        tribolab.incline.analyze([str(f)], phi_deg=[95.0])
    assert str(e.value) == as_keywords(cli.error("incline", "analyze", f, "--phi-deg", 95))


def test_mu_from_slide_equals_cli(cli, demo):
    f = demo / "incline" / "slide_41.09deg.txt"
    r = tribolab.incline.mu_from_slide([str(f)], phi_deg=[41.09])
    c = cli("incline", "mu-from-slide", f, "--phi-deg", 41.09)
    assert_same_as_cli(r, c)
    (s,) = r["slides"]
    # Positions at every moving point; speeds by central differences, so two fewer (the ends).
    assert s["t"].shape == s["s"].shape and s["v"].shape == s["v_t"].shape == (len(s["t"]) - 2,)


def test_length_unit_keyword(cli, demo, tmp_path):
    """length_unit= as --length-unit: a slide written in cm, declared so, gives the metre file's a."""
    f = demo / "incline" / "slide_41.09deg.txt"
    rows = []
    for line in open(f, encoding="utf-8"):
        try:
            rows.append([float(c) for c in line.split()[:3]])
        except ValueError:
            pass  # the name and header rows
    rows = [r for r in rows if len(r) == 3]
    assert len(rows) > 20
    cm = tmp_path / "slide_cm.csv"
    cm.write_text("t,x,y\n" + "".join("%r,%r,%r\n" % (t, 100 * x, 100 * y) for t, x, y in rows))
    metres = tribolab.incline.mu_from_slide([str(f)], phi_deg=[41.09])
    r = tribolab.incline.mu_from_slide([str(cm)], phi_deg=[41.09], length_unit="cm")
    assert r["a"] == pytest.approx(metres["a"], rel=1e-6)
    assert_same_as_cli(r, cli("incline", "mu-from-slide", cm, "--phi-deg", 41.09, "--length-unit", "cm"))


def test_report_plotly_keyword(tmp_path):
    # plotly="file": the page links plotly-<version>.min.js written once beside it (as --plotly file).
    page = tmp_path / "p.html"
    tribolab.incline.predict(**LAUNCH, report=str(page), plotly="file")
    scripts = list(tmp_path.glob("plotly-*.min.js"))
    assert len(scripts) == 1
    assert f'<script src="{scripts[0].name}"></script>' in page.read_text(encoding="utf-8")
    assert page.stat().st_size < 200_000 < scripts[0].stat().st_size
    cdn = tmp_path / "c.html"
    tribolab.incline.predict(**LAUNCH, report=str(cdn), plotly="cdn")
    assert 'integrity="sha384-' in cdn.read_text(encoding="utf-8")
    # The keyword, not the command line's --plotly (docs/design.md "Errors").
    with pytest.raises(ValueError, match=r"^plotly: 'web' is not one of embed, cdn, file$"):
        tribolab.incline.predict(**LAUNCH, report=str(tmp_path / "x.html"), plotly="web")
    assert not (tmp_path / "x.html").exists()


def test_synth_equals_cli(cli, tmp_path):
    # `incline synth` in Python (issue 23): the same file and keys as the command line.
    a, b = tmp_path / "py.txt", tmp_path / "cli.txt"
    r = tribolab.incline.synth(mu=0.634, phi_deg=20.96, v0=2.62, seed=3, out=str(a))
    c = cli("incline", "synth", "--mu", 0.634, "--phi-deg", 20.96, "--v0", 2.62, "--seed", 3, "--out", b)
    assert {k: v for k, v in r.items() if k in c and k != "out"} == {k: v for k, v in c.items() if k != "out"}
    assert a.read_text() == b.read_text()
    assert r["track_points"]["t"].shape == (r["points"],) == r["truth"]["x"].shape
    with pytest.raises(ValueError, match="^fps: "):
        tribolab.incline.synth(mu=0.634, phi_deg=20.96, v0=2.62, fps=0)


def test_normal_friction_test_equals_cli(cli, demo):
    # `incline normal-friction-test` in Python (issue 23): the same keys and numbers.
    runs = [("run_12deg.csv", 12), ("run_16deg.txt", 16), ("run_20.96deg.txt", 20.96), ("run_25deg.txt", 25)]
    files = [str(demo / "incline" / f) for f, _ in runs]
    angles = [a for _, a in runs]
    r = tribolab.incline.normal_friction_test(files, phi_deg=angles)
    c = cli("incline", "normal-friction-test", *files, "--phi-deg", ",".join(str(a) for a in angles))
    assert_same_as_cli(r, c)
    assert r["points"]["tan_phi"].shape == (len(runs),)


def test_render_equals_cli(cli, tmp_path):
    # `incline render` in Python (issue 25): the same keys and truth as the command line.
    kw = ["--size", "160x120", "--duration", 0.2, "--supersample", 1]
    r = tribolab.incline.render(mu=0.45, phi_deg=20.0, v0=1.2, size="160x120", duration=0.2, supersample=1,
                                out=str(tmp_path / "py.avi"), truth=str(tmp_path / "py.csv"))
    c = cli("incline", "render", "--mu", 0.45, "--phi-deg", 20, "--v0", 1.2, *kw, "--out", tmp_path / "cli.avi",
            "--truth", tmp_path / "cli.csv")
    skip = ("out", "truth_file")
    assert {k: v for k, v in r.items() if k in c and k not in skip} == {k: v for k, v in c.items() if k not in skip}
    assert (tmp_path / "py.csv").read_text() == (tmp_path / "cli.csv").read_text()
    assert r["truth_track"]["x"].shape == (r["frames"],)
