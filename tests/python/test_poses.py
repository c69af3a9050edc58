"""Pose files and parameterizations: .jts rows and Autoscoper xyzypr against rotation matrices
computed here, the JTML .jts files read, .tra and .jts written and read back (NaN frames too),
files the CLI wrote read, and bad files refused by name and line; compare_poses scores known
errors as `fluoromatch compare` does."""
import numpy as np
import pytest

import fluoromatch as fm
from conftest import pose, rotation


def test_jts_rows_are_rz_rx_ry_and_back():
    row = [12.0, -7.5, -980.0, 30.0, -20.0, 65.0]  # x, y, z, z_rot, x_rot, y_rot
    m = fm.jts_to_matrix(row)
    r = rotation("z", 30) @ rotation("x", -20) @ rotation("y", 65)
    np.testing.assert_allclose(m, pose(r, row[:3]), atol=1e-12)
    np.testing.assert_allclose(fm.matrix_to_jts(m), row, atol=1e-9)


def test_xyzypr_is_rz_ry_rx_and_back():
    v = [1.0, 2.0, 3.0, 40.0, -25.0, 70.0]  # x, y, z, yaw, pitch, roll
    m = fm.xyzypr_to_matrix(v)
    np.testing.assert_allclose(m, pose(rotation("z", 40) @ rotation("y", -25) @ rotation("x", 70), v[:3]), atol=1e-12)
    np.testing.assert_allclose(fm.matrix_to_xyzypr(m), v, atol=1e-9)
    with pytest.raises(fm.Error, match="6 numbers"):
        fm.xyzypr_to_matrix([1, 2, 3])


def test_the_jtml_jts_files(jtml):
    fem = fm.read_jts(jtml / "fem.jts")
    assert fem.shape == (3, 4, 4)
    assert np.all(np.isfinite(fem))
    text = (jtml / "fem.jts").read_text().splitlines()
    first = [float(x) for x in text[2].split(",")]
    np.testing.assert_allclose(fm.matrix_to_jts(fem[0]), first, atol=1e-6)


def test_written_pose_files_read_back(tmp_path):
    rng = np.random.default_rng(7)
    poses = np.stack([fm.xyzypr_to_matrix(np.r_[rng.uniform(-50, 50, 3), rng.uniform(-80, 80, 3)]) for _ in range(4)])
    poses[2] = np.nan  # a frame without a pose
    fm.write_jts(tmp_path / "p.jts", poses)
    back = fm.read_jts(tmp_path / "p.jts")
    assert np.all(np.isnan(back[2]))
    np.testing.assert_allclose(back[[0, 1, 3]], poses[[0, 1, 3]], atol=1e-8)
    two = np.stack([poses, poses[::-1]], axis=1)  # (frames, objects, 4, 4)
    for form in ("matrix", "xyzypr"):
        fm.write_tra(tmp_path / f"p_{form}.tra", two, form=form)
        back = fm.read_tra(tmp_path / f"p_{form}.tra", form=form, objects=2)
        assert back.shape == (4, 2, 4, 4)
        assert np.all(np.isnan(back[2, 0])) and np.all(np.isnan(back[1, 1]))
        ok = np.isfinite(two)
        np.testing.assert_allclose(back[ok], two[ok], atol=1e-10)
    one = fm.read_tra(tmp_path / "p_matrix.tra")  # 32 numbers a row: two matrices, decided
    assert one.shape == (4, 2, 4, 4)


def test_bad_pose_files_name_the_file_and_line(tmp_path):
    (tmp_path / "bad.jts").write_text("JT_EULER_312\nx,y,z,zr,xr,yr\n1,2,3,4,5\n")
    with pytest.raises(fm.Error, match=r"bad.jts.*line 3"):
        fm.read_jts(tmp_path / "bad.jts")
    (tmp_path / "bad.tra").write_text("1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,2\n")
    with pytest.raises(fm.Error, match="bad.tra"):
        fm.read_tra(tmp_path / "bad.tra")
    with pytest.raises(fm.Error, match="partly NaN"):
        p = np.eye(4)[None].copy()
        p[0, 0, 1] = np.nan
        fm.write_tra(tmp_path / "x.tra", p)
    with pytest.raises(fm.Error, match="rotation|orthonormal|determinant"):
        m = 2 * np.eye(4)
        m[3, 3] = 1
        fm.write_tra(tmp_path / "x.tra", m[None])


