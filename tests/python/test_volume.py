"""Volumes: read as the CLI reads them, wrapped from numpy, written and read back; the array is a
view of the engine's values in (z, y, x) order; bad input raises fluoromatch.Error naming it."""
import numpy as np
import pytest

import fluoromatch as fm
from conftest import REPO


def test_a_numpy_volume_keeps_its_axes_spacing_and_placement():
    a = np.arange(2 * 3 * 4, dtype=np.float32).reshape(2, 3, 4)  # (z, y, x)
    v = fm.Volume(a, spacing=(0.5, 2.0, 3.0), origin=(10, 20, 30), units="hu")
    assert v.shape == (2, 3, 4)
    assert v.units == "hu"
    np.testing.assert_array_equal(v.array, a)
    # Voxel (i, j, k) = (3, 2, 1) is array[1, 2, 3], at origin + spacing * (i, j, k).
    np.testing.assert_allclose(v.index_to_world((3, 2, 1)), (10 + 1.5, 20 + 4.0, 30 + 3.0))
    np.testing.assert_allclose(v.world_to_index((11.5, 24.0, 33.0)), (3, 2, 1))
    np.testing.assert_allclose(v.center, (10 + 0.75, 20 + 2.0, 30 + 1.5))


def test_the_array_is_a_view_not_a_copy():
    v = fm.Volume(np.zeros((2, 2, 2), np.float32))
    view = v.array
    view[1, 0, 1] = 7.0
    assert v.array[1, 0, 1] == 7.0  # the engine's values changed
    assert view.base is not None and not view.flags.owndata


def test_a_written_volume_reads_back_the_same(tmp_path):
    rng = np.random.default_rng(3)
    a = rng.normal(size=(3, 4, 5)).astype(np.float32)
    direction = np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1]], float)
    v = fm.Volume(a, spacing=(0.7, 0.8, 1.5), origin=(-5, 6, 7), direction=direction)
    for name in ("v.mha", "v.nii.gz"):
        fm.write_volume(v, tmp_path / name)
        back = fm.read_volume(str(tmp_path / name))
        np.testing.assert_array_equal(back.array, a)
        np.testing.assert_allclose(back.spacing, v.spacing, rtol=1e-6)
        np.testing.assert_allclose(back.origin, v.origin, atol=1e-5)
        np.testing.assert_allclose(back.direction, direction, atol=1e-6)


def test_the_knee_phantom_is_the_cli_default():
    v = fm.read_volume("phantom:knee")
    assert v.shape == (141, 128, 128)
    assert v.units == "hu"
    assert v.is_hounsfield()[0]


def test_bad_input_names_the_file_or_argument(tmp_path):
    with pytest.raises(fm.Error, match="nothing.nii"):
        fm.read_volume(str(tmp_path / "nothing.nii"))
    bad = tmp_path / "bad.mha"
    bad.write_text("ObjectType = Image\nNDims = 3\nDimSize = 4 4\n")
    with pytest.raises(fm.Error, match="bad.mha"):
        fm.read_volume(str(bad))
    with pytest.raises(fm.Error, match="3-D array"):
        fm.Volume(np.zeros((4, 4), np.float32))
    with pytest.raises(fm.Error, match="spacing"):
        fm.Volume(np.zeros((2, 2, 2), np.float32), spacing=(1, 0, 1))
    with pytest.raises(fm.Error, match="spacing"):
        fm.Volume(np.zeros((2, 2, 2), np.float32), spacing=(1, 1))
    with pytest.raises(fm.Error, match="units"):
        fm.Volume(np.zeros((2, 2, 2), np.float32), units="kelvin")


def test_one_bone_and_the_rest_of_the_pelvis_ct_add_up_to_the_ct(data_dir):
    # Line integrals add over disjoint voxel sets: DRR(bone) + DRR(CT without it) = DRR(CT).
    d = data_dir / "totalseg-example-ct"
    ct = fm.read_volume(str(d / "example_ct.nii.gz"))
    labels = fm.read_labels(str(d / "example_seg_fast_force_split.nii.gz"), ct,
                            table=str(REPO / "data" / "totalseg_bones.json"))
    assert "femur_right" in labels.names.values()
    bone = fm.bone_volume(ct, labels, "femur_right")
    rest = fm.volume_without(ct, labels, "femur_right")
    assert rest.shape == ct.shape and np.prod(bone.shape) < np.prod(ct.shape) / 4
    g = fm.scene_geometry([0, 0, 0, 90, 0, 0], ct.center, size=(128, 128))
    whole = fm.drr(ct, g, values="mu")
    parts = fm.drr(bone, g, values="mu") + fm.drr(rest, g, values="mu")
    assert whole.max() > 1
    np.testing.assert_allclose(parts, whole, rtol=1e-5, atol=1e-5)
    with pytest.raises(fm.Error, match="femur_middle"):
        fm.bone_volume(ct, labels, "femur_middle")
