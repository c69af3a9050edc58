"""Meshes: marching cubes against a known volume and Euler characteristic, mesh DRRs against
exact chords, the implant models as `--model` reads them, files written and read back."""
import numpy as np
import pytest

import fluoromatch as fm
from test_drr import box_chords, pixel_centres


def ball(radius, spacing=1.0, n=40):
    c = (np.arange(n) - (n - 1) / 2) * spacing
    z, y, x = np.meshgrid(c, c, c, indexing="ij")
    return fm.Volume((np.sqrt(x * x + y * y + z * z) <= radius).astype(np.float32) * 1000,
                     spacing=(spacing,) * 3, origin=(c[0],) * 3)


def test_marching_cubes_of_a_ball_is_one_closed_sphere_of_its_volume():
    mesh = fm.marching_cubes(ball(12.0), iso=500)
    assert mesh.closed
    assert mesh.euler_characteristic == 2  # a sphere
    assert mesh.vertices.dtype == np.float32 and mesh.faces.dtype == np.uint32
    assert mesh.normals.shape == mesh.vertices.shape
    # Vertices lie on the sphere to within a voxel; the enclosed volume within 3 %.
    r = np.linalg.norm(mesh.vertices, axis=1)
    assert abs(r.mean() - 12.0) < 0.5 and r.max() < 13.0
    assert mesh.volume == pytest.approx(4 / 3 * np.pi * 12.0**3, rel=0.03)
    # Outward normals: along the position.
    assert np.mean(np.sum(mesh.normals * mesh.vertices, axis=1) / r) > 0.95


def test_the_largest_component_of_two_balls():
    small, big = ball(5.0).array, ball(9.0).array
    two = fm.Volume(np.maximum(np.roll(small, -12, axis=2), np.roll(big, 8, axis=2)), spacing=(1, 1, 1))
    both = fm.marching_cubes(two, iso=500)
    largest = fm.marching_cubes(two, iso=500, components=1)
    assert both.euler_characteristic == 4  # two spheres
    assert largest.closed and largest.euler_characteristic == 2
    assert largest.volume == pytest.approx(4 / 3 * np.pi * 9.0**3, rel=0.03)
    with pytest.raises(fm.Error, match="components"):
        fm.marching_cubes(two, iso=500, components=-1)


def cube(lower, upper):
    corners = np.array([[x, y, z] for x in (lower[0], upper[0]) for y in (lower[1], upper[1])
                        for z in (lower[2], upper[2])], np.float32)
    faces = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                      [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    return fm.Mesh(corners, faces)


def test_a_mesh_drr_is_mu_times_the_exact_chords():
    lower, upper = np.array([-10.0, -6.0, -4.0]), np.array([12.0, 6.0, 8.0])
    box = cube(lower, upper)
    assert box.closed and box.volume == pytest.approx(22 * 12 * 12)
    g = fm.scene_geometry([0, 0, 0, 35, 20, 10], (0, 0, 0), size=(48, 40), film=(60, 50))
    image = box.render(g, mu=2.0)
    truth = 2.0 * box_chords(np.array(g.source), pixel_centres(g), lower, upper)
    assert truth.max() > 20
    np.testing.assert_allclose(image, truth, rtol=1e-5, atol=1e-4)


def test_the_implant_models_read_as_model_reads_them(jtml):
    implant = fm.read_mesh(str(jtml / "KR_right_7_fem.stl"))
    assert implant.closed and implant.volume > 0 and implant.euler_characteristic == 2
    lo, hi = implant.vertices.min(axis=0), implant.vertices.max(axis=0)
    g = fm.scene_geometry([0, 0, 0, 0, 0, 0], (lo + hi) / 2, size=(64, 64), film=(120, 120))
    image = implant.render(g, mu=1.0)
    hit = np.argwhere(image > 0)
    assert len(hit) > 100
    for row, col in hit[:: max(1, len(hit) // 5)]:
        target = g.origin + col * g.spacing[0] * g.u + row * g.spacing[1] * g.v
        assert image[row, col] == pytest.approx(implant.chord(g.source, target), rel=1e-5)


def test_written_meshes_read_back(tmp_path):
    mesh = fm.marching_cubes(ball(8.0), iso=500)
    for name in ("b.ply", "b.stl", "b.obj"):
        mesh.write(tmp_path / name)
        back = fm.read_mesh(str(tmp_path / name))
        assert back.closed
        assert back.volume == pytest.approx(mesh.volume, rel=1e-5)
        assert len(back.faces) == len(mesh.faces)


def test_bad_meshes_are_refused_by_name(tmp_path):
    (tmp_path / "broken.stl").write_bytes(b"solid x\nfacet normal 0 0 1\n")
    with pytest.raises(fm.Error, match="broken.stl"):
        fm.read_mesh(str(tmp_path / "broken.stl"))
    with pytest.raises(fm.Error, match="face 0 refers to vertex 5"):
        fm.Mesh(np.zeros((3, 3), np.float32), np.array([[0, 1, 5]]))
