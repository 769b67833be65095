"""Colour meshes in Python: H x W x 3 arrays, N x 3 values, F x 3 x 3 corner values, RGB reconstructions."""
import numpy as np
import pytest

import erd

# A 3 x 3 colour .erd whose centre vertex has two wedges that differ in blue (docs/manual.md).
COLOUR_ERD = """erd-header 1
channels 3
end
255
5
0 0 10 11 12
4 0 20 21 22
0 4 30 31 32
4 4 40 41 42
2 2 25 26 25
4
0 1 4
1 3 4
3 2 4
2 0 4
4
4 0 25 26 10
4 1 25 26 10
4 2 25 26 40
4 3 25 26 40
"""


def test_colour_erd_loads_with_channel_axes(tmp_path):
    path = tmp_path / "c.erd"
    path.write_text(COLOUR_ERD)
    mesh = erd.load(path)
    assert mesh.channels == 3
    assert mesh.values.shape == (5, 3)
    assert mesh.values[4].tolist() == [25, 26, 25]
    assert mesh.corner_values.shape == (4, 3, 3)
    assert sorted(set(mesh.corner_values[:, :, 2].ravel().tolist())) == [10, 12, 22, 32, 40, 42]
    img = mesh.reconstruct(supersample=False)
    assert img.shape == (3, 3, 3) and img.dtype == np.uint8
    # Point evaluation gives the vertex values at the corners, in every channel.
    assert img[0, 0].tolist() == [10, 11, 12] and img[2, 2].tolist() == [40, 41, 42]
    again = tmp_path / "d.erd"
    mesh.save(again)
    assert again.read_text() == COLOUR_ERD
    assert mesh.stats["image"]["channels"] == 3


def test_gray_meshes_keep_their_shapes(tmp_path):
    path = tmp_path / "g.model"
    path.write_text("255\n4\n0 0 10\n1 0 18\n0 1 10\n1 1 18\n2\n0 1 3\n0 3 2\n")
    mesh = erd.load(path)
    assert mesh.channels == 1
    assert mesh.values.shape == (4,)
    assert mesh.corner_values.shape == (2, 3)
    assert mesh.reconstruct().shape == (2, 2)


def test_bad_colour_file_is_a_value_error(tmp_path):
    path = tmp_path / "bad.erd"
    path.write_text(COLOUR_ERD.replace("2 2 25 26 25", "2 2 25 26"))
    with pytest.raises(ValueError, match="vertex 4 has 2 values on its line, expected 3"):
        erd.load(path)


def test_edges_keyword(lena):
    small = np.ascontiguousarray(lena[100:164, 200:264])
    hard = erd.generate(small, "erdgpi", density=3.0, edges="hard")
    soft = erd.generate(small, "erdgpi", density=3.0, edges="soft")
    assert hard.stats["parameters"]["edges"] == "hard"
    assert soft.stats["parameters"]["edges"] == "soft"
    assert erd.generate(small, "erdgpi", density=3.0, edges="auto", thesis=True).stats["parameters"]["edges"] == "soft"
    with pytest.raises(ValueError, match="edges: 'sharp' is not 'hard', 'soft' or 'auto'"):
        erd.generate(small, edges="sharp")
    with pytest.raises(TypeError, match="edges must be 'hard', 'soft' or 'auto'"):
        erd.generate(small, edges=1)


def test_edges_refuses_colour():
    with pytest.raises(ValueError, match="erd.edges takes a gray image"):
        erd.edges(np.zeros((8, 8, 3), np.uint8))
