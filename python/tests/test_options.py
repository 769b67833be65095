"""generate()'s keywords: the CLI's long names, checked as the CLI checks them."""
import os
import warnings

import numpy as np
import pytest

import erd


@pytest.fixture(scope="module")
def small(lena):
    return np.ascontiguousarray(lena[:128, :128])


def test_unknown_names_are_a_type_error_naming_them(small):
    with pytest.raises(TypeError, match=r"'betta' \(did you mean 'beta'\?\), 'wedgefit' \(did you mean 'wedge_fit'\?\)"):
        erd.generate(small, betta=0.1, wedgefit=2)
    with pytest.raises(TypeError, match="'zzz'; options: aa_errors, alpha_max, alpha_min, beta"):
        erd.generate(small, zzz=1)


def test_wrong_types_and_values(small):
    with pytest.raises(TypeError, match="wedge_order must be an int, got float"):
        erd.generate(small, wedge_order=5.0)
    with pytest.raises(TypeError, match="beta must be a number, got str"):
        erd.generate(small, beta="0.1")
    with pytest.raises(TypeError, match="thesis must be True or False"):
        erd.generate(small, thesis=1)
    with pytest.raises(ValueError, match="wedge_order: 4 is not an odd filter order"):
        erd.generate(small, wedge_order=4)
    with pytest.raises(ValueError, match="beta: 2 is outside"):
        erd.generate(small, beta=2)
    with pytest.raises(ValueError, match="alpha_max 0.5 is below alpha_min 0.75"):
        erd.generate(small, alpha_max=0.5)
    with pytest.raises(ValueError, match="density -1 is not a positive percentage"):
        erd.generate(small, density=-1)
    with pytest.raises(ValueError, match="unknown method 'erdx'"):
        erd.generate(small, "erdx")
    with pytest.raises(ValueError, match="exceeds"):
        erd.generate(small, points=10**9)


def test_density_and_points(small):
    assert len(erd.generate(small, "gpi", density=2.0)) == round(0.02 * 128 * 128)
    assert len(erd.generate(small, "gpi", points=100)) == 100
    assert len(erd.generate(small, "gpi", density=50.0, points=100)) == 100  # points wins


def test_exit_modes(small):
    flat = np.zeros((64, 64), np.uint8)
    flat[:, 32:] = 200  # fitted exactly by a few vertices: the greedy method stops early
    with pytest.raises(erd.DensityError, match=r"requested 82 but got \d+") as info:
        erd.generate(flat, density=2.0)
    assert isinstance(info.value, ValueError) and len(info.value.mesh) < 82
    with pytest.warns(RuntimeWarning, match="not achieved exactly"):
        erd.generate(flat, density=2.0, exit_mode=1)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert len(erd.generate(flat, density=2.0, exit_mode=2)) < 82


def test_stop_rules_and_thesis_change_the_mesh(small):
    base = erd.generate(small, "erdgpi", density=3.0)
    assert erd.generate(small, "erdgpi", density=3.0, psnr=25.0, exit_mode=2).stats["vertices"] < len(base)
    thesis = erd.generate(small, "erdgpi", density=3.0, thesis=True)
    assert not np.array_equal(thesis.corner_values, base.corner_values)
    same = erd.generate(small, "erdgpi", density=3.0, thesis=True, wedge_fit=6, flips=2, moves=2, alpha_min=0.75,
                        alpha_max=1.0, edge_zero_radius=1, aa_errors=0)
    assert np.array_equal(same.corner_values, base.corner_values)  # explicit values beat thesis=True


def test_threads_give_the_same_mesh(small):
    one = erd.generate(small, "erded", density=3.0, threads=1)
    for t in (0, 2, 3):
        other = erd.generate(small, "erded", density=3.0, threads=t)
        assert np.array_equal(one.vertices, other.vertices) and np.array_equal(one.corner_values, other.corner_values)
    with pytest.raises(ValueError):
        erd.generate(small, density=3.0, threads=-1)


