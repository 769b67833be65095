"""Edge kinds per edge (issue 44): a picture half photo, half anti-aliased drawing gets a model
with edges of two kinds; the package shows them, reconstructs them as `erd reconstruct` does and
saves them byte for byte; its PSNR never falls with density."""
import numpy as np

import erd
from conftest import read_pgm, run, write_pgm


def drawing(w, h, n):
    """A disc, a bar and a triangle on gray ground, each pixel its coverage (n x n sub-samples)."""
    ys, xs = np.mgrid[0:h * n, 0:w * n]
    x, y = (xs + 0.5) / n - 0.5, (ys + 0.5) / n - 0.5
    v = np.full(x.shape, 90.0)
    v[np.hypot(x - 0.35 * w, y - 0.45 * h) < 0.3 * h] = 215
    v[(y > 0.1 * h) & (y < 0.1 * h + 1.7) & (x > 0.05 * w) & (x < 0.95 * w)] = 250
    v[(y > 0.55 * h) & (x - 0.55 * w < (y - 0.55 * h) * 0.8) & (x > 0.5 * w)] = 25
    return np.rint(v.reshape(h, n, w, n).mean(axis=(1, 3))).astype(np.uint8)


def blur(a, passes):
    a = a.astype(float)
    for _ in range(passes):
        a = (np.roll(a, 1, 0) + 2 * a + np.roll(a, -1, 0)) / 4
        a = (np.roll(a, 1, 1) + 2 * a + np.roll(a, -1, 1)) / 4
    return a


def half_photo():
    """Left a blurred, textured 'photo' of the drawing, right the anti-aliased drawing (96 x 192)."""
    ys, xs = np.mgrid[0:96, 0:96]
    texture = 8 * np.sin(xs * 0.9 + ys * 0.3) * np.cos(ys * 0.7) + 5 * np.sin(xs * ys * 0.0115)
    photo = np.clip(np.rint(blur(blur(drawing(96, 96, 4), 3) + texture, 1)), 0, 255).astype(np.uint8)
    return np.concatenate([photo, drawing(96, 96, 8)], axis=1)


def test_two_kinds_shown_reconstructed_and_saved(erd_bin, tmp_path):
    image = half_photo()
    mesh = erd.generate(image, "erdgpi", density=1.0)
    assert mesh.edge_kind in ("hard", "soft")
    other = mesh.edges_of_other_kind
    assert other.dtype == np.int64 and other.ndim == 2 and other.shape[1] == 2
    assert len(other) > 0  # measured: 33 of 53 constrained edges
    assert mesh.stats["other_kind_edges"] == len(other)
    assert (other[:, 0] < other[:, 1]).all()
    assert set(map(tuple, other)) <= set(map(tuple, mesh.constrained_edges))
    # The file, the CLI's reconstruction of it, and ours.
    mesh.save(tmp_path / "m.erd")
    loaded = erd.load(tmp_path / "m.erd")
    assert loaded.edge_kind == mesh.edge_kind
    assert np.array_equal(loaded.edges_of_other_kind, other)
    r = run([erd_bin, "reconstruct", str(tmp_path / "m.erd"), "-o", str(tmp_path / "rec.pgm")])
    assert r.returncode == 0, r.stderr
    cli, _ = read_pgm(tmp_path / "rec.pgm")
    assert np.array_equal(mesh.reconstruct(), cli)
    # supersample=True / False: that evaluation at every pixel, whatever the edges' kinds.
    r = run([erd_bin, "reconstruct", "--no-aa", str(tmp_path / "m.erd"), "-o", str(tmp_path / "point.pgm")])
    assert np.array_equal(mesh.reconstruct(supersample=False), read_pgm(tmp_path / "point.pgm")[0])
    # The CLI makes the same model from the same image.
    write_pgm(tmp_path / "d.pgm", image)
    r = run([erd_bin, "generate", "-m", "erdgpi", "-d", "1", "-i", str(tmp_path / "d.pgm"), "-o", str(tmp_path / "cli.erd"), "-q"])
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "cli.erd").read_bytes() == (tmp_path / "m.erd").read_bytes()


def test_more_points_never_cost_quality():
    image, last = half_photo(), 0.0
    for d in (0.5, 1.0, 2.0):
        ours = erd.psnr(image, erd.generate(image, "erdgpi", density=d, exit_mode=2).reconstruct())
        assert ours > erd.psnr(image, erd.generate(image, "gpi", density=d, exit_mode=2).reconstruct()) + 3
        assert ours >= last - 0.05
        last = ours
