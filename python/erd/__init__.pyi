# Type stub of the erd package (the compiled module erd._erd plus the constants of __init__.py).
import os
from typing import Dict, List, Literal, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

PathLike = Union[str, bytes, os.PathLike]
ImageArray = Union[npt.NDArray[np.uint8], npt.NDArray[np.uint16]]
RealArray = Union[npt.NDArray[np.float32], npt.NDArray[np.float64], npt.NDArray[np.int16], npt.NDArray[np.int32], npt.NDArray[np.uint32]]
MethodName = Literal["ed", "gpi", "erded", "erdgpi", "gpr", "gprfs", "id", "erdgpr"]

METHODS: Tuple[str, ...]
__version__: str

class DensityError(ValueError):
    """The vertex count was not met exactly (exit_mode=0); the mesh made is in .mesh."""
    mesh: Mesh

class Mesh:
    """A triangle mesh of an image (basic model: ed, gpi; ERD model: erded, erdgpi)."""
    @property
    def kind(self) -> Literal["basic", "erd"]: ...
    @property
    def method(self) -> Optional[str]:
        """The method that made it; None when loaded from a file."""
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def maxval(self) -> int: ...
    @property
    def channels(self) -> int:
        """1 (gray) or 3 (RGB)."""
    @property
    def stats(self) -> Dict[str, object]:
        """The `erd generate --stats` fields that describe the mesh."""
    @property
    def vertices(self) -> npt.NDArray[np.float64]:
        """N x 2: (x, y) in pixel units."""
    @property
    def faces(self) -> npt.NDArray[np.int64]:
        """F x 3 vertex indices."""
    @property
    def values(self) -> npt.NDArray[np.float64]:
        """N (N x 3 for colour): value per vertex (ERD: mean of its wedge values)."""
    @property
    def corner_values(self) -> npt.NDArray[np.float64]:
        """F x 3 (F x 3 x 3 for colour): value of each face at each corner (the wedge values)."""
    @property
    def constrained_edges(self) -> npt.NDArray[np.int64]:
        """E x 2 vertex pairs."""
    @property
    def real(self) -> bool:
        """True for a mesh of a real-valued image (values in its units)."""
    @property
    def value_range(self) -> Tuple[float, float]:
        """(lo, hi) of a real mesh's image; (0, maxval) otherwise."""
    def reconstruct(self, supersample: Optional[bool] = None) -> Union[ImageArray, npt.NDArray[np.float64]]:
        """H x W image (H x W x 3 for colour); None: 4x4 supersampling for ERD, point evaluation for basic (as `erd reconstruct`).
        A real mesh gives float64 with NaN where its image had no data."""
    def save(self, path: PathLike) -> None:
        """Writes the .model/.erd bytes `erd generate -o` writes."""
    def export(self, path: PathLike, format: Optional[str] = None, zscale: Optional[float] = None) -> None:
        """Writes .obj, .ply, .stl or .glb (glTF 2.0) as `erd export`."""
    def glb(self, zscale: Optional[float] = None) -> bytes:
        """The mesh as glTF 2.0 binary bytes."""
    def __len__(self) -> int: ...

class Edges:
    """The half-pixel edge map and the simplified polylines of erd.edges."""
    map: npt.NDArray[np.bool_]
    polylines: List[npt.NDArray[np.float64]]
    tau_high: float
    tau_low: float

def generate(
    image: Union[ImageArray, RealArray],
    method: MethodName = "erdgpi",
    density: float = 1.0,
    points: Optional[int] = None,
    *,
    exit_mode: int = ...,
    max_error: float = ...,
    psnr: float = ...,
    min_length: int = ...,
    beta: float = ...,
    ratio: float = ...,
    epsilon: float = ...,
    select: int = ...,
    wedge_rule: int = ...,
    wedge_order: int = ...,
    startup: int = ...,
    simple: int = ...,
    seed: int = ...,
    thesis: bool = ...,
    edges: str = ...,
    wedge_fit: int = ...,
    alpha_min: float = ...,
    alpha_max: float = ...,
    edge_zero_radius: int = ...,
    flips: int = ...,
    oversample: float = ...,
    lazy: int = ...,
    bpr: int = ...,
    id_cycles: int = ...,
    id_share: float = ...,
    removal_refit: int = ...,
    removal_stages: int = ...,
    removal_cycles: int = ...,
    moves: int = ...,
    aa_errors: int = ...,
    count_search: int = ...,
    triangles: int = ...,
    maxval: int = ...,
    nodata: float = ...,
    max_slack: float = ...,
    minimax: int = ...,
    min_step: float = ...,
    max_memory: int = ...,
    threads: int = ...,
) -> Mesh:
    """Meshes a 2-D uint8/uint16 image, or a real-valued float/int16/int32 array (NaN and nodata= mark
    pixels without data), as `erd generate` does (options: its long flag names)."""

def load(path: PathLike) -> Mesh:
    """Reads a .model or .erd file."""

def psnr(a: Union[ImageArray, RealArray], b: Union[ImageArray, RealArray], maxval: Optional[int] = None) -> float:
    """PSNR of b against a in dB (inf when equal)."""

def edges(
    image: ImageArray,
    *,
    beta: float = 0.055,
    ratio: float = 0.4,
    tolerance: float = 1.0,
    min_length: int = 5,
    length_after: bool = False,
    plain_canny: bool = False,
    maxval: Optional[int] = None,
) -> Edges:
    """Half-pixel edges and simplified polylines, as `erd edges`."""
