"""glTF skins, morph targets and animation (docs/dynamic-scenes.md): a
morphed triangle written here, its expected vertices worked out by hand."""

import base64
import json
import struct

import numpy as np
import pytest

import proxima


def _morphed_triangle():
    """The unit right triangle in z = 0, one morph target lifting vertex 2 by
    1 in z, and an animation 'lift' of its weight, LINEAR from 0 at t = 0 to
    1 at t = 2 s: a .gltf's bytes, its buffer embedded."""
    data = (struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<9f", 0, 0, 0, 0, 0, 0, 0, 0, 1)
            + struct.pack("<2f", 0, 2) + struct.pack("<2f", 0, 1))
    return json.dumps({
        "asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "targets": [{"POSITION": 1}]}]}],
        "animations": [{"name": "lift", "channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}}],
                        "samplers": [{"input": 2, "output": 3}]}],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 72, "byteLength": 8},
                        {"buffer": 0, "byteOffset": 80, "byteLength": 8}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
                      {"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR"},
                      {"bufferView": 3, "componentType": 5126, "count": 2, "type": "SCALAR"}]}).encode()


def _lifted_z(mesh):
    """The z of the vertex at (0, 1)."""
    v, _ = mesh.triangles()
    (row,) = np.flatnonzero((v[:, 0] == 0) & (v[:, 1] == 1))
    return v[row, 2]


def test_animations_and_animate(world):
    mesh = world.load_mesh_bytes(_morphed_triangle(), "morph.gltf")
    assert mesh.animations == [proxima.Animation("lift", 2.0, 0.0, 1)]
    assert mesh.rig == proxima.RigInfo(skin_count=0, joint_count=0, morph_weight_count=1, animation_count=1)
    assert _lifted_z(mesh) == 0.0  # at rest: weight 0
    mesh.animate(0, 1.5)  # weight 0.75
    assert _lifted_z(mesh) == pytest.approx(0.75, abs=1e-15)
    mesh.animate(0, 10.0)  # past the last keyframe: its value
    assert _lifted_z(mesh) == 1.0
    mesh.set_morph_weights([0.25])
    assert _lifted_z(mesh) == 0.25
    # set_vertices moves the vertices by hand; the next animate poses the rig again.
    v, _ = mesh.triangles()
    mesh.set_vertices(v * 2.0)
    assert np.array_equal(mesh.triangles()[0], v * 2.0)
    mesh.animate(0, 1.5)
    assert _lifted_z(mesh) == pytest.approx(0.75, abs=1e-15)


def test_skins(world):
    from conftest import ASSETS
    mesh = world.load_mesh(ASSETS / "gltf" / "RiggedFigure.glb")
    assert mesh.skins == [proxima.Skin("Armature", 19)]
    assert mesh.rig.joint_count == 19


def test_misuse_is_refused_by_name(world, bunny):
    mesh = world.load_mesh_bytes(_morphed_triangle(), "morph.gltf")
    with pytest.raises(proxima.InvalidArgument, match="animation 1 does not exist"):
        mesh.animate(1, 0.0)
    with pytest.raises(proxima.InvalidArgument, match="animate: index must be an integer"):
        mesh.animate(0.5, 0.0)
    with pytest.raises(proxima.InvalidArgument, match="count is 2 but the mesh has 1 morph weights"):
        mesh.set_morph_weights([0.1, 0.2])
    with pytest.raises(proxima.InvalidArgument, match="skin 0 does not exist"):
        mesh.set_joint_matrices(0, np.eye(4)[None])
    with pytest.raises(proxima.InvalidArgument, match=r"expected a \(J, 4, 4\) array"):
        mesh.set_joint_matrices(0, np.eye(4))
    assert bunny.animations == []
    with pytest.raises(proxima.InvalidArgument, match="the mesh has no rig"):
        bunny.animate(0, 0.0)