def test_the_2011_parameters_as_an_object_pose_give_the_same_image():
    knee = fm.read_volume("phantom:knee")
    prepared = fm.prepare(knee)
    params = [6.0, -4.0, 3.0, 35.0, -20.0, 15.0]
    zero = fm.scene_geometry([0] * 6, knee.center, size=(96, 96))
    moved_camera = prepared.render(fm.scene_geometry(params, knee.center, size=(96, 96)))
    moved_object = prepared.render(zero, pose=fm.pose_from_2011(params, knee.center))
    assert moved_camera.max() > 1
    np.testing.assert_allclose(moved_object, moved_camera, rtol=1e-4, atol=1e-4)
    np.testing.assert_allclose(fm.pose_from_2011([0] * 6, knee.center), np.eye(4), atol=1e-12)
    with pytest.raises(fm.Error, match="elevation"):
        fm.pose_from_2011([0, 0, 0, 0, 95, 0], knee.center)


def axis_rotation(axis, deg):
    """Rodrigues: the rotation by deg about a unit axis (independent of the engine)."""
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    t = np.radians(deg)
    return np.eye(3) + np.sin(t) * k + (1 - np.cos(t)) * k @ k


def test_compare_poses_scores_known_errors_and_names_missing_frames(cli, tmp_path):
    rng = np.random.default_rng(4)
    centre = np.array([12.0, -5.0, 30.0])
    truth, result, shifts, angles = [], [], [], []
    for f in range(8):
        t = pose(axis_rotation(rng.normal(size=3), rng.uniform(0, 90)), rng.normal(size=3) * 50)
        shift = rng.normal(size=3) * 0.4
        angle = rng.uniform(0.05, 1.5)
        # The result: the truth turned by `angle` about an axis through its centre, then shifted.
        c = t[:3, :3] @ centre + t[:3, 3]
        turn = pose(axis_rotation(rng.normal(size=3), angle))
        turn[:3, 3] = c - turn[:3, :3] @ c
        truth.append(t)
        result.append(pose(np.eye(3), shift) @ turn @ t)
        shifts.append(np.linalg.norm(shift))
        angles.append(angle)
    truth, result = np.array(truth), np.array(result)
    truth[6] = np.nan   # the truth lacks frame 6
    result[3] = np.nan  # the result lacks frame 3
    c = fm.compare_poses(truth, result, centre)
    compared = [0, 1, 2, 4, 5, 7]
    assert list(c["frames"]) == compared
    assert c["missing_in_result"] == [3] and c["missing_in_truth"] == [6]
    np.testing.assert_allclose(c["centre_mm"], [shifts[f] for f in compared], atol=1e-9)
    np.testing.assert_allclose(c["rotation_deg"], [angles[f] for f in compared], atol=1e-7)
    np.testing.assert_allclose(c["centre"]["rms"], np.sqrt(np.mean(np.square([shifts[f] for f in compared]))), atol=1e-9)
    np.testing.assert_allclose(c["rotation"]["worst"], max(angles[f] for f in compared), atol=1e-7)
    within = np.mean([shifts[f] <= 0.5 and angles[f] <= 0.5 for f in compared])
    assert c["within_05mm_05deg"] == pytest.approx(within)
    assert c["bone"].shape == (6, 6) and "camera" not in c
    # The CLI's per-frame CSV says the same.
    fm.write_tra(tmp_path / "t.tra", truth)
    fm.write_tra(tmp_path / "r.tra", result)
    cli("compare", "--truth", tmp_path / "t.tra", "--tra", tmp_path / "r.tra", "--center", "12,-5,30",
        "--csv", tmp_path / "c.csv")
    rows = [line.split(",") for line in (tmp_path / "c.csv").read_text().splitlines()[1:]]
    cli_rows = {int(r[0]): (float(r[2]), float(r[3])) for r in rows if r[1] == "compared"}
    assert sorted(cli_rows) == compared
    for i, f in enumerate(compared):
        assert cli_rows[f] == pytest.approx((c["centre_mm"][i], c["rotation_deg"][i]), abs=2e-6)
    with pytest.raises(fm.Error, match="truth"):
        fm.compare_poses(truth[:, :3], result, centre)  # not 4x4 poses
    with pytest.raises(fm.Error):
        fm.compare_poses(truth[6:7], result[3:4], centre)  # no frame holds both
