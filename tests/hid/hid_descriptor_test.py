#!/usr/bin/env python3
"""Proxima's HID report descriptor parser against an independent one: the
shared devices folder's own decoder (pid/piddecode.py, which follows Linux's
hid-core and was cross-checked against hid-tools), on every real descriptor
there. Every field of every report must agree: report, bit offset, size,
count, flags, logical and physical range, unit, exponent, usages and the
logical collections around it; and so must every report's size.

    hid_descriptor_test.py DUMP_PROGRAM SHARED_DEVICES_DIR
"""
import glob
import json
import os
import subprocess
import sys


def main():
    dump, devices = sys.argv[1], sys.argv[2]
    sys.path.insert(0, os.path.join(devices, "pid"))
    import piddecode  # the shared folder's decoder, the reference here

    files = sorted(glob.glob(os.path.join(devices, "*.rdesc.bin")) + glob.glob(os.path.join(devices, "pid", "*.rdesc.bin")))
    if len(files) < 7:
        sys.exit("expected the 7 shared descriptors (4 HID, 3 PID) in %s, found %d" % (devices, len(files)))
    failures = 0
    fields_checked = 0
    for path in files:
        raw = open(path, "rb").read()
        _, ref_fields, uses_ids = piddecode.parse(raw)
        ref_sizes = {"%s:0x%02x" % k: v for k, v in piddecode.report_sizes(ref_fields, uses_ids).items()}
        ours = json.loads(subprocess.run([dump, path], check=True, capture_output=True, text=True).stdout)
        name = os.path.basename(path)
        if ours["numbered"] != uses_ids:
            print("%s: numbered %s, reference %s" % (name, ours["numbered"], uses_ids))
            failures += 1
        if ours["sizes"] != ref_sizes:
            print("%s: report sizes differ:\n  ours      %s\n  reference %s" % (name, ours["sizes"], ref_sizes))
            failures += 1
        if len(ours["fields"]) != len(ref_fields):
            print("%s: %d fields, reference %d" % (name, len(ours["fields"]), len(ref_fields)))
            failures += 1
            continue
        for k, (a, r) in enumerate(zip(ours["fields"], ref_fields)):
            want = dict(type=r["type"], report_id=r["report_id"], bit=r["bit"], size=r["size"], count=r["count"],
                        flags=r["flags"], declared_usages=r["declared_usages"], lmin=r["lmin"], lmax=r["lmax"],
                        pmin=r["pmin"], pmax=r["pmax"], unit=r["unit"], unit_exp=r["unit_exp"],
                        usages=list(r["usages"]), logical_collections=list(r["collection_path"]))
            got = dict(a)
            got["logical_collections"] = [piddecode.usage_name(u) for u in got["logical_collections"]]
            for key in want:
                if got[key] != want[key]:
                    print("%s field %d (descriptor byte %d): %s is %r, reference %r"
                          % (name, k, r["desc_offset"], key, got[key], want[key]))
                    failures += 1
            fields_checked += 1
    print("%d descriptors, %d fields compared with piddecode.py: %d differences" % (len(files), fields_checked, failures))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
