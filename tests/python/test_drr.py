"""DRRs from Python: exact chords of a box of ones (sources outside and inside it), bit for bit
the CLI's `drr --raw`, batches equal single renders, poses move the object, scenes add up."""
import numpy as np
import pytest

import fluoromatch as fm
from conftest import pose, rotation


def box_chords(source, pixels, lower, upper):
    """Length of each segment source -> pixel inside the box [lower, upper] (slab method)."""
    d = pixels - source
    with np.errstate(divide="ignore", invalid="ignore"):
        t0 = (lower - source) / d
        t1 = (upper - source) / d
    lo = np.where(d == 0, np.where((source >= lower) & (source <= upper), -np.inf, np.inf), np.minimum(t0, t1))
    hi = np.where(d == 0, np.where((source >= lower) & (source <= upper), np.inf, -np.inf), np.maximum(t0, t1))
    enter = np.clip(lo.max(axis=-1), 0, 1)
    leave = np.clip(hi.min(axis=-1), 0, 1)
    return np.maximum(leave - enter, 0) * np.linalg.norm(d, axis=-1)


def pixel_centres(g):
    cols, rows = g.size
    c, r = np.meshgrid(np.arange(cols), np.arange(rows))
    du, dv = g.spacing
    return g.origin + (c * du)[..., None] * g.u + (r * dv)[..., None] * g.v


@pytest.mark.parametrize("source", [(-300.0, 20.0, 10.0), (3.0, 2.0, 1.0)], ids=["outside", "inside"])
def test_a_box_of_ones_gives_its_exact_chords(source):
    spacing = np.array([1.5, 1.0, 2.0])
    origin = np.array([-10.0, -8.0, -6.0])
    ones = fm.Volume(np.ones((7, 17, 14), np.float32), spacing=spacing, origin=origin)
    lower = origin - spacing / 2
    upper = origin + spacing * (np.array([14, 17, 7]) - 0.5)
    # A detector 400 mm beyond the source, facing the box's centre, turned 20 deg in its plane.
    n = (lower + upper) / 2 - np.array(source)
    n /= np.linalg.norm(n)
    u = np.cross(n, [0.0, 0.0, 1.0])
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    u, v = np.cos(np.radians(20)) * u + np.sin(np.radians(20)) * v, -np.sin(np.radians(20)) * u + np.cos(np.radians(20)) * v
    cols, rows, pitch = 64, 48, 1.2
    centre = np.array(source) + 400 * n
    g = fm.Geometry(source, (cols, rows), (pitch, pitch), centre - pitch * ((cols - 1) / 2 * u + (rows - 1) / 2 * v), u, v)
    image = fm.drr(ones, g, values="raw")
    truth = box_chords(np.array(source), pixel_centres(g), lower, upper)
    assert image.shape == (rows, cols) and image.dtype == np.float32
    assert truth.max() > 10
    np.testing.assert_allclose(image, truth, rtol=2e-6, atol=2e-5)
    prepared = fm.prepare(ones, values="raw")
    far = np.array(source) + 400 * n
    assert prepared.line_integral(source, far) == pytest.approx(box_chords(np.array(source), far[None], lower, upper)[0], abs=1e-9)


def test_equal_bit_for_bit_to_the_cli(cli, tmp_path):
    knee = fm.read_volume("phantom:knee")
    cli("drr", "--volume", "phantom:knee", "--pose", "5,-3,2,30,10,5", "--size", "96x80",
        "--out", tmp_path / "knee.png", "--raw", tmp_path / "knee.mha")
    from_cli = fm.read_volume(str(tmp_path / "knee.mha")).array[0]
    g = fm.scene_geometry([5, -3, 2, 30, 10, 5], knee.center, size=(96, 80))
    image = fm.drr(knee, g)
    assert image.shape == from_cli.shape
    assert np.array_equal(image, from_cli)  # bit for bit
    # The same through a geometry file the CLI reads.
    (tmp_path / "g.json").write_text(g.to_json())
    assert fm.read_geometry(str(tmp_path / "g.json")) == g
    cli("drr", "--volume", "phantom:knee", "--geometry", tmp_path / "g.json", "--out", tmp_path / "k2.png",
        "--raw", tmp_path / "k2.mha", "--intensity")
    assert np.array_equal(fm.drr(knee, g, output="intensity"), fm.read_volume(str(tmp_path / "k2.mha")).array[0])


def test_equal_bit_for_bit_to_the_cli_on_a_real_ct(cli, data_dir, tmp_path):
    path = data_dir / "totalseg-example-ct" / "example_ct.nii.gz"
    ct = fm.read_volume(str(path))
    cli("drr", "--volume", path, "--pose", "0,0,0,-60,15,0", "--size", "128x128", "--threshold", "100",
        "--out", tmp_path / "ct.png", "--raw", tmp_path / "ct.mha")
    g = fm.scene_geometry([0, 0, 0, -60, 15, 0], ct.center, size=(128, 128))
    assert np.array_equal(fm.drr(ct, g, threshold=100), fm.read_volume(str(tmp_path / "ct.mha")).array[0])


def test_a_batch_equals_one_render_at_a_time_and_poses_move_the_object():
    knee = fm.read_volume("phantom:knee")
    prepared = fm.prepare(knee)
    assert prepared.values == "mu"
    g = fm.scene_geometry([0, 0, 0, 0, 0, 0], knee.center, size=(64, 64))
    poses = np.stack([pose(rotation("z", a), (a / 10, 0, 0)) for a in (0, 10, 25)])
    batch = prepared.render_batch(g, poses=poses)
    assert batch.shape == (3, 64, 64)
    for p, image in zip(poses, batch):
        assert np.array_equal(image, prepared.render(g, pose=p))
    views = [fm.scene_geometry([0, 0, 0, az, 0, 0], knee.center, size=(64, 64)) for az in (0, 45)]
    assert np.array_equal(prepared.render_batch(views)[1], prepared.render(views[1]))
    # A pure translation of the object is the same as moving its origin.
    shift = np.array([7.0, -4.0, 3.0])
    moved = fm.Volume(knee.array, spacing=knee.spacing, origin=knee.origin + shift, units="hu")
    np.testing.assert_allclose(prepared.render(g, pose=pose(t=shift)), fm.drr(moved, g), rtol=1e-5, atol=1e-5)


def test_a_scene_is_the_sum_of_its_objects():
    knee = fm.prepare(fm.read_volume("phantom:knee"))
    cube = fm.Mesh(np.array([[x, y, z] for x in (0, 10) for y in (0, 10) for z in (0, 10)], np.float32),
                   np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                             [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]]))
    assert cube.closed and cube.volume == pytest.approx(1000) and cube.euler_characteristic == 2
    g = fm.scene_geometry([0, 0, 0, 0, 0, 0], (0, 0, 0), size=(64, 64))
    at = pose(rotation("x", 30), (-5, -5, -5))
    scene = fm.render([(knee, np.eye(4)), (cube, at, 0.5)], g)
    np.testing.assert_allclose(scene, knee.render(g) + cube.render(g, pose=at, mu=0.5), rtol=1e-5, atol=1e-5)
    with pytest.raises(fm.Error, match="PreparedVolume"):
        fm.render([("knee", np.eye(4))], g)
