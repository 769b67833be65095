"""The package gives what the erd program gives: saved meshes byte for byte, reconstructions,
PSNR, edges; and `python3 -m erd` is the program."""
import os
import sys

import numpy as np
import pytest

import erd
from conftest import read_pgm, run, write_pgm


def cli_generate(erd_bin, tmp_path, image_path, method, args, ext):
    out = tmp_path / ("cli" + ext)
    r = run([erd_bin, "generate", "--method", method, "-i", image_path, "-o", str(out), "-q"] + args)
    assert r.returncode == 0, r.stderr
    return out.read_bytes()


CASES = [
    # (image, method, python keywords, CLI flags)
    ("lena.pgm", "erdgpi", dict(density=1.0), ["-d", "1"]),
    ("peppers.pgm", "erded", dict(density=0.5), ["-d", "0.5"]),
    ("house.pgm", "gpi", dict(density=1.0), ["-d", "1"]),
    ("cameraman.pgm", "ed", dict(points=1500, exit_mode=2), ["-n", "1500", "-x", "2"]),
    ("lena.pgm", "erdgpi", dict(density=0.5, thesis=True), ["-d", "0.5", "--thesis"]),
    ("lena.pgm", "erdgpi", dict(points=311, lower_beta=0), ["-n", "311", "--lower-beta", "0"]),
    ("phantom.pgm", "erdgpi", dict(density=1.0, beta=0.05, ratio=0.5, wedge_fit=2, alpha_max=1.25, exit_mode=2),
     ["-d", "1", "-b", "0.05", "-r", "0.5", "--wedge-fit", "2", "--alpha-max", "1.25", "-x", "2"]),
    ("ct_head_12b.pgm", "erdgpi", dict(density=1.0, maxval=4095), ["-d", "1"]),
]


@pytest.mark.parametrize("name,method,kw,flags", CASES, ids=[c[0] + "-" + c[1] + "-" + str(i) for i, c in enumerate(CASES)])
def test_saved_mesh_is_the_cli_file(erd_bin, images, tmp_path, name, method, kw, flags):
    path = os.path.join(images, name)
    image, maxval = read_pgm(path)
    ext = ".erd" if method.startswith("erd") else ".model"
    mesh = erd.generate(image, method, **kw)
    mesh.save(tmp_path / ("py" + ext))
    assert (tmp_path / ("py" + ext)).read_bytes() == cli_generate(erd_bin, tmp_path, path, method, flags, ext)
    assert mesh.method == method and mesh.kind == ("erd" if ext == ".erd" else "basic")
    assert (mesh.width, mesh.height, mesh.maxval) == (image.shape[1], image.shape[0], maxval)
    # Loading the CLI's file gives the same mesh (the file keeps the constrained edges across which
    # values jump, and an .erd vertex's value is the mean of its wedge values summed again), and
    # saving it again the same bytes.
    loaded = erd.load(tmp_path / ("cli" + ext))
    for field in ("vertices", "faces", "corner_values"):
        assert np.array_equal(getattr(loaded, field), getattr(mesh, field)), field
    assert np.allclose(loaded.values, mesh.values, rtol=0, atol=1e-9)
    assert set(map(tuple, loaded.constrained_edges)) <= set(map(tuple, mesh.constrained_edges))
    loaded.save(tmp_path / ("again" + ext))
    if ext == ".model":
        assert (tmp_path / ("again" + ext)).read_bytes() == (tmp_path / ("cli" + ext)).read_bytes()
    else:  # the vertex line of a multi-wedge vertex holds the recomputed mean (ignored on reading)
        assert np.array_equal(erd.load(tmp_path / ("again" + ext)).corner_values, mesh.corner_values)


