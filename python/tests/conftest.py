"""Shared fixtures: the erd binary and the test images (both required: a missing one fails)."""
import os
import subprocess

import numpy as np
import pytest


def read_pgm(path):
    """A P5 PGM as (array, maxval): uint8 for maxval < 256, else uint16."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos)
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    assert fields[0] == b"P5", path
    w, h, maxval = int(fields[1]), int(fields[2]), int(fields[3])
    dtype = np.uint8 if maxval < 256 else np.dtype(">u2")
    return np.frombuffer(data[pos + 1:], dtype=dtype, count=w * h).reshape(h, w).astype(
        np.uint8 if maxval < 256 else np.uint16), maxval


def write_pgm(path, a, maxval=None):
    maxval = maxval or (255 if a.dtype == np.uint8 else 65535)
    body = a.astype(">u2").tobytes() if maxval > 255 else a.astype(np.uint8).tobytes()
    with open(path, "wb") as f:
        f.write(b"P5\n%d %d\n%d\n" % (a.shape[1], a.shape[0], maxval) + body)


@pytest.fixture(scope="session")
def erd_bin():
    path = os.environ.get("ERD_BIN", "")
    if not os.access(path, os.X_OK):
        pytest.fail("ERD_BIN must name the erd binary (got %r)" % path)
    return path


@pytest.fixture(scope="session")
def images():
    path = os.environ.get("ERD_IMAGES", "")
    if not os.path.isfile(os.path.join(path, "lena.pgm")):
        pytest.fail("ERD_IMAGES must name the folder of the test images (got %r)" % path)
    return path


@pytest.fixture(scope="session")
def lena(images):
    return read_pgm(os.path.join(images, "lena.pgm"))[0]


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, **kw)
