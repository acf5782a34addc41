"""The build backend: scikit-build-core's, with an sdist that holds the SDK.

The package builds the SDK from the repository around bindings/python, which
scikit-build-core's sdist (this directory only) would leave out. This sdist
adds the repository's top-level CMakeLists.txt and sdk/ under sdk-root/
(CMakeLists.txt finds them there), and pins the version, read from the
header at sdist time, into its pyproject.toml: a wheel built from it needs
nothing outside it.
"""

import io
import os
import re
import tarfile

from scikit_build_core.build import *  # noqa: F401,F403 (the PEP 517 hooks this backend does not change)
from scikit_build_core.build import build_sdist as _build_sdist

_HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
_ROOT = os.path.dirname(os.path.dirname(_HERE))


def _sdk_files():
    yield os.path.join(_ROOT, "CMakeLists.txt")
    for top, dirs, files in os.walk(os.path.join(_ROOT, "sdk")):
        dirs[:] = sorted(d for d in dirs if d != "__pycache__")
        for name in sorted(files):
            yield os.path.join(top, name)


def _pinned_pyproject(text, version):
    text = text.replace('dynamic = ["version"]', f'version = "{version}"')
    return re.sub(r"\n\[tool\.scikit-build\.metadata\.version\]\n(?:[^\[\n][^\n]*\n|\n)*", "\n", text)


def build_sdist(sdist_directory, config_settings=None):
    if not os.path.isfile(os.path.join(_ROOT, "sdk", "include", "proxima", "proxima.h")):
        # Already an sdist (or a copy of this directory alone): it holds sdk-root/.
        return _build_sdist(sdist_directory, config_settings)
    name = _build_sdist(sdist_directory, config_settings)
    path = os.path.join(sdist_directory, name)
    with tarfile.open(path, "r:gz") as original:
        members = [(m, original.extractfile(m).read() if m.isfile() else None) for m in original.getmembers()]
    prefix = members[0][0].name.split("/")[0]
    version = prefix.rsplit("-", 1)[1]
    with tarfile.open(path, "w:gz", format=tarfile.PAX_FORMAT) as out:
        for member, data in members:
            if member.name == f"{prefix}/pyproject.toml":
                data = _pinned_pyproject(data.decode(), version).encode()
                member.size = len(data)
            out.addfile(member, io.BytesIO(data) if data is not None else None)
        for file in _sdk_files():
            arcname = f"{prefix}/sdk-root/{os.path.relpath(file, _ROOT)}"
            info = out.gettarinfo(file, arcname)
            info.uid = info.gid = 0
            info.uname = info.gname = ""
            info.mtime = members[0][0].mtime
            with open(file, "rb") as f:
                out.addfile(info, f)
    return name
