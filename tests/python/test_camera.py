"""Cameras: K, R, t against the pinhole arithmetic done here, the renderer's geometry on the same
rays, the field's calibration files read and MayaCam written and read back, bad input refused."""
import numpy as np
import pytest

import fluoromatch as fm
from conftest import rotation


def make_camera():
    K = np.array([[1100.0, 0, 500.5], [0, 1080.0, 470.25], [0, 0, 1]])
    R = rotation("y", 25) @ rotation("x", -10)
    t = np.array([15.0, -30.0, 900.0])
    return fm.Camera.from_krt(K, R, t, image_size=(1024, 960)), K, R, t


def test_a_camera_projects_as_k_r_t_say():
    cam, K, R, t = make_camera()
    points = np.array([[0.0, 0.0, 0.0], [40.0, -25.0, 60.0], [-70.0, 10.0, -30.0]])
    x = (R @ points.T).T + t
    expected = (K @ x.T).T
    expected = expected[:, :2] / expected[:, 2:]
    np.testing.assert_allclose(cam.project(points), expected, atol=1e-9)
    np.testing.assert_allclose(cam.center, -R.T @ t, atol=1e-9)
    np.testing.assert_allclose(cam.K, K)
    # The renderer's geometry puts DRR pixel (c, r) on camera pixel (c, r)'s ray.
    np.testing.assert_allclose(cam.geometry().project(points), expected, atol=1e-6)
    assert cam.geometry().size == (1024, 960)
    behind = cam.center - 100 * R[2]  # on the optical axis, behind the source
    assert np.isnan(cam.project(behind)).all()


def test_mayacam_written_reads_back_and_the_cli_reads_it(tmp_path, cli):
    cam, K, R, t = make_camera()
    cam.write_mayacam(tmp_path / "cam.txt")
    back = fm.read_camera(tmp_path / "cam.txt")
    np.testing.assert_allclose(back.K, K, atol=1e-9)
    np.testing.assert_allclose(back.R, R, atol=1e-9)
    np.testing.assert_allclose(back.t, t, atol=1e-9)
    cli("geometry", "--camera", tmp_path / "cam.txt", "--out", tmp_path / "g.json")
    assert fm.read_geometry(str(tmp_path / "g.json")) == back.geometry()


def test_the_jtml_calibration_needs_its_image_size(jtml):
    with pytest.raises(fm.Error, match="image size"):
        fm.read_camera(jtml / "calibration.txt")
    cam = fm.read_camera(jtml / "calibration.txt", image_size=(1024, 1024))
    assert cam.image_size == (1024, 1024) and cam.pixel_pitch > 0


def test_bad_cameras_are_refused():
    K = np.array([[1000.0, 0, 500], [0, 1000, 500], [0, 0, 1]])
    with pytest.raises(fm.Error, match="R"):
        fm.Camera.from_krt(K, 2 * np.eye(3), (0, 0, 1000), (1000, 1000))
    with pytest.raises(fm.Error, match="image_size"):
        fm.Camera.from_krt(K, np.eye(3), (0, 0, 1000), (0, 1000))
    with pytest.raises(fm.Error, match="3 x 3"):
        fm.Camera.from_krt(K[:2], np.eye(3), (0, 0, 1000), (1000, 1000))


def test_a_camera_is_taken_wherever_a_geometry_is():
    cam, _, _, _ = make_camera()
    box = fm.Volume(np.ones((4, 4, 4), np.float32), spacing=(10, 10, 10), origin=(-15, -15, -15))
    small = fm.Camera.from_krt(cam.K / 8 + np.diag([0, 0, 7 / 8]), cam.R, cam.t, image_size=(128, 120))
    assert fm.Geometry(small) == small.geometry()
    image = fm.drr(box, small, values="raw")
    assert image.max() > 0
    assert np.array_equal(image, fm.drr(box, small.geometry(), values="raw"))
