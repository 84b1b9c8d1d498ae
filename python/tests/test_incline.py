"""tribolab.incline against `tribolab incline ... --json`: the same dict to the last digit, arrays
of the right shapes, the CLI's error messages."""
import pytest

from conftest import assert_same_as_cli
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
    assert str(e.value) == cli.error("incline", "predict", "--mu", 0.634, "--phi-deg", 95, "--v0", 2.62)


def test_unknown_keyword_is_type_error():
    with pytest.raises(TypeError, match="unexpected keyword argument 'phi'"):
        tribolab.incline.predict(mu=0.6, phi=20, v0=1)
