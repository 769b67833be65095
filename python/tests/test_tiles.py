"""erd.tiles (issue 48): the same bytes from one process and from a Dask LocalCluster of 2 workers."""
import filecmp
import os

import pytest

import erd
import erd.tiles

from conftest import run


def same_folders(a, b):
    names = sorted(os.listdir(a))
    assert names == sorted(os.listdir(b))
    match, mismatch, errors = filecmp.cmpfiles(a, b, names, shallow=False)
    assert not mismatch and not errors, (mismatch, errors)
    return names


@pytest.fixture(scope="module")
def dem(tmp_path_factory, erd_bin):
    path = tmp_path_factory.mktemp("tiles") / "dem.pgm"
    assert run([erd_bin, "synth", "-q", "--kind", "dem", "--solid", "-W", "257", "-H", "257", "-o", str(path)]).returncode == 0
    return path


def test_tiles_python_equals_cli(dem, tmp_path, erd_bin):
    index = erd.tiles.run(dem, tmp_path / "py", "gpi", 64, merge=tmp_path / "py.ply", density=2)
    assert index["grid"] == [4, 4] and index["vertices"] == round(257 * 257 * 0.02)
    assert run([erd_bin, "tiles", "-q", "-m", "gpi", "-i", str(dem), "--tile", "64", "-d", "2", "-o", str(tmp_path / "cli"),
                "--merge", str(tmp_path / "cli.ply")]).returncode == 0
    assert "tile_3_3.model" in same_folders(tmp_path / "py", tmp_path / "cli")
    assert filecmp.cmp(tmp_path / "py.ply", tmp_path / "cli.ply", shallow=False)


def test_tiles_refusal_raises(dem, tmp_path):
    with pytest.raises(erd.tiles.TilesError):
        erd.tiles.run(dem, tmp_path / "ed", "ed", 64)


def test_tiles_dask_local_cluster_same_bytes(dem, tmp_path):
    import distributed  # Debian's python3-distributed (make python-deps installs it): missing is a failure

    one = erd.tiles.run(dem, tmp_path / "one", "erdgpi", 64, merge=tmp_path / "one.glb", density=2)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster, \
            distributed.Client(cluster) as client:
        many = erd.tiles.run(dem, tmp_path / "dask", "erdgpi", 64, merge=tmp_path / "dask.glb", density=2, client=client)
        workers = client.run(os.getpid)
    assert len(workers) == 2
    assert one == many
    same_folders(tmp_path / "one", tmp_path / "dask")
    assert filecmp.cmp(tmp_path / "one.glb", tmp_path / "dask.glb", shallow=False)
