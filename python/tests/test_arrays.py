"""Image arrays in: what is accepted, what is refused and how; results do not depend on layout."""
import numpy as np
import pytest

import erd


@pytest.fixture(scope="module")
def small(lena):
    return np.ascontiguousarray(lena[100:196, 200:300])


def same(a, b):
    return np.array_equal(a.vertices, b.vertices) and np.array_equal(a.faces, b.faces) and \
        np.array_equal(a.corner_values, b.corner_values)


@pytest.mark.parametrize("dtype", [np.int8, np.int64, np.uint64, np.float16, np.complex64, np.bool_])
def test_wrong_dtype_is_refused_by_name(small, dtype):
    # float32/64, int16/32 and uint32 are real-valued rasters (test_rasters.py).
    with pytest.raises(ValueError, match="dtype .*uint8, uint16 .*float32, float64, int16, int32, uint32"):
        erd.generate(small.astype(dtype))


@pytest.mark.parametrize("shape,pattern", [
    ((100,), r"2-D array \(H x W\) or H x W x 3 \(RGB\), got shape \(100,\)"),
    ((2, 3, 4, 5), r"2-D array \(H x W\) or H x W x 3 \(RGB\), got shape \(2, 3, 4, 5\)"),
    ((10, 10, 2), r"or H x W x 3 \(RGB\), got shape \(10, 10, 2\)"),
    ((10, 10, 4), r"RGBA is not taken; drop the alpha channel \(image\[..., :3\]\)"),
    ((0, 10), r"empty: shape \(0, 10\)"),
    ((10, 0), r"empty: shape \(10, 0\)"),
])
def test_wrong_shape_is_refused(shape, pattern):
    with pytest.raises(ValueError, match=pattern):
        erd.generate(np.zeros(shape, np.uint8))


def test_not_an_array_is_refused():
    with pytest.raises(ValueError, match="must be a numpy array.*got list"):
        erd.generate([[1, 2], [3, 4]])


def test_too_small_and_bad_samples_give_the_library_message(small):
    with pytest.raises(ValueError, match="meshing needs at least 2x2 pixels"):
        erd.generate(np.zeros((1, 5), np.uint8), points=4)
    with pytest.raises(ValueError, match=r"sample 200 at \(0,0\) exceeds maxval 100"):
        erd.generate(np.full((8, 8), 200, np.uint8), "ed", maxval=100)
    with pytest.raises(ValueError, match="maxval 0 outside|maxval: 0 is outside"):
        erd.generate(small, maxval=0)


@pytest.mark.parametrize("view", [
    lambda a: a[::2, ::3],            # strided both ways
    lambda a: a.T,                    # transposed (Fortran order)
    lambda a: a[::-1, ::-1],          # negative strides
    lambda a: a[5:60, 7:90],          # a window with a row stride larger than its width
])
@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.dtype(">u2")])
def test_views_give_what_their_copies_give(small, view, dtype):
    a = small.astype(dtype)
    v = view(a)
    assert not v.flags.c_contiguous or v.base is not None
    got = erd.generate(v, "erdgpi", density=3.0, maxval=255)
    ref = erd.generate(np.ascontiguousarray(v, dtype=np.uint16), "erdgpi", density=3.0, maxval=255)
    assert same(got, ref)
    assert got.width == v.shape[1] and got.height == v.shape[0]


def test_gray_with_a_channel_axis_and_16_bit(small):
    base = erd.generate(small, "gpi", density=2.0)
    assert same(erd.generate(small[:, :, None], "gpi", density=2.0), base)
    # The same samples as uint16 with maxval 255 make the same mesh; uint16 defaults to maxval 65535.
    assert same(erd.generate(small.astype(np.uint16), "gpi", density=2.0, maxval=255), base)
    assert erd.generate(small.astype(np.uint16), "gpi", density=2.0).maxval == 65535


def test_input_array_is_not_changed_and_outputs_are_owned(small):
    before = small.copy()
    mesh = erd.generate(small, "erdgpi", density=2.0)
    assert np.array_equal(small, before)
    v = mesh.vertices
    v[:] = -1  # a fresh array each time: the mesh is not changed through it
    assert mesh.vertices.min() >= 0
    assert mesh.vertices.shape == (len(mesh), 2) and mesh.faces.shape[1] == 3
    assert mesh.vertices.dtype == np.float64 and mesh.faces.dtype == np.int64
    assert mesh.values.shape == (len(mesh),)
    assert mesh.faces.max() < len(mesh) and mesh.constrained_edges.max() < len(mesh)


def test_psnr_checks_both_arrays(small):
    with pytest.raises(ValueError, match="b has dtype"):
        erd.psnr(small, small.astype(np.int8))
    with pytest.raises(ValueError):
        erd.psnr(small, small[:-1])
    assert erd.psnr(small, small) == float("inf")
    other = small.copy()
    other[0, 0] ^= 1
    assert 60 < erd.psnr(small, other) < 100
    assert erd.psnr(small, other, maxval=65535) > erd.psnr(small, other)
