#!/usr/bin/env python3
"""Runs an NUnit 2.6 test assembly with nunit-console and prints the plain
closing line CI reads, "N passed, N failed", from the XML report. A test
that did not run (ignored, skipped, inconclusive, not runnable) counts as
failed: nothing may look green without having run.

    run_nunit.py NUNIT_CONSOLE TESTS.dll XML_OUT
"""
import subprocess
import sys
import xml.etree.ElementTree as ET


def main():
    console, assembly, xml_out = sys.argv[1:4]
    # -noshadow: the tests must load the Proxima.dll beside libproxima.so, not a copy.
    run = subprocess.run(
        ["mono", "--debug", console, "-nologo", "-noshadow", "-labels", "-xml=" + xml_out, assembly],
        check=False,
    )
    try:
        root = ET.parse(xml_out).getroot()
    except (OSError, ET.ParseError) as e:
        print(f"no NUnit report ({e}); nunit-console exited with {run.returncode}")
        print("0 passed, 1 failed")
        return 1
    passed, failed = 0, []
    for case in root.iter("test-case"):
        name = case.get("name")
        if case.get("executed") == "True" and case.get("result") == "Success":
            passed += 1
        else:
            failed.append(f"{name}: {case.get('result')}")
    for f in failed:
        print("FAILED " + f)
    if passed + len(failed) == 0:
        failed.append("no test ran")
    print(f"{passed} passed, {len(failed)} failed")
    return 0 if not failed and run.returncode == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
