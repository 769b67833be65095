"""Real-valued arrays (issue 47): float and signed elevation with nodata, meshed to a bound in its
units, reconstructed as float64 with NaN holes, saved, loaded and exported (glTF among them)."""
import os

import numpy as np
import pytest

import erd

DEM = "/usr/share/matplotlib/mpl-data/sample_data/topobathy.npz"


@pytest.fixture(scope="module")
def topo():
    if not os.path.exists(DEM):
        pytest.fail(DEM + " missing (Debian's python-matplotlib-data; make deps installs it)")
    return np.load(DEM)["topo"].astype(np.float32)  # 91 x 120 metres, negative below the sea


@pytest.mark.parametrize("method", ["gpi", "erdgpi", "ed", "erded"])
def test_float_dem_with_nodata_meets_the_bound_and_keeps_its_holes(topo, method):
    z = topo.copy()
    z[30:45, 40:70] = np.nan
    density = 100 if method in ("gpi", "erdgpi") else 5
    mesh = erd.generate(z, method, density=density, max_error=25.0, exit_mode=2)
    assert mesh.real
    assert mesh.value_range == (float(np.nanmin(z)), float(np.nanmax(z)))
    r = mesh.reconstruct()
    assert r.dtype == np.float64
    assert np.array_equal(np.isnan(r), np.isnan(z))
    valid = ~np.isnan(z)
    assert np.abs(r[valid] - z[valid]).max() <= 25.0


def test_int16_with_nodata_keyword(topo):
    z = np.round(topo).astype(np.int16)
    z[:5, :] = -32768
    mesh = erd.generate(z, "erdgpi", density=100, max_error=30.0, nodata=-32768.0, exit_mode=2)
    r = mesh.reconstruct()
    assert np.isnan(r[:5]).all() and not np.isnan(r[5:]).any()
    assert np.abs(r[5:] - z[5:]).max() <= 30.0
    # Without nodata= the value -32768 is data: no holes.
    assert not np.isnan(erd.generate(z, "gpi", density=5, exit_mode=2).reconstruct()).any()


def test_tiny_range_does_not_collapse(topo):
    z = (topo.astype(np.float64) - topo.min()) / float(topo.max() - topo.min()) * 0.001  # 0 .. 1 mm
    mesh = erd.generate(z, "erdgpi", density=100, max_error=1e-5, exit_mode=2)
    r = mesh.reconstruct()
    assert np.abs(r - z).max() <= 1e-5
    assert len(np.unique(r)) > 1000


def test_real_mesh_files_and_exports(topo, tmp_path):
    z = topo.copy()
    z[0:10, 0:10] = np.nan
    mesh = erd.generate(z, "erdgpi", density=20, exit_mode=2)
    mesh.save(tmp_path / "t.erd")
    back = erd.load(tmp_path / "t.erd")
    assert back.real and back.value_range == mesh.value_range
    assert np.array_equal(back.reconstruct(), mesh.reconstruct(), equal_nan=True)
    glb = mesh.glb()
    assert glb[:4] == b"glTF" and int.from_bytes(glb[8:12], "little") == len(glb)
    for ext in ("obj", "ply", "stl", "glb"):
        mesh.export(tmp_path / ("t." + ext))
        assert (tmp_path / ("t." + ext)).stat().st_size > 0
    with pytest.raises(ValueError, match="obj, ply, stl or glb"):
        mesh.export(tmp_path / "t.xyz")


def test_psnr_of_float_arrays_is_over_the_valid_pixels(topo):
    z = topo.astype(np.float64)
    noisy = z + 1.0
    peak = z.max() - z.min()
    assert erd.psnr(z, noisy) == pytest.approx(20 * np.log10(peak), abs=1e-9)
    z2, n2 = z.copy(), noisy.copy()
    z2[:10] = np.nan
    n2[:10] = np.nan
    assert erd.psnr(z2, n2) == pytest.approx(20 * np.log10(np.nanmax(z2) - np.nanmin(z2)), abs=1e-9)
