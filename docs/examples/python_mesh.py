"""docs/python.md's example as one script: mesh peppers with ERDGPI, print the PSNR, draw the mesh
over the image (matplotlib, when installed) into docs/img/python_peppers_mesh.png.

    PYTHONPATH=python /usr/bin/python3 docs/examples/python_mesh.py ../shared/images/peppers.pgm docs/img
"""
import sys

import numpy as np

import erd


def read_pgm(path):
    """An 8-bit binary PGM (P5) without comments, as a 2-D uint8 array."""
    with open(path, "rb") as f:
        magic, width, height, maxval, pixels = f.read().split(maxsplit=4)
    assert magic == b"P5" and int(maxval) < 256
    return np.frombuffer(pixels, np.uint8, int(width) * int(height)).reshape(int(height), int(width))


image = read_pgm(sys.argv[1] if len(sys.argv) > 1 else "../shared/images/peppers.pgm")
mesh = erd.generate(image, "erdgpi", density=0.5)
approx = mesh.reconstruct()
print(mesh)
print("PSNR %.2f dB" % erd.psnr(image, approx))
print("constrained edges:", len(mesh.constrained_edges))

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
except ImportError:
    sys.exit("matplotlib is not installed (apt-get install python3-matplotlib): no picture")

v = mesh.vertices
fig, axes = plt.subplots(1, 2, figsize=(10, 5.4))
axes[0].imshow(image, cmap="gray", vmin=0, vmax=255)
axes[0].triplot(v[:, 0], v[:, 1], mesh.faces, color="deepskyblue", linewidth=0.3)
axes[0].add_collection(LineCollection(v[mesh.constrained_edges], colors="red", linewidths=0.8))
axes[0].set_title("%s mesh: %d vertices, constrained edges red" % (mesh.method, len(mesh)))
axes[1].imshow(approx, cmap="gray", vmin=0, vmax=255)
axes[1].set_title("reconstruction, %.2f dB" % erd.psnr(image, approx))
for ax in axes:
    ax.set_axis_off()
fig.tight_layout()
out = (sys.argv[2] if len(sys.argv) > 2 else ".") + "/python_peppers_mesh.png"
fig.savefig(out, dpi=90)
print("wrote", out)
