"""erd: image -> triangle mesh with explicit edge discontinuities, from numpy.

    import erd, numpy as np
    mesh = erd.generate(image, "erdgpi", density=1.0)   # image: 2-D uint8/uint16 array
    approx = mesh.reconstruct()                          # H x W array
    print(erd.psnr(image, approx), "dB")
    mesh.save("image.erd")                               # the bytes `erd generate -o` writes

Everything runs in the compiled extension erd._erd over the library's public C++ API.
erd.tiles: rasters larger than memory in tiles (`erd tiles`), also on Dask.
`python3 -m erd ...` is the erd program itself (same subcommands, options and exit statuses).
"""
from ._erd import DensityError, Edges, Mesh, edges, generate, load, psnr
from . import tiles

METHODS = ("ed", "gpi", "erded", "erdgpi", "gpr", "gprfs", "id", "erdgpr")
__version__ = "0.1.0"
__all__ = ["DensityError", "Edges", "Mesh", "METHODS", "edges", "generate", "load", "psnr", "tiles"]
