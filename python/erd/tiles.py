"""Rasters larger than memory in tiles that meet exactly (`erd tiles`, issue 48), from Python and on Dask.

    import erd.tiles
    index = erd.tiles.run("dem.tif", "out", method="gpi", tile=4096, merge="out/all.glb", max_error=0.5)

On a cluster, every tile is a task of its own; the result is byte for byte the one-process run's:

    from distributed import Client
    client = Client("tcp://scheduler:8786")   # workers that see the raster and `out` (a shared folder)
    erd.tiles.run("dem.tif", "out", method="erdgpi", tile=4096, density=0.5, client=client)

Options are generate's flags as keywords (max_error=0.5 -> --max-error 0.5, thesis=True -> --thesis).
The steps are also there alone: plan(), run_task(out, k) (what a worker runs), finish().
"""
import json
import os

from ._erd import _cli_main


class TilesError(RuntimeError):
    """An `erd tiles` step failed (its message went to stderr); .status is its exit status."""

    def __init__(self, step, status):
        super().__init__("erd tiles %s failed (exit status %d)" % (step, status))
        self.status = status


def _tiles(args, step):
    status = _cli_main(["erd", "tiles", "-q"] + [str(a) for a in args])
    if status != 0:
        raise TilesError(step, status)


def _flags(options):
    out = []
    for name, value in options.items():
        flag = "--" + name.replace("_", "-")
        if value is True:
            out.append(flag)
        elif value is not None and value is not False:
            out += [flag, str(value)]
    return out


def plan(raster, out, method, tile, fmt=None, **options):
    """Writes out/plan.txt (the task list: the shared borders' vertices and each tile's budget) and
    returns the number of tasks."""
    args = ["-m", method, "-i", os.fspath(raster), "--tile", tile, "-o", os.fspath(out), "--plan"]
    if fmt:
        args += ["--format", fmt]
    _tiles(args + _flags(options), "--plan")
    return tasks(out)


def tasks(out):
    """The number of tasks of the plan in out."""
    with open(os.path.join(os.fspath(out), "plan.txt")) as f:
        return sum(1 for line in f if line.startswith("task "))


def run_task(out, k):
    """Runs task k of out/plan.txt (one tile); returns k. What a Dask worker runs."""
    _tiles(["-o", os.fspath(out), "--task", k], "--task %d" % k)
    return k


def finish(out, merge=None, psnr_report=False, zscale=None):
    """Writes out/index.json (the seams checked) and, with merge, the merged mesh; returns the index."""
    args = ["-o", os.fspath(out), "--finish"]
    if merge:
        args += ["--merge", os.fspath(merge)]
    if psnr_report:
        args.append("--psnr-report")
    if zscale is not None:
        args += ["--zscale", zscale]
    _tiles(args, "--finish")
    with open(os.path.join(os.fspath(out), "index.json")) as f:
        return json.load(f)


def run(raster, out, method, tile, merge=None, client=None, fmt=None, psnr_report=False, **options):
    """plan, every task (on the Dask client's workers when given, else here in turn), finish.
    Returns the index (a dict)."""
    n = plan(raster, out, method, tile, fmt=fmt, **options)
    out = os.fspath(out)
    if client is None:
        for k in range(n):
            run_task(out, k)
    else:
        futures = client.map(run_task, [out] * n, list(range(n)), pure=False)
        client.gather(futures)
    return finish(out, merge=merge, psnr_report=psnr_report)
