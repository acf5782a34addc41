"""Shared fixtures: the shared assets, the bunny scene, the repository."""

import os
import pathlib

import numpy as np
import pytest

import proxima

REPO = pathlib.Path(__file__).resolve().parents[3]


def _assets():
    for candidate in (os.environ.get("PROXIMA_ASSETS"), REPO.parent / "shared" / "assets"):
        if candidate and (pathlib.Path(candidate) / "bunny.obj").is_file():
            return pathlib.Path(candidate)
    raise RuntimeError("the shared assets (bunny.obj) are not found: set PROXIMA_ASSETS to their folder")


ASSETS = _assets()
BUNNY = ASSETS / "bunny.obj"


@pytest.fixture
def world():
    with proxima.World() as w:
        yield w


@pytest.fixture
def bunny(world):
    return world.load_mesh(BUNNY)


def box_centre(mesh):
    info = mesh.info
    return (info.bounds_min + info.bounds_max) / 2


def unit(q):
    q = np.asarray(q, dtype=float)
    return q / np.linalg.norm(q)


# A pose of the tool bunny near the static one with several contacts (six
# with the precise method) and a rotation, so no axis is special.
NEAR_POSE = ((0.135, 0.01, 0.0), tuple(unit([0.98, 0.05, 0.1, 0.03])))


def cube():
    """A closed unit cube: 8 vertices, 12 triangles, counter-clockwise from outside."""
    v = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    t = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                  [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    return v, t