def test_stats_are_the_cli_fields(small):
    s = erd.generate(small, "erdgpi", density=2.0).stats
    assert s["method"] == "erdgpi" and s["model"] == "erd"
    assert s["image"] == {"width": 128, "height": 128, "maxval": 255, "channels": 1}
    assert s["points"]["requested"] == s["points"]["achieved"] == s["vertices"]
    assert 0 < s["constrained_edges"] and 0 < s["constrained_vertices"] < s["vertices"]
    assert set(s["parameters"]) == {"beta", "r", "l", "epsilon", "simple", "edges"} and s["stop"] == "target"
    assert [t["name"] for t in s["stages"]][:2] == ["initial mesh", "wedge values"]
    basic = erd.generate(small, "ed", density=2.0).stats
    assert basic["parameters"] is None and basic["stop"] is None and basic["model"] == "basic"


def test_stats_match_the_cli_json(erd_bin, images, tmp_path):
    import json
    import subprocess
    from conftest import read_pgm
    path = os.path.join(images, "house.pgm")
    r = subprocess.run([erd_bin, "generate", "--method", "erdgpi", "-i", path, "-d", "1", "-o", str(tmp_path / "h.erd"),
                        "-q", "--stats", str(tmp_path / "s.json")])
    assert r.returncode == 0
    cli = json.loads((tmp_path / "s.json").read_text())
    ours = erd.generate(read_pgm(path)[0], "erdgpi", density=1.0).stats
    for key in ("method", "model", "image", "points", "vertices", "faces", "constrained_vertices", "constrained_edges",
                "dropped_constraints", "parameters", "stop"):
        assert ours[key] == cli[key], key
    assert [t["name"] for t in ours["stages"]] == [t["name"] for t in cli["stages"]][1:-1]  # less read and write


def test_load_errors(tmp_path):
    with pytest.raises(OSError, match="nosuch.erd"):
        erd.load(tmp_path / "nosuch.erd")
    bad = tmp_path / "bad.erd"
    bad.write_text("255\n3\n0 0 1\n")
    with pytest.raises(ValueError, match="bad.erd: "):
        erd.load(bad)
    (tmp_path / "x.tri").write_text("erd-triangulation 1\n")
    with pytest.raises(ValueError, match="no values"):
        erd.load(tmp_path / "x.tri")


def test_save_errors(small, tmp_path):
    mesh = erd.generate(small, "gpi", density=1.0)
    with pytest.raises(OSError, match="nodir"):
        mesh.save(tmp_path / "nodir" / "m.model")
    mesh.save(str(tmp_path / "m.model"))
    mesh.save(os.fsencode(tmp_path / "b.model"))
    assert (tmp_path / "m.model").read_bytes() == (tmp_path / "b.model").read_bytes()


def test_removal_methods_and_bpr_are_reachable(small):
    """Issue 45: gpr, gprfs, id, erdgpr and --bpr from Python, N exact, the options' CLI names."""
    assert {"gpr", "gprfs", "id", "erdgpr"} <= set(erd.METHODS)
    n = 160
    for method in ("gprfs", "id", "erdgpr"):
        mesh = erd.generate(small, method, points=n)
        assert len(mesh.vertices) == n
    plain = erd.generate(small, "gpi", points=n)
    moved = erd.generate(small, "gpi", points=n, bpr=1)
    assert len(moved.vertices) == n
    assert not np.array_equal(plain.vertices, moved.vertices)
    erd.generate(small, "gprfs", points=n, oversample=8.0, lazy=1)
    erd.generate(small, "id", points=n, id_cycles=1, id_share=0.5)
    with pytest.raises(ValueError, match="oversample"):
        erd.generate(small, "gprfs", points=n, oversample=0.5)
    # erdgpr's own end (3 rounds of flips and moves, longer moves) unless flips= or moves= is given:
    # the generic end given makes another mesh.
    own = erd.generate(small, "erdgpr", points=n)
    generic = erd.generate(small, "erdgpr", points=n, flips=2, moves=2)
    assert len(generic.vertices) == n
    assert not (np.array_equal(own.vertices, generic.vertices) and np.array_equal(own.corner_values, generic.corner_values))
