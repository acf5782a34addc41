"""The package's dataclasses and dtypes, each derived from a struct of proxima.h."""

import collections

import numpy as np

from ._core import c_dtype, check, enum_value, ffi, lib, make_dataclass, snake

_hard = ffi.new("proxForceSettings*")
check(lib.proxGetForcePreset(enum_value("proxForcePreset", "hard", "preset"), _hard, ffi.new("double*")))

ForceSettings = make_dataclass(
    "proxForceSettings", "ForceSettings",
    "A world's force settings (proxForceSettings); the defaults are the 'hard' preset's.",
    defaults=_hard[0])
MeshInfo = make_dataclass("proxMeshInfo", "MeshInfo", "Counts and bounds of a mesh (proxMeshInfo).")
MeshStats = make_dataclass("proxMeshStats", "MeshStats", "A mesh's input counts and hierarchy (proxMeshStats).")
RigInfo = make_dataclass("proxRigInfo", "RigInfo", "What a glTF mesh's rig holds (proxRigInfo).")
# proxAnimationInfo, its name decoded (a char array has no dataclass field).
Animation = collections.namedtuple("Animation", "name duration start channels")
Animation.__doc__ = "A glTF animation of a mesh (proxAnimationInfo): duration and start in seconds."
Skin = collections.namedtuple("Skin", "name joints")
Skin.__doc__ = "A glTF skin of a mesh (proxSkinInfo): its name and joint count."
WorldStats = make_dataclass("proxWorldStats", "WorldStats", "The last step's figures (proxWorldStats).")
SearchStats = make_dataclass("proxSearchStats", "SearchStats",
                             "The last step's global searches (proxSearchStats).")
PatchSettings = make_dataclass("proxPatchSettings", "PatchSettings",
                               "How LMDs merge into patches (proxPatchSettings, docs/patches.md).")
PatchStats = make_dataclass("proxPatchStats", "PatchStats",
                            "What the last step merged and found crossing (proxPatchStats).")
TrackStats = make_dataclass("proxTrackStats", "TrackStats", "The last World.track() (proxTrackStats).")
IntersectionStats = make_dataclass("proxIntersectionStats", "IntersectionStats",
                                   "The last Body.intersections() (proxIntersectionStats).")
ThreadStats = make_dataclass("proxThreadStats", "ThreadStats", "One thread's timing (proxThreadStats).")
SafetyStats = make_dataclass("proxSafetyStats", "SafetyStats",
                             "The haptic loop's safety decisions (proxSafetyStats).")
StreamDeviceStats = make_dataclass("proxStreamDeviceStats", "StreamDeviceStats",
                                   "What a streamed device saw (proxStreamDeviceStats).")
HidDeviceStats = make_dataclass("proxHidDeviceStats", "HidDeviceStats",
                                "What a HID device did since it was opened (proxHidDeviceStats).")
XrDeviceStats = make_dataclass("proxXrDeviceStats", "XrDeviceStats",
                               "What an OpenXR device did since it was created (proxXrDeviceStats); "
                               "session_state and time_source by their short names.")
# proxHidDeviceInfo, its strings decoded (a char array has no dataclass field).
HidDeviceInfo = collections.namedtuple(
    "HidDeviceInfo", "path name serial vendor_id product_id profile interface_number usage_page usage")
HidDeviceInfo.__doc__ = ("A supported HID device present now (proxHidDeviceInfo): `path` is what "
                         "World.open_hid_device opens; `profile` how its reports are read.")
ScriptedDeviceRecord = make_dataclass("proxScriptedDeviceRecord", "ScriptedDeviceRecord",
                                      "What a scripted device was handed (proxScriptedDeviceRecord).")


#: proxContactPatch's fields as contact_dtype names them: (public, C name).
PATCH_FIELDS = [("patch_" + snake(n), n) for n in c_dtype("proxContactPatch").names if n != "reserved"]


def _public_contact_dtype():
    """proxContact in snake_case: vectors as (3,) float64; then its patch's
    fields as patch_count, patch_extent, patch_spread, patch_angle; the other
    body as an object (a Body), last."""
    raw = c_dtype("proxContact")
    fields, objects = [], []
    for name, field in ffi.typeof("proxContact").fields:
        if field.type.cname == "struct proxVec3":
            fields.append((snake(name), np.float64, (3,)))
        elif field.type.cname == "struct proxBodyId":
            objects.append((snake(name), object))
        else:
            fields.append((snake(name), raw.fields[name][0]))
    # The contact's patch (proxContactPatch, docs/patches.md) beside it.
    patch = c_dtype("proxContactPatch")
    fields += [(public, patch.fields[c][0]) for public, c in PATCH_FIELDS]
    return np.dtype(fields + objects)


#: The dtype of Body.contacts(): one row per contact.
contact_dtype = _public_contact_dtype()
