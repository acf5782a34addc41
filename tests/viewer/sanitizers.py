"""The environment the viewer runs in during its tests. Under
AddressSanitizer (scripts/test.sh builds the whole suite with it), the
Vulkan loader unloads the driver and the validation layer before the leak
check at exit, so their own allocations would show as leaks of unknown
modules: preload keep_loaded.c's library (after the ASan runtime, which
must come first) so that lsan.supp can name those modules, and only them.
ctest passes the library's path in PROX_VIEWER_KEEP_LOADED."""

import os
import re
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))


def environment(viewer, base=None):
    env = dict(os.environ if base is None else base)
    ldd = subprocess.run(["ldd", viewer], capture_output=True, text=True).stdout
    asan = re.search(r"libasan\.so\S*\s+=>\s+(\S+)", ldd)
    if asan:
        keep = os.environ.get("PROX_VIEWER_KEEP_LOADED")
        if not keep or not os.path.exists(keep):
            raise RuntimeError("the viewer is built with AddressSanitizer: set PROX_VIEWER_KEEP_LOADED to the "
                               "proxima_viewer_keep_loaded library (ctest does)")
        # umockdev-run's own preload, if any, after these.
        env["LD_PRELOAD"] = " ".join(p for p in (asan.group(1), keep, env.get("LD_PRELOAD", "")) if p)
        options = env.get("LSAN_OPTIONS", "")
        env["LSAN_OPTIONS"] = ((options + ":") if options else "") + "print_suppressions=0:suppressions=" + \
            os.path.join(HERE, "lsan.supp")
    return env