@pytest.mark.parametrize("method,ext", [("erdgpi", ".erd"), ("gpi", ".model")])
@pytest.mark.parametrize("no_aa", [False, True])
def test_reconstruct_is_the_cli_image(erd_bin, images, tmp_path, method, ext, no_aa):
    path = os.path.join(images, "peppers.pgm")
    image, _ = read_pgm(path)
    mesh = erd.generate(image, method, density=0.5)
    model = tmp_path / ("m" + ext)
    mesh.save(model)
    out = tmp_path / "rec.pgm"
    r = run([erd_bin, "reconstruct", str(model), "-o", str(out)] + (["--no-aa"] if no_aa else []))
    assert r.returncode == 0, r.stderr
    cli_image, _ = read_pgm(out)
    ours = mesh.reconstruct(supersample=False) if no_aa else mesh.reconstruct()
    assert ours.dtype == np.uint8 and ours.shape == image.shape
    assert np.array_equal(ours, cli_image)


def test_psnr_is_the_cli_number(erd_bin, images, tmp_path, lena):
    approx = erd.generate(lena, "gpi", density=0.5).reconstruct()
    write_pgm(tmp_path / "a.pgm", approx)
    r = run([erd_bin, "psnr", os.path.join(images, "lena.pgm"), str(tmp_path / "a.pgm")], text=True)
    assert r.returncode == 0, r.stderr
    assert "%.4f" % erd.psnr(lena, approx) in r.stdout
    assert erd.psnr(lena, lena) == float("inf")
    ct, maxval = read_pgm(os.path.join(images, "ct_head_12b.pgm"))
    rec = erd.generate(ct, "erdgpi", density=1.0, maxval=maxval).reconstruct()
    assert rec.dtype == np.uint16 and rec.max() <= maxval
    write_pgm(tmp_path / "ct.pgm", rec, maxval)
    r = run([erd_bin, "psnr", os.path.join(images, "ct_head_12b.pgm"), str(tmp_path / "ct.pgm")], text=True)
    assert "%.4f" % erd.psnr(ct, rec, maxval=maxval) in r.stdout


def test_edges_are_the_cli_edges(erd_bin, images, tmp_path):
    path = os.path.join(images, "cameraman.pgm")
    image, _ = read_pgm(path)
    r = run([erd_bin, "edges", path, "-o", str(tmp_path / "e.pgm"), "-p", str(tmp_path / "p.txt"), "-b", "0.08", "-q"])
    assert r.returncode == 0, r.stderr
    e = erd.edges(image, beta=0.08)
    cli_map, _ = read_pgm(tmp_path / "e.pgm")
    assert e.map.shape == (2 * image.shape[0] - 1, 2 * image.shape[1] - 1)
    assert np.array_equal(e.map, cli_map == 255)
    lines = (tmp_path / "p.txt").read_text().split("\n")
    assert int(lines[1]) == len(e.polylines) > 0
    first = [int(v) for v in lines[2].split()]
    assert np.array_equal(e.polylines[0] * 2, np.array(first[1:]).reshape(-1, 2))


def test_python_m_erd_is_the_program(erd_bin, images, tmp_path):
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(erd.__file__)))
    path = os.path.join(images, "house.pgm")
    r = run([sys.executable, "-m", "erd", "generate", "--method", "erdgpi", "-i", path, "-d", "0.5",
             "-o", str(tmp_path / "py.erd"), "-q"], env=env)
    assert r.returncode == 0, r.stderr
    cli_generate(erd_bin, tmp_path, path, "erdgpi", ["-d", "0.5"], ".erd")
    assert (tmp_path / "py.erd").read_bytes() == (tmp_path / "cli.erd").read_bytes()
    for args in (["info", path], ["help"], ["nosuch"], ["generate", "--method", "erdgpi"], ["--version"]):
        ours, theirs = run([sys.executable, "-m", "erd"] + args, env=env), run([erd_bin] + args)
        assert (ours.returncode, ours.stdout, ours.stderr) == (theirs.returncode, theirs.stdout, theirs.stderr), args
    # Output to stdout goes through the same file descriptor.
    ours = run([sys.executable, "-m", "erd", "reconstruct", str(tmp_path / "py.erd")], env=env)
    theirs = run([erd_bin, "reconstruct", str(tmp_path / "py.erd")])
    assert ours.returncode == 0 and ours.stdout == theirs.stdout and len(ours.stdout) > 512 * 512
