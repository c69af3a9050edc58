"""`track` from Python against the CLI on the shipped wrist trial: the same .tra for the same
arguments, the per-frame records, stopping from the callback, refusals."""
import numpy as np
import pytest

import fluoromatch as fm
from conftest import REPO

TRIAL = str(REPO / "data" / "trials" / "wrist.json")


@pytest.fixture
def wrist(data_dir):
    if not (data_dir / "autoscoper-bvr").exists():
        pytest.fail("autoscoper-bvr missing from the shared data")
    return TRIAL


def test_the_radius_as_the_cli_tracks_it(wrist, cli, tmp_path):
    cli("track", "--trial", wrist, "--bone", "radius", "--frames", "0:2", "--threads", "2", "--out", tmp_path / "cli.tra")
    frames = []
    result = fm.track(wrist, "radius", frames="0:2", threads=2, out=str(tmp_path / "py.tra"), progress=frames.append)
    assert (tmp_path / "py.tra").read_bytes() == (tmp_path / "cli.tra").read_bytes()
    np.testing.assert_allclose(result["poses"], fm.read_tra(tmp_path / "cli.tra")[:, 0], atol=1e-12)
    assert [r["frame"] for r in result["frames"]] == [0, 1, 2]
    # From the keyframe on: each frame judged against the last good one's similarity.
    for r in result["frames"]:
        assert r["status"] == "tracked" and r["verdict"] == "ok", r["verdict_text"]
        assert r["similarity_ratio"] >= 0.9 and r["uncertainty"]["evaluations"] == 73
    assert len(frames) == 3 and frames[-1]["done"] == 3 and frames[-1]["total"] == 3
    assert all(len(r["costs"]) == 2 for r in result["frames"])


def test_several_bones_and_a_stop(wrist):
    calls = []
    results = fm.track(wrist, ["radius", "ulna"], frames="0:2", progress=lambda p: calls.append(p) or False)
    assert set(results) == {"radius", "ulna"}
    assert results["radius"]["stopped"] and len(calls) == 1
    assert np.isnan(results["radius"]["poses"][1:]).all()


def test_refusals(wrist, tmp_path):
    with pytest.raises(fm.Error, match="radius, ulna, mc3"):
        fm.track(wrist, "femur")
    with pytest.raises(fm.Error, match="frames 0..2"):
        fm.track(wrist, "radius", frames="0:5")
    with pytest.raises(fm.Error, match="cameras"):
        fm.track(wrist, "radius", cameras=[3])
    with pytest.raises(fm.Error, match=".tra"):
        fm.track(wrist, "radius", out=str(tmp_path / "x.csv"))
