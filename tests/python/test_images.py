"""Radiographs and similarity: the JTML frames read and prepared as `radiograph` prepares them
(compared with the CLI's output), and the similarity measures against arithmetic."""
import numpy as np
import pytest

import fluoromatch as fm


def test_ncc_is_one_for_a_linear_change_and_minus_one_for_a_negation():
    rng = np.random.default_rng(1)
    a = rng.normal(size=(40, 50)).astype(np.float32)
    assert fm.similarity(a, a) == pytest.approx(1.0, abs=1e-6)
    assert fm.similarity(a, 3 * a + 7) == pytest.approx(1.0, abs=1e-5)
    assert fm.similarity(a, -a) == pytest.approx(-1.0, abs=1e-6)
    b = rng.normal(size=a.shape).astype(np.float32)
    mask = np.zeros(a.shape, bool)
    mask[:, :25] = True
    mixed = np.where(mask, a, b)  # equal to a where the mask says
    assert fm.similarity(a, mixed, mask=mask) == pytest.approx(1.0, abs=1e-6)
    assert abs(fm.similarity(a, mixed)) < 0.9
    for measure in ("gncc", "gd", "mi"):
        assert np.isfinite(fm.similarity(a, a, measure=measure))
    with pytest.raises(fm.Error, match="similarity|measure"):
        fm.similarity(a, a, measure="sad")
    with pytest.raises(fm.Error, match="size"):
        fm.similarity(a, a[:, :10])


def test_a_radiograph_prepared_as_the_cli_prepares_it(jtml, cli, tmp_path):
    path = jtml / "AT_K1_V1_0160.tif"
    image, bits = fm.read_radiograph(path)
    assert image.shape == (1024, 1024) and bits in (8, 16)
    prepared, valid = fm.prepare_radiograph(image, invert=True, bits=bits)
    np.testing.assert_array_equal(prepared, fm.full_scale(bits) - image)
    assert valid.dtype == bool and valid.all()
    logged, _ = fm.prepare_radiograph(image, log=True, bits=bits)
    full = fm.full_scale(bits)
    np.testing.assert_allclose(logged, -np.log(np.clip(image, 1, full) / full), rtol=1e-5, atol=1e-6)
    cli("radiograph", path, "--exclude-below", "5", "--erode", "2", "--out", tmp_path / "p.mha",
        "--mask-out", tmp_path / "m.png")
    _, valid = fm.prepare_radiograph(image, exclude_below=5, erode=2, bits=bits)
    np.testing.assert_array_equal(valid, fm.read_mask(tmp_path / "m.png", (1024, 1024)))
    with pytest.raises(fm.Error, match="i0"):
        fm.prepare_radiograph(image, i0=100.0)
