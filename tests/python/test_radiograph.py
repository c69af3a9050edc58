"""Realistic radiographs from Python (fm.radiograph): one energy through a box of tissue is
exp(-mu rho L) with NIST's mu/rho and the exact chords, bit for bit the CLI's `drr --spectrum`,
noise seeded and the same for any thread count, bad arguments refused."""
import json

import numpy as np
import pytest

import fluoromatch as fm
from conftest import REPO
from test_drr import box_chords, pixel_centres


def nist_mu_rho(material, kev):
    """mu/rho (cm^2/g) at a tabulated energy, read from the table the engine embeds."""
    table = json.loads((REPO / "data" / "xray" / "nist_mass_attenuation.json").read_text())["materials"][material]
    return table["mu_rho_cm2_g"][table["energy_kev"].index(kev)]


def tissue_box():
    """A box of 0 HU tissue (1.030 g/cm^3) inside air, and its bounds in mm."""
    spacing = np.array([1.5, 1.0, 2.0])
    origin = np.array([-10.0, -8.0, -6.0])
    hu = np.full((9, 19, 16), -1000.0, np.float32)
    hu[1:-1, 1:-1, 1:-1] = 0.0
    ct = fm.Volume(hu, spacing=spacing, origin=origin)
    lower = origin + spacing * 0.5
    upper = origin + spacing * (np.array([16, 19, 9]) - 1.5)
    return ct, lower, upper


def facing(source, target, cols=40, rows=32, pitch=2.0):
    """A detector 400 mm beyond the source, facing `target`."""
    n = np.asarray(target) - np.array(source)
    n /= np.linalg.norm(n)
    u = np.cross(n, [0.0, 0.0, 1.0])
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    centre = np.array(source) + 400 * n
    return fm.Geometry(source, (cols, rows), (pitch, pitch), centre - pitch * ((cols - 1) / 2 * u + (rows - 1) / 2 * v), u, v)


@pytest.mark.parametrize("source", [(-300.0, 20.0, 10.0), (2.0, 1.0, 1.0)], ids=["outside", "inside"])
def test_one_energy_through_tissue_is_exp_of_mu_rho_times_the_exact_chords(source):
    ct, lower, upper = tissue_box()
    g = facing(source, (lower + upper) / 2)
    rows, cols = 32, 40
    image = fm.radiograph(ct, g, spectrum="mono=60")
    chords = box_chords(np.array(source), pixel_centres(g), lower, upper)
    assert image.shape == (rows, cols) and image.dtype == np.float32
    assert chords.max() > 10
    # -ln(I/I0) = mu/rho x rho x L; rho of 0 HU is 1.030 g/cm^3, L in cm.
    np.testing.assert_allclose(image, nist_mu_rho("soft_tissue", 60.0) * 1.030 * chords / 10.0, rtol=2e-5, atol=2e-6)
    intensity = fm.radiograph(ct, g, spectrum="mono=60", output="intensity")
    np.testing.assert_allclose(intensity, np.exp(-image.astype(np.float64)), rtol=2e-6)


def test_equal_bit_for_bit_to_the_cli(cli, tmp_path):
    cli("drr", "--volume", "phantom:knee", "--pose", "5,-3,2,30,10,5", "--size", "96x80", "--spectrum", "80,filter=3",
        "--photons", "1000", "--blur", "0.7", "--scatter", "0.1", "--seed", "3", "--out", tmp_path / "k.png",
        "--raw", tmp_path / "k.mha")
    knee = fm.read_volume("phantom:knee")
    g = fm.scene_geometry([5, -3, 2, 30, 10, 5], knee.center, size=(96, 80))
    image = fm.radiograph(knee, g, spectrum="80,filter=3", photons=1000, blur=0.7, scatter=0.1, seed=3)
    assert np.array_equal(image, fm.read_volume(str(tmp_path / "k.mha")).array[0])  # bit for bit


def test_noise_is_seeded_and_the_same_for_any_thread_count():
    knee = fm.read_volume("phantom:knee")
    g = fm.scene_geometry([0, 0, 0, 90, 0, 0], knee.center, size=(64, 48))
    one = fm.radiograph(knee, g, photons=300, electronic_noise=2, seed=5, threads=1)
    assert np.array_equal(one, fm.radiograph(knee, g, photons=300, electronic_noise=2, seed=5, threads=2))
    assert not np.array_equal(one, fm.radiograph(knee, g, photons=300, electronic_noise=2, seed=6, threads=1))
    clean = fm.radiograph(knee, g)
    assert 0.001 < np.std(one - clean) < 1.0  # noise there, and of the photon count's size


def test_refuses_what_it_cannot_use():
    ct, _, _ = tissue_box()
    g = fm.scene_geometry([0, 0, 0, 0, 0, 0], ct.center, size=(16, 16))
    ones = fm.Volume(np.ones((4, 4, 4), np.float32))
    with pytest.raises(fm.Error, match="HU"):
        fm.radiograph(ones, g)
    with pytest.raises(fm.Error, match="detector"):
        fm.radiograph(ct, g, detector="film")
    with pytest.raises(fm.Error, match="output"):
        fm.radiograph(ct, g, output="png")
    with pytest.raises(fm.Error, match="spectrum"):
        fm.radiograph(ct, g, spectrum="80,flter=2")
    with pytest.raises(fm.Error, match="photons"):
        fm.radiograph(ct, g, photons=-1)


def test_a_bone_mask_says_which_voxels_are_bone():
    ct, lower, upper = tissue_box()
    g = facing((-300.0, 20.0, 10.0), (lower + upper) / 2)
    soft = fm.radiograph(ct, g, spectrum="mono=60")
    everything = fm.Volume(np.ones(ct.array.shape, np.float32), spacing=ct.spacing, origin=ct.origin)
    bone = fm.radiograph(ct, g, spectrum="mono=60", bone_mask=everything)
    # The same density, attenuating as cortical bone: the ratio of the two is NIST's.
    inside = soft > 0.05
    assert inside.sum() > 50
    np.testing.assert_allclose(bone[inside] / soft[inside], nist_mu_rho("cortical_bone", 60.0) / nist_mu_rho("soft_tissue", 60.0),
                               rtol=2e-5)
    with pytest.raises(fm.Error, match="grid"):
        fm.radiograph(ct, g, bone_mask=fm.Volume(np.ones((3, 3, 3), np.float32)))
